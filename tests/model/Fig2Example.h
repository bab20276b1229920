#pragma once
// The example of 000 Fig. 2 (a cubic B-spline on 5 points with an eigenvalue plot of its S_i),
// as the eigenvalue plot tests of the model and of the window open it.
#include "TestPaths.h"
#include <QString>

namespace awb::test {

inline const QString fig2File = (awb::test::sourceDir() + QStringLiteral("/examples/000-fig02-cubic-bspline-from-point.awb"));
inline const QString fig2Plot = QStringLiteral("000 Fig. 2: spectra of S_i");
inline const QString fig2Curve = QStringLiteral("000 Fig. 2: cubic B-spline from a point");

} // namespace awb::test
