#include "model/SubdivisionCurveItem.h"

#include "core/analysis/Regularity.h"
#include "core/schemes/Scheme.h"
#include "model/Commands.h"
#include "model/ComplexBezierItem.h"
#include "model/NumberFormat.h"
#include "model/ProjectIO.h"

#include <cmath>

namespace awb {

namespace {

QString fromStd(const std::string &s) { return QString::fromStdString(s); }

QString kindName(SchemeSpec::Kind kind) { return SchemeSpec::kindNames().at(int(kind)); }

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

// ---- SchemeSpec -------------------------------------------------------------------------------

const QStringList &SchemeSpec::kindNames()
{
    static const QStringList names{"bspline",     "bspline-end-interpolating", "chaikin",
                                   "corner-cutting", "four-point",          "bezier",
                                   "matrices",    "mask"};
    return names;
}

bool SchemeSpec::operator==(const SchemeSpec &o) const
{
    if (kind != o.kind || degree != o.degree || t != o.t || omega != o.omega || a != o.a
        || b != o.b || matrices.size() != o.matrices.size() || maskArity != o.maskArity
        || maskOffset != o.maskOffset || mask != o.mask || maskText != o.maskText)
        return false;
    for (size_t i = 0; i < matrices.size(); ++i)
        if (matrices[i].rows() != o.matrices[i].rows()
            || matrices[i].cols() != o.matrices[i].cols()
            || !(matrices[i].array() == o.matrices[i].array()).all())
            return false;
    return true;
}

int SchemeSpec::arity() const
{
    return kind == Kind::Matrices ? int(matrices.size()) : kind == Kind::Mask ? maskArity : 2;
}

std::unique_ptr<CurveScheme> SchemeSpec::makeScheme() const
{
    switch (kind) {
    case Kind::BSpline: return std::make_unique<UniformScheme>(bsplineScheme(degree));
    case Kind::EndInterpolatingBSpline:
        return std::make_unique<EndInterpolatingBSplineScheme>(degree);
    case Kind::Chaikin: return std::make_unique<UniformScheme>(chaikinScheme());
    case Kind::CornerCutting: return std::make_unique<UniformScheme>(cornerCuttingScheme(a, b));
    case Kind::FourPoint: return std::make_unique<UniformScheme>(fourPointScheme(omega));
    case Kind::Bezier:
        if (isComplex())
            throw InputError(
                CurveItemTr::tr("a complex Bézier parameter has no real scheme").toStdString());
        return std::make_unique<BezierScheme>(degree, t.real());
    case Kind::Matrices: return std::make_unique<MatrixScheme>(matrices);
    case Kind::Mask:
        return std::make_unique<UniformScheme>(maskScheme(maskArity, mask, maskOffset));
    }
    throw InputError(CurveItemTr::tr("unknown scheme kind").toStdString());
}

MaybeProblem SchemeSpec::check() const
{
    // The core's constructors are the judges of the parameters; name the field they concern.
    QString field;
    try {
        switch (kind) {
        case Kind::BSpline:
        case Kind::EndInterpolatingBSpline:
            field = "degree";
            makeScheme();
            break;
        case Kind::Chaikin: break;
        case Kind::CornerCutting:
            field = std::isfinite(a) && a > 0.0 && a < 1.0 ? "b" : "a";
            makeScheme();
            break;
        case Kind::FourPoint:
            field = "omega";
            makeScheme();
            break;
        case Kind::Bezier:
            field = "degree";
            (void)BezierScheme(degree, 0.5);
            field = "t";
            if (!isComplex()) {
                makeScheme();
            } else if (!std::isfinite(t.real()) || !std::isfinite(t.imag())
                       || !(std::abs(t) < 1.0 && std::abs(1.0 - t) < 1.0)) {
                return Problem{field, CurveItemTr::tr("the complex parameter t = %1 %2 %3i must satisfy "
                                         "|t| < 1 and |1 - t| < 1 (004 §3.7)")
                                          .arg(t.real())
                                          .arg(t.imag() < 0 ? "-" : "+")
                                          .arg(std::abs(t.imag()))};
            }
            break;
        case Kind::Matrices:
            field = "matrices";
            makeScheme();
            break;
        case Kind::Mask:
            field = maskArity < 2 || maskArity > 64 ? "arity" : "mask";
            makeScheme();
            break;
        }
    } catch (const InputError &e) {
        return Problem{field, fromStd(e.what())};
    }
    return std::nullopt;
}

QString SchemeSpec::maskLine() const
{
    QStringList entries;
    for (size_t i = 0; i < mask.size(); ++i)
        entries << (i < size_t(maskText.size()) && !maskText[int(i)].isEmpty()
                        ? maskText[int(i)]
                        : displayNumber(mask[i]));
    return entries.join(QStringLiteral(", "));
}

bool SchemeSpec::setMaskLine(const QString &line, QString *error)
{
    const QChar separator = line.contains(QLatin1Char(';')) ? QLatin1Char(';') : QLatin1Char(',');
    QStringList entries = line.split(separator);
    if (entries.size() == 1 && !line.contains(separator))
        entries = line.simplified().split(QLatin1Char(' '));  // "1 4 6 4 1" would read as one
    std::vector<double> values;
    QStringList texts;
    for (int i = 0; i < entries.size(); ++i) {
        const QString entry = entries[i].trimmed();
        const auto v = parseNumber(entry);
        if (!v) {
            if (error)
                *error = CurveItemTr::tr("mask entry %1, \"%2\", is not a number (fractions "
                                         "such as 3/8 and expressions such as "
                                         "(1 + sqrt(3))/8 are)")
                             .arg(i + 1)
                             .arg(entry);
            return false;
        }
        values.push_back(*v);
        bool plain = false;
        entry.toDouble(&plain);
        texts << (plain ? QString() : entry);
    }
    mask = std::move(values);
    maskText = texts;
    return true;
}

QString SchemeSpec::symbolText() const
{
    const int N = maskArity;
    const DifferenceMask d = dividedDifferenceMask(mask, N);
    const QString sigma = N == 2   ? QStringLiteral("1 + z")
                          : N == 3 ? QStringLiteral("1 + z + z²")
                                   : QStringLiteral("1 + z + … + z^(%1)").arg(N - 1);
    if (d.order == 0)
        return CurveItemTr::tr("no sum rule: σ(z) = %1 does not divide the symbol a(z), so the "
                               "scheme has no difference scheme and cannot converge")
            .arg(sigma);
    QStringList b;
    for (size_t i = 0; i < d.mask.size() && i < 8; ++i)
        b << displayNumber(d.mask[i]);
    if (d.mask.size() > 8)
        b << QStringLiteral("…");
    const QString rules = d.order == 1 ? CurveItemTr::tr("1 sum rule")
                                       : CurveItemTr::tr("%1 sum rules").arg(d.order);
    // Exponents as superscripts: "σ(z)⁴ b(z) / 2⁴ … from z⁻³".
    const auto power = [](int n) {
        static const QString digits = QStringLiteral("⁰¹²³⁴⁵⁶⁷⁸⁹");
        QString out = n < 0 ? QStringLiteral("⁻") : QString();
        for (const QChar c : QString::number(std::abs(n)))
            out += digits[c.digitValue()];
        return out;
    };
    return CurveItemTr::tr("%1: a(z) = σ(z)%2 b(z) / %3%2 with σ(z) = %4 and b = (%5) from "
                           "z%6")
        // one pass: a superscript digit after a marker would read as part of its number
        .arg(rules, power(d.order), QString::number(N), sigma, b.join(QStringLiteral(", ")),
             power(maskOffset));
}

bool SchemeSpec::takeMaskOf(const SchemeSpec &other)
{
    if (other.kind == Kind::Bezier || other.kind == Kind::Matrices
        || other.kind == Kind::EndInterpolatingBSpline || other.check())
        return false;
    std::unique_ptr<CurveScheme> scheme;
    try {
        scheme = other.makeScheme();
    } catch (const InputError &) {
        return false;
    }
    const auto *uniform = dynamic_cast<const UniformScheme *>(scheme.get());
    if (!uniform)
        return false;
    std::vector<double> a = uniform->mask();
    int offset = uniform->maskStart();
    while (a.size() > 1 && a.back() == 0.0)  // the core's padding
        a.pop_back();
    while (a.size() > 1 && a.front() == 0.0) {
        a.erase(a.begin());
        ++offset;
    }
    maskArity = uniform->arity();
    maskOffset = offset;
    mask = a;
    maskText.clear();
    for (double v : a) {
        const auto f = exactFraction(v, 4096, 1e-15);
        maskText << (f && f->denominator > 1 ? QStringLiteral("%1/%2").arg(f->numerator)
                                                    .arg(f->denominator)
                                             : QString());
    }
    return true;
}

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
    QJsonObject scheme{{"kind", kindName(m_scheme.kind)}};
    switch (m_scheme.kind) {
    case SchemeSpec::Kind::BSpline:
    case SchemeSpec::Kind::EndInterpolatingBSpline: scheme["degree"] = m_scheme.degree; break;
    case SchemeSpec::Kind::Chaikin: break;
    case SchemeSpec::Kind::CornerCutting:
        scheme["a"] = m_scheme.a;
        scheme["b"] = m_scheme.b;
        break;
    case SchemeSpec::Kind::FourPoint: scheme["omega"] = m_scheme.omega; break;
    case SchemeSpec::Kind::Bezier:
        scheme["degree"] = m_scheme.degree;
        scheme["t"] = QJsonArray{m_scheme.t.real(), m_scheme.t.imag()};
        break;
    case SchemeSpec::Kind::Matrices: {
        QJsonArray list;
        for (const Mat &S : m_scheme.matrices) {
            QJsonArray rows;
            for (Eigen::Index r = 0; r < S.rows(); ++r) {
                QJsonArray row;
                for (Eigen::Index c = 0; c < S.cols(); ++c)
                    row.append(S(r, c));
                rows.append(row);
            }
            list.append(rows);
        }
        scheme["matrices"] = list;
        break;
    }
    case SchemeSpec::Kind::Mask: {
        scheme["arity"] = m_scheme.maskArity;
        QJsonArray mask;
        for (size_t i = 0; i < m_scheme.mask.size(); ++i) {
            const QString text = i < size_t(m_scheme.maskText.size())
                                     ? m_scheme.maskText[int(i)]
                                     : QString();
            mask.append(text.isEmpty() ? QJsonValue(m_scheme.mask[i]) : QJsonValue(text));
        }
        scheme["mask"] = mask;
        scheme["offset"] = m_scheme.maskOffset;
        break;
    }
    }
    json["scheme"] = scheme;
    json["control_points"] = ProjectIO::pointsToJson(m_points);
}

void SubdivisionCurveItem::read(const FieldReader &fields)
{
    AttractorItem::read(fields);
    const FieldReader s = *fields.object("scheme", true);
    SchemeSpec spec;
    spec.kind = SchemeSpec::Kind(s.choice("kind", SchemeSpec::kindNames()));
    switch (spec.kind) {
    case SchemeSpec::Kind::BSpline:
    case SchemeSpec::Kind::EndInterpolatingBSpline:
        spec.degree = int(s.integer("degree", spec.degree));
        break;
    case SchemeSpec::Kind::Chaikin: break;
    case SchemeSpec::Kind::CornerCutting:
        spec.a = s.number("a", spec.a);
        spec.b = s.number("b", spec.b);
        break;
    case SchemeSpec::Kind::FourPoint: spec.omega = s.number("omega", spec.omega); break;
    case SchemeSpec::Kind::Bezier: {
        spec.degree = int(s.integer("degree", spec.degree));
        const QJsonValue t = s.value("t");
        const QJsonArray pair = t.toArray();
        if (t.isArray() && pair.size() == 2)
            spec.t = {FieldReader::toNumber(pair[0], s.path("t") + "[1]"),
                      FieldReader::toNumber(pair[1], s.path("t") + "[2]")};
        else if (t.isDouble()) // a real t may be written as a plain number
            spec.t = FieldReader::toNumber(t, s.path("t"));
        else if (!t.isUndefined())
            s.fail("t", CurveItemTr::tr("expected [re, im] or a number"));
        break;
    }
    case SchemeSpec::Kind::Matrices: spec.matrices = s.matrices("matrices"); break;
    case SchemeSpec::Kind::Mask: {
        spec.maskArity = int(s.integer("arity", 2, 2, 64));
        spec.maskOffset = int(s.integer("offset", 0, -1000000, 1000000));
        const QJsonValue v = s.value("mask");
        const QJsonArray list = v.toArray();
        if (!v.isArray() || list.isEmpty())
            s.fail("mask", CurveItemTr::tr("expected a non-empty array of coefficients"));
        spec.mask.clear();
        spec.maskText.clear();
        for (qsizetype i = 0; i < list.size(); ++i) {
            spec.mask.push_back(FieldReader::toExactNumber(
                list[i], s.path("mask") + QStringLiteral("[%1]").arg(i + 1)));
            spec.maskText << (list[i].isString() ? list[i].toString().trimmed() : QString());
        }
        break;
    }
    }
    s.require(spec.check());
    m_scheme = spec;
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
