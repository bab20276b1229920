#pragma once
// Number formatting shared by the views and the CLI (layer 2, QtCore only): matrices and
// eigenvalues of subdivision schemes are often small dyadic fractions (3/8, -1/16), which read
// far better as fractions than as 0.375 or -0.0625. Anything else gets a fixed number of
// significant digits.

#include <QString>

#include <complex>
#include <optional>

namespace awb {

struct Fraction {
    long long numerator = 0;
    long long denominator = 1;  // > 0, lowest terms
};

// The fraction p/q with the smallest q <= maxDenominator such that |v - p/q| < tolerance;
// nullopt when there is none (or v is not finite or too large for the numerator).
std::optional<Fraction> exactFraction(double v, int maxDenominator = 1024,
                                      double tolerance = 1e-12);

// "3/8", "−1/16", "1", "0" when exact, otherwise v with `digits` significant digits
// ("0.112", "−1.5e-07"). Minus signs are the typographic U+2212.
QString formatNumber(double v, int digits = 6);

// "0.112 + 0.449i", "1/2 − (1/4)i", "−0.25" (no imaginary part below 1e-12 relative).
QString formatComplex(std::complex<double> z, int digits = 6);

// Parses what a user types for a number (a matrix cell, a parameter): decimals, exponents,
// fractions "3/8", "-1/16", and expressions of them with + - * / ^ and parentheses, pi (π), e,
// sqrt (√), cbrt, sin, cos, tan, exp, ln: "sqrt(3)/6", "1/2 + 1/16", "2^-5". ASCII or
// typographic minus; a decimal comma. Returns nullopt for anything else (the whole text must
// parse) and for non-finite results.
std::optional<double> parseNumber(const QString &text);

// What an editor shows for a value: a short exact decimal as it is ("0.25", "3"), a value only
// a fraction writes exactly as the fraction ("1/3", "5/24"), else 10 significant digits.
QString displayNumber(double v);

// A name with a subscript as plain text: "S_1" -> "S₁", "M_{12}" -> "M₁₂" (legends and axis
// labels have no rich text). Names without "_" are returned unchanged.
QString subscriptName(const QString &name);

// Full precision text of v for an editor (round-trips exactly): the fraction when exact.
QString editableNumber(double v);

// For machine-read output (JSON): "3/8", "-1/16", "2" when v is such a fraction (denominator
// up to 4096, within 1e-13), otherwise v with 17 significant digits. ASCII minus.
QString exactText(double v);

} // namespace awb
