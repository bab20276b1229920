// libFuzzer target of flam3 genomes (issue 34): any bytes through importFlameText
// (model/FlameExchange.h). Reading never throws: every flame is imported or named as a problem
// with its place, every loss is a warning with its place. An imported flame is a custom
// fractal of affine maps of the plane with finite coefficients and probabilities -- written
// back by flameOf and read again, it has as many maps with the same coefficients -- or a flame
// item (issue 45) whose flame the core can play; written back by flameFileText and read again,
// that flame is the same, number for number.
#include "core/flame/FlameChaos.h"
#include "model/CifsItem.h"
#include "model/FlameExchange.h"
#include "model/FlameFile.h"
#include "model/FlameItem.h"
#include "model/FractalItem.h"

#include <QByteArray>
#include <QString>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>

namespace {

[[noreturn]] void fail(const char *what)
{
    std::fprintf(stderr, "fuzz_flame: %s\n", what);
    std::abort();
}

bool near(double a, double b)
{
    return std::abs(a - b) <= 1e-8 * std::max({1.0, std::abs(a), std::abs(b)});
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    const QByteArray bytes(reinterpret_cast<const char *>(data), qsizetype(size));
    awb::ImportedItems imported;
    try {
        imported = awb::importFlameText(bytes, QStringLiteral("fuzz.flame"));
    } catch (...) {
        fail("importFlameText threw");
    }
    for (const QString &p : imported.problems + imported.warnings)
        if (!p.startsWith(QStringLiteral("fuzz.flame")))
            fail("a problem or warning without its file");
    // The round trip costs a cage (6000 steps of random iteration) per flame: the first few.
    int checked = 0;
    for (const auto &item : imported.items) {
        if (const auto *flameItem = qobject_cast<const awb::FlameItem *>(item.get())) {
            try {
                awb::flame::checkFlame(flameItem->flame());
            } catch (...) {
                fail("a flame item the core cannot play");
            }
            if (checked++ >= 3)
                continue;
            const QByteArray text = awb::flameFileText({flameItem->namedFlame()});
            const awb::FlameFileRead back = awb::readFlameText(text, QStringLiteral("back.flame"));
            if (back.flames.size() != 1 || !back.problems.isEmpty())
                fail("a written flame item does not come back");
            // The palette goes out as flam3 writes it, channels times 255: back within 1e-12.
            awb::flame::Flame again = awb::canonicalFlame(back.flames.front().flame);
            for (std::size_t i = 0; i < again.palette.size(); ++i) {
                const auto &a = again.palette[i], &b = flameItem->flame().palette[i];
                if (!near(a.r, b.r) || !near(a.g, b.g) || !near(a.b, b.b))
                    fail("a palette colour changed on the way back");
            }
            again.palette = flameItem->flame().palette;
            if (again != flameItem->flame())
                fail("a written flame item comes back changed");
            continue;
        }
        // A linear flame with xaos: a controlled IFS whose matrices are finite and stochastic.
        if (const auto *cifs = qobject_cast<const awb::CifsItem *>(item.get())) {
            if (cifs->spec().check())
                fail("an imported automaton its own check refuses");
            if (cifs->spec().arcs.empty() || cifs->spec().states.empty())
                fail("an imported automaton without states or arcs");
            continue;
        }
        const auto *fractal = qobject_cast<const awb::FractalItem *>(item.get());
        if (!fractal)
            fail("an imported flame that is neither a fractal, an automaton nor a flame item");
        const auto &maps = fractal->fractal().maps;
        if (maps.empty())
            fail("a flame without maps");
        for (const awb::AffineMap &f : maps)
            if (f.A.rows() != 2 || f.A.cols() != 2 || f.b.size() != 2 || !f.A.allFinite()
                || !f.b.allFinite())
                fail("a map that is not a finite affine map of the plane");
        for (double p : fractal->algorithm().probabilities)
            if (!(p >= 0) || !std::isfinite(p))
                fail("a probability that is negative or not finite");
        if (checked++ >= 3)
            continue;
        QString why;
        const auto text = awb::flameOf(*fractal, {}, {QRectF(-1, -1, 2, 2), QSize(100, 100)}, &why);
        if (!text)
            continue;  // an item the writer refuses says why
        const awb::ImportedItems back = awb::importFlameText(*text, QStringLiteral("back.flame"));
        if (back.items.size() != 1) {
            // The cage of maps that leave every bound is refused on the way back too.
            if (!back.problems.isEmpty())
                continue;
            fail("a written flame does not come back");
        }
        const auto &again =
            qobject_cast<const awb::FractalItem *>(back.items.front().get())->fractal().maps;
        if (again.size() != maps.size())
            fail("a written flame comes back with another number of maps");
        for (std::size_t i = 0; i < maps.size(); ++i)
            for (int r = 0; r < 2; ++r) {
                if (!near(again[i].b(r), maps[i].b(r)))
                    fail("a translation changed on the way back");
                for (int c = 0; c < 2; ++c)
                    if (!near(again[i].A(r, c), maps[i].A(r, c)))
                        fail("a coefficient changed on the way back");
            }
    }
    return 0;
}
