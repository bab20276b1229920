#include "model/NumberFormat.h"

#include <QLocale>

#include <cmath>
#include <numeric>

namespace awb {

namespace {

const QChar kMinus(0x2212);

// Numerators beyond this cannot be represented exactly together with a 1e-12 tolerance.
constexpr double kMaxFractionMagnitude = 1e9;

QString withTypographicMinus(QString s)
{
    s.replace(QLatin1Char('-'), kMinus);
    return s;
}

QString fractionText(const Fraction &f)
{
    if (f.denominator == 1)
        return QString::number(f.numerator);
    return QStringLiteral("%1/%2").arg(f.numerator).arg(f.denominator);
}

} // namespace

std::optional<Fraction> exactFraction(double v, int maxDenominator, double tolerance)
{
    if (!std::isfinite(v) || std::abs(v) > kMaxFractionMagnitude)
        return std::nullopt;
    for (long long q = 1; q <= maxDenominator; ++q) {
        const double p = std::round(v * double(q));
        if (std::abs(v - p / double(q)) < tolerance) {
            Fraction f{(long long)p, q};
            const long long g = std::gcd(f.numerator < 0 ? -f.numerator : f.numerator, q);
            if (g > 1) {
                f.numerator /= g;
                f.denominator /= g;
            }
            return f;
        }
    }
    return std::nullopt;
}

QString formatNumber(double v, int digits)
{
    if (std::isnan(v))
        return QStringLiteral("NaN");
    if (std::isinf(v))
        return v > 0 ? QStringLiteral("∞") : QString(kMinus) + QStringLiteral("∞");
    if (const auto f = exactFraction(v))
        return withTypographicMinus(fractionText(*f));
    return withTypographicMinus(QString::number(v, 'g', std::max(1, digits)));
}

QString formatComplex(std::complex<double> z, int digits)
{
    const double re = z.real(), im = z.imag();
    // Eigen solvers leave ~1e-17 imaginary parts on real eigenvalues: not worth showing.
    const double scale = std::max(1.0, std::abs(z));
    const bool hasIm = std::abs(im) >= 1e-12 * scale;
    const bool hasRe = std::abs(re) >= 1e-12 * scale || !hasIm;
    if (!hasIm)
        return formatNumber(re, digits);
    QString imText;
    const double a = std::abs(im);
    if (std::abs(a - 1.0) < 1e-12)
        imText = QStringLiteral("i");
    else {
        QString t = formatNumber(a, digits);
        imText = t.contains(QLatin1Char('/')) ? QStringLiteral("(%1)i").arg(t) : t + 'i';
    }
    if (!hasRe)
        return im < 0 ? QString(kMinus) + imText : imText;
    return QStringLiteral("%1 %2 %3")
        .arg(formatNumber(re, digits), im < 0 ? QString(kMinus) : QStringLiteral("+"), imText);
}

std::optional<double> parseNumber(const QString &text)
{
    QString s = text.trimmed();
    s.replace(kMinus, QLatin1Char('-'));
    s.remove(QLatin1Char(' '));
    if (s.isEmpty())
        return std::nullopt;
    const QLocale c = QLocale::c();
    bool ok = false;
    double v = 0;
    const qsizetype slash = s.indexOf(QLatin1Char('/'));
    if (slash >= 0) {
        bool okNum = false, okDen = false;
        const double num = c.toDouble(s.left(slash), &okNum);
        const double den = c.toDouble(s.mid(slash + 1), &okDen);
        ok = okNum && okDen && den != 0.0;
        v = ok ? num / den : 0.0;
    } else {
        v = c.toDouble(s, &ok);
        if (!ok) // a user may type a decimal comma in their own locale
            v = QLocale().toDouble(s, &ok);
    }
    if (!ok || !std::isfinite(v))
        return std::nullopt;
    return v;
}

QString subscriptName(const QString &name)
{
    const qsizetype u = name.indexOf(QLatin1Char('_'));
    if (u < 0)
        return name;
    QString out = name.left(u);
    for (QChar c : name.mid(u + 1)) {
        if (c.isDigit())
            out += QChar(0x2080 + c.digitValue());
        else if (c != QLatin1Char('{') && c != QLatin1Char('}'))
            out += c;
    }
    return out;
}

QString editableNumber(double v)
{
    // Only a fraction that is exactly v: the editor's text must give back the same double.
    if (const auto f = exactFraction(v); f && double(f->numerator) / double(f->denominator) == v)
        return fractionText(*f);
    return QString::number(v, 'g', QLocale::FloatingPointShortest);
}

QString exactText(double v)
{
    if (const auto f = exactFraction(v, 4096, 1e-13)) {
        if (f->denominator == 1)
            return QString::number(f->numerator);
        return QStringLiteral("%1/%2").arg(f->numerator).arg(f->denominator);
    }
    return QString::number(v, 'g', 17);
}

} // namespace awb
