// The examples gallery (examples/*.awb): every example loads, validates, analyses, renders to a
// real image and round-trips byte-identically; papers' numbers come out of `analyse`.

#include "TestPaths.h"
#include <QDir>
#include <QImage>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>
#include <QtTest>

#include "TestMain.h"

#include "TestTime.h"

#include <set>

class TestExamples : public QObject {
    Q_OBJECT
private slots:
    void everyExample_data();
    void everyExample();
    void thesisExample362FixedPoints();
    void junctionSubdominant();
    void cliErrors();

private:
    QString cli() const
    {
        return qEnvironmentVariable("AWB_BIN_DIR", QCoreApplication::applicationDirPath() + "/../bin")
               + "/attractor-cli";
    }
    QString examples() const
    {
        return awb::test::sourceDir() + "/examples";
    }
    int run(const QStringList &args, QByteArray *out = nullptr, QByteArray *err = nullptr)
    {
        QProcess p;
        p.start(cli(), args);
        if (!p.waitForFinished(awb::test::ms(300000)))
            return -1;
        if (out)
            *out = p.readAllStandardOutput();
        if (err)
            *err = p.readAllStandardError();
        return p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -1;
    }
};

void TestExamples::everyExample_data()
{
    QTest::addColumn<QString>("file");
    const QStringList files = QDir(examples()).entryList({"*.awb"}, QDir::Files, QDir::Name);
    QVERIFY(files.size() >= 27);
    // The instrumented builds (scripts/sanitize.sh sets AWB_TEST_TIME_SCALE) take fewer (each
    // example starts four instrumented processes): AddressSanitizer every second one (76 s for
    // all), ThreadSanitizer, which looks for races in the workers an item starts, the first
    // example of each kind of item not seen before (every kind once; 84 s for every second
    // one). The normal suite takes them all.
    if (awb::test::kThreadSanitizer) {
        std::set<QString> kinds;
        for (const QString &name : files) {
            QFile f(QDir(examples()).filePath(name));
            QVERIFY(f.open(QIODevice::ReadOnly));
            bool added = false;
            for (const QJsonValue &item : QJsonDocument::fromJson(f.readAll())["items"].toArray())
                added |= kinds.insert(item["type"].toString()).second;
            if (added)
                QTest::newRow(qPrintable(name)) << QDir(examples()).filePath(name);
        }
        QVERIFY(kinds.size() >= 10);
        return;
    }
    const int step = qEnvironmentVariableIntValue("AWB_TEST_TIME_SCALE") > 1 ? 2 : 1;
    for (int k = 0; k < int(files.size()); k += step)
        QTest::newRow(qPrintable(files[k])) << QDir(examples()).filePath(files[k]);
}

void TestExamples::everyExample()
{
    QFETCH(QString, file);
    QByteArray out, err;
    QCOMPARE(run({"check", file}, &out, &err), 0);
    QVERIFY2(out.contains("OK"), err.constData());

    // Analyse: every attractor item has maps with eigenvalues, and every map contracts.
    QCOMPARE(run({"analyse", file, "--json"}, &out, &err), 0);
    const QJsonObject root = QJsonDocument::fromJson(out).object();
    // Printed piece by piece (CommandSupport.h printJson), byte for byte Qt's indented text.
    QCOMPARE(out, QJsonDocument(root).toJson(QJsonDocument::Indented));
    const QJsonArray items = root["items"].toArray();
    QVERIFY(!items.isEmpty());
    for (const QJsonValue &v : items) {
        const QJsonObject item = v.toObject();
        QVERIFY2(!item.contains("error"), qPrintable(item["error"].toString()));
        const QJsonArray maps = item["maps"].toArray();
        // Normal-vector curves are not linear in their control points: no matrices S_i.
        // A BCIFS junction lists its junction matrix T^i (one, or T^il and T^ir).
        const QString type = item["type"].toString();
        if (type != "normal-vector")
            QVERIFY2(maps.size() >= (type == "bcifs-junction" ? 1 : 2),
                     qPrintable(item["name"].toString()));
        for (const QJsonValue &m : maps) {
            QVERIFY(!m.toObject()["eigenvalues"].toArray().isEmpty());
            if (m.toObject().contains("contractive"))
                QVERIFY2(m.toObject()["contractive"].toBool(), qPrintable(item["name"].toString()));
        }
    }

    // Render: a real picture.
    QTemporaryDir dir;
    const QString png = dir.filePath("out.png");
    QCOMPARE(run({"render", file, "--out", png, "--size", "400x300"}, &out, &err), 0);
    const QImage img(png);
    QVERIFY(!img.isNull());
    int coloured = 0;
    for (int y = 0; y < img.height(); ++y)
        for (int x = 0; x < img.width(); ++x) {
            const QColor c = img.pixelColor(x, y);
            if (std::max({c.red(), c.green(), c.blue()}) - std::min({c.red(), c.green(), c.blue()}) > 60)
                ++coloured;
        }
    QVERIFY2(coloured > 300, qPrintable(QString("%1 coloured pixels").arg(coloured)));

    // Save -> load -> save is byte-identical (the examples are stored in canonical form).
    const QString copy = dir.filePath("copy.awb");
    QCOMPARE(run({"rewrite", file, "--out", copy}), 0);
    QFile a(file), b(copy);
    QVERIFY(a.open(QIODevice::ReadOnly) && b.open(QIODevice::ReadOnly));
    QCOMPARE(b.readAll(), a.readAll());
}

void TestExamples::thesisExample362FixedPoints()
{
    // 004 Example 3.6.2: the fixed points of f_1, f_2 are (1/2, 2) and (6, -1/2).
    QByteArray out;
    QCOMPARE(run({"analyse", examples() + "/004-fig3.2-quadratic-bspline-ifs.awb", "--json"}, &out), 0);
    const QJsonArray maps =
        QJsonDocument::fromJson(out).object()["items"].toArray()[0].toObject()["maps"].toArray();
    QCOMPARE(maps.size(), 2);
    const QJsonArray f1 = maps[0].toObject()["fixed_point"].toArray();
    const QJsonArray f2 = maps[1].toObject()["fixed_point"].toArray();
    QVERIFY(std::abs(f1[0].toDouble() - 0.5) < 1e-12 && std::abs(f1[1].toDouble() - 2) < 1e-12);
    QVERIFY(std::abs(f2[0].toDouble() - 6) < 1e-12 && std::abs(f2[1].toDouble() + 0.5) < 1e-12);
}

void TestExamples::junctionSubdominant()
{
    // 003 §4.1, Fig. 16 (top): the subdominant eigenvalue of T^i is 0.696 (3 decimals).
    QByteArray out;
    QCOMPARE(run({"analyse", examples() + "/003-fig16-junction-g1.awb", "--json"}, &out), 0);
    const QJsonObject item =
        QJsonDocument::fromJson(out).object()["items"].toArray()[0].toObject();
    const QJsonArray sub = item["subdominant"].toArray();
    QCOMPARE(sub.size(), 1);
    QVERIFY(std::abs(sub[0].toArray()[0].toDouble() - 0.696) < 5e-4);
    QCOMPARE(sub[0].toArray()[1].toDouble(), 0.0);
}

void TestExamples::cliErrors()
{
    QTemporaryDir dir;
    QByteArray out, err;
    // A corrupt file: exit 1 with the loader's message naming the file.
    const QString bad = dir.filePath("bad.awb");
    QFile f(bad);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write("{\"format\": \"attractor-workbench\", \"version\": 1, \"items\": [{\"type\": "
            "\"subdivision-curve\", \"name\": \"c\", \"scheme\": {\"kind\": \"bspline\", "
            "\"degree\": \"three\"}, \"control_points\": [[0,0],[1,1],[2,0],[3,1]]}]}");
    f.close();
    QCOMPARE(run({"check", bad}, &out, &err), 1);
    QVERIFY2(err.contains("bad.awb") && err.contains("degree"), err.constData());
    QCOMPARE(run({"render", bad, "--out", dir.filePath("x.png")}, &out, &err), 1);
    // A file that loads but cannot be computed (three points for a cubic): check exits 3.
    QVERIFY(f.open(QIODevice::WriteOnly | QIODevice::Truncate));
    f.write("{\"format\": \"attractor-workbench\", \"version\": 1, \"items\": [{\"type\": "
            "\"subdivision-curve\", \"name\": \"c\", \"scheme\": {\"kind\": \"bspline\", "
            "\"degree\": 3}, \"control_points\": [[0,0],[1,1],[2,0]]}]}");
    f.close();
    QCOMPARE(run({"check", bad}, &out, &err), 3);
    QVERIFY2(err.contains("at least 4 control points"), err.constData());
    const QString good = examples() + "/000-fig02-cubic-bspline-from-point.awb";
    QCOMPARE(run({"render", good}, &out, &err), 2);         // --out missing
    QVERIFY(err.contains("--out"));
    QCOMPARE(run({"render", good, "--out", dir.filePath("x.bmpx")}, &out, &err), 1);
    QVERIFY(err.contains("unknown output format"));
    QCOMPARE(run({"render", good, "--item", "nope", "--out", dir.filePath("x.png")}, &out, &err), 1);
    QVERIFY(err.contains("no item named 'nope'"));
    QCOMPARE(run({"points", good, "--item", "000 Fig. 2: cubic B-spline from a point", "--depth",
                  "40", "--csv"}, &out, &err), 1);
    QVERIFY(err.contains("--max-points"));
    QCOMPARE(run({"points", good, "--item", "000 Fig. 2: cubic B-spline from a point", "--depth",
                  "3", "--start", "segment:0,0,1,1", "--csv"}, &out, &err), 0);
    QCOMPARE(out.count('\n'), 1 + 8 * 2);   // header + 2^3 images of 2 vertices
    QCOMPARE(run({"render", good, "--out", dir.filePath("x.svg")}, &out, &err), 0);
    QFile svg(dir.filePath("x.svg"));
    QVERIFY(svg.open(QIODevice::ReadOnly));
    // The control polygon is vector (a polyline element), the deep attractor an image.
    const QByteArray svgText = svg.readAll();
    QVERIFY(svgText.contains("<polyline") || svgText.contains("<path"));
    QCOMPARE(run({"render", good, "--out", dir.filePath("x.pdf")}, &out, &err), 0);
    QVERIFY(QFileInfo(dir.filePath("x.pdf")).size() > 1000);
}

AWB_TEST_GUILESS_MAIN(TestExamples)
#include "test_examples.moc"
