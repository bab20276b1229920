#include "model/FlameExchange.h"

#include "core/Messages.h"
#include "core/analysis/Spectrum.h"
#include "core/ifs/Attractor.h"
#include "core/flame/FlameChaos.h"
#include "model/AttractorItem.h"
#include "model/CifsItem.h"
#include "core/ifs/Cifs.h"
#include "model/FlameFile.h"
#include "model/FlameItem.h"
#include "model/Item.h"
#include "model/ProjectIO.h"

#include <QColor>
#include <QJsonArray>
#include <QFileInfo>

#include <Eigen/LU>

#include <algorithm>
#include <cmath>
#include <optional>

namespace awb {

namespace {

struct FlameTr {
    Q_DECLARE_TR_FUNCTIONS(awb::FlameExchange)
};

// Row convention (Ifs.h: x |-> x A + b) of a flame's affine map, in the flame's orientation.
AffineMap rowAffine(const flame::Affine2 &m)
{
    AffineMap f{Mat(2, 2), RowVec(2)};
    f.A << m.a, m.d, m.b, m.e;
    f.b << m.c, m.f;
    return f;
}

// g = R f R with R = diag(1, -1): the map in the other orientation of y.
AffineMap mirrored(const AffineMap &f)
{
    AffineMap g = f;
    g.A(0, 1) = -f.A(0, 1);
    g.A(1, 0) = -f.A(1, 0);
    g.b(1) = -f.b(1);
    return g;
}

// post(w pre(x)) in the row convention.
AffineMap composed(const AffineMap &pre, double w, const AffineMap &post)
{
    AffineMap f;
    f.A = w * pre.A * post.A;
    f.b = w * pre.b * post.A + post.b;
    return f;
}

// An xform that is an affine map: the linear variation alone, every point it gives drawn.
bool affineXform(const flame::FlameXform &x)
{
    return x.variations.size() == 1 && x.variations.front().id == 0 && x.opacity == 1;
}

AffineMap xformMap(const flame::FlameXform &x)
{
    return composed(rowAffine(x.pre), x.variations.front().weight, rowAffine(x.post));
}

// A flame that is the IFS of its maps post(w pre(x)): every xform affine, no xaos row that
// forbids or reweights a transition, and a final xform, if any, affine and invertible (the
// picture is then F(A), the attractor of the conjugates F f_i F^-1). It is imported as a
// fractal with control points, whose maps are analysed exactly; every other flame as a flame
// item, drawn by flam3's chaos game (model/FlameItem.h).
bool affineFlame(const flame::Flame &f)
{
    for (const flame::FlameXform &x : f.xforms) {
        if (!affineXform(x))
            return false;
        for (std::size_t j = 0; j < f.xforms.size(); ++j)
            if (x.xaosTo(j) != 1.0)
                return false;
    }
    if (f.finalXform) {
        if (!affineXform(*f.finalXform))
            return false;
        const AffineMap F = xformMap(*f.finalXform);
        if (!(std::abs(F.A.determinant()) > 1e-12 * std::max(1.0, F.A.squaredNorm())))
            return false;
    }
    return true;
}

QString place(const QString &file, qint64 line, qint64 column)
{
    return FlameTr::tr("%1, line %2, column %3: ").arg(file).arg(line).arg(column);
}

// An affine flame as a fractal with control points, or a problem.
void importAffineFlame(const FlameRead &r, const QString &name, const QString &file,
                       ImportedItems &out)
{
    const flame::Flame &flame = r.flame;
    FractintEntry e;
    e.name = name.toStdString();
    e.dimension = 2;
    e.line = int(r.line);
    std::optional<AffineMap> F, Finv;
    if (flame.finalXform) {
        F = xformMap(*flame.finalXform);
        Finv = AffineMap{};
        Finv->A = F->A.inverse();
        Finv->b = -F->b * Finv->A;
    }
    QStringList colours;
    for (const flame::FlameXform &x : flame.xforms) {
        const AffineMap m = xformMap(x);
        AffineMap f = m;
        if (F) {
            f.A = Finv->A * m.A * F->A;
            f.b = Finv->b * m.A * F->A + m.b * F->A + F->b;
        }
        e.maps.push_back(mirrored(f));
        e.probabilities.push_back(x.weight);
        const flame::FlameColour &c =
            flame.palette[std::size_t(std::clamp(int(x.colour * 255.0 + 0.5), 0, 255))];
        colours << QColor::fromRgbF(float(c.r), float(c.g), float(c.b)).name();
    }
    double total = 0;
    for (double p : e.probabilities)
        total += p;
    if (!(total > 0)) {
        out.problems << place(file, r.line, r.column)
                            + FlameTr::tr("flame '%1': every xform has weight 0").arg(name);
        return;
    }
    try {
        out.items.push_back(importedFractal(e, colours, 1000000));
    } catch (const LoadError &error) {
        out.problems << place(file, r.line, r.column)
                            + FlameTr::tr("flame '%1': %2 (%3)").arg(name, error.message, error.field);
        return;
    } catch (const std::exception &error) {
        out.problems << place(file, r.line, r.column)
                            + FlameTr::tr("flame '%1': %2").arg(name, QString::fromUtf8(error.what()));
        return;
    }
    // flam3 draws any genome, discarding the points that escape; an IFS that does not even
    // contract on average has no attractor, and the user hears it here, not at the render.
    if (const auto *item = dynamic_cast<const AttractorItem *>(out.items.back().get()))
        if (const auto d = item->derivedIfs(); d && d->ifs.size() > 0)
            if (const IfsCheck check = checkIfs(d->ifs); !check.contractsOnAverage())
                out.warnings << place(file, r.line, r.column)
                                    + FlameTr::tr("flame '%1': its maps do not contract, not "
                                                  "even on average (the Lyapunov exponent of "
                                                  "their products, %2, is not clearly negative: "
                                                  "not below -0.001), so it may have no "
                                                  "attractor; flam3 draws it only by discarding "
                                                  "the points that escape")
                                          .arg(name)
                                          .arg(check.lyapunov ? *check.lyapunov : qQNaN(), 0,
                                               'g', 3);
}

// A flame whose xforms are all affine but whose xaos rows restrict which xform may follow which
// (and whose final xform, if any, is affine): the controlled IFS it is (issue 46). State j holds
// the points just drawn by xform j, A_j = f_j(union of A_i over the xforms i that may precede
// j), so state j's arcs lead to those i, each carrying f_j. All states share one frame
// triangle around flam3's camera, the maps written in its barycentric coordinates; a final
// xform F, affine, moves the frame: F(lambda P) = lambda F(P). The arcs' weights make the
// item's random iteration (a path drawn backwards from each state) the time reversal of
// flam3's chain: P(i before j) = pi_i P(j | i) / pi_j with pi flam3's stationary law, so the
// two draw the same measure, not only the same set.
bool linearXaosFlame(const flame::Flame &f)
{
    for (const flame::FlameXform &x : f.xforms)
        if (!affineXform(x))
            return false;
    return !f.finalXform || affineXform(*f.finalXform);
}

void importXaosFlame(const FlameRead &r, const QString &name, const QString &file,
                     ImportedItems &out)
{
    const flame::Flame &f = r.flame;
    const int n = int(f.xforms.size());
    // flam3's chain: P(j | i) = w_j xaos(i, j) / sum_k w_k xaos(i, k).
    Mat P = Mat::Zero(n, n);
    for (int i = 0; i < n; ++i) {
        double z = 0;
        for (int j = 0; j < n; ++j)
            z += (P(i, j) = std::max(0.0, f.xforms[size_t(j)].weight)
                            * std::max(0.0, f.xforms[size_t(i)].xaosTo(size_t(j))));
        if (z > 0)
            P.row(i) /= z;
    }
    // Its stationary law, by the lazy chain (it converges for periodic chains too).
    RowVec pi = RowVec::Constant(n, 1.0 / n);
    for (int k = 0; k < 4000; ++k)
        pi = 0.5 * (pi + pi * P);
    // The states that keep an arc: an xform no other may precede is never drawn again.
    std::vector<bool> alive(size_t(n), true);
    for (bool changed = true; changed;) {
        changed = false;
        for (int j = 0; j < n; ++j) {
            if (!alive[size_t(j)])
                continue;
            bool arc = false;
            for (int i = 0; i < n && !arc; ++i)
                arc = alive[size_t(i)] && P(i, j) > 0;
            if (!arc) {
                alive[size_t(j)] = false;
                changed = true;
            }
        }
    }
    if (std::none_of(alive.begin(), alive.end(), [](bool a) { return a; })) {
        out.problems << place(file, r.line, r.column)
                            + FlameTr::tr("flame '%1': its xaos rows let no xform follow another")
                                  .arg(name);
        return;
    }
    const RasterFrame camera = flame::flameFrame(f);
    // The frame: a triangle holding the camera's rectangle (y up, the application's).
    const double w = camera.x1 - camera.x0, h = camera.y1 - camera.y0;
    Mat frame(3, 2);
    frame << camera.x0 - w / 2, camera.y0, camera.x1 + w / 2, camera.y0,
        (camera.x0 + camera.x1) / 2, camera.y1 + h;
    Mat drawnFrame = frame;
    if (f.finalXform) {
        const AffineMap F = mirrored(xformMap(*f.finalXform));
        drawnFrame = (frame * F.A).rowwise() + F.b;
    }
    QJsonArray points;
    for (Eigen::Index k = 0; k < drawnFrame.rows(); ++k)
        points.append(QJsonArray{drawnFrame(k, 0), drawnFrame(k, 1)});
    const auto stateName = [&](int j) {
        const QString own = QString::fromStdString(f.xforms[size_t(j)].name).trimmed();
        return own.isEmpty() || own == CifsSpec::allStates ? QStringLiteral("x%1").arg(j + 1)
                                                           : own;
    };
    QJsonArray states, arcs, colours;
    for (int j = 0; j < n; ++j)
        if (alive[size_t(j)])
            states.append(QJsonObject{{"name", stateName(j)}, {"control_points", points}});
    for (int j = 0; j < n; ++j) {
        if (!alive[size_t(j)])
            continue;
        Mat S;
        try {
            S = barycentricMatrix(mirrored(xformMap(f.xforms[size_t(j)])), frame, frame);
        } catch (const InputError &e) {
            out.problems << place(file, r.line, r.column)
                                + FlameTr::tr("flame '%1': %2").arg(name, QString::fromUtf8(e.what()));
            return;
        }
        QJsonArray rows;
        for (Eigen::Index k = 0; k < S.rows(); ++k)
            rows.append(QJsonArray{S(k, 0), S(k, 1), S(k, 2)});
        const flame::FlameColour &c = f.palette[std::size_t(
            std::clamp(int(f.xforms[size_t(j)].colour * 255.0 + 0.5), 0, 255))];
        for (int i = 0; i < n; ++i)
            if (alive[size_t(i)] && P(i, j) > 0) {
                arcs.append(QJsonObject{{"name", stateName(j) + " after " + stateName(i)},
                                        {"from", stateName(j)},
                                        {"to", stateName(i)},
                                        {"matrix", rows},
                                        {"weight", std::max(1e-300, pi(i) * P(i, j))}});
                colours.append(QColor::fromRgbF(float(c.r), float(c.g), float(c.b)).name());
            }
    }
    if (arcs.size() > kMaxMaps) {
        out.problems << place(file, r.line, r.column)
                            + FlameTr::tr("flame '%1': its xaos rows make %2 arcs between its "
                                          "xforms, more than the %3 a controlled IFS may have")
                                  .arg(name).arg(arcs.size()).arg(kMaxMaps);
        return;
    }
    const QJsonObject json{
        {"type", "cifs"},
        {"name", name},
        {"states", states},
        {"arcs", arcs},
        {"state", CifsSpec::allStates},
        {"algorithm",
         QJsonObject{{"mode", "random"},
                     {"samples", qint64(std::clamp(flame::flameSamples(f), 2e6, 2e7))},
                     {"seed", 1},
                     {"depth", 6}}},
        {"style", QJsonObject{{"color_by", "map"}, {"colors", colours}}}};
    try {
        auto item = std::make_unique<CifsItem>();
        const FieldReader fields(json, QString());
        item->read(fields);
        item->checkLoaded(fields);
        item->setName(name);
        if (!item->derivedIfs())
            out.warnings << place(file, r.line, r.column)
                                + FlameTr::tr("flame '%1': %2").arg(name, item->derivedError());
        out.items.push_back(std::move(item));
    } catch (const LoadError &error) {
        out.problems << place(file, r.line, r.column)
                            + FlameTr::tr("flame '%1': %2 (%3)").arg(name, error.message, error.field);
    }
}

// Any other flame as a flame item: everything flam3 draws is kept.
void importFlameItem(const FlameRead &r, const QString &name, const QString &file,
                     ImportedItems &out)
{
    auto item = std::make_unique<FlameItem>();
    item->setName(name);
    const flame::Flame f = canonicalFlame(r.flame);
    QString error;
    if (!item->setFlame(f, 0, &error)) {
        out.problems << place(file, r.line, r.column)
                            + FlameTr::tr("flame '%1': %2").arg(name, error);
        return;
    }
    AlgorithmSpec algorithm = item->algorithm();
    // flam3's sample count (quality x width x height), within what one picture takes: at least
    // 2e6, since flam3-genome's thumbnails (quality 1, 100 x 100) would look like dust.
    algorithm.samples = qint64(std::clamp(flame::flameSamples(f), 2e6, 1e8));
    // Unused in random mode, but still bounded by the number of maps.
    algorithm.depth = std::min(algorithm.depth, AlgorithmSpec::maxDepthFor(int(f.xforms.size())));
    item->setAlgorithm(algorithm);
    out.items.push_back(std::move(item));
}

// The shortest text that reads back as exactly v: round trips keep every map.
QString number(double v)
{
    return QString::fromStdString(shortestNumber(v));
}

} // namespace

ImportedItems importFlameText(const QByteArray &text, const QString &fileName)
{
    const FlameFileRead read = readFlameText(text, fileName);
    const QString file = QFileInfo(fileName).fileName();
    ImportedItems out;
    out.problems = read.problems;
    out.warnings = read.warnings;
    for (std::size_t k = 0; k < read.flames.size(); ++k) {
        const FlameRead &r = read.flames[k];
        QString name = QString::fromStdString(r.flame.name).trimmed();
        if (name.isEmpty())
            name = FlameTr::tr("flame %1").arg(k + 1);
        const std::size_t before = out.items.size();
        if (affineFlame(r.flame))
            importAffineFlame(r, name, file, out);
        else if (linearXaosFlame(r.flame))
            importXaosFlame(r, name, file, out);
        else
            importFlameItem(r, name, file, out);
        // What is imported must read back as a project file holds it (the fields' declared
        // ranges: quality="1e12" would be refused by every reader of the project it went
        // into): an item that does not is left out, with the reader's words.
        for (std::size_t i = before; i < out.items.size();) {
            QString error;
            if (ProjectIO::copyItem(*out.items[i], &error)) {
                ++i;
                continue;
            }
            out.problems << FlameTr::tr("%1: flame '%2' not imported: %3").arg(file, name, error);
            out.items.erase(out.items.begin() + std::ptrdiff_t(i));
        }
    }
    return out;
}

ImportedItems importFlame(const QString &fileName)
{
    return importFlameText(readExchangeFile(fileName), fileName);
}

std::optional<FractintEntry> flameEntryOf(const AttractorItem &item, QString *why)
{
    auto entry = fractintEntryOf(item, why, FlameTr::tr("a flam3 flame"));
    if (entry && entry->dimension != 2) {
        if (why)
            *why = FlameTr::tr("%1 is an IFS of space: a flam3 flame holds maps of the plane "
                               "(export it as a Fractint .ifs entry)")
                       .arg(item.name());
        return std::nullopt;
    }
    return entry;
}

std::optional<QByteArray> flameOf(const AttractorItem &item, const QStringList &mapColours,
                                  const FlameFrame &frame, QString *why)
{
    // A flame item is written as it is: every field flam3 draws (model/FlameFile.h), its own
    // camera and palette.
    if (const auto *flame = qobject_cast<const FlameItem *>(&item))
        return flameFileText({flame->namedFlame()});
    const auto entry = flameEntryOf(item, why);
    if (!entry)
        return std::nullopt;
    const QRectF w = frame.world.normalized();
    if (!(w.width() > 0) || frame.size.isEmpty() || !std::isfinite(w.width())) {
        if (why)
            *why = FlameTr::tr("the flame's frame is empty");
        return std::nullopt;
    }
    const int n = int(entry->maps.size());
    // Map i takes palette entry c_i = 255 i / (n - 1); the palette holds each map's colour
    // from its entry to the next one's.
    std::vector<int> entryOf(std::size_t(n), 0);
    for (int i = 0; i < n; ++i)
        entryOf[std::size_t(i)] = n > 1 ? int(std::lround(255.0 * i / (n - 1))) : 0;
    QByteArray out;
    out += "<flames name=\"Attractor Workbench\">\n";
    const double scale = frame.size.width() / w.width();
    out += QStringLiteral("<flame name=\"%1\" version=\"Attractor Workbench\" size=\"%2 %3\" "
                          "center=\"%4 %5\" scale=\"%6\" rotate=\"0\" quality=\"50\" "
                          "supersample=\"1\" filter=\"0.5\" filter_shape=\"gaussian\" "
                          "oversample=\"1\" background=\"0 0 0\" brightness=\"4\" gamma=\"4\" "
                          "vibrancy=\"1\" estimator_radius=\"0\" palette_mode=\"step\">\n")
               .arg(item.name().toHtmlEscaped())
               .arg(frame.size.width())
               .arg(frame.size.height())
               .arg(number(w.center().x()), number(-w.center().y()), number(scale))
               .toUtf8();
    // color_speed 1: a point takes the colour of the last map applied, as the window colours
    // by map (with flam3's usual 0.5 the colours of successive maps mix: issue 47's fern
    // showed one frond in another colour in flam3-render).
    for (int i = 0; i < n; ++i) {
        const AffineMap f = mirrored(entry->maps[std::size_t(i)]);
        out += QStringLiteral("   <xform weight=\"%1\" color=\"%2\" color_speed=\"1\" "
                              "linear=\"1\" coefs=\"%3 %4 %5 %6 %7 %8\" opacity=\"1\"/>\n")
                   .arg(number(entry->probabilities[std::size_t(i)]),
                        number(entryOf[std::size_t(i)] / 255.0), number(f.A(0, 0)),
                        number(f.A(0, 1)), number(f.A(1, 0)), number(f.A(1, 1)), number(f.b(0)),
                        number(f.b(1)))
                   .toUtf8();
    }
    for (int k = 0, i = 0; k < 256; ++k) {
        while (i + 1 < n && k >= entryOf[std::size_t(i + 1)])
            ++i;
        QColor c(mapColours.value(i));
        if (!c.isValid())
            c = Qt::white;
        out += QStringLiteral("   <color index=\"%1\" rgb=\"%2 %3 %4\"/>\n")
                   .arg(k)
                   .arg(c.red())
                   .arg(c.green())
                   .arg(c.blue())
                   .toUtf8();
    }
    out += "</flame>\n</flames>\n";
    return out;
}

} // namespace awb
