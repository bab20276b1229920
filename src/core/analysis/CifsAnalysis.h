#pragma once
// What a controlled IFS (ifs/Cifs.h, 003 §2.2) contracts by (layer 1, no Qt): the constrained
// joint spectral radius of its arcs, the spectra of its cycles, and its Lyapunov exponent
// under random iteration.
//
// An arc t: from -> to acts on barycentric DIRECTIONS (rows summing to 0) by its linear part
// R_t = arcLinearPart(S_t), (n_to - 1) x (n_from - 1). Only admissible products occur: a path
// t_1 .. t_k (to(t_i) = from(t_{i+1})) gives R_{t_k} .. R_{t_1}. The constrained JSR
//   rho_G = lim_k max_{admissible |w| = k} ||R_w||^{1/k}
// decides whether every state's attractor exists and how fast the deterministic iteration
// converges (rho_G < 1: all long paths contract). It is the ordinary JSR of the LIFTED arcs
// (X. Dai, "A Gel'fand-type spectral radius formula and stability of linear constrained
// switching systems", Linear Algebra Appl. 436 (2012) 1099-1113; M. Philippe, R. Essick,
// G. Dullerud, R. Jungers, "Stability of discrete-time switching systems with constrained
// switching sequences", Automatica 72 (2016) 242-250): on the direct sum of the states'
// direction spaces, B_t carries R_t from the `to` block to the `from` block and is zero
// elsewhere, so a product of B's is zero unless its word is an admissible path, and then
// carries that path's product. Both analyses of JointSpectralRadius.h (Gripenberg's bounds)
// and InvariantPolytope.h (exact, with a certificate) then apply unchanged; a polytope of the
// lifted space is an extremal multinorm, one polytope per state.

#include "core/Types.h"
#include "core/analysis/InvariantPolytope.h"

#include <optional>

namespace awb {

struct Cifs;

// R: the linear map of the row-stochastic S (n_to x n_from) on barycentric directions, in the
// bases e_k - e_{n-1} of both spaces: R(k, j) = S(k, j) - S(n_to - 1, j), (n_to-1) x (n_from-1).
// For square S it is Cifs.h's barycentricPart().
Mat arcLinearPart(const Mat &S);

// The lifted arcs B_t (L x L, L = sum over states of (n_s - 1)), in the arcs' order, and where
// each state's block starts.
struct LiftedArcs {
    std::vector<Mat> matrices;
    std::vector<int> offsets;  // offsets[s]: first row / column of state s's block
    int dimension = 0;
};
LiftedArcs liftedArcs(const Cifs &cifs);

struct CifsCycle {
    std::vector<int> arcs;            // t_1 .. t_m; starts at its lowest-index state
    int state = 0;                    // from(t_1)
    std::vector<Complex> eigenvalues; // of the cycle's product on barycentric directions
    double spectralRadius = 0.0;
    double perArc = 0.0;              // spectralRadius^(1/m): a lower bound on rho_G
};

struct CifsAnalysisOptions {
    double timeBudget = 1.0;      // seconds for each of the bounds and the polytope, at most
    int maxCycles = 2000;         // simple cycles listed, at most
    long long lyapunovSteps = 200000;  // steps of the random path for the exponent
    std::uint64_t seed = 1;
    const std::atomic<bool> *cancel = nullptr;  // set from another thread to stop early
};

struct CifsAnalysis {
    std::vector<CifsCycle> cycles;   // the simple cycles, each once
    bool cyclesComplete = true;      // false when there were more than maxCycles
    // rho_G: certified bounds (lower from cycles and longer admissible products, upper from
    // Gripenberg's branch and bound on the lifted arcs); the word is of arc indices.
    JsrBounds bounds;
    // Exact by an invariant polytope of the lifted arcs, when one closes.
    PolytopeResult polytope;
    bool exact() const { return polytope.closed; }
    double lower() const { return polytope.closed ? polytope.lower : bounds.lower; }
    double upper() const { return polytope.closed ? polytope.upper : bounds.upper; }
    // The top Lyapunov exponent of random iteration's products: along a path drawn as the
    // random iteration draws it (from each state an arc leaving it, by weight), the average
    // of log ||R_{t_k} .. R_{t_1}|| / k. Negative: random iteration contracts on average.
    std::optional<double> lyapunov;
    int lyapunovState = 0;           // where the path started
    bool contractive() const { return upper() < 1.0; }
    bool cancelled = false;
};

// Validates first (Cifs::validate()'s InputError). When the lifted space has more than
// maxLiftedDimension dimensions, the bounds come from the cycles alone (upper: infinity).
constexpr int maxLiftedDimension = 240;
CifsAnalysis analyseCifs(const Cifs &cifs, const CifsAnalysisOptions &options = {});

} // namespace awb
