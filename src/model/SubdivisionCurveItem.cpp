#include "model/SubdivisionCurveItem.h"

#include "core/schemes/Scheme.h"
#include "model/Commands.h"
#include "model/ComplexBezierItem.h"
#include "model/ProjectIO.h"

#include <cmath>

namespace awb {

namespace {

QString fromStd(const std::string &s) { return QString::fromStdString(s); }

// lupdate takes the context of CurveItemTr::tr() from the macro (a free tr() would get the
// enclosing namespace as its context).
struct CurveItemTr {
    Q_DECLARE_TR_FUNCTIONS(awb::SubdivisionCurveItem)
};

DerivedIfs complexBezierIfs(int n, Complex t, const Mat &P)
{
    requireFinite(P, "control points");
    const int m = int(P.rows());
    if (m != n + 1)
        throw InputError(CurveItemTr::tr("Bézier of degree %1 needs exactly %2 control points, got %3")
                             .arg(n).arg(n + 1).arg(m).toStdString());
    return complexBezierDerivedIfs(P, t);
}

} // namespace

// ---- SubdivisionCurveItem ---------------------------------------------------------------------

SubdivisionCurveItem::SubdivisionCurveItem()
    : AttractorItem(CurveItemTr::tr("Curve")), m_points{{0.0, 0.0}, {1.0, 2.0}, {3.0, 2.0}, {4.0, 0.0}}
{
}

MaybeProblem SubdivisionCurveItem::checkScheme(const SchemeSpec &scheme) const
{
    if (auto p = scheme.check())
        return Problem{"scheme." + p->field, p->message};
    if (auto p = algorithm().check(scheme.arity()))
        return Problem{"algorithm." + p->field, p->message};
    return std::nullopt;
}

bool SubdivisionCurveItem::setScheme(const SchemeSpec &scheme, int gesture)
{
    if (checkScheme(scheme))
        return false;
    applyProperty(&SubdivisionCurveItem::m_scheme, scheme, &SubdivisionCurveItem::schemeChanged,
                  CurveItemTr::tr("Change scheme of %1").arg(name()), gesture);
    return true;
}

std::vector<Mat> SubdivisionCurveItem::startingMatrices() const
{
    const int m = int(m_points.size());
    for (const SchemeSpec &from : {m_scheme, SchemeSpec{}}) {
        if (from.kind == SchemeSpec::Kind::Matrices || from.check())
            continue;
        try {
            return from.makeScheme()->matrices(m).S;
        } catch (const InputError &) {
        }
    }
    // Too few points even for the cubic B-spline: the linear B-spline's split (m >= 2).
    return bsplineScheme(1).matrices(std::max(m, 2)).S;
}

DerivedIfs SubdivisionCurveItem::computeIfs() const
{
    const Mat P = toMatrix(m_points);
    DerivedIfs out;
    if (m_scheme.isComplex()) {
        out = complexBezierIfs(m_scheme.degree, m_scheme.t, P);
    } else {
        const auto s = std::make_shared<const SubdivisionIfs>(
            buildSubdivisionIfs(*m_scheme.makeScheme(), P));
        out.S.real = s->matrices.S;
        for (const LiftedMap &l : s->lifted)
            out.A.real.push_back(l.A);
        if (s->lifted.empty())
            out.A.unavailable = fromStd(s->lifting.reason);
        out.note = fromStd(s->lifting.note());
        out.ifs = s->ifs;
        out.toIfsSpace = [s](const Mat &X) { return s->toIfsSpace(X); };
        out.subdivision = s;
    }
    applyAlgorithm(out.ifs);
    return out;
}

void SubdivisionCurveItem::write(QJsonObject &json) const
{
    AttractorItem::write(json);
    json["scheme"] = m_scheme.toJson();
    json["control_points"] = ProjectIO::pointsToJson(m_points);
}

void SubdivisionCurveItem::read(const FieldReader &fields)
{
    AttractorItem::read(fields);
    m_scheme = SchemeSpec::fromJson(*fields.object("scheme", true));
    m_points = fields.points("control_points");
}

// ---- generic parameters ---------------------------------------------------------------------

QList<ParameterInfo> SubdivisionCurveItem::parameters() const
{
    using P = ParameterInfo;
    const QString group = CurveItemTr::tr("Scheme");
    QList<ParameterInfo> list;
    list << P::make("scheme.kind", CurveItemTr::tr("Scheme"), P::Type::Choice)
                .options({CurveItemTr::tr("Uniform B-spline"), CurveItemTr::tr("End-interpolating B-spline"),
                          CurveItemTr::tr("Chaikin"),
                          CurveItemTr::tr("Corner cutting"), CurveItemTr::tr("Four-point"),
                          CurveItemTr::tr("Bézier (de Casteljau)"),
                          CurveItemTr::tr("Own matrices"), CurveItemTr::tr("Mask")})
                .in(group);
    const bool bezier = m_scheme.kind == SchemeSpec::Kind::Bezier;
    if (bezier || m_scheme.kind == SchemeSpec::Kind::BSpline
        || m_scheme.kind == SchemeSpec::Kind::EndInterpolatingBSpline) {
        list << P::make("scheme.degree", CurveItemTr::tr("Degree"), P::Type::Integer)
                    .range(1, bezier ? 30 : 15)
                    .in(group)
                    .tip(bezier ? CurveItemTr::tr("Degree n: the curve has n + 1 control points")
                                : CurveItemTr::tr("Degree of the B-spline (Lane–Riesenfeld, 004 eq. 2.7)"));
    }
    if (bezier) {
        list << P::make("scheme.t", CurveItemTr::tr("Split parameter t"), P::Type::Complex)
                    .in(group)
                    .tip(CurveItemTr::tr("de Casteljau split at t (004 eq. 2.5). A complex t inside both "
                            "discs |t| < 1, |1 − t| < 1 gives a fractal curve (004 §3.7)."));
    }
    if (m_scheme.kind == SchemeSpec::Kind::FourPoint) {
        list << P::make("scheme.omega", CurveItemTr::tr("Tension ω"), P::Type::Real)
                    .slider(-0.5, 0.5)
                    .in(group)
                    .tip(CurveItemTr::tr("1/16 gives C1 curves reproducing cubics; −1/2 < ω < 0 or "
                            "1/4 ≤ ω < 1/2 gives fractal curves (004 Thm. 2.4.1)"));
    }
    if (m_scheme.kind == SchemeSpec::Kind::CornerCutting) {
        const QString tip =
            CurveItemTr::tr("New points at parameters a < b on every edge (Chaikin: 1/4, 3/4)");
        for (const auto &[key, label] : {std::pair{"scheme.a", CurveItemTr::tr("First cut a")},
                                         std::pair{"scheme.b", CurveItemTr::tr("Second cut b")}})
            list << P::make(key, label, P::Type::Real).range(0, 1).slider(0, 1).in(group).tip(tip);
    }
    if (m_scheme.kind == SchemeSpec::Kind::Mask) {
        list << P::make("scheme.arity", CurveItemTr::tr("Arity N"), P::Type::Integer)
                    .range(2, 64)
                    .in(group)
                    .tip(CurveItemTr::tr("Each step makes N new points per old one. A new "
                                         "arity whose cosets the mask does not fit starts "
                                         "from the N-ary piecewise linear mask."));
        list << P::make("scheme.mask", CurveItemTr::tr("Mask a_k"), P::Type::Text)
                    .in(group)
                    .tip(CurveItemTr::tr("q_n = Σ a_(n − N l) p_l. Separate the coefficients "
                                         "by commas (by semicolons to use decimal commas); "
                                         "fractions (3/8) and expressions ((1 + sqrt(3))/8) are "
                                         "kept as typed. Each of the N cosets a_(r + N k) must "
                                         "sum to 1."));
        list << P::make("scheme.offset", CurveItemTr::tr("First index k"), P::Type::Integer)
                    .range(-100000, 100000)
                    .in(group)
                    .tip(CurveItemTr::tr("The index of the mask's first coefficient: the cubic "
                                         "B-spline is 1/8, 1/2, 3/4, 1/2, 1/8 from k = −2"));
        list << P::make("scheme.symbol", CurveItemTr::tr("Symbol"), P::Type::Text)
                    .in(group)
                    .shownOnly()
                    .tip(CurveItemTr::tr("The symbol a(z) = Σ a_k z^k divided by "
                                         "σ(z) = 1 + z + … + z^(N−1) as often as it goes: "
                                         "each factor is one sum rule (polynomials of one more "
                                         "degree reproduced, one more difference scheme)"));
    }
    return list;
}

QVariant SubdivisionCurveItem::parameter(const QString &key) const
{
    if (key == "scheme.kind")
        return int(m_scheme.kind);
    if (key == "scheme.degree")
        return m_scheme.degree;
    if (key == "scheme.t")
        return QPointF(m_scheme.t.real(), m_scheme.t.imag());
    if (key == "scheme.omega")
        return m_scheme.omega;
    if (key == "scheme.a")
        return m_scheme.a;
    if (key == "scheme.b")
        return m_scheme.b;
    if (key == "scheme.arity")
        return m_scheme.maskArity;
    if (key == "scheme.mask")
        return m_scheme.maskLine();
    if (key == "scheme.offset")
        return m_scheme.maskOffset;
    if (key == "scheme.symbol")
        return m_scheme.symbolText();
    return {};
}

bool SubdivisionCurveItem::setParameter(const QString &key, const QVariant &value, int gesture,
                                        QString *error)
{
    SchemeSpec next = m_scheme;
    bool ok = true;
    if (key == "scheme.kind") {
        const int k = value.toInt(&ok);
        ok = ok && k >= 0 && k < SchemeSpec::kindNames().size();
        if (ok)
            next.kind = SchemeSpec::Kind(k);
        // A new mask or own matrices start from what the curve has now (the cubic B-spline's
        // when there is nothing to take), so the first step is always a valid scheme.
        if (ok && next.kind == SchemeSpec::Kind::Mask && m_scheme.kind != next.kind)
            next.takeMaskOf(m_scheme) || next.takeMaskOf(SchemeSpec{});
        if (ok && next.kind == SchemeSpec::Kind::Matrices && m_scheme.kind != next.kind)
            next.matrices = startingMatrices();
    } else if (key == "scheme.degree") {
        next.degree = value.toInt(&ok);
    } else if (key == "scheme.t") {
        const QPointF t = value.toPointF();
        next.t = {t.x(), t.y()};
    } else if (key == "scheme.omega") {
        next.omega = value.toDouble(&ok);
    } else if (key == "scheme.a") {
        next.a = value.toDouble(&ok);
    } else if (key == "scheme.b") {
        next.b = value.toDouble(&ok);
    } else if (key == "scheme.arity") {
        next.maskArity = value.toInt(&ok);
        if (ok && next.maskArity != m_scheme.maskArity && next.maskArity >= 2
            && next.maskArity <= 64 && next.check()) {
            // The N-ary hat (1, 2, .., N, .., 2, 1) / N: piecewise linear interpolation.
            const int N = next.maskArity;
            next.mask.clear();
            next.maskText.clear();
            for (int k = 1 - N; k <= N - 1; ++k) {
                next.mask.push_back(double(N - std::abs(k)) / N);
                next.maskText << (std::abs(k) == 0 ? QStringLiteral("1")
                                                   : QStringLiteral("%1/%2")
                                                         .arg(N - std::abs(k))
                                                         .arg(N));
            }
            next.maskOffset = 1 - N;
        }
    } else if (key == "scheme.mask") {
        QString why;
        if (!next.setMaskLine(value.toString(), &why)) {
            if (error)
                *error = why;
            return false;
        }
    } else if (key == "scheme.offset") {
        next.maskOffset = value.toInt(&ok);
    } else if (key == "scheme.symbol") {
        if (error)
            *error = CurveItemTr::tr("the symbol follows from the mask: edit the mask");
        return false;
    } else {
        return Item::setParameter(key, value, gesture, error);
    }
    return commitParameter(key, value, ok, checkScheme(next),
                           [&] { return setScheme(next, gesture); }, error);
}

} // namespace awb
