#pragma once
// Where a one-parameter family of schemes is C^k (layer 1, no Qt): the four-point scheme's
// tension omega, a corner cutting's a or b. Each parameter value gets certified Hölder bounds
// [lower, upper] (Regularity.h); the value is certified C^k when lower > k and certified not
// C^k when upper <= k (upper is the exact exponent when the shifts are stable, as for the
// interpolatory four-point scheme; see Regularity.h). A grid over [from, to] finds the runs of
// certified C^k values, and bisection on certified values narrows each end of a run to a
// bracket [inner, outer]: inner certified C^k, outer certified not (or undecided where the
// bounds cannot tell, near r = k, or the search range's end). The four-point scheme is C^1
// exactly for 0 < omega < omega*, omega* the real root of 32 w^3 + 4 w - 1 = 0 (0.19273,
// Hechler, Mößner & Reif 2009).

#include "core/analysis/Regularity.h"

#include <atomic>
#include <functional>
#include <vector>

namespace awb {

struct FamilySample {
    double parameter = 0.0;
    double lower = 0.0;   // certified bounds on the Hölder exponent r at `parameter`
    double upper = 0.0;
    bool applies = false;
};

// One end of a run of C^k values: `inner` is certified C^k; `outer` is certified not C^k, or
// (rangeEnd) the end of the searched range, or (undecided) the nearest value the bounds could
// not decide. The true boundary lies in [min, max] of the two.
struct FamilyBoundary {
    double inner = 0.0;
    double outer = 0.0;
    bool rangeEnd = false;
    bool undecided = false;
    double width() const { return std::abs(outer - inner); }
};

struct FamilyRun {
    FamilyBoundary from;  // its lower end (outer <= inner)
    FamilyBoundary to;    // its upper end (inner <= outer)
};

struct FamilyOptions {
    int grid = 24;                    // values of the first sweep
    double tolerance = 1e-6;          // bisection stops at this bracket width
    int maxBisections = 40;           // per boundary
    double budgetPerValue = 0.3;      // seconds of JSR per parameter value
    const std::atomic<bool> *cancel = nullptr;
    // Called after each evaluation with the samples so far and the fraction done (approximate).
    std::function<void(const std::vector<FamilySample> &, double fraction)> progress;
};

struct FamilyResult {
    int smoothness = 1;
    std::vector<FamilyRun> runs;          // in increasing parameter order
    std::vector<FamilySample> samples;    // every evaluation, sorted by parameter
    bool cancelled = false;
    double seconds = 0.0;
};

// `regularity(t, budget)` gives the certified bounds of the family's member t within `budget`
// seconds (a member that does not exist, e.g. a corner cutting with a >= b, returns
// applies = false and counts as not C^k). from < to, k >= 0. Throws InputError otherwise.
FamilyResult regularityInterval(
    const std::function<Regularity(double t, const RegularityOptions &)> &regularity,
    double from, double to, int k, const FamilyOptions &options = {});

} // namespace awb
