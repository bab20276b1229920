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

namespace {

// A recursive-descent reader of what a user may type for a number:
//   expr   := term (('+' | '-') term)*
//   term   := factor (('*' | '/') factor)*
//   factor := ('+' | '-') factor | power
//   power  := atom ('^' factor)?
//   atom   := number | 'pi' | 'π' | 'e' | name '(' expr ')' | '(' expr ')' | '√' atom
// with sqrt, cbrt, sin, cos, tan, exp and ln (log) as names. Whitespace is ignored.
class ExpressionReader {
public:
    explicit ExpressionReader(const QString &text) : m_s(text) {}

    std::optional<double> read()
    {
        const std::optional<double> v = expr();
        if (!v || m_i != m_s.size())
            return std::nullopt;
        return v;
    }

private:
    QChar peek() const { return m_i < m_s.size() ? m_s[m_i] : QChar(); }
    bool take(QChar c)
    {
        if (peek() != c)
            return false;
        ++m_i;
        return true;
    }
    std::optional<double> expr()
    {
        auto v = term();
        while (v) {
            if (take(QLatin1Char('+'))) {
                const auto r = term();
                v = r ? std::optional(*v + *r) : std::nullopt;
            } else if (take(QLatin1Char('-'))) {
                const auto r = term();
                v = r ? std::optional(*v - *r) : std::nullopt;
            } else {
                break;
            }
        }
        return v;
    }
    std::optional<double> term()
    {
        auto v = factor();
        while (v) {
            if (take(QLatin1Char('*')) || take(QChar(0x00d7)) || take(QChar(0x22c5))) {
                const auto r = factor();
                v = r ? std::optional(*v * *r) : std::nullopt;
            } else if (take(QLatin1Char('/'))) {
                const auto r = factor();
                v = r && *r != 0.0 ? std::optional(*v / *r) : std::nullopt;
            } else {
                break;
            }
        }
        return v;
    }
    std::optional<double> factor()
    {
        if (take(QLatin1Char('-'))) {
            const auto v = factor();
            return v ? std::optional(-*v) : std::nullopt;
        }
        if (take(QLatin1Char('+')))
            return factor();
        return power();
    }
    std::optional<double> power()
    {
        const auto base = atom();
        if (base && take(QLatin1Char('^'))) {
            const auto e = factor();
            return e ? std::optional(std::pow(*base, *e)) : std::nullopt;
        }
        return base;
    }
    std::optional<double> atom()
    {
        if (++m_depth > 64) // "((((((...": refused, not a stack overflow
            return std::nullopt;
        struct Leave {
            int &d;
            ~Leave() { --d; }
        } leave{m_depth};
        if (take(QLatin1Char('('))) {
            const auto v = expr();
            return v && take(QLatin1Char(')')) ? v : std::nullopt;
        }
        if (take(QChar(0x221a))) { // √
            const auto v = atom();
            return v ? std::optional(std::sqrt(*v)) : std::nullopt;
        }
        if (take(QChar(0x03c0)))
            return M_PI;
        if (peek().isLetter()) {
            const qsizetype start = m_i;
            while (peek().isLetterOrNumber())
                ++m_i;
            const QString name = m_s.mid(start, m_i - start).toLower();
            if (name == QLatin1String("pi"))
                return M_PI;
            if (name == QLatin1String("e") && peek() != QLatin1Char('('))
                return M_E;
            if (!take(QLatin1Char('(')))
                return std::nullopt;
            const auto v = expr();
            if (!v || !take(QLatin1Char(')')))
                return std::nullopt;
            if (name == QLatin1String("sqrt"))
                return std::sqrt(*v);
            if (name == QLatin1String("cbrt"))
                return std::cbrt(*v);
            if (name == QLatin1String("sin"))
                return std::sin(*v);
            if (name == QLatin1String("cos"))
                return std::cos(*v);
            if (name == QLatin1String("tan"))
                return std::tan(*v);
            if (name == QLatin1String("exp"))
                return std::exp(*v);
            if (name == QLatin1String("ln") || name == QLatin1String("log"))
                return std::log(*v);
            return std::nullopt;
        }
        // A number: digits, one decimal point (or a comma), an exponent.
        const qsizetype start = m_i;
        while (peek().isDigit() || peek() == QLatin1Char('.') || peek() == QLatin1Char(','))
            ++m_i;
        if (m_i > start && (peek() == QLatin1Char('e') || peek() == QLatin1Char('E'))) {
            const qsizetype mark = m_i;
            ++m_i;
            if (peek() == QLatin1Char('+') || peek() == QLatin1Char('-'))
                ++m_i;
            if (!peek().isDigit())
                m_i = mark; // "2e" is 2 times e? No: not a number's exponent, leave it
            while (peek().isDigit())
                ++m_i;
        }
        if (m_i == start)
            return std::nullopt;
        QString number = m_s.mid(start, m_i - start);
        bool ok = false;
        double v = QLocale::c().toDouble(number, &ok);
        if (!ok) // a user may type a decimal comma in their own locale
            v = QLocale().toDouble(number, &ok);
        if (!ok) {
            number.replace(QLatin1Char(','), QLatin1Char('.'));
            v = QLocale::c().toDouble(number, &ok);
        }
        return ok ? std::optional(v) : std::nullopt;
    }

    QString m_s;
    qsizetype m_i = 0;
    int m_depth = 0;
};

} // namespace

std::optional<double> parseNumber(const QString &text)
{
    QString s = text.trimmed();
    s.replace(kMinus, QLatin1Char('-'));
    s.remove(QLatin1Char(' '));
    if (s.isEmpty() || s.size() > 1000)
        return std::nullopt;
    const std::optional<double> v = ExpressionReader(s).read();
    if (!v || !std::isfinite(*v))
        return std::nullopt;
    return v;
}

QString displayNumber(double v)
{
    // A short exact decimal stays one (0.25, 0.0625, 3); a value that only a fraction writes
    // exactly becomes the fraction (1/3, 5/24); anything else gets 10 significant digits.
    if (!std::isfinite(v))
        return formatNumber(v);
    const QString shortDecimal = QString::number(v, 'g', 6);
    if (QLocale::c().toDouble(shortDecimal) == v)
        return withTypographicMinus(shortDecimal);
    if (const auto f = exactFraction(v))
        return withTypographicMinus(fractionText(*f));
    return withTypographicMinus(QString::number(v, 'g', 10));
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
