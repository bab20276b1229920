// attractor-cli analyse --json reports the certified Hölder regularity of each subdivision
// curve's scheme (issue 16): the cubic B-spline of 000 Fig. 2 (exactly 3, C^2), the classic
// four-point scheme of 000 Fig. 5 (2, not attained: C^1), a Bézier curve (C^infinity), and a
// scheme edited to omega = 1 (not convergent). Issue 32: `regularity-interval` brackets where
// the four-point scheme is C^1 (0 < omega < omega*, omega* the real root of 32 w^3 + 4 w - 1,
// Hechler, Mößner & Reif 2009), and a mask typed in a project (Daubechies' D4) gets its Hölder
// exponent 2 - log2(1 + sqrt 3) (Daubechies & Lagarias 1992) and Sobolev exponent 1.

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QtTest>

#include "TestMain.h"
#include "TestTime.h"

#include "CliRunner.h"

#include <cmath>

class TestRegularityCli : public QObject {
    Q_OBJECT
private slots:
    void cubicBSpline();
    void fourPointClassic();
    void bezierIsPolynomial();
    void divergentFourPoint();
    void fourPointC1Interval();
    void maskOfDaubechiesD4();
    void certificatesVerifiedAndTamperingCaught();

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

namespace {
// The seconds each member's certificate may take: 0.2, times the instrumented builds' slowness
// (TestTime.h), so that the bisection reaches its tolerance there too.
QString budget() { return QString::number(0.2 * awb::test::ms(1)); }
} // namespace

void TestRegularityCli::fourPointC1Interval()
{
    QByteArray out, err;
    const QString file = awb::test::examplePath("000-fig05-four-point-from-segment.awb");
    QCOMPARE(awb::test::runProgram(awb::test::cliPath(),
                                   {"regularity-interval", file, "--parameter", "omega", "--from",
                                    "-0.1", "--to", "0.3", "--smoothness", "1", "--grid", "17",
                                    "--budget", budget(), "--json"},
                                   &out, &err),
             0);
    const QJsonObject r = QJsonDocument::fromJson(out).object();
    QCOMPARE(r["smoothness"].toInt(), 1);
    const QJsonArray runs = r["intervals"].toArray();
    QCOMPARE(runs.size(), 1);
    // omega*: Newton on 32 w^3 + 4 w - 1 from 0.2.
    double w = 0.2;
    for (int i = 0; i < 50; ++i)
        w -= (32 * w * w * w + 4 * w - 1) / (96 * w * w + 4);
    QVERIFY(std::abs(w - 0.19273) < 1e-5);
    const QJsonObject from = runs[0].toObject()["from"].toObject();
    const QJsonObject to = runs[0].toObject()["to"].toObject();
    const auto contains = [](const QJsonObject &b, double x) {
        const double lo = std::min(b["inner"].toDouble(), b["outer"].toDouble());
        const double hi = std::max(b["inner"].toDouble(), b["outer"].toDouble());
        return lo <= x && x <= hi;
    };
    QVERIFY2(contains(from, 0.0), QJsonDocument(from).toJson().constData());
    QVERIFY2(contains(to, w), QJsonDocument(to).toJson().constData());
    QVERIFY(to["certified_not"].toBool());
    // (each member exact by its invariant polytope: the bisection reaches the tolerance)
    QVERIFY2(to["width"].toDouble() < 1e-4, QJsonDocument(to).toJson().constData());
    QVERIFY(from["width"].toDouble() < 1e-2);

    // The same family as a mask with a free coefficient: the same bracket.
    const QString mask = m_dir.filePath("four-point-mask.awb");
    QFile f(mask);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write(R"({"format": "attractor-workbench", "version": 1, "items": [
        {"type": "subdivision-curve", "name": "m",
         "scheme": {"kind": "mask", "arity": 2, "offset": -3,
                    "mask": ["-1/16", 0, "9/16", 1, "9/16", 0, "-1/16"]},
         "control_points": [[0, 0], [1, 2], [2, 1], [3, 3], [4, 0], [5, 1], [6, 2], [7, 0]]}]})");
    f.close();
    QCOMPARE(awb::test::runProgram(awb::test::cliPath(),
                                   {"regularity-interval", mask, "--parameter", "w", "--mask",
                                    "-w, 0, 1/2 + w, 1, 1/2 + w, 0, -w", "--from", "-0.1",
                                    "--to", "0.3", "--grid", "17", "--budget", budget(), "--json"},
                                   &out, &err),
             0);
    const QJsonArray viaMask = QJsonDocument::fromJson(out).object()["intervals"].toArray();
    QCOMPARE(viaMask.size(), 1);
    QVERIFY(contains(viaMask[0].toObject()["to"].toObject(), w));
    QCOMPARE(awb::test::runProgram(awb::test::cliPath(),
                                   {"regularity-interval", mask, "--parameter", "sqrt", "--mask",
                                    "sqrt", "--from", "0", "--to", "1"},
                                   &out, &err),
             2);
    QVERIFY2(err.contains("not a function or constant"), err.constData());

    // No omega for a Chaikin curve; --from/--to required; an unknown item.
    QCOMPARE(awb::test::runProgram(awb::test::cliPath(),
                                   {"regularity-interval", file, "--parameter", "a", "--from",
                                    "0", "--to", "1"},
                                   &out, &err),
             2);
    QVERIFY2(err.contains("has no parameter 'a'"), err.constData());
    QCOMPARE(awb::test::runProgram(awb::test::cliPath(),
                                   {"regularity-interval", file, "--parameter", "omega"}, &out,
                                   &err),
             2);
    QVERIFY2(err.contains("--from and --to are required"), err.constData());
}

void TestRegularityCli::maskOfDaubechiesD4()
{
    const QString file = m_dir.filePath("d4.awb");
    QFile f(file);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write(R"({"format": "attractor-workbench", "version": 1, "items": [
        {"type": "subdivision-curve", "name": "D4",
         "scheme": {"kind": "mask", "arity": 2, "offset": 0, "mask":
             ["(1 + sqrt(3))/4", "(3 + sqrt(3))/4", "(3 - sqrt(3))/4", "(1 - sqrt(3))/4"]},
         "control_points": [[0, 0], [1, 2], [3, 2], [4, 0], [5, 1]]}]})");
    f.close();
    const QJsonObject r = regularity(file, "D4");
    const double alpha = 2 - std::log2(1 + std::sqrt(3.0));  // 0.550016 (Daubechies-Lagarias)
    QVERIFY(r["lower"].toDouble() <= alpha + 1e-12 && alpha - 1e-9 <= r["lower"].toDouble());
    QVERIFY(r["upper"].toDouble() >= alpha - 1e-12 && r["upper"].toDouble() <= alpha + 1e-9);
    QCOMPARE(r["smoothness"].toString(), QString("C^0"));
    QCOMPARE(r["sum_rules"].toInt(), 2);
    QVERIFY(std::abs(r["sobolev"].toDouble() - 1.0) < 1e-9);  // Villemoes 1994
}

void TestRegularityCli::certificatesVerifiedAndTamperingCaught()
{
    // The Dubuc-Deslauriers 6-point scheme (Rioul 1992: 2.830075 = 6 - log2 9): exact, its
    // certificate written by analyse and accepted by verify-regularity; every tampering is
    // rejected with its reason.
    const QString file = m_dir.filePath("dd6.awb");
    QFile f(file);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write(R"({"format": "attractor-workbench", "version": 1, "items": [
        {"type": "subdivision-curve", "name": "DD6",
         "scheme": {"kind": "mask", "arity": 2, "offset": -5, "mask": ["3/256", 0, "-25/256",
                    0, "75/128", 1, "75/128", 0, "-25/256", 0, "3/256"]},
         "control_points": [[0, 0], [1, 2], [2, 1], [3, 3], [4, 0], [5, 1], [6, 2], [7, 0],
                            [8, 1], [9, 0], [10, 2]]}]})");
    f.close();
    const QString cert = m_dir.filePath("dd6.json");
    QByteArray out, err;
    QCOMPARE(awb::test::runProgram(awb::test::cliPath(),
                                   {"analyse", file, "--item", "DD6", "--json", "--certificate",
                                    cert},
                                   &out, &err),
             0);
    const QJsonObject r = QJsonDocument::fromJson(out)
                              .object()["items"].toArray().first().toObject()["regularity"]
                              .toObject();
    const double exact = 6 - std::log2(9.0);
    QVERIFY(r["exact"].toBool());
    QCOMPARE(r["smp"].toArray(), QJsonArray{0});
    QVERIFY(std::abs(r["lower"].toDouble() - exact) < 1e-10);
    QVERIFY(std::abs(r["upper"].toDouble() - exact) < 1e-10);

    QCOMPARE(awb::test::runProgram(awb::test::cliPath(),
                                   {"verify-regularity", cert, "--json"}, &out, &err),
             0);
    const QJsonObject v = QJsonDocument::fromJson(out).object();
    QVERIFY(v["ok"].toBool());
    const double lo = v["holder"].toObject()["lower"].toDouble();
    const double hi = v["holder"].toObject()["upper"].toDouble();
    QVERIFY2(lo <= exact && exact <= hi && hi - lo < 1e-9, qPrintable(QString::number(hi - lo)));

    QFile in(cert);
    QVERIFY(in.open(QIODevice::ReadOnly));
    const QJsonObject good = QJsonDocument::fromJson(in.readAll()).object();
    const auto rejected = [&](const QJsonObject &tampered, const char *reason) {
        const QString bad = m_dir.filePath("bad.json");
        QFile o(bad);
        if (!o.open(QIODevice::WriteOnly))
            return false;
        o.write(QJsonDocument(tampered).toJson());
        o.close();
        QByteArray o1, e1;
        const int code =
            awb::test::runProgram(awb::test::cliPath(), {"verify-regularity", bad}, &o1, &e1);
        if (code != 1 || !e1.contains("certificate rejected") || !e1.contains(reason))
            qWarning("exit %d: %s", code, e1.constData());
        return code == 1 && e1.contains(reason);
    };
    // A matrix entry changed: not the scheme's transition matrix.
    QJsonObject t = good;
    QJsonObject p = t["polytope"].toObject();
    QJsonArray ms = p["matrices"].toArray();
    QJsonArray m0 = ms[0].toArray();
    QJsonArray row = m0[0].toArray();
    row[0] = row[0].toDouble() + 1e-6;
    m0[0] = row;
    ms[0] = m0;
    p["matrices"] = ms;
    t["polytope"] = p;
    QVERIFY(rejected(t, "is not the scheme's"));
    // The mask changed (its matrices with it): the certificate's are no longer its own.
    t = good;
    QJsonObject scheme = t["scheme"].toObject();
    scheme["mask"] = QJsonArray{"1/16", 0, "-1/8", 0, "9/16", 1, "9/16", 0, "-1/8", 0, "1/16"};
    t["scheme"] = scheme;
    QVERIFY(rejected(t, "is not the scheme's"));
    // A vertex moved.
    t = good;
    p = t["polytope"].toObject();
    QJsonArray vs = p["vertices"].toArray();
    QJsonArray v0 = vs[0].toArray();
    v0[0] = v0[0].toDouble() * 1.5 + 0.1;
    vs[0] = v0;
    p["vertices"] = vs;
    t["polytope"] = p;
    QVERIFY(rejected(t, "vertex"));
    // A claim better than the proof.
    t = good;
    t["holder"] = QJsonObject{{"lower", 2.9}, {"upper", 2.95}};
    QVERIFY(rejected(t, "is not what the polytope proves"));
    // The scaling changed (T_1 for T_0 would be no tampering: the scheme is symmetric, both
    // are spectrum maximizing).
    t = good;
    p = t["polytope"].toObject();
    p["rhoHat"] = p["rhoHat"].toDouble() * 1.001;
    t["polytope"] = p;
    QVERIFY(rejected(t, "rho"));
    // An empty word.
    t = good;
    p = t["polytope"].toObject();
    p["smp"] = QJsonArray{};
    t["polytope"] = p;
    QVERIFY(rejected(t, "certificate rejected"));
    // Not a certificate at all.
    QVERIFY(rejected(QJsonObject{{"format", "something"}}, "not an attractor-workbench"));
}

AWB_TEST_GUILESS_MAIN(TestRegularityCli)
#include "test_regularity_cli.moc"
