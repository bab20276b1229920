#include "model/ComplexBezierItem.h"

#include "core/schemes/ComplexBezier.h"
#include "model/Commands.h"
#include "model/ProjectIO.h"

#include <cmath>

namespace awb {

ComplexBezierItem::ComplexBezierItem()
    : AttractorItem(tr("Complex Bézier")), m_points{{0, 0}, {1, 0}}
{
}

MaybeProblem ComplexBezierItem::checkT(std::complex<double> t) const
{
    if (!std::isfinite(t.real()) || !std::isfinite(t.imag()))
        return Problem{"t", tr("the parameter t must be a finite complex number")};
    return std::nullopt;
}

bool ComplexBezierItem::setT(std::complex<double> t, int gesture)
{
    if (checkT(t))
        return false;
    applyProperty(&ComplexBezierItem::m_t, t, &ComplexBezierItem::tChanged,
                  tr("Change t of %1").arg(name()), gesture);
    return true;
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

DerivedIfs ComplexBezierItem::computeIfs() const
{
    DerivedIfs out = complexBezierDerivedIfs(toMatrix(m_points), m_t);
    // Outside the discs the maps exist but have no attractor: an error, in the core's words.
    const ParameterReport report = classifyParameter(m_t);
    if (!report.hyperbolic)
        throw InputError(report.message);
    applyAlgorithm(out.ifs);
    return out;
}

void ComplexBezierItem::write(QJsonObject &json) const
{
    AttractorItem::write(json);
    json["t"] = QJsonArray{m_t.real(), m_t.imag()};
    json["control_points"] = ProjectIO::pointsToJson(m_points);
}

void ComplexBezierItem::read(const FieldReader &fields)
{
    AttractorItem::read(fields);
    const QJsonValue t = fields.value("t");
    if (t.isUndefined())
        fields.fail("t", tr("missing"));
    if (!t.isArray() || t.toArray().size() != 2)
        fields.fail("t", tr("expected [re, im]"));
    const std::complex<double> value{
        FieldReader::toNumber(t.toArray()[0], fields.path("t") + "[1]"),
        FieldReader::toNumber(t.toArray()[1], fields.path("t") + "[2]")};
    fields.require(checkT(value));
    m_t = value;
    m_points = fields.points("control_points");
}

QList<ParameterInfo> ComplexBezierItem::parameters() const
{
    using P = ParameterInfo;
    return {P::make("t", tr("Split parameter t"), P::Type::Complex)
                .in(tr("Curve"))
                .tip(tr("de Casteljau split at a complex t; inside both discs |t| < 1 and "
                        "|1 − t| < 1 the curve is a fractal (004 §3.7, Fig. 3.3)"))};
}

QVariant ComplexBezierItem::parameter(const QString &key) const
{
    if (key == "t")
        return QPointF(m_t.real(), m_t.imag());
    return {};
}

bool ComplexBezierItem::setParameter(const QString &key, const QVariant &value, int gesture,
                                     QString *error)
{
    if (key != "t")
        return Item::setParameter(key, value, gesture, error);
    if (!value.canConvert<QPointF>() || value.typeId() != QMetaType::QPointF) {
        if (error)
            *error = tr("\"%1\" is not a valid value for %2").arg(value.toString(), key);
        return false;
    }
    const QPointF p = value.toPointF();
    const std::complex<double> t{p.x(), p.y()};
    if (const MaybeProblem problem = checkT(t)) {
        if (error)
            *error = problem->message;
        return false;
    }
    return setT(t, gesture);
}

} // namespace awb
