#pragma once
// Spectral analysis of subdivision and IFS matrices: eigenvalues/eigenvectors, the subdominant
// eigenvalue and what it says about the curve (003 §4, 004 §2.1), contractivity (004 Thm 3.5.1)
// and fixed points x* = b (I - A)^-1 (004 eq. (3.21), row convention).

#include "core/ifs/Ifs.h"

#include <optional>

namespace awb {

struct Spectrum {
    // Sorted by modulus, largest first (ties: larger real part, then larger imaginary part).
    std::vector<Complex> values;
    std::vector<CVec> vectors;        // right eigenvectors: M v = lambda v (unit 2-norm)
    std::vector<int> multiplicity;    // algebraic multiplicity of values[i] (its cluster size)
    double spectralRadius = 0.0;
};
// Every eigenvalue is listed once per copy (values.size() == rows). Copies within `tol`
// (relative) of each other form a cluster: each is snapped to the cluster mean and carries the
// cluster size as its multiplicity, so a defective 1/8 twice comes out as 1/8, 1/8 with
// multiplicity 2 rather than two values 1e-8 apart.
Spectrum spectrum(const Mat &M, double tol = 1e-6);
Spectrum spectrum(const CMat &M, double tol = 1e-6);

// Complex: one non-real eigenvalue (repeats allowed) without its conjugate, which only a
// complex matrix has (L(t) of a complex de Casteljau split, 004 §3.7).
enum class SubdominantKind { None, RealPositive, RealNegative, ComplexPair, Complex, Mixed };
std::string toString(SubdominantKind kind);

struct Subdominant {
    SubdominantKind kind = SubdominantKind::None;
    std::vector<Complex> values;   // all eigenvalues of the subdominant modulus (with repeats)
    std::vector<CVec> vectors;     // their eigenvectors
    double modulus = 0.0;
    int multiplicity = 0;
    // What it means for the curve at the fixed point (003 §4/§6): half-tangent, oscillation,
    // spiral.
    std::string meaning() const;
};
// The eigenvalues of largest modulus after removing one dominant eigenvalue 1 (the affine
// invariance eigenvalue of a row-stochastic S_i). Pass dominantIsOne = false for A_i (whose
// largest eigenvalue is already the subdominant one of S_i).
Subdominant subdominant(const Spectrum &s, bool dominantIsOne = true, double tol = 1e-6);

struct Contractivity {
    double spectralRadius = 0.0;     // rho(A)
    bool eventuallyContractive = false;  // rho(A) < 1 (004 Thm 3.5.1)
    double normFactor = 0.0;         // ||A||_2, a contraction factor when < 1
    int exponent = -1;               // smallest k <= 200 with ||A^k||_2 < 1; -1 if none
    std::string verdict() const;
};
Contractivity contractivity(const Mat &A);
Contractivity contractivity(const CMat &A);

// x* with x* = x* A + b, i.e. x* = b (I - A)^-1; nullopt when 1 is an eigenvalue of A.
std::optional<RowVec> fixedPoint(const Mat &A, const RowVec &b);
std::optional<RowVec> fixedPoint(const AffineMap &f);
// The fixed weights of a subdivision matrix S (m x m, rows summing to 1): the left eigenvector
// l S = l with sum(l) = 1 of the eigenvalue 1, when that eigenvalue is simple. l P is then the
// fixed point of the map S_i on the curve, with or without an invertible lifting (the
// eigenvector of eigenvalue 1 of S_i gives it; NOTES.md, 000 §2).
std::optional<RowVec> fixedWeights(const Mat &S);

// Per-map analysis of an IFS: the verdict of each map, and whether all are eventually
// contractive (the IFS then has a unique attractor).
struct IfsCheck {
    std::vector<Contractivity> maps;
    bool contractive = true;
    std::string message;  // empty when contractive; names the first offending map otherwise
    // When a map is not contractive: the top Lyapunov exponent of the random products of the
    // linear parts, the maps chosen with the IFS's probabilities (equal ones when it has none),
    // estimated along one orbit of 20 000 steps (a fixed seed). Negative, the IFS contracts on
    // average (Barnsley-Elton 1988): random iteration converges to its attractor, as flame
    // renderers rely on, although deterministic iteration does not.
    std::optional<double> lyapunov;
    bool contractsOnAverage() const { return contractive || (lyapunov && *lyapunov < -1e-3); }
};
IfsCheck checkIfs(const Ifs &ifs);

} // namespace awb
