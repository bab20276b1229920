#pragma once
// A small dense linear-programming solver (layer 1, no Qt) for the invariant polytope algorithm
// (InvariantPolytope.h), which asks one question many times: the norm of a point y in the
// symmetric convex hull absco(V) = {V lambda : sum |lambda_j| <= 1} of the columns of V,
//     ||y||_V = min sum_j |lambda_j|  subject to  V lambda = y.
// Sizes there: L <= ~20 rows, up to a few thousand columns. A two-phase tableau simplex
// (Dantzig's rule, Bland's rule after a run of degenerate pivots, so it terminates; Chvátal,
// "Linear Programming", 1983, ch. 2-3) is enough and has no dependencies. Its answer is not
// trusted by the callers: InvariantPolytope re-checks every combination with a rigorous
// residual bound.

#include "core/Types.h"

#include <limits>
#include <utility>
#include <vector>

namespace awb {

struct LpResult {
    enum Status { Optimal, Infeasible, Unbounded, IterationLimit };
    Status status = IterationLimit;
    double value = std::numeric_limits<double>::infinity();  // c^T x at the optimum
    Vec x;                    // n: the optimal basic solution (Optimal only)
    std::vector<int> basis;   // columns of A basic at the optimum (redundant rows omitted)
    int iterations = 0;
};

// min c^T x subject to A x = b, x >= 0 (A: m x n, b: m, c: n). Redundant equations are
// allowed; feasibility is decided to a tolerance of 1e-9 relative to ||b||_1 + 1.
LpResult solveStandardLp(const Mat &A, const Vec &b, const Vec &c);

// The sparse coefficients of a shortest absolute combination: y = sum lambda_j v_j.
struct AbsoluteCombination {
    bool feasible = false;   // y lies in the span of V (to tolerance)
    double norm = std::numeric_limits<double>::infinity();  // sum |lambda_j|
    std::vector<std::pair<int, double>> lambda;              // (column j, lambda_j), j ascending
    double residual = 0.0;   // ||V lambda - y||_2 as computed
};

// ||y||_V by the LP with lambda = lambda+ - lambda-, both >= 0 (V: L x n, y: L). The basic
// solution is polished by a least-squares solve on its columns.
AbsoluteCombination absoluteCombination(const Mat &V, const Vec &y);

} // namespace awb
