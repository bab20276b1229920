#include "model/SubdivisionCurveItem.h"

#include "core/schemes/Scheme.h"
#include "model/Commands.h"
#include "model/ComplexBezierItem.h"
#include "model/PointSetProperty.h"
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
    return checkWithMaps(scheme.check(), scheme.arity(), QStringLiteral("scheme."));
}

bool SubdivisionCurveItem::setScheme(const SchemeSpec &scheme, int gesture)
{
    return setDeclared(*this, scheme, gesture);
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

// ---- declared properties ----------------------------------------------------------------------

const PropertyTable &SubdivisionCurveItem::declaration()
{
    static const PropertyTable table = [] {
        using K = SchemeSpec::Kind;
        const auto kindIn = [](std::vector<K> kinds) {
            return [kinds](const SchemeSpec &s) {
                return std::find(kinds.begin(), kinds.end(), s.kind) != kinds.end();
            };
        };
        Declaration<SubdivisionCurveItem> d(&AttractorItem::attractorProperties());
        auto scheme = d.part(&SubdivisionCurveItem::m_scheme, &SubdivisionCurveItem::checkScheme,
                             &SubdivisionCurveItem::schemeChanged,
                             QT_TR_NOOP("Change scheme of %1"));
        scheme.checkedOnRead(
            [](const SubdivisionCurveItem &, const SchemeSpec &s) { return s.check(); },
            QStringLiteral("scheme"));
        scheme
            .choice("scheme.kind", &SchemeSpec::kind, SchemeSpec::kindNames(),
                    {QT_TR_NOOP("Uniform B-spline"), QT_TR_NOOP("End-interpolating B-spline"),
                     QT_TR_NOOP("Chaikin"), QT_TR_NOOP("Corner cutting"), QT_TR_NOOP("Four-point"),
                     QT_TR_NOOP("Bézier (de Casteljau)"), QT_TR_NOOP("Own matrices"),
                     QT_TR_NOOP("Mask")})
            .label(QT_TR_NOOP("Scheme"))
            .group(QT_TR_NOOP("Scheme"))
            .required()
            // A new mask or own matrices start from what the curve has now (the cubic
            // B-spline's when there is nothing to take), so the first step is always a valid
            // scheme.
            .onEdit([](const SubdivisionCurveItem &c, SchemeSpec &next) -> MaybeProblem {
                if (next.kind == K::Mask && c.m_scheme.kind != next.kind)
                    next.takeMaskOf(c.m_scheme) || next.takeMaskOf(SchemeSpec{});
                if (next.kind == K::Matrices && c.m_scheme.kind != next.kind)
                    next.matrices = c.startingMatrices();
                return std::nullopt;
            });
        scheme.integer("scheme.degree", &SchemeSpec::degree)
            .label(QT_TR_NOOP("Degree"))
            .group(QT_TR_NOOP("Scheme"))
            .when(kindIn({K::BSpline, K::EndInterpolatingBSpline, K::Bezier}))
            .adjust([](const SubdivisionCurveItem &, const SchemeSpec &s, ParameterInfo &i) {
                const bool bezier = s.kind == K::Bezier;
                i.minimum = 1;
                i.maximum = bezier ? 30 : 15;
                i.toolTip = bezier ? tr("Degree n: the curve has n + 1 control points")
                                   : tr("Degree of the B-spline (Lane–Riesenfeld, 004 eq. 2.7)");
            });
        scheme.complex("scheme.t", &SchemeSpec::t)
            .label(QT_TR_NOOP("Split parameter t"))
            .group(QT_TR_NOOP("Scheme"))
            .tip(QT_TR_NOOP("de Casteljau split at t (004 eq. 2.5). A complex t inside both "
                            "discs |t| < 1, |1 − t| < 1 gives a fractal curve (004 §3.7)."))
            .when(kindIn({K::Bezier}));
        scheme.real("scheme.omega", &SchemeSpec::omega)
            .label(QT_TR_NOOP("Tension ω"))
            .group(QT_TR_NOOP("Scheme"))
            .slider(-0.5, 0.5)
            .tip(QT_TR_NOOP("1/16 gives C1 curves reproducing cubics; −1/2 < ω < 0 or "
                            "1/4 ≤ ω < 1/2 gives fractal curves (004 Thm. 2.4.1)"))
            .when(kindIn({K::FourPoint}));
        for (const auto &[key, member, label] :
             {std::tuple{"scheme.a", &SchemeSpec::a, QT_TR_NOOP("First cut a")},
              std::tuple{"scheme.b", &SchemeSpec::b, QT_TR_NOOP("Second cut b")}})
            scheme.real(key, member)
                .label(label)
                .group(QT_TR_NOOP("Scheme"))
                .range(0, 1)
                .slider(0, 1)
                .tip(QT_TR_NOOP("New points at parameters a < b on every edge (Chaikin: 1/4, "
                                "3/4)"))
                .when(kindIn({K::CornerCutting}));
        scheme.matrices("scheme.matrices", &SchemeSpec::matrices)
            .label(QT_TR_NOOP("Matrices S_i"))
            .tip(QT_TR_NOOP("The subdivision matrices S_1 .. S_p, m x m with rows summing to "
                            "1; edited cell by cell in the Matrices dock"))
            .when(kindIn({K::Matrices}))
            .required();
        scheme.integer("scheme.arity", &SchemeSpec::maskArity)
            .label(QT_TR_NOOP("Arity N"))
            .group(QT_TR_NOOP("Scheme"))
            .range(2, 64)
            .tip(QT_TR_NOOP("Each step makes N new points per old one. A new arity whose "
                            "cosets the mask does not fit starts from the N-ary piecewise "
                            "linear mask."))
            .when(kindIn({K::Mask}))
            .onEdit([](const SubdivisionCurveItem &c, SchemeSpec &next) -> MaybeProblem {
                if (next.maskArity == c.m_scheme.maskArity || next.maskArity < 2
                    || next.maskArity > 64 || !next.check())
                    return std::nullopt;
                // The N-ary hat (1, 2, .., N, .., 2, 1) / N: piecewise linear interpolation.
                const int N = next.maskArity;
                next.mask.clear();
                next.maskText.clear();
                for (int k = 1 - N; k <= N - 1; ++k) {
                    next.mask.push_back(double(N - std::abs(k)) / N);
                    next.maskText << (k == 0 ? QStringLiteral("1")
                                             : QStringLiteral("%1/%2")
                                                   .arg(N - std::abs(k))
                                                   .arg(N));
                }
                next.maskOffset = 1 - N;
                return std::nullopt;
            });
        scheme
            .text("scheme.mask",
                  [](const SubdivisionCurveItem &, const SchemeSpec &s) { return s.maskLine(); },
                  [](const SubdivisionCurveItem &, SchemeSpec &s,
                     const QString &line) -> MaybeProblem {
                      QString why;
                      if (!s.setMaskLine(line, &why))
                          return Problem{"scheme.mask", why};
                      return std::nullopt;
                  })
            .label(QT_TR_NOOP("Mask a_k"))
            .group(QT_TR_NOOP("Scheme"))
            .tip(QT_TR_NOOP("q_n = Σ a_(n − N l) p_l. Separate the coefficients by commas (by "
                            "semicolons to use decimal commas); fractions (3/8) and expressions "
                            "((1 + sqrt(3))/8) are kept as typed. Each of the N cosets "
                            "a_(r + N k) must sum to 1."))
            .when(kindIn({K::Mask}))
            .required(QT_TR_NOOP("expected a non-empty array of coefficients"))
            // The file keeps each coefficient as a number, or as the text typed where it is
            // not a plain number ("3/8", "(1 + sqrt(3))/8").
            .codec(
                [](const SubdivisionCurveItem &, const SchemeSpec &s) {
                    QJsonArray coefficients;
                    for (size_t i = 0; i < s.mask.size(); ++i) {
                        const QString text =
                            i < size_t(s.maskText.size()) ? s.maskText[int(i)] : QString();
                        coefficients.append(text.isEmpty() ? QJsonValue(s.mask[i])
                                                           : QJsonValue(text));
                    }
                    return QJsonValue(coefficients);
                },
                [](const SubdivisionCurveItem &, SchemeSpec &s, const QJsonValue &v,
                   const QString &where) {
                    const QJsonArray list = v.toArray();
                    if (!v.isArray() || list.isEmpty())
                        throw LoadError{where, tr("expected a non-empty array of coefficients")};
                    s.mask.clear();
                    s.maskText.clear();
                    for (qsizetype i = 0; i < list.size(); ++i) {
                        s.mask.push_back(FieldReader::toExactNumber(
                            list[i], where + QStringLiteral("[%1]").arg(i + 1)));
                        s.maskText << (list[i].isString() ? list[i].toString().trimmed()
                                                          : QString());
                    }
                });
        scheme.integer("scheme.offset", &SchemeSpec::maskOffset)
            .label(QT_TR_NOOP("First index k"))
            .group(QT_TR_NOOP("Scheme"))
            .range(-1000000, 1000000)
            .tip(QT_TR_NOOP("The index of the mask's first coefficient: the cubic B-spline is "
                            "1/8, 1/2, 3/4, 1/2, 1/8 from k = −2"))
            .when(kindIn({K::Mask}))
            .fileDefault(0);
        scheme
            .text("scheme.symbol",
                  [](const SubdivisionCurveItem &, const SchemeSpec &s) { return s.symbolText(); },
                  nullptr)
            .notSaved()
            .label(QT_TR_NOOP("Symbol"))
            .group(QT_TR_NOOP("Scheme"))
            .tip(QT_TR_NOOP("The symbol a(z) = Σ a_k z^k divided by σ(z) = 1 + z + … + "
                            "z^(N−1) as often as it goes: each factor is one sum rule "
                            "(polynomials of one more degree reproduced, one more difference "
                            "scheme)"))
            .when(kindIn({K::Mask}));
        declarePointSet(d, 0, QStringLiteral("control_points"), QT_TR_NOOP("Control points"));
        return d.table();
    }();
    return table;
}

} // namespace awb
