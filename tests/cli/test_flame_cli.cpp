// attractor-cli and fractal flames (issue 34), judged by flam3 itself (Debian flam3-utils,
// installed by scripts/setup.sh): genomes that flam3-genome generated with linear variations
// only are imported, rendered by us and by flam3-render in the same frame, and the two
// pictures' density (block means of alpha) must agree -- and disagree once ours is mirrored,
// so that the comparison can fail; an item we export as a .flame renders in flam3-render to
// the attractor we draw. The coefficient order (coefs="a d b e c f"), post, the final xform,
// non-linear variations dropped with a warning, malformed flames with line and column, and the
// raw density out (.exr float counts, 16-bit PNG) are checked on small hand-made files.

#include "TestPaths.h"
#include <QFile>
#include <QImage>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QRegularExpression>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QtTest>

#include "TestFiles.h"
#include "BlockCompare.h"
#include "Flam3Judge.h"
#include "TestMain.h"
#include "TestTime.h"

#include "CliRunner.h"

#include "render/DensityFile.h"

#include <cmath>

using namespace awb;
using namespace awb::test;

namespace {

bool put(const QString &path, const QByteArray &text)
{
    QFile f(path);
    return f.open(QIODevice::WriteOnly) && f.write(text) == text.size();
}

QString dataPath(const QString &name)
{
    return awb::test::sourceDir()
           + "/tests/cli/data/" + name;
}

} // namespace

class TestFlameCli : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void coefficientOrderPostAndMirror();
    void finalXformConjugates();
    void nonLinearVariationsAreNamed();
    void symmetryAddsFlam3sXforms();
    void malformedFlames();
    void genomesRenderAsFlam3Renders_data();
    void genomesRenderAsFlam3Renders();
    void liveGenomeImports();
    void manyMapsAndNoAttractor();
    void bundledGenomes();
    void exportRendersInFlam3();
    void rawDensityOut();

private:
    int run(const QStringList &args, QByteArray *out = nullptr, QByteArray *err = nullptr)
    {
        return awb::test::runProgram(awb::test::cliPath(), args, out, err);
    }
    // The maps of the first item of a project as saved: per map {A (2x2), b}, row convention.
    QJsonArray affineMaps(const QString &project)
    {
        QFile f(project);
        if (!f.open(QIODevice::ReadOnly))
            return {};
        return QJsonDocument::fromJson(f.readAll())["items"][0]["maps"].toArray();
    }
    QTemporaryDir m_dir;
};

void TestFlameCli::initTestCase()
{
    QVERIFY(m_dir.isValid());
    QVERIFY2(!QStandardPaths::findExecutable("flam3-render").isEmpty(),
             "flam3-render (Debian flam3-utils) is missing: run scripts/setup.sh");
}

void TestFlameCli::coefficientOrderPostAndMirror()
{
    AWB_SKIP_WITHOUT_THREADS();
    // x' = a x + b y + c, y' = d x + e y + f is written coefs="a d b e c f"; post the same.
    const QString flame = m_dir.filePath("order.flame");
    QVERIFY(put(flame, R"(<flame name="order" size="100 100" center="0 0" scale="30">
  <xform weight="1" linear="1" coefs="0.5 0.1 0.2 0.4 0.3 -0.2"/>
  <xform weight="3" linear="0.5" coefs="1 0 0 1 0 0" post="0.6 0 0 0.6 0.1 0.2"/>
</flame>
)"));
    const QString project = m_dir.filePath("order.awb");
    QByteArray err;
    QCOMPARE(run({"import", flame, "--out", project}, nullptr, &err), 0);
    QVERIFY2(err.isEmpty(), err.constData());
    const QJsonArray maps = affineMaps(project);
    QCOMPARE(maps.size(), 2);
    // Ours is the flame's map seen with y up: R f R, R = diag(1, -1), in the row convention
    // x |-> x A + b: A = [[a, d], [b, e]] with the off-diagonal signs flipped, b = (c, -f).
    auto A = [&](int i, int r, int c) { return maps[i]["A"][r][c].toDouble(); };
    auto b = [&](int i, int k) { return maps[i]["b"][k].toDouble(); };
    QCOMPARE(A(0, 0, 0), 0.5);
    QCOMPARE(A(0, 0, 1), -0.1);  // d
    QCOMPARE(A(0, 1, 0), -0.2);  // b
    QCOMPARE(A(0, 1, 1), 0.4);
    QCOMPARE(b(0, 0), 0.3);
    QCOMPARE(b(0, 1), 0.2);
    // post(0.5 pre(p)): 0.3 p + (0.1, 0.2), mirrored.
    QVERIFY(std::abs(A(1, 0, 0) - 0.3) < 1e-12 && std::abs(A(1, 1, 1) - 0.3) < 1e-12);
    QVERIFY(std::abs(b(1, 0) - 0.1) < 1e-12 && std::abs(b(1, 1) + 0.2) < 1e-12);
    // The weights are the random iteration's probabilities.
    QFile f(project);
    QVERIFY(f.open(QIODevice::ReadOnly));
    const QJsonObject item = QJsonDocument::fromJson(f.readAll())["items"][0].toObject();
    QCOMPARE(item["algorithm"]["probabilities"][1].toDouble(), 3.0);
    QCOMPARE(item["algorithm"]["mode"].toString(), QString("random"));

    // And back: export writes the same coefficients in flam3's order.
    const QString out = m_dir.filePath("order-out.flame");
    QCOMPARE(run({"export", project, "--item", "order", "--format", "flame", "--out", out}), 0);
    QFile g(out);
    QVERIFY(g.open(QIODevice::ReadOnly));
    const QString text = QString::fromUtf8(g.readAll());
    QVERIFY2(text.contains("coefs=\"0.5 0.1 0.2 0.4 0.3 -0.2\""), qPrintable(text.left(800)));
    QVERIFY(text.contains("weight=\"3\""));
}

void TestFlameCli::finalXformConjugates()
{
    AWB_SKIP_WITHOUT_THREADS();
    // A final xform F (here x |-> 2x + (1, 0)) is drawn on every point: the picture is F(A),
    // the attractor of F f F^-1. For f = x/2 (fixed point 0) that is x/2 + (0.5, 0), whose
    // fixed point is F(0) = (1, 0); the second, x/2 + (0.5, 0), becomes x/2 + (1.5, 0).
    const QString flame = m_dir.filePath("final.flame");
    QVERIFY(put(flame, R"(<flames><flame name="final">
  <xform weight="1" linear="1" coefs="0.5 0 0 0.5 0 0"/>
  <xform weight="1" linear="1" coefs="0.5 0 0 0.5 0.5 0"/>
  <finalxform linear="1" coefs="2 0 0 2 1 0"/>
</flame></flames>
)"));
    const QString project = m_dir.filePath("final.awb");
    QCOMPARE(run({"import", flame, "--out", project}), 0);
    const QJsonArray maps = affineMaps(project);
    QCOMPARE(maps.size(), 2);
    QVERIFY(std::abs(maps[0]["A"][0][0].toDouble() - 0.5) < 1e-12);
    QVERIFY(std::abs(maps[0]["b"][0].toDouble() - 0.5) < 1e-12);
    QVERIFY(std::abs(maps[1]["b"][0].toDouble() - 1.5) < 1e-12);
}

void TestFlameCli::nonLinearVariationsAreNamed()
{
    AWB_SKIP_WITHOUT_THREADS();
    const QString flame = m_dir.filePath("vars.flame");
    QVERIFY(put(flame, R"(<flame name="vars">
  <xform weight="1" linear="1" coefs="0.5 0 0 0.5 0 0"/>
  <xform weight="1" linear="0.8" spherical="0.5" blob_low="0.3" coefs="0.5 0 0 0.5 0.5 0"/>
  <xform weight="1" swirl="1" coefs="0.5 0 0 0.5 0 0.5"/>
  <xform weight="1" linear="1" frobnicate="2" coefs="0.5 0 0 0.5 0.5 0.5"/>
  <xform linear="1" coefs="0.1 0 0 0.1 0 0"/>
</flame>
)"));
    const QString project = m_dir.filePath("vars.awb");
    QByteArray err;
    QCOMPARE(run({"import", flame, "--out", project}, nullptr, &err), 0);
    // Non-linear variations: a flame item that keeps them all (issue 45); only what flam3
    // does not draw is named.
    const QString text = QString::fromUtf8(err);
    QVERIFY2(!text.contains("dropped"), qPrintable(text));
    QVERIFY2(text.contains(QRegularExpression("vars.flame, line 5, column \\d+: flame 'vars': "
                                              "xform 4: attributes flam3 does not draw, "
                                              "ignored: frobnicate")),
             qPrintable(text));
    // No weight: flam3's 0 (initialize_xforms), and the user is told.
    QVERIFY2(text.contains("xform 5: no weight given; taken as 0"), qPrintable(text));
    QVERIFY2(!text.contains("blob_low"), qPrintable(text));  // the parameter of a variation
    QFile f(project);
    QVERIFY(f.open(QIODevice::ReadOnly));
    const QJsonObject item = QJsonDocument::fromJson(f.readAll())["items"][0].toObject();
    QCOMPARE(item["type"].toString(), QString("flame"));
    const QJsonArray xforms = item["xforms"].toArray();
    QCOMPARE(xforms.size(), 5);
    QCOMPARE(xforms[1]["variations"]["linear"].toDouble(), 0.8);
    QCOMPARE(xforms[1]["variations"]["spherical"].toDouble(), 0.5);
    QCOMPARE(xforms[2]["variations"]["swirl"].toDouble(), 1.0);
    QVERIFY(!xforms[2]["variations"].toObject().contains("linear"));
    QCOMPARE(xforms[4]["weight"].toDouble(), 0.0);
}

void TestFlameCli::symmetryAddsFlam3sXforms()
{
    AWB_SKIP_WITHOUT_THREADS();
    // kind = -3: the reflection x |-> -x (y up: the same), then the rotations by 120 and 240
    // degrees with cosines and sines rounded to 6 decimals, as flam3_add_symmetry.
    const QString flame = m_dir.filePath("sym.flame");
    QVERIFY(put(flame, R"(<flame name="sym"><symmetry kind="-3"/>
  <xform weight="1" linear="1" coefs="0.5 0 0 0.5 0.3 0"/>
</flame>
)"));
    const QString project = m_dir.filePath("sym.awb");
    QByteArray err;
    QCOMPARE(run({"import", flame, "--out", project}, nullptr, &err), 0);
    QVERIFY2(err.isEmpty(), err.constData());
    const QJsonArray maps = affineMaps(project);
    QCOMPARE(maps.size(), 4);
    QCOMPARE(maps[0]["A"][0][0].toDouble(), -1.0);
    QCOMPARE(maps[0]["A"][1][1].toDouble(), 1.0);
    QCOMPARE(maps[1]["A"][0][0].toDouble(), -0.5);
    QCOMPARE(maps[1]["A"][0][1].toDouble(), -0.866025);  // sin 120 deg, mirrored
    QCOMPARE(maps[2]["A"][0][1].toDouble(), 0.866025);
    QCOMPARE(maps[3]["b"][0].toDouble(), 0.3);
}

void TestFlameCli::malformedFlames()
{
    AWB_SKIP_WITHOUT_THREADS();
    const QString flame = m_dir.filePath("bad.flame");
    QVERIFY(put(flame, R"(<flames>
<flame name="good"><xform weight="1" linear="1" coefs="0.5 0 0 0.5 0 0"/>
  <xform weight="1" linear="1" coefs="0.5 0 0 0.5 1 0"/></flame>
<flame name="short">
  <xform weight="1" linear="1" coefs="0.5 0 0 0.5 0"/>
</flame>
<flame name="negative"><xform weight="-1" coefs="0.5 0 0 0.5 0 0"/></flame>
<flame name="empty"></flame>
</flames>
)"));
    const QString project = m_dir.filePath("bad.awb");
    QByteArray out, err;
    QCOMPARE(run({"import", flame, "--out", project}, &out, &err), 1);
    const QString text = QString::fromUtf8(err);
    QVERIFY2(text.contains(QRegularExpression("bad.flame, line 5, column \\d+: flame 'short': "
                                              "xform 1: coefs=\"0.5 0 0 0.5 0\" must be 6 "
                                              "finite numbers")),
             qPrintable(text));
    QVERIFY2(text.contains(QRegularExpression("line 7, column \\d+: flame 'negative': xform 1: "
                                              "weight=\"-1\" is negative")),
             qPrintable(text));
    QVERIFY2(text.contains(QRegularExpression("line 8, column \\d+: flame 'empty': the flame has "
                                              "no xform")),
             qPrintable(text));
    QVERIFY(out.contains("1 item(s): good"));

    // XML that does not parse: the line and column of the fault.
    const QString broken = m_dir.filePath("broken.flame");
    QVERIFY(put(broken, "<flames>\n<flame name=\"x\">\n<xform coefs=\"1 0 0 1 0 0\">\n</flame>\n"));
    QCOMPARE(run({"import", broken, "--out", project}, nullptr, &err), 1);
    QVERIFY2(QString::fromUtf8(err).contains(
                 QRegularExpression("broken.flame, line 4, column \\d+: the XML is malformed")),
             err.constData());

    // Counts range-checked before anything is allocated: a symmetry kind of INT_MIN (a
    // 234-byte file once took 1.5 GB), and more xforms than the engine iterates.
    const QString bomb = m_dir.filePath("bomb.flame");
    QByteArray many = "<flames><flame name=\"sym\"><symmetry kind=\"-2147483648\"/>"
                      "<xform weight=\"1\" coefs=\"0.5 0 0 0.5 0 0\"/></flame>\n"
                      "<flame name=\"many\">";
    for (int k = 0; k < 300; ++k)
        many += "<xform weight=\"1\" coefs=\"0.5 0 0 0.5 0 0\"/>\n";
    QVERIFY(put(bomb, many + "</flame></flames>\n"));
    QCOMPARE(run({"import", bomb, "--out", project}, nullptr, &err), 1);
    const QString bombText = QString::fromUtf8(err);
    QVERIFY2(bombText.contains("flame 'sym': <symmetry> needs kind=\"k\", a whole number from "
                               "-256 to 256"),
             err.constData());
    QVERIFY2(bombText.contains("flame 'many': more than 256 xforms"), err.constData());
}

void TestFlameCli::genomesRenderAsFlam3Renders_data()
{
    QTest::addColumn<QString>("genome");
    QTest::newRow("contractive") << "flam3-genome-contractive.flame";
    QTest::newRow("contractive on average") << "flam3-genome-contractive-on-average.flame";
    // <symmetry kind="-4">: a reflection and three rotations, which flam3's parser adds to
    // those the file lists.
    QTest::newRow("symmetry") << "flam3-genome-symmetry.flame";
}

void TestFlameCli::genomesRenderAsFlam3Renders()
{
    QFETCH(QString, genome);
    QFile in(dataPath(genome));
    QVERIFY(in.open(QIODevice::ReadOnly));
    // Larger and denser than flam3-genome's thumbnail: 400 x 400 at the same frame.
    QByteArray flame = withQuality(in.readAll(), 100);
    flame.replace("size=\"100 100\"", "size=\"400 400\"");
    const QRegularExpression scaleRe("scale=\"([^\"]+)\"");
    const double scale = scaleRe.match(QString::fromUtf8(flame)).captured(1).toDouble();
    flame.replace(scaleRe.match(QString::fromUtf8(flame)).captured(0).toUtf8(),
                  QStringLiteral("scale=\"%1\"").arg(4 * scale, 0, 'g', 17).toUtf8());
    const QString file = m_dir.filePath(genome);
    QVERIFY(put(file, flame));
    QString why;
    const QString theirs = m_dir.filePath(genome + ".flam3.png");
    QVERIFY2(flam3Render(file, theirs, &why), qPrintable(why));

    const QString project = m_dir.filePath(genome + ".awb");
    QByteArray err;
    QCOMPARE(run({"import", file, "--out", project}, nullptr, &err), 0);
    QVERIFY2(err.isEmpty(), err.constData());  // linear variations only: nothing is lost
    int w = 0, h = 0;
    const QString bounds = boundsOfFlame(flame, &w, &h);
    const QString ours = m_dir.filePath(genome + ".ours.png");
    QCOMPARE(run({"render", project, "--size", QStringLiteral("%1x%2").arg(w).arg(h), "--bounds",
                  bounds, "--samples", "8000000", "--bits", "16", "--out", ours}),
             0);
    const QImage a(theirs), b(ours);
    QCOMPARE(a.size(), QSize(400, 400));
    QCOMPARE(b.size(), QSize(400, 400));
    const auto A = blockAlpha(a, 10), B = blockAlpha(b, 10), Bm = blockAlpha(b, 10, true);
    const double same = awb::test::correlation(A, B), mirrored = awb::test::correlation(A, Bm);
    qInfo("%s: correlation of 10 x 10 block alpha %.3f (mirrored %.3f); flam3's lit blocks "
          "lit in ours %.3f",
          qPrintable(genome), same, mirrored, awb::test::litCovered(A, B, 0.05, 0.05));
    QVERIFY2(same > 0.8, qPrintable(QString::number(same)));
    QVERIFY2(same > mirrored + 0.2, qPrintable(QString::number(mirrored)));
    // flam3's density estimator (estimator_radius 9 in these genomes) spreads a sparse tail's
    // single hits over up to 9 pixels, so its lit blocks reach a little beyond ours.
    QVERIFY(awb::test::litCovered(A, B, 0.05, 0.05) > 0.8);
}

void TestFlameCli::liveGenomeImports()
{
    // Whatever flam3-genome makes today with linear variations only (a new genome each run:
    // flam3-genome seeds from the clock) imports and analyses; nothing is lost but, when its
    // maps do not contract even on average, the import says so, and the analysis agrees.
    QProcess p;
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert("use_vars", "0");
    p.setProcessEnvironment(env);
    p.start("flam3-genome", {});
    QVERIFY(p.waitForFinished(awb::test::ms(60000)));
    const QByteArray genome = p.readAllStandardOutput();
    const QString file = m_dir.filePath("live.flame");
    QVERIFY(put(file, genome));
    const QString project = m_dir.filePath("live.awb");
    QByteArray err, out;
    QCOMPARE(run({"import", file, "--out", project}, nullptr, &err), 0);
    QCOMPARE(run({"analyse", project, "--json"}, &out, &err), 0);
    const auto why = [&] { return qPrintable(QString::fromUtf8(err + "\n" + genome)); };
    const QJsonObject item = QJsonDocument::fromJson(out)["items"][0].toObject();
    QVERIFY2(item.contains("box_dimension"), why());
    const bool noAttractor = item.contains("contractive_on_average")
                             && !item["contractive_on_average"].toBool();
    if (item.contains("contractive_on_average"))
        QVERIFY2(item["contractive_on_average"].toBool()
                     == (item["lyapunov_exponent"].toDouble() < 0),
                 why());
    QByteArray importErr;
    QCOMPARE(run({"import", file, "--out", project}, nullptr, &importErr), 0);
    QVERIFY2(importErr.isEmpty() != noAttractor, importErr.constData());
}

void TestFlameCli::manyMapsAndNoAttractor()
{
    AWB_SKIP_WITHOUT_THREADS();
    // Ten xforms and symmetry kind -5 (a reflection and four rotations): 15 maps, whose
    // depth-8 deterministic iteration would make 2.6e9 images. The import picks the deepest
    // depth under 2^31 (7), so the project it writes is one the next command loads (a live
    // flam3-genome once made such a project that analyse refused).
    QByteArray ten = "<flame name=\"many\"><symmetry kind=\"-5\"/>\n";
    for (int i = 0; i < 10; ++i)
        ten += QStringLiteral("<xform weight=\"1\" linear=\"1\" "
                               "coefs=\"0.3 0.1 -0.1 0.3 %1 0\"/>\n")
                    .arg(0.1 * i)
                    .toUtf8();
    ten += "</flame>\n";
    const QString flame = m_dir.filePath("many.flame");
    QVERIFY(put(flame, ten));
    const QString project = m_dir.filePath("many.awb");
    QByteArray err, out;
    QCOMPARE(run({"import", flame, "--out", project}, nullptr, &err), 0);
    QVERIFY2(err.isEmpty(), err.constData());
    QCOMPARE(affineMaps(project).size(), 15);
    QFile f(project);
    QVERIFY(f.open(QIODevice::ReadOnly));
    QCOMPARE(QJsonDocument::fromJson(f.readAll())["items"][0]["algorithm"]["depth"].toInt(), 7);
    QCOMPARE(run({"analyse", project, "--json"}, &out, &err), 0);

    // A genome flam3-genome made whose maps grow on average (top Lyapunov exponent about
    // +0.22): imported, with the warning that it has no attractor; the analysis agrees, and
    // the render refuses with the map that does not contract.
    const QString none = m_dir.filePath("none.awb");
    QCOMPARE(run({"import", dataPath("flam3-genome-no-attractor.flame"), "--out", none},
                 nullptr, &err),
             0);
    QVERIFY2(err.contains("do not contract, not even on average (the Lyapunov exponent of "
                          "their products, 0.2"),
             err.constData());
    QCOMPARE(run({"analyse", none, "--json"}, &out), 0);
    const QJsonObject item = QJsonDocument::fromJson(out)["items"][0].toObject();
    QCOMPARE(item["contractive_on_average"].toBool(true), false);
    QVERIFY(item["lyapunov_exponent"].toDouble() > 0.1);
    QCOMPARE(run({"render", none, "--out", m_dir.filePath("none.png")}, nullptr, &err), 1);
    QVERIFY2(err.contains("is not contractive"), err.constData());
}

void TestFlameCli::bundledGenomes()
{
    AWB_SKIP_WITHOUT_THREADS();
    // examples/flam3-linear-genomes.flame: the three genomes above in one file, each an item,
    // nothing lost; the analysis tells the two kinds of contraction apart.
    const QString project = m_dir.filePath("genomes.awb");
    QByteArray out, err;
    QCOMPARE(run({"import", awb::test::examplePath("flam3-linear-genomes.flame"), "--out",
                  project},
                 &out, &err),
             0);
    QVERIFY2(err.isEmpty(), err.constData());
    QVERIFY2(out.contains("3 item(s): contractive, contractive on average, flam3 symmetry kind -4"),
             out.constData());
    QCOMPARE(run({"analyse", project, "--json"}, &out), 0);
    const QJsonArray items = QJsonDocument::fromJson(out)["items"].toArray();
    QCOMPARE(items.size(), 3);
    QVERIFY(!items[0].toObject().contains("contractive_on_average"));  // every map contracts
    for (int i : {1, 2}) {
        QVERIFY(items[i]["contractive_on_average"].toBool());
        QVERIFY(items[i]["lyapunov_exponent"].toDouble() < -0.01);
    }
    // flam3's symmetry kind -4 adds a reflection and three rotations to the 6 listed xforms
    // (which hold them already): 2 + 4 + 4 maps.
    QFile f(project);
    QVERIFY(f.open(QIODevice::ReadOnly));
    QCOMPARE(QJsonDocument::fromJson(f.readAll())["items"][2]["maps"].toArray().size(), 10);
}

void TestFlameCli::exportRendersInFlam3()
{
    // Barnsley's fern of the bundled Fractint library, out as a flame: flam3-render draws the
    // attractor we draw, in the frame of render's --size.
    const QString project = m_dir.filePath("classics.awb");
    QByteArray err;
    run({"import", awb::test::examplePath("fractint-classics.ifs"), "--out", project}, nullptr,
        &err);
    const QString flame = m_dir.filePath("fern.flame");
    QCOMPARE(run({"export", project, "--item", "fern", "--format", "flame", "--size", "300x400",
                  "--out", flame},
                 nullptr, &err),
             0);
    QString why;
    const QString theirs = m_dir.filePath("fern.flam3.png");
    QVERIFY2(flam3Render(flame, theirs, &why), qPrintable(why));
    const QString ours = m_dir.filePath("fern.ours.png");
    QCOMPARE(run({"render", project, "--item", "fern", "--size", "300x400", "--samples",
                  "4000000", "--bits", "16", "--out", ours}),
             0);
    const QImage a(theirs), b(ours);
    QCOMPARE(a.size(), QSize(300, 400));
    QCOMPARE(b.size(), QSize(300, 400));
    const auto A = blockAlpha(a, 10), B = blockAlpha(b, 10), Bm = blockAlpha(b, 10, true);
    const double same = awb::test::correlation(A, B), mirrored = awb::test::correlation(A, Bm);
    qInfo("fern: correlation %.3f (mirrored %.3f), lit covered %.3f / %.3f", same, mirrored,
          awb::test::litCovered(A, B, 0.05, 0.05), awb::test::litCovered(B, A, 0.05, 0.05));
    QVERIFY2(same > 0.8, qPrintable(QString::number(same)));
    QVERIFY(same > mirrored + 0.2);
    QVERIFY(awb::test::litCovered(A, B, 0.05, 0.05) > 0.9);
    QVERIFY(awb::test::litCovered(B, A, 0.05, 0.05) > 0.9);
    // In the same colours: each map's points in its colour (issue 47: with flam3's usual
    // color_speed 0.5 one frond came out in a mix of two maps' colours).
    const double hue = chromaDistance(blockChroma(a, 10), blockChroma(b, 10));
    qInfo("fern: mean chromaticity distance %.3f", hue);
    QVERIFY2(hue < 0.15, qPrintable(QString::number(hue)));
}

void TestFlameCli::rawDensityOut()
{
    // The Sierpinski triangle ("triangle") by random iteration: every sample lands in the frame, so the
    // EXR's counts add up to the samples; the 16-bit PNG gives the same counts back through
    // its max-count chunk.
    const QString project = m_dir.filePath("classics.awb");
    QCOMPARE(run({"import", awb::test::examplePath("fractint-classics.ifs"), "--out", project},
                 nullptr, nullptr) <= 1,
             true);
    const QString exr = m_dir.filePath("triangle.exr");
    QCOMPARE(run({"render", project, "--item", "triangle", "--size", "256x256", "--samples",
                  "1000000", "--out", exr}),
             0);
    QRectF world;
    QString error;
    const AttractorDensity d = readDensityExr(exr, &world, &error);
    QVERIFY2(error.isEmpty(), qPrintable(error));
    QCOMPARE(d.frame.width, 256);
    QCOMPARE(d.frame.height, 256);
    QVERIFY(world.width() > 0);
    double total = 0, most = 0, colourError = 0;
    for (std::size_t i = 3; i < d.rgba.size(); i += 4) {
        total += d.rgba[i];
        most = std::max(most, double(d.rgba[i]));
        // R, G, B are hits times a colour in 0..1.
        for (int k = 1; k <= 3; ++k)
            colourError = std::max(colourError, double(d.rgba[i - k]) - d.rgba[i]);
    }
    QVERIFY2(std::abs(total - 1e6) <= 64, qPrintable(QString::number(total, 'f', 0)));
    QVERIFY(colourError <= 1e-3);

    const QString png = m_dir.filePath("triangle16.png");
    QCOMPARE(run({"render", project, "--item", "triangle", "--size", "256x256", "--samples",
                  "1000000", "--bits", "16", "--out", png}),
             0);
    const QImage image(png);
    QCOMPARE(image.depth(), 64);
    const double maxCount = image.text(kDensityMaxCountKey).toDouble();
    QCOMPARE(maxCount, most);
    // Pixel by pixel, n = (1 + n_max)^alpha - 1 to 1/65535 of the log density.
    const QImage rgba = image.convertToFormat(QImage::Format_RGBA64);
    double worst = 0;
    for (int y = 0; y < 256; ++y) {
        const auto *row = reinterpret_cast<const QRgba64 *>(rgba.constScanLine(y));
        for (int x = 0; x < 256; ++x) {
            const double n = d.rgba[4 * (std::size_t(y) * 256 + x) + 3];
            const double back = std::pow(1 + maxCount, row[x].alpha() / 65535.0) - 1;
            worst = std::max(worst, std::abs(back - n) / (1 + n));
        }
    }
    QVERIFY2(worst < 2e-4, qPrintable(QString::number(worst)));
    QVERIFY(!image.text("attractor-workbench:project").isEmpty());

    // --bits takes 8 or 16; an attractor of space has no plane density.
    QByteArray err;
    QCOMPARE(run({"render", project, "--item", "triangle", "--bits", "12", "--out", png},
                 nullptr, &err),
             2);
    QVERIFY2(err.contains("--bits must be 8 or 16"), err.constData());
    QCOMPARE(run({"render", project, "--item", "tetrahedron", "--out", exr}, nullptr, &err), 1);
    QVERIFY2(err.contains("drawn in space"), err.constData());
}

AWB_TEST_MAIN(TestFlameCli)
#include "test_flame_cli.moc"
