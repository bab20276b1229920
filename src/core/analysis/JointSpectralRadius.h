#pragma once
// Certified bounds on the joint spectral radius (JSR) of a finite family of square matrices,
// rho(A_0, .., A_{K-1}) = lim_k max_{|w| = k} ||A_w||^{1/k} (Rota & Strang 1960). Used by
// Regularity.h for the Hölder regularity of subdivision schemes (layer 1, no Qt).
//
// Lower bound: max over products A_w of length k <= kmax of rho(A_w)^{1/k} (every such value
// is <= JSR). Upper bound: Gripenberg's branch and bound (G. Gripenberg, "Computing the joint
// spectral radius", Linear Algebra Appl. 234 (1996) 43-60) in one fixed operator norm: if every
// product of length k has a prefix A_v with ||A_v||^{1/|v|} <= g, then JSR <= g (cut any
// infinite product into such blocks). The norm is the best, on short products, of the induced
// 1-, 2- and infinity-norms and an ellipsoid norm ||x||_Q = sqrt(x^T Q x) with
// Q = sum_{|w| <= d} (A_w / l)^T (A_w / l) (l the lower bound): an approximation of an extremal
// (Barabanov) norm in the spirit of Jungers' monograph (R. Jungers, "The Joint Spectral
// Radius", LNCIS 385, Springer 2009, §2.3). Rounding: both bounds are widened by a relative
// margin (1e-12 on norms, more for eigenvalues of nearly defective products), so they hold
// for the matrices as stored in double precision.

#include "core/Types.h"

#include <atomic>
#include <functional>
#include <limits>

namespace awb {

struct JsrBounds {
    double lower = 0.0;                                        // certified: lower <= JSR
    double upper = std::numeric_limits<double>::infinity();    // certified: JSR <= upper
    std::vector<int> product;     // the word w (indices, A_w = A_{w0} A_{w1} ...) giving lower
    int enumerated = 0;           // every product up to this length was examined
    int depth = 0;                // longest product examined by the branch and bound
    long long nodes = 0;          // products evaluated
    std::string norm;             // the norm the upper bound was proved in
    bool converged = false;       // the branch and bound closed: upper within tolerance
    bool cancelled = false;
    bool timedOut = false;
    bool workSpent = false;       // stopped at JsrOptions::maxNodes (deterministic)
    double seconds = 0.0;
};

struct JsrOptions {
    double timeBudget = 2.0;          // seconds of wall time, at most
    double tolerance = 1e-9;          // stop when upper <= lower * (1 + tolerance)
    int maxLength = 1000;              // longest product in the branch and bound
    long long maxFrontier = 200000;   // live products at one depth, at most
    // Stop after about this many products (0: no limit). A budget of work, not of time: the
    // same bounds on every machine (the regularity atlas's rows are reproducible this way).
    long long maxNodes = 0;
    const std::atomic<bool> *cancel = nullptr;  // set from another thread to stop early
    // Called now and then with the current bounds and the fraction of the budget spent.
    std::function<void(const JsrBounds &, double fraction)> progress;
};

// A: K >= 1 matrices, all L x L (L >= 0; L = 0 gives JSR 0). Throws InputError on sizes or
// non-finite entries. The bounds are valid whenever the call returns, also after a cancel or
// a time-out (then just wider).
JsrBounds jointSpectralRadius(const std::vector<Mat> &A, const JsrOptions &options = {});
// The checks above, for other algorithms on the same input (InvariantPolytope.h).
void requireMatrixFamily(const std::vector<Mat> &A);

// Spectral radius of one square matrix, and a relative error margin for it: about 1e-12
// for a well separated dominant eigenvalue, larger when the top eigenvalues cluster (a nearly
// defective eigenvalue moves by ~ sqrt(eps)).
double spectralRadiusOf(const Mat &M, double *margin = nullptr);
// The shortest word r with w = r^k (a product's spectral radius per letter is its root's): the
// lower bound's product is often a long power.
std::vector<int> primitiveRoot(const std::vector<int> &w);

} // namespace awb
