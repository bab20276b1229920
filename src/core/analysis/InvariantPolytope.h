#pragma once
// The exact joint spectral radius of a finite family of real L x L matrices A_0..A_{K-1} by the
// invariant polytope algorithm, with a certificate that a separate verifier re-checks
// (layer 1, no Qt). Used by Regularity.h to make the Hölder exponent of a scheme exact.
//
// N. Guglielmi & V. Protasov, "Exact computation of joint spectral characteristics of linear
// operators", Found. Comput. Math. 13 (2013) 37-97, and "Invariant polytopes of sets of
// matrices with application to regularity of wavelets and subdivisions", SIAM J. Matrix Anal.
// Appl. 37 (2016) 18-52; T. Mejstrik, "Algorithm 1011: improved invariant polytope algorithm
// and applications", ACM TOMS 46 (2020) (the t-toolboxes). The steps here:
//  1. s.m.p. candidate: over the Lyndon words w of length <= kmax (one per class of cyclic
//     shifts, no powers), the largest rho(A_w)^{1/|w|}; among values within 1e-10 (relative)
//     of the largest, the shortest word. Its leading eigenvalue must be real and simple in
//     modulus ("dominant"); otherwise the algorithm does not apply (the complex-polytope
//     variant is out of scope) and the result says why. The other near-ties with a dominant
//     real eigenvalue also seed the polytope (no balancing: Guglielmi & Protasov 2016, §4,
//     need it only in rare cases; then the search just does not close).
//  2. rho^ = rho(A_w)^{1/k}, B_i = A_i / rho^. Start vertices: the leading eigenvector v of A_w
//     (unit 2-norm) and its orbit along the cycle, B_{w_k} v, B_{w_{k-1}} B_{w_k} v, ...
//  3. Breadth first: each new vertex x and each map i give y = B_i x; y is dropped when its
//     norm in the symmetric convex hull P = absco(V) is <= 1 + tolerance (LP, LinearProgram.h)
//     and becomes a vertex otherwise. A generation that adds nothing closes the proof:
//     ||B_i||_P <= 1 for all i, so JSR = rho^.
//  4. Reducibility: if the vertices closed but span only a proper subspace W (then W is
//     invariant under every A_i: the family is block triangular in a basis W + W'), the
//     polytope is extended by eps * u_k for an orthonormal basis u_k of the orthogonal
//     complement of W and the iteration continues from those vertices (eps in [1e-3, 1], as
//     large as keeps the W-parts of the images B_i u_k within half of P|W: the inner ball, and
//     so the tolerance to residuals, grows with eps; the combinations found before are then
//     re-solved against the full polytope, which absorbs components off W). This is
//     the same algorithm on the whole space: the new orbits carry the quotient (diagonal)
//     block D, and the search closes when D's products stay in eps-scaled copies of the
//     polytope, i.e. when JSR(D) < rho^ or D has an invariant polytope of its own at level
//     rho^. JSR = max(JSR(A|W), JSR(D)) is then certified by one full-dimensional polytope,
//     and the verifier needs no block structure.
//  5. Certified bracket (the verifier's, never the search's numbers): lower = (rho(A_w)
//     (1 - margin))^{1/k}, margin from spectralRadiusOf plus the rounding of the product;
//     upper = rho^ max_{i,j} (sum |lambda| + ||r||_2 / delta) where B_i v_j = V lambda + r is
//     recomputed with a componentwise rounding bound added to r, and delta = sigma_min(V_S) /
//     sqrt(L) is the radius of a Euclidean ball inside P (V_S: L columns of V chosen by
//     pivoted QR; absco(V_S) contains V_S times the l2 ball of radius 1/sqrt(L)).
// Trivial cases: L = 0 and all-zero matrices give JSR 0 exactly (an empty certificate). A
// family whose products of length L all vanish to rounding (1e-10 max ||A_i||_F^L) is
// numerically nilpotent: its computed rho(A_w) are noise, and the algorithm does not apply.

#include "core/analysis/JointSpectralRadius.h"

#include <memory>
#include <utility>

namespace awb {

// Everything needed to re-check JSR(A) = rhoHat: the polytope absco(vertices) is mapped into
// itself by every A_i / rhoHat, and rho(A_smp)^{1/|smp|} = rhoHat.
struct PolytopeCertificate {
    std::vector<Mat> matrices;    // A_0..A_{K-1}, L x L, as given
    std::vector<int> smp;         // the word w: A_w = A_{w0} A_{w1} .. A_{w(k-1)}
    double rhoHat = 0.0;          // the scaling: rho(A_w)^{1/k}; 0 for all-zero matrices
    std::vector<Vec> vertices;    // v_0..v_{n-1}, L each, spanning R^L
    // lambda[j][i]: A_i v_j / rhoHat = sum_m lambda_m v_m, sparse (m, lambda_m), m ascending.
    std::vector<std::vector<std::vector<std::pair<int, double>>>> lambda;
};

struct PolytopeVerdict {
    bool ok = false;
    double lower = 0.0;   // certified: lower <= JSR (when ok)
    double upper = std::numeric_limits<double>::infinity();   // certified: JSR <= upper
    double normBound = std::numeric_limits<double>::infinity();  // max_i ||A_i/rhoHat||_P
    double delta = 0.0;   // radius of a Euclidean ball inside the polytope
    int failingVertex = -1, failingMap = -1;
    std::string message;
};

// Re-checks a certificate from its matrices alone: the word's spectral radius, the span of
// the vertices, and every (vertex, map) combination with rigorous rounding bounds. `ok` when
// every ||A_i v_j / rhoHat||_P <= 1 + tolerance and rho(A_w)^{1/k} agrees with rhoHat to
// `tolerance` (relative); the message names the first failure.
PolytopeVerdict verifyPolytopeCertificate(const PolytopeCertificate &c,
                                          double tolerance = 1e-9);

// The certificate as JSON text (numbers with 17 significant digits: they read back to the
// same doubles): {"format", "version", "matrices", "smp", "rhoHat", "vertices", "lambda"}.
std::string certificateJson(const PolytopeCertificate &c);

struct PolytopeOptions {
    double timeBudget = 2.0;     // seconds of wall time, at most
    int maxVertices = 2000;      // give up beyond this many vertices
    int maxLength = 0;           // longest s.m.p. candidate; 0: as many as ~2^15 products allow
    double tolerance = 1e-10;    // y is inside when ||y||_P <= 1 + tolerance
    const std::atomic<bool> *cancel = nullptr;
};

struct PolytopeResult {
    bool applies = false;    // a dominant real s.m.p. candidate was found
    bool closed = false;     // the polytope is invariant and verified: lower <= JSR <= upper
    double lower = 0.0;      // certified lower bound (rho of the candidate), also when not closed
    double upper = std::numeric_limits<double>::infinity();   // certified when closed
    std::vector<int> smp;    // the candidate word
    std::vector<std::vector<int>> ties;   // other near-tie words whose eigenvectors seeded P
    int vertices = 0;
    int generations = 0;
    bool extended = false;   // the vertices spanned a proper invariant subspace (step 4)
    std::string message;     // why it does not apply / did not close, or a verdict
    double seconds = 0.0;
    std::shared_ptr<const PolytopeCertificate> certificate;   // set when closed
};

// A: K >= 1 matrices, all L x L. Throws InputError on sizes or non-finite entries.
PolytopeResult invariantPolytope(const std::vector<Mat> &A, const PolytopeOptions &options = {});

} // namespace awb
