#include "model/ExactCurve.h"

#include "core/analysis/HausdorffBracket.h"
#include "core/schemes/ComplexBezier.h"
#include "core/schemes/Scheme.h"
#include "model/ComplexBezierItem.h"
#include "model/SubdivisionCurveItem.h"

#include <QCoreApplication>

#include <cmath>

namespace awb {

namespace {

// lupdate takes the context of ExactCurveTr::tr() from the macro (a free tr() would get the
// enclosing namespace as its context).
struct ExactCurveTr {
    Q_DECLARE_TR_FUNCTIONS(awb::ExactCurve)
};

bool isRealParameter(Complex t) { return std::abs(t.imag()) < 1e-12; }

// Whether the complex Bézier item of parameter t has a known exact curve.
bool hasComplexExactCurve(Complex t, const Mat &P)
{
    // Otherwise the attractor is c(A_1), known only through the IFS.
    return P.rows() >= 2 && (isRealParameter(t) || std::abs(t.real() - 0.5) <= 1e-12);
}

CVec complexPoints(const Mat &P)
{
    return P.col(0).cast<Complex>() + Complex(0.0, 1.0) * P.col(1).cast<Complex>();
}

QString complexLabel(Complex t)
{
    return isRealParameter(t)
               ? ExactCurveTr::tr("Bézier curve c([0, 1])")
               : ExactCurveTr::tr("Takagi image c(x + 2iy·T(x)), y = %1 (Conj. 3.7.1)")
                     .arg(t.imag(), 0, 'g', 4);
}

QString schemeLabel(const CurveScheme &scheme)
{
    return ExactCurveTr::tr("exact curve: %1").arg(QString::fromStdString(scheme.name()));
}

std::optional<ExactCurve> complexBezierCurve(Complex t, const Mat &P, int samples)
{
    const bool real = isRealParameter(t);
    if (!hasComplexExactCurve(t, P))
        return std::nullopt;
    const CVec z = complexPoints(P);
    int depth = 1;
    while ((1 << depth) < samples && depth < 12)
        ++depth;
    const std::vector<Complex> c = takagiImage(z, real ? 0.0 : t.imag(), depth);
    ExactCurve out;
    out.points.resize(Eigen::Index(c.size()), 2);
    for (std::size_t i = 0; i < c.size(); ++i)
        out.points.row(Eigen::Index(i)) << c[i].real(), c[i].imag();
    out.label = complexLabel(t);
    return out;
}

std::optional<CertifiedExactCurve> complexCertified(Complex t, const Mat &P)
{
    if (!hasComplexExactCurve(t, P))
        return std::nullopt;
    CertifiedExactCurve out{nullptr, complexLabel(t)};
    if (isRealParameter(t))
        out.curve = std::make_shared<BezierPiecesCurve>(std::vector<Mat>{P.leftCols(2)});
    else
        out.curve = std::make_shared<TakagiImageCurve>(complexPoints(P), t.imag());
    return out;
}

} // namespace

std::optional<ExactCurve> exactCurveOf(const Item *item, int samples)
{
    samples = std::max(samples, 2);
    try {
        if (const auto *cb = qobject_cast<const ComplexBezierItem *>(item)) {
            auto c = complexBezierCurve(cb->t(), toMatrix(cb->controlPoints()), samples);
            if (c && cb->scaled() && cb->scaledApplies()) {
                // In g(z, 1/(2y)) the image x + 2iy T(x) of the segment [0, 1] is the Takagi
                // graph itself; other real control points are an affine image of it.
                c->points.col(1) /= 2.0 * cb->t().imag();
                c->label = ExactCurveTr::tr("Takagi graph x + i T(x), scaled (004 Thm 3.7.3)");
            }
            return c;
        }
        const auto *curve = qobject_cast<const SubdivisionCurveItem *>(item);
        if (!curve)
            return std::nullopt;
        const Mat P = toMatrix(curve->controlPoints());
        if (curve->scheme().isComplex())
            return complexBezierCurve(curve->scheme().t, P, samples);
        const auto scheme = curve->scheme().makeScheme();
        auto points = scheme->exactCurve(P, samples);
        if (!points || points->rows() < 2)
            return std::nullopt;
        return ExactCurve{*points, schemeLabel(*scheme)};
    } catch (const std::exception &) {
        return std::nullopt; // bad data: the item's derived error reports it
    }
}

std::optional<CertifiedExactCurve> certifiedExactCurveOf(const Item *item)
{
    try {
        if (const auto *cb = qobject_cast<const ComplexBezierItem *>(item))
            // The certified distance is of the unscaled curves (g is not an isometry).
            return cb->scaled() && cb->scaledApplies()
                       ? std::nullopt
                       : complexCertified(cb->t(), toMatrix(cb->controlPoints()));
        const auto *curve = qobject_cast<const SubdivisionCurveItem *>(item);
        if (!curve)
            return std::nullopt;
        const Mat P = toMatrix(curve->controlPoints());
        if (curve->scheme().isComplex())
            return complexCertified(curve->scheme().t, P);
        const auto scheme = curve->scheme().makeScheme();
        auto pieces = scheme->bezierPieces(P);
        if (!pieces || pieces->empty())
            return std::nullopt;
        return CertifiedExactCurve{std::make_shared<BezierPiecesCurve>(std::move(*pieces)),
                                   schemeLabel(*scheme)};
    } catch (const std::exception &) {
        return std::nullopt; // bad data: the item's derived error reports it
    }
}

} // namespace awb
