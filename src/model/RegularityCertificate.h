#pragma once
// The certificate of an exact Hölder exponent (issue 32; layer 2, model): when the invariant
// polytope closes (core InvariantPolytope.h), the scheme, the spectrum maximizing product, the
// polytope's vertices and, for every vertex v_j and map A_i, the coefficients of A_i v_j / rho
// in the vertices, written as JSON that `attractor-cli verify-regularity` re-checks without
// any search:
//
//   {"format": "awb-regularity-certificate", "version": 1,
//    "scheme": {the item's "scheme" object},  "arity": N, "shift": n, "cap": c,
//    "holder": {"lower": r0, "upper": r1},      "smp": [indices],
//    "polytope": {"format": "awb-invariant-polytope", "matrices", "smp", "rhoHat",
//                 "vertices", "lambda"}}
//
// The Hölder exponent is r = shift - log_N rho (masks: shift = the number of sum rules n and
// the matrices are the transition matrices of the n-th divided-difference mask; own matrices:
// shift = 0 and the matrices act on the quotient by the polynomials), capped at `cap`.
// Checking re-derives the matrices from the scheme (plain linear algebra), verifies the
// polytope (the word's spectral radius, the vertices spanning R^L, every A_i v_j inside rho P
// with the residuals bounded), and accepts the claimed exponent only if what is proved lies
// inside it.

#include "core/analysis/Regularity.h"

#include <QByteArray>
#include <QString>

#include <vector>

namespace awb {

struct SchemeSpec;

// The certificate of `r` for `scheme`; empty with `error` set when r is not exact.
QByteArray regularityCertificate(const SchemeSpec &scheme, const Regularity &r,
                                 QString *error = nullptr);

struct CertificateCheck {
    bool ok = false;
    QString message;              // the verdict, or the first reason for rejecting
    double lower = 0.0;           // the Hölder exponent's bracket the certificate proves
    double upper = 0.0;
    double jsrLower = 0.0;        // and the joint spectral radius's
    double jsrUpper = 0.0;
    std::vector<int> smp;
    QString scheme;               // e.g. "mask of arity 2"
};
CertificateCheck verifyRegularityCertificate(const QByteArray &json);

} // namespace awb
