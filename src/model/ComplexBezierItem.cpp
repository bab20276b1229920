#include "model/ComplexBezierItem.h"

#include "core/schemes/ComplexBezier.h"
#include "model/Commands.h"
#include "model/PointSetProperty.h"
#include "model/ProjectIO.h"
#include "model/PropertyDeclaration.h"

#include <algorithm>
#include <cmath>

namespace awb {

ComplexBezierItem::ComplexBezierItem()
    : AttractorItem(tr("Complex Bézier")), m_points{{0, 0}, {1, 0}}
{
}

MaybeProblem ComplexBezierItem::checkT(const std::complex<double> &t) const
{
    if (!std::isfinite(t.real()) || !std::isfinite(t.imag()))
        return Problem{"t", tr("the parameter t must be a finite complex number")};
    return std::nullopt;
}

bool ComplexBezierItem::setT(std::complex<double> t, int gesture)
{
    return setDeclared(*this, t, gesture);
}

DerivedIfs complexBezierDerivedIfs(const Mat &P, std::complex<double> t)
{
    requireFinite(P, "control points");
    const CVec z = P.col(0).cast<Complex>() + Complex(0.0, 1.0) * P.col(1).cast<Complex>();
    const ComplexBezierIfs c = complexBezierIfs(z, t);
    DerivedIfs out;
    out.ifs = c.ifs;
    const int n = c.degree();
    for (std::size_t i = 0; i < 2; ++i) {
        out.S.complex.push_back(c.S[i]);
        out.A.complex.push_back(c.M[i].topLeftCorner(n, n));
        out.liftedComplex.push_back(c.M[i]);
    }
    out.note = QString::fromStdString(c.parameter.message);
    // A plane point is the first complex coordinate; the other lifted ones are 0 (any start
    // set converges to the same attractor).
    const int D = int(c.ifs.dim());
    out.toIfsSpace = [D](const Mat &X) {
        Mat Y = Mat::Zero(X.rows(), D);
        Y.leftCols(2) = X;
        return Y;
    };
    return out;
}

bool ComplexBezierItem::scaledApplies() const
{
    if (std::abs(m_t.real() - 0.5) > 1e-12 || std::abs(m_t.imag()) < 1e-12)
        return false;
    return std::all_of(m_points.begin(), m_points.end(),
                       [](const Point &p) { return p.y == 0.0; });
}

bool ComplexBezierItem::setScaled(bool scaled)
{
    return setDeclared(*this, scaled, 0);
}

DerivedIfs ComplexBezierItem::computeIfs() const
{
    DerivedIfs out = complexBezierDerivedIfs(toMatrix(m_points), m_t);
    // Outside the discs the maps exist but have no attractor: an error, in the core's words.
    const ParameterReport report = classifyParameter(m_t);
    if (!report.hyperbolic)
        throw InputError(report.message);
    applyAlgorithm(out.ifs);
    if (m_scaled && scaledApplies()) {
        // g(z, 1/(2y)): the views' imaginary (second) coordinate divided by 2y. The control
        // points and the start set lie on the real axis, which g keeps.
        const double k = 1.0 / (2.0 * m_t.imag());
        for (Projection &v : out.ifs.views) {
            v.V.col(1) *= k;
            v.c(1) *= k;
        }
        out.note = tr("Scaled coordinates g(z, 1/(2y)) = Re z + i Im z / (2y), y = %1 (004 "
                      "eq. (3.40)): as y → 0 the curve approaches the Takagi graph x + i T(x) "
                      "(Thm 3.7.3, Figs. 3.6–3.8). %2")
                       .arg(m_t.imag(), 0, 'g', 6)
                       .arg(out.note);
    } else if (m_scaled) {
        out.note = tr("Scaled coordinates apply to t = 1/2 + iy with y ≠ 0 and control points "
                      "on the real axis (004 Thm 3.7.3); drawn unscaled. %1")
                       .arg(out.note);
    }
    return out;
}

// ---- declared properties ----------------------------------------------------------------------

const PropertyTable &ComplexBezierItem::declaration()
{
    static const PropertyTable table = [] {
        using Z = std::complex<double>;
        Declaration<ComplexBezierItem> d(&AttractorItem::attractorProperties());
        auto t = d.part(&ComplexBezierItem::m_t, &ComplexBezierItem::checkT,
                        &ComplexBezierItem::tChanged, QT_TR_NOOP("Change t of %1"));
        t.checkedOnRead([](const ComplexBezierItem &item, const Z &z) { return item.checkT(z); });
        t.complex("t", [](Z &z) -> Z & { return z; })
            .label(QT_TR_NOOP("Split parameter t"))
            .group(QT_TR_NOOP("Curve"))
            .tip(QT_TR_NOOP("de Casteljau split at a complex t; inside both discs |t| < 1 and "
                            "|1 − t| < 1 the curve is a fractal (004 §3.7, Fig. 3.3)"))
            .required()
            .codec([](const ComplexBezierItem &, const Z &z) { return property::complexToJson(z); },
                   [](const ComplexBezierItem &, Z &z, const QJsonValue &v, const QString &where) {
                       if (!v.isArray() || v.toArray().size() != 2)
                           throw LoadError{where, tr("expected [re, im]")};
                       z = property::complexFromJson(v, where);
                   });
        auto scaled = d.part(&ComplexBezierItem::m_scaled, &ComplexBezierItem::checkScaled,
                             &ComplexBezierItem::scaledChanged,
                             QT_TR_NOOP("Change scaled coordinates of %1"));
        scaled.boolean("scaled", [](bool &b) -> bool & { return b; })
            .label(QT_TR_NOOP("Scaled coordinates g(z, 1/(2y))"))
            .group(QT_TR_NOOP("Curve"))
            .tip(QT_TR_NOOP("Draw Re z + i Im z / (2y) for t = 1/2 + iy: the coordinates of "
                            "004 Thm 3.7.3 and Figs. 3.6–3.8, where the curve approaches the "
                            "Takagi graph"))
            .fileDefault(false)
            .omitWhenDefault()
            .notAnimated()
            .enabledWhen([](const ComplexBezierItem &item, const bool &) {
                return item.scaledApplies();
            });
        declarePointSet(d, 0, QStringLiteral("control_points"), QT_TR_NOOP("Control points"));
        return d.table();
    }();
    return table;
}

} // namespace awb
