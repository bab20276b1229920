#include "model/ExactCurve.h"

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

std::optional<ExactCurve> complexBezierCurve(Complex t, const Mat &P, int samples)
{
    const bool real = std::abs(t.imag()) < 1e-12;
    if (P.rows() < 2 || (!real && std::abs(t.real() - 0.5) > 1e-12))
        return std::nullopt; // the attractor is c(A_1), known only through the IFS
    const CVec z = P.col(0).cast<Complex>() + Complex(0.0, 1.0) * P.col(1).cast<Complex>();
    int depth = 1;
    while ((1 << depth) < samples && depth < 12)
        ++depth;
    const std::vector<Complex> c = takagiImage(z, real ? 0.0 : t.imag(), depth);
    ExactCurve out;
    out.points.resize(Eigen::Index(c.size()), 2);
    for (std::size_t i = 0; i < c.size(); ++i)
        out.points.row(Eigen::Index(i)) << c[i].real(), c[i].imag();
    out.label = real ? ExactCurveTr::tr("Bézier curve c([0, 1])")
                     : ExactCurveTr::tr("Takagi image c(x + 2iy·T(x)), y = %1 (Conj. 3.7.1)")
                           .arg(t.imag(), 0, 'g', 4);
    return out;
}

} // namespace

std::optional<ExactCurve> exactCurveOf(const Item *item, int samples)
{
    samples = std::max(samples, 2);
    try {
        if (const auto *cb = qobject_cast<const ComplexBezierItem *>(item))
            return complexBezierCurve(cb->t(), toMatrix(cb->controlPoints()), samples);
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
        return ExactCurve{*points, ExactCurveTr::tr("exact curve: %1")
                                       .arg(QString::fromStdString(scheme->name()))};
    } catch (const std::exception &) {
        return std::nullopt; // bad data: the item's derived error reports it
    }
}

} // namespace awb
