// libFuzzer target of Fractint's .ifs files (issue 34): any bytes through readFractintIfs
// (core/exchange/FractintIfs.h). Reading never throws: every entry is kept or named as a
// problem with a place in the file. A kept entry must hold what the reader promises (2D or 3D
// maps of its dimension, finite, one probability each, >= 0), come back from the writer with
// the same shape and the same coefficients, and give a control cage of
// finite corners or an InputError (maps that do not contract).
// Numbers come back bit for bit (shortest round-trip numbers), names as written.
#include "core/exchange/FractintIfs.h"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>

namespace {

[[noreturn]] void fail(const char *what)
{
    std::fprintf(stderr, "fuzz_fractint_ifs: %s\n", what);
    std::abort();
}

// The writer's numbers are the shortest that read back exactly: the same doubles.
bool near(double a, double b)
{
    return a == b;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    std::istringstream in(std::string(reinterpret_cast<const char *>(data), size));
    const awb::FractintFile file = awb::readFractintIfs(in);
    for (const awb::FractintProblem &p : file.problems)
        if (p.line < 1 || p.column < 1 || p.message.empty())
            fail("a problem without its place or message");
    // The checks of an entry cost far more than reading it (the cage runs 6000 steps of random
    // iteration): the first entries only, so that one input stays well within libFuzzer's 1 s.
    std::size_t checked = 0;
    for (const awb::FractintEntry &e : file.entries) {
        if (++checked > 8)
            break;
        if ((e.dimension != 2 && e.dimension != 3) || e.maps.empty()
            || e.probabilities.size() != e.maps.size())
            fail("an entry without maps, or maps and probabilities of different counts");
        for (std::size_t i = 0; i < e.maps.size(); ++i) {
            const awb::AffineMap &f = e.maps[i];
            if (f.dim() != e.dimension || f.b.size() != e.dimension || !f.A.allFinite()
                || !f.b.allFinite() || !(e.probabilities[i] >= 0)
                || !std::isfinite(e.probabilities[i]))
                fail("a map not of the entry's dimension, or a number not finite");
        }
        std::istringstream back(awb::fractintEntryText(e));
        const awb::FractintFile again = awb::readFractintIfs(back);
        if (again.entries.size() != 1 || !again.problems.empty())
            fail("the writer's entry does not read back as one entry");
        const awb::FractintEntry &g = again.entries.front();
        if (g.dimension != e.dimension || g.maps.size() != e.maps.size())
            fail("the entry read back has another shape");
        if (g.name != e.name && e.name.find_first_of("{};,\t\r\n\v\f") == std::string::npos
            && e.name.rfind("entry at line", 0) != 0
            && (e.name.size() < 4 || (e.name.substr(e.name.size() - 4) != "(3D)"
                                      && e.name.substr(e.name.size() - 4) != "(3d)")))
            fail("the entry's name read back differs");
        for (std::size_t i = 0; i < e.maps.size(); ++i) {
            const std::vector<double> a = awb::fractintCoefficients(e.maps[i]);
            const std::vector<double> b = awb::fractintCoefficients(g.maps[i]);
            for (std::size_t k = 0; k < a.size(); ++k)
                if (!near(a[k], b[k]))
                    fail("a coefficient read back differs beyond the writer's digits");
            if (!near(e.probabilities[i], g.probabilities[i]))
                fail("a probability read back differs");
        }
        if (checked > 2)
            continue;
        try {
            if (!awb::fractintControlCage(e).allFinite())
                fail("a control cage with corners that are not finite");
        } catch (const awb::InputError &) {
            // maps that do not contract: refused with a message
        }
    }
    return 0;
}
