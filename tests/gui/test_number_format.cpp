// Number formatting of the views: exact small fractions, significant digits otherwise,
// complex values, and parsing what a user types into a matrix cell.

#include "gui/app/CompactEditors.h"
#include "model/ItemValues.h"
#include "model/NumberFormat.h"

#include <QLineEdit>
#include <QtTest>

#include "TestMain.h"

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
    void expressions();
    void displayedValues();
    void exactEditors();
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
    // A decimal comma, as typed in a French or Czech locale.
    QCOMPARE(parseNumber(QStringLiteral("0,25")).value_or(-1), 0.25);
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

// What the parameter fields and matrix cells read (issue 28): exact values typed as the papers
// write them.
void TestNumberFormat::expressions()
{
    const auto near = [](const char *text, double expected) {
        const auto v = parseNumber(QString::fromUtf8(text));
        return v && std::abs(*v - expected) <= 1e-15 * std::max(1.0, std::abs(expected));
    };
    QVERIFY(near("sqrt(3)/6", std::sqrt(3.0) / 6));
    QVERIFY(near("√3/6", std::sqrt(3.0) / 6));
    QVERIFY(near("1/2 + 1/16", 0.5625));
    QVERIFY(near("-1/16", -0.0625));
    QVERIFY(near("2^-5", 1.0 / 32));
    QVERIFY(near("-2^2", -4.0));         // the power binds tighter than the sign
    QVERIFY(near("(1 - 2*1/3)/2", 1.0 / 6));
    QVERIFY(near("pi/4", M_PI / 4));
    QVERIFY(near("π/3", M_PI / 3));
    QVERIFY(near("cos(pi/3)", 0.5));
    QVERIFY(near("3*1e-2", 0.03));
    QVERIFY(near("1/3", 1.0 / 3));
    QVERIFY(near("e", M_E));
    QVERIFY(!parseNumber(QStringLiteral("sqrt(3")));
    QVERIFY(!parseNumber(QStringLiteral("sqrt 3")));
    QVERIFY(!parseNumber(QStringLiteral("foo(2)")));
    QVERIFY(!parseNumber(QStringLiteral("sqrt(-1)")));     // NaN
    QVERIFY(!parseNumber(QStringLiteral("1/(1-1)")));      // division by zero
    QVERIFY(!parseNumber(QString(200, QLatin1Char('('))));  // deep nesting: refused, no crash
    QVERIFY(!parseNumber(QString(2000, QLatin1Char('1'))));  // absurdly long
}

void TestNumberFormat::displayedValues()
{
    QCOMPARE(displayNumber(0.25), QStringLiteral("0.25"));
    QCOMPARE(displayNumber(1.0 / 3), QStringLiteral("1/3"));
    QCOMPARE(displayNumber(-5.0 / 24), kMinus + QStringLiteral("5/24"));
    QCOMPARE(displayNumber(0.0), QStringLiteral("0"));
    QCOMPARE(displayNumber(2.0), QStringLiteral("2"));
    QCOMPARE(displayNumber(std::sqrt(3.0) / 6), QStringLiteral("0.2886751346"));
    // Whatever is shown reads back to the value (to 10 digits where it is not exact).
    for (double v : {1.0 / 3, 0.0625, -7.0 / 1024, std::sqrt(2.0), 1e-9, 123456.789})
        QVERIFY(std::abs(*parseNumber(displayNumber(v)) - v) <= 1e-9 * std::abs(v));
}

void TestNumberFormat::exactEditors()
{
    ExactSpinBox spin;
    QStringList refused;
    spin.setRefusal([&](const QString &why) { refused << why; });
    spin.setRange(0, 0.5);
    spin.setValue(1.0 / 3);
    QCOMPARE(spin.text(), QStringLiteral("1/3"));
    QCOMPARE(spin.value(), 1.0 / 3); // not rounded to 6 decimals
    spin.show();
    spin.setFocus();
    spin.findChild<QLineEdit *>()->setText(QStringLiteral("sqrt(3)/6"));
    QTest::keyClick(&spin, Qt::Key_Return);
    QCOMPARE(spin.value(), std::sqrt(3.0) / 6);
    QVERIFY(refused.isEmpty());
    // Out of range: refused with the range, the value kept (not clamped silently).
    spin.findChild<QLineEdit *>()->setText(QStringLiteral("3/4"));
    QTest::keyClick(&spin, Qt::Key_Return);
    QCOMPARE(spin.value(), std::sqrt(3.0) / 6);
    QCOMPARE(refused.size(), 1);
    QVERIFY2(refused.last().contains(QStringLiteral("0.75")) && refused.last().contains(QStringLiteral("0.5")),
             qPrintable(refused.last()));
    spin.findChild<QLineEdit *>()->setText(QStringLiteral("half"));
    QTest::keyClick(&spin, Qt::Key_Return);
    QCOMPARE(refused.size(), 2);
    QVERIFY(refused.last().contains(QStringLiteral("not a number")));

    CheckedSpinBox depth;
    depth.setRange(0, 19);
    depth.setValue(8);
    depth.setRefusal([&](const QString &why) { refused << why; });
    depth.show();
    depth.setFocus();
    depth.findChild<QLineEdit *>()->setText(QStringLiteral("-3"));
    QTest::keyClick(&depth, Qt::Key_Return);
    QCOMPARE(depth.value(), 8); // not 3
    QVERIFY2(refused.last().contains(QStringLiteral("0")) && refused.last().contains(QStringLiteral("19")),
             qPrintable(refused.last()));
    depth.findChild<QLineEdit *>()->setText(QStringLiteral("40"));
    QTest::keyClick(&depth, Qt::Key_Return);
    QCOMPARE(depth.value(), 8);
    QVERIFY(refused.last().startsWith(QStringLiteral("40 ")));
    depth.findChild<QLineEdit *>()->setText(QStringLiteral("12"));
    QTest::keyClick(&depth, Qt::Key_Return);
    QCOMPARE(depth.value(), 12);
    // The model's own message names the deepest level for the map count.
    QCOMPARE(AlgorithmSpec::maxDepthFor(3), 19);
    QCOMPARE(AlgorithmSpec::maxDepthFor(2), 31);
    QCOMPARE(AlgorithmSpec::maxDepthFor(1), AlgorithmSpec::maxDepth);
    AlgorithmSpec a;
    a.depth = 40;
    QVERIFY(a.check(3)->message.contains(QStringLiteral("at most depth 19")));
}

AWB_TEST_MAIN(TestNumberFormat)
#include "test_number_format.moc"
