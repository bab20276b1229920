// attractor-cli analyse --json reports the certified Hölder regularity of each subdivision
// curve's scheme (issue 16): the cubic B-spline of 000 Fig. 2 (exactly 3, C^2), the classic
// four-point scheme of 000 Fig. 5 (2, not attained: C^1), a Bézier curve (C^infinity), and a
// scheme edited to omega = 1 (not convergent).

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QtTest>

#include "TestMain.h"

#include "CliRunner.h"

#include <cmath>

class TestRegularityCli : public QObject {
    Q_OBJECT
private slots:
    void cubicBSpline();
    void fourPointClassic();
    void bezierIsPolynomial();
    void divergentFourPoint();

private:
    QJsonObject regularity(const QString &file, const QString &item)
    {
        QByteArray out, err;
        const int code = awb::test::runProgram(awb::test::cliPath(),
                                               {"analyse", file, "--item", item, "--json"}, &out,
                                               &err);
        if (code != 0)
            qWarning("%s", err.constData());
        return QJsonDocument::fromJson(out)
            .object()["items"]
            .toArray()
            .first()
            .toObject()["regularity"]
            .toObject();
    }
    QTemporaryDir m_dir;
};

void TestRegularityCli::cubicBSpline()
{
    const QJsonObject r = regularity(awb::test::examplePath("000-fig02-cubic-bspline-from-point.awb"),
                                     "000 Fig. 2: cubic B-spline from a point");
    QCOMPARE(r["smoothness"].toString(), QString("C^2"));
    QVERIFY(std::abs(r["lower"].toDouble() - 3.0) < 1e-9);
    QVERIFY(std::abs(r["upper"].toDouble() - 3.0) < 1e-9);
    QCOMPARE(r["width"].toDouble(), r["upper"].toDouble() - r["lower"].toDouble());
    QCOMPARE(r["sum_rules"].toInt(), 4);
    QVERIFY(r["method"].toString().contains("joint spectral radius"));
    QVERIFY(r["method"].toString().contains("divided-difference"));
}

void TestRegularityCli::fourPointClassic()
{
    const QJsonObject r = regularity(awb::test::examplePath("000-fig05-four-point-from-segment.awb"),
                                     "000 Fig. 5: four-point scheme from a segment");
    QCOMPARE(r["smoothness"].toString(), QString("C^1"));
    QVERIFY(r["lower"].toDouble() > 2.0 - 1e-6 && r["lower"].toDouble() <= 2.0);
    QVERIFY(r["upper"].toDouble() >= 2.0 - 1e-12);
    QVERIFY(r["jsr"].toObject()["lower"].toDouble() <= r["jsr"].toObject()["upper"].toDouble());
}

void TestRegularityCli::bezierIsPolynomial()
{
    const QJsonObject r = regularity(awb::test::examplePath("004-fig2.2-decasteljau-cubic.awb"),
                                     "004 Fig. 2.2: cubic Bézier by de Casteljau (Ex. 2.2.1)");
    QCOMPARE(r["smoothness"].toString(), QString("C^infinity"));
    QVERIFY(!r.contains("lower"));
    QVERIFY(r["message"].toString().contains("polynomial"));
}

void TestRegularityCli::divergentFourPoint()
{
    QFile in(awb::test::examplePath("000-fig05-four-point-from-segment.awb"));
    QVERIFY(in.open(QIODevice::ReadOnly));
    QByteArray text = in.readAll();
    QVERIFY(text.contains("\"omega\": 0.0625"));
    text.replace("\"omega\": 0.0625", "\"omega\": 1");
    const QString path = m_dir.filePath("omega-1.awb");
    QFile out(path);
    QVERIFY(out.open(QIODevice::WriteOnly));
    out.write(text);
    out.close();
    const QJsonObject r = regularity(path, "000 Fig. 5: four-point scheme from a segment");
    QCOMPARE(r["smoothness"].toString(), QString("not convergent"));
    QVERIFY(r["message"].toString().startsWith("not convergent"));
    QVERIFY(r["upper"].toDouble() <= 0.0);
}

AWB_TEST_GUILESS_MAIN(TestRegularityCli)
#include "test_regularity_cli.moc"
