#pragma once
// The matrices of an item as the views, the figure sheet and the CLI show them (layer 2, model:
// QtCore only): S_1..S_p (real or complex), the lifted M_i = P^-1 S_i P with its A_i / b_i
// blocks, or the affine maps f_i as [[A, 0], [b, 1]] for items without subdivision matrices;
// and their LaTeX text (amsmath bmatrix, exact fractions as \frac), for papers.

#include "core/Types.h"

#include <QList>
#include <QString>

#include <utility>

namespace awb {

struct DerivedIfs;

struct NamedMatrix {
    NamedMatrix() = default;
    NamedMatrix(QString name, Mat values, int affineBlock = -1, bool editable = false)
        : name(std::move(name)), values(std::move(values)), affineBlock(affineBlock),
          editable(editable)
    {
    }
    NamedMatrix(QString name, CMat complexValues, int affineBlock = -1)
        : name(std::move(name)), affineBlock(affineBlock),
          complexValues(std::move(complexValues))
    {
    }

    QString name;            // "S_1", "M_2", ...
    Mat values;
    // Size of the A block of a lifted map M = [[A, 0], [b, 1]] (A top-left, b the row below
    // it); -1 for a plain matrix. Shades the blocks differently.
    int affineBlock = -1;
    bool editable = false;   // the user's own matrix (only then can cells be edited)
    // A complex matrix (complex de Casteljau L(t), R(t) of 004 §3.7 and their lifted maps):
    // shown instead of `values` when non-empty, never editable.
    CMat complexValues;

    bool isComplex() const { return complexValues.size() > 0; }
    Eigen::Index rows() const { return isComplex() ? complexValues.rows() : values.rows(); }
    Eigen::Index cols() const { return isComplex() ? complexValues.cols() : values.cols(); }
};

// S_1..S_p and M_1..M_p, or f_1..f_p: see above. `sEditable` marks the S_i as the user's own.
QList<NamedMatrix> namedMatrices(const DerivedIfs &d, bool sEditable = false);

// One entry in LaTeX: "\frac{3}{8}", "-\frac{1}{16}", "2", "0.1123" (`digits` significant
// digits when not a small fraction), complex entries as "a + bi".
QString latexNumber(double v, int digits = 6);
QString latexComplex(std::complex<double> z, int digits = 6);
// "S_{1} = \begin{bmatrix} ... \end{bmatrix}" (amsmath), one matrix.
QString latexMatrix(const NamedMatrix &m, int digits = 6);
// All of them, one display-math block each, with a comment naming the item.
QString latexMatrices(const QList<NamedMatrix> &matrices, const QString &title = {},
                      int digits = 6);

// The matrices as MATLAB / Octave cell arrays, one per kind, ready for jsr() of the JSR
// toolbox (Jungers) and the t-toolboxes (Mejstrik): "S = {[1/2 1/2 0; ...], [...]};" for the
// S_i, "M = {...};" for the lifted M_i, "f = {...};" for plain affine maps as [[A, 0]; [b, 1]],
// and "A = {...};" for the linear parts of either (their top-left blocks). Entries are exact fractions where rational
// ("3/8", "-1/16"), otherwise 17 significant digits (the eigenvalues come back to the last
// digit); complex entries as "0.5+0.25i". A comment line names the item.
QString matlabMatrices(const QList<NamedMatrix> &matrices, const QString &title = {});

} // namespace awb
