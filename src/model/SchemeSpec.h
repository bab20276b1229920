#pragma once
// The scheme of a subdivision-curve item with all its parameters (layer 2, model): the kind
// (B-spline, end-interpolating B-spline, Chaikin, corner cutting, four-point, Bézier, own
// matrices, a mask), its core CurveScheme, its check, its JSON form and the mask as text.

#include "core/Types.h"
#include "model/ItemValues.h"

#include <QCoreApplication>
#include <QJsonObject>
#include <QStringList>

#include <complex>
#include <memory>

namespace awb {

class FieldReader;
class CurveScheme;

// The scheme and all its parameters. Parameters of other kinds are kept (switching the kind
// back restores them) but only the current kind's are saved.
struct SchemeSpec {
    Q_DECLARE_TR_FUNCTIONS(awb::SchemeSpec)
public:
    enum class Kind {
        BSpline,
        EndInterpolatingBSpline,
        Chaikin,
        CornerCutting,
        FourPoint,
        Bezier,
        Matrices,
        Mask,
    };
    Kind kind = Kind::BSpline;
    int degree = 3;                       // bspline, bspline-end-interpolating, bezier
    std::complex<double> t{0.5, 0.0};     // bezier: de Casteljau split parameter
    double omega = 1.0 / 16.0;            // four-point tension
    double a = 0.25, b = 0.75;            // corner cutting
    std::vector<Mat> matrices;            // matrices: S_1..S_p, m x m, row-stochastic
    // mask: a_k for k = maskOffset .. maskOffset + size - 1, arity maskArity (core maskScheme).
    // maskText[i] is the entry as written when it is not a plain number ("3/8",
    // "(1 + sqrt(3))/8"): kept, so the file says what the user typed; empty otherwise.
    int maskArity = 2;
    int maskOffset = -2;
    std::vector<double> mask{0.125, 0.5, 0.75, 0.5, 0.125};
    QStringList maskText{"1/8", "1/2", "3/4", "1/2", "1/8"};

    bool operator==(const SchemeSpec &other) const;
    // The parameters the core refuses (degree out of range, t outside the lens |t| < 1,
    // |1 - t| < 1, a matrix of the wrong size or with a row not summing to 1, ...). The
    // field is the parameter's JSON key.
    MaybeProblem check() const;
    // Number of maps: 2, or the number of matrices.
    int arity() const;
    bool isComplex() const { return kind == Kind::Bezier && t.imag() != 0.0; }
    // The core scheme of a real kind. Throws InputError.
    std::unique_ptr<CurveScheme> makeScheme() const;
    // JSON spellings, in enum order.
    static const QStringList &kindNames();
    // The "scheme" object of a subdivision-curve item (docs/file-format.md), and back: read
    // and checked (LoadError with the field's path otherwise).
    QJsonObject toJson() const;
    static SchemeSpec fromJson(const FieldReader &scheme);
    // The mask as one line of text, "1/8, 1/2, 3/4, 1/2, 1/8" (what the user typed where it
    // was not a plain number), and back: entries separated by commas, or by semicolons when
    // there is one (then a comma may be a decimal comma). False with `error` set when an
    // entry is no number.
    QString maskLine() const;
    bool setMaskLine(const QString &line, QString *error);
    // How many sum rules the mask satisfies and its symbol's factorisation, in one line.
    QString symbolText() const;
    // The mask of a uniform scheme (B-spline, Chaikin, corner cutting, four-point), as a mask
    // kind would hold it; false for Bézier and matrices.
    bool takeMaskOf(const SchemeSpec &other);
};

} // namespace awb
