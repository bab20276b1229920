// Number formatting of the views: exact small fractions, significant digits otherwise,
// complex values, and parsing what a user types into a matrix cell.

#include "model/NumberFormat.h"

#include <QtTest>

#include <cmath>

using namespace awb;

namespace {
const QString kMinus(QChar(0x2212));
}

class TestNumberFormat : public QObject {
    Q_OBJECT
private slots:
    void fractions_data();
    void fractions();
    void irrationalAndLarge();
    void complexValues();
    void parsing();
    void editableRoundTrips();
    void subscripts();
};

void TestNumberFormat::fractions_data()
{
    QTest::addColumn<double>("value");
    QTest::addColumn<QString>("text");
    QTest::newRow("3/8") << 0.375 << QStringLiteral("3/8");
    QTest::newRow("-1/16") << -0.0625 << kMinus + QStringLiteral("1/16");
    QTest::newRow("one") << 1.0 << QStringLiteral("1");
    QTest::newRow("zero") << 0.0 << QStringLiteral("0");
    QTest::newRow("negative zero") << -0.0 << QStringLiteral("0");
    QTest::newRow("6/8 reduced") << 6.0 / 8.0 << QStringLiteral("3/4");
    QTest::newRow("1/3") << 1.0 / 3.0 << QStringLiteral("1/3");
    QTest::newRow("-5/2") << -2.5 << kMinus + QStringLiteral("5/2");
    QTest::newRow("1/1024") << 1.0 / 1024 << QStringLiteral("1/1024");
    // Rounding noise of a matrix product is still the fraction.
    QTest::newRow("noisy 1/8") << 0.125 + 3e-14 << QStringLiteral("1/8");
    QTest::newRow("1/1025 is not small") << 1.0 / 1025 << QStringLiteral("0.00097561");
}

void TestNumberFormat::fractions()
{
    QFETCH(double, value);
    QFETCH(QString, text);
    QCOMPARE(formatNumber(value), text);
}

void TestNumberFormat::irrationalAndLarge()
{
    QCOMPARE(formatNumber(std::sqrt(2.0)), QStringLiteral("1.41421"));
    QCOMPARE(formatNumber(M_PI, 3), QStringLiteral("3.14"));
    QCOMPARE(formatNumber(-std::sqrt(2.0) / 2), kMinus + QStringLiteral("0.707107"));
    QCOMPARE(formatNumber(1.5e-7), QStringLiteral("1.5e") + kMinus + QStringLiteral("07"));
    QCOMPARE(formatNumber(std::nan("")), QStringLiteral("NaN"));
    QVERIFY(!exactFraction(std::sqrt(2.0)).has_value());
    QVERIFY(!exactFraction(1e15).has_value());
    const auto f = exactFraction(-0.0625);
    QVERIFY(f.has_value());
    QCOMPARE(f->numerator, -1LL);
    QCOMPARE(f->denominator, 16LL);
}

void TestNumberFormat::complexValues()
{
    QCOMPARE(formatComplex({0.1123, 0.4491}, 3), QStringLiteral("0.112 + 0.449i"));
    QCOMPARE(formatComplex({0.1123, -0.4491}, 3), QStringLiteral("0.112 ") + kMinus
                                                       + QStringLiteral(" 0.449i"));
    QCOMPARE(formatComplex({0.5, 0.25}), QStringLiteral("1/2 + (1/4)i"));
    QCOMPARE(formatComplex({0.25, 1e-17}), QStringLiteral("1/4"));
    QCOMPARE(formatComplex({0.0, -1.0}), kMinus + QStringLiteral("i"));
    QCOMPARE(formatComplex({0.0, std::sqrt(2.0) / 10}), QStringLiteral("0.141421i"));
    QCOMPARE(formatComplex({0.0, 0.3}), QStringLiteral("(3/10)i"));
}

void TestNumberFormat::parsing()
{
    QCOMPARE(parseNumber(QStringLiteral("3/8")).value_or(-1), 0.375);
    QCOMPARE(parseNumber(QStringLiteral(" -1/16 ")).value_or(-1), -0.0625);
    QCOMPARE(parseNumber(kMinus + QStringLiteral("1/16")).value_or(-1), -0.0625);
    QCOMPARE(parseNumber(QStringLiteral("2.5e-3")).value_or(-1), 0.0025);
    QCOMPARE(parseNumber(QStringLiteral("1")).value_or(-1), 1.0);
    QVERIFY(!parseNumber(QStringLiteral("abc")));
    QVERIFY(!parseNumber(QString()));
    QVERIFY(!parseNumber(QStringLiteral("1/0")));
    QVERIFY(!parseNumber(QStringLiteral("inf")));
    QVERIFY(!parseNumber(QStringLiteral("nan")));
    QVERIFY(!parseNumber(QStringLiteral("1e999")));
    QVERIFY(!parseNumber(QStringLiteral("3/")));
}

void TestNumberFormat::editableRoundTrips()
{
    for (double v : {0.375, -0.0625, 0.1, std::sqrt(2.0), -1e-20, 123456.789}) {
        const auto back = parseNumber(editableNumber(v));
        QVERIFY2(back.has_value(), qPrintable(editableNumber(v)));
        QCOMPARE(*back, v);
    }
    QCOMPARE(editableNumber(-0.0625), QStringLiteral("-1/16"));
}

void TestNumberFormat::subscripts()
{
    QCOMPARE(subscriptName(QStringLiteral("S_1")), QStringLiteral("S₁"));
    QCOMPARE(subscriptName(QStringLiteral("M_{12}")), QStringLiteral("M₁₂"));
    QCOMPARE(subscriptName(QStringLiteral("A_i")), QStringLiteral("Ai"));
    QCOMPARE(subscriptName(QStringLiteral("plain")), QStringLiteral("plain"));
}

QTEST_MAIN(TestNumberFormat)
#include "test_number_format.moc"
