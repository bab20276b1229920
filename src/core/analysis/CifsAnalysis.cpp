#include "core/analysis/CifsAnalysis.h"

#include "core/Messages.h"
#include "core/analysis/Spectrum.h"
#include "core/ifs/Cifs.h"

#include <cmath>
#include <random>

namespace awb {

Mat arcLinearPart(const Mat &S)
{
    if (S.rows() == 0 || S.cols() == 0)
        throw InputError(coreTranslate("awb::ifs", "the barycentric part needs a non-empty "
                                                   "matrix"));
    const Eigen::Index m = S.rows() - 1, n = S.cols() - 1;
    // Row convention: the direction e_k - e_m of the to-space goes to S_k - S_m, whose first
    // n coordinates are its coordinates in the basis e_j - e_n (it sums to 0).
    return S.topLeftCorner(m, n) - S.row(m).head(n).replicate(m, 1);
}

LiftedArcs liftedArcs(const Cifs &cifs)
{
    LiftedArcs out;
    for (const CifsState &s : cifs.states) {
        out.offsets.push_back(out.dimension);
        out.dimension += std::max(0, s.dim() - 1);
    }
    const int L = out.dimension;
    for (const CifsTransition &t : cifs.transitions) {
        Mat B = Mat::Zero(L, L);
        const Mat R = arcLinearPart(t.S);
        // Row convention: a lifted row x maps to x B; the to-block of x, times R, lands in the
        // from-block. Products B_{t_k} .. B_{t_1} then carry R_{t_k} .. R_{t_1} exactly when
        // the word is a path.
        B.block(out.offsets[size_t(t.to)], out.offsets[size_t(t.from)], R.rows(), R.cols()) = R;
        out.matrices.push_back(std::move(B));
    }
    return out;
}

namespace {

// The exponent along one random path of the chain "from each state an arc leaving it, by
// weight" (what Cifs.h's chaosGame draws): a column u of the current state's directions,
// u <- R_t u, renormalised; the first tenth of the steps is not counted.
std::optional<double> lyapunovExponent(const Cifs &cifs, int start, long long steps,
                                       std::uint64_t seed)
{
    std::vector<std::vector<int>> out(cifs.states.size());
    std::vector<std::vector<double>> cumulative(cifs.states.size());
    for (size_t t = 0; t < cifs.transitions.size(); ++t)
        out[size_t(cifs.transitions[t].from)].push_back(int(t));
    for (size_t q = 0; q < out.size(); ++q) {
        double sum = 0;
        for (int t : out[q])
            cumulative[q].push_back(sum += cifs.transitions[size_t(t)].weight);
        for (double &c : cumulative[q])
            c /= sum;
    }
    std::vector<Mat> R;
    for (const CifsTransition &t : cifs.transitions)
        R.push_back(arcLinearPart(t.S));
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> uni(0.0, 1.0);
    std::normal_distribution<double> gauss;
    int state = start;
    Vec u(std::max(0, cifs.states[size_t(state)].dim() - 1));
    for (Eigen::Index k = 0; k < u.size(); ++k)
        u(k) = gauss(rng);
    const long long burn = steps / 10;
    double sum = 0;
    for (long long k = 0; k < steps; ++k) {
        const auto &cum = cumulative[size_t(state)];
        const size_t i = std::min(size_t(std::lower_bound(cum.begin(), cum.end(), uni(rng)) -
                                         cum.begin()),
                                  cum.size() - 1);
        const int t = out[size_t(state)][i];
        // The product R_{t_k} .. R_{t_1} on a column of the start state's directions grows
        // as its norm: R_t takes the from-state's directions (columns) to the to-state's.
        u = (R[size_t(t)] * u).eval();
        state = cifs.transitions[size_t(t)].to;
        const double n = u.norm();
        if (!(n > 0) || !std::isfinite(n))
            return std::nullopt; // a map collapses every direction (or a point-like state)
        if (k >= burn)
            sum += std::log(n);
        u /= n;
    }
    return sum / double(steps - burn);
}

} // namespace

CifsAnalysis analyseCifs(const Cifs &cifs, const CifsAnalysisOptions &options)
{
    const CifsCheck check = checkCifs(cifs, options.maxCycles);
    CifsAnalysis a;
    a.cyclesComplete = check.complete;
    double cycleBound = 0.0;
    for (const CycleCheck &c : check.cycles) {
        CifsCycle cycle;
        cycle.arcs = c.transitions;
        cycle.state = cifs.transitions[size_t(c.transitions.front())].from;
        Mat M = Mat::Identity(cifs.states[size_t(cycle.state)].dim(),
                              cifs.states[size_t(cycle.state)].dim());
        for (int t : c.transitions)
            M = (cifs.transitions[size_t(t)].S * M).eval();
        if (M.rows() > 1) {
            const Spectrum s = spectrum(arcLinearPart(M));
            cycle.eigenvalues = s.values;
            cycle.spectralRadius = s.spectralRadius;
        }
        cycle.perArc = std::pow(cycle.spectralRadius, 1.0 / double(cycle.arcs.size()));
        cycleBound = std::max(cycleBound, cycle.perArc);
        a.cycles.push_back(std::move(cycle));
    }
    a.bounds.lower = cycleBound;
    const LiftedArcs lifted = liftedArcs(cifs);
    if (lifted.dimension > 0 && lifted.dimension <= maxLiftedDimension) {
        JsrOptions jo;
        jo.timeBudget = options.timeBudget;
        jo.tolerance = 1e-9;
        jo.cancel = options.cancel;
        a.bounds = jointSpectralRadius(lifted.matrices, jo);
        // The simple cycles are admissible products too (rounding aside: the polytope and
        // the branch and bound certify theirs).
        PolytopeOptions po;
        po.timeBudget = options.timeBudget;
        po.maxVertices = 1000;
        po.cancel = options.cancel;
        a.polytope = invariantPolytope(lifted.matrices, po);
    } else if (lifted.dimension == 0) {
        a.bounds.upper = 0.0;
        a.bounds.converged = true;
    }
    a.cancelled = options.cancel && options.cancel->load();
    if (a.cancelled)
        return a;
    // The drawn state of most items is state 0; a path from there meets what it can reach.
    a.lyapunovState = 0;
    if (options.lyapunovSteps > 0)
        a.lyapunov = lyapunovExponent(cifs, a.lyapunovState, options.lyapunovSteps,
                                      options.seed);
    return a;
}

} // namespace awb
