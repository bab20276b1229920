#include "model/SchemeSpec.h"

#include "core/analysis/Regularity.h"
#include "core/schemes/Scheme.h"
#include "model/NumberFormat.h"
#include "model/ProjectIO.h"

#include <QJsonArray>

#include <cmath>

namespace awb {

namespace {

QString kindName(SchemeSpec::Kind kind) { return SchemeSpec::kindNames().at(int(kind)); }

// The messages keep the context they had in SubdivisionCurveItem.cpp (their translations).
struct SchemeSpecTr {
    Q_DECLARE_TR_FUNCTIONS(awb::SubdivisionCurveItem)
};

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
                SchemeSpecTr::tr("a complex Bézier parameter has no real scheme").toStdString());
        return std::make_unique<BezierScheme>(degree, t.real());
    case Kind::Matrices: return std::make_unique<MatrixScheme>(matrices);
    case Kind::Mask:
        return std::make_unique<UniformScheme>(maskScheme(maskArity, mask, maskOffset));
    }
    throw InputError(SchemeSpecTr::tr("unknown scheme kind").toStdString());
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
                return Problem{field, SchemeSpecTr::tr("the complex parameter t = %1 %2 %3i must satisfy "
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
        return Problem{field, QString::fromStdString(e.what())};
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
                *error = SchemeSpecTr::tr("mask entry %1, \"%2\", is not a number (fractions "
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
        return SchemeSpecTr::tr("no sum rule: σ(z) = %1 does not divide the symbol a(z), so the "
                               "scheme has no difference scheme and cannot converge")
            .arg(sigma);
    QStringList b;
    for (size_t i = 0; i < d.mask.size() && i < 8; ++i)
        b << displayNumber(d.mask[i]);
    if (d.mask.size() > 8)
        b << QStringLiteral("…");
    const QString rules = d.order == 1 ? SchemeSpecTr::tr("1 sum rule")
                                       : SchemeSpecTr::tr("%1 sum rules").arg(d.order);
    // Exponents as superscripts: "σ(z)⁴ b(z) / 2⁴ … from z⁻³".
    const auto power = [](int n) {
        static const QString digits = QStringLiteral("⁰¹²³⁴⁵⁶⁷⁸⁹");
        QString out = n < 0 ? QStringLiteral("⁻") : QString();
        for (const QChar c : QString::number(std::abs(n)))
            out += digits[c.digitValue()];
        return out;
    };
    return SchemeSpecTr::tr("%1: a(z) = σ(z)%2 b(z) / %3%2 with σ(z) = %4 and b = (%5) from "
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


QJsonObject SchemeSpec::toJson() const
{
    QJsonObject scheme{{"kind", kindName(kind)}};
    switch (kind) {
    case Kind::BSpline:
    case Kind::EndInterpolatingBSpline: scheme["degree"] = degree; break;
    case Kind::Chaikin: break;
    case Kind::CornerCutting:
        scheme["a"] = a;
        scheme["b"] = b;
        break;
    case Kind::FourPoint: scheme["omega"] = omega; break;
    case Kind::Bezier:
        scheme["degree"] = degree;
        scheme["t"] = QJsonArray{t.real(), t.imag()};
        break;
    case Kind::Matrices: {
        QJsonArray list;
        for (const Mat &S : matrices) {
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
    case Kind::Mask: {
        scheme["arity"] = maskArity;
        QJsonArray coefficients;
        for (size_t i = 0; i < mask.size(); ++i) {
            const QString text = i < size_t(maskText.size()) ? maskText[int(i)] : QString();
            coefficients.append(text.isEmpty() ? QJsonValue(mask[i]) : QJsonValue(text));
        }
        scheme["mask"] = coefficients;
        scheme["offset"] = maskOffset;
        break;
    }
    }
    return scheme;
}

SchemeSpec SchemeSpec::fromJson(const FieldReader &s)
{
    SchemeSpec spec;
    spec.kind = SchemeSpec::Kind(s.choice("kind", SchemeSpec::kindNames()));
    switch (spec.kind) {
    case Kind::BSpline:
    case Kind::EndInterpolatingBSpline:
        spec.degree = int(s.integer("degree", spec.degree));
        break;
    case Kind::Chaikin: break;
    case Kind::CornerCutting:
        spec.a = s.number("a", spec.a);
        spec.b = s.number("b", spec.b);
        break;
    case Kind::FourPoint: spec.omega = s.number("omega", spec.omega); break;
    case Kind::Bezier: {
        spec.degree = int(s.integer("degree", spec.degree));
        const QJsonValue t = s.value("t");
        const QJsonArray pair = t.toArray();
        if (t.isArray() && pair.size() == 2)
            spec.t = {FieldReader::toNumber(pair[0], s.path("t") + "[1]"),
                      FieldReader::toNumber(pair[1], s.path("t") + "[2]")};
        else if (t.isDouble()) // a real t may be written as a plain number
            spec.t = FieldReader::toNumber(t, s.path("t"));
        else if (!t.isUndefined())
            s.fail("t", SchemeSpecTr::tr("expected [re, im] or a number"));
        break;
    }
    case Kind::Matrices: spec.matrices = s.matrices("matrices"); break;
    case Kind::Mask: {
        spec.maskArity = int(s.integer("arity", 2, 2, 64));
        spec.maskOffset = int(s.integer("offset", 0, -1000000, 1000000));
        const QJsonValue v = s.value("mask");
        const QJsonArray list = v.toArray();
        if (!v.isArray() || list.isEmpty())
            s.fail("mask", SchemeSpecTr::tr("expected a non-empty array of coefficients"));
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
    return spec;
}

} // namespace awb
