// attractor-cli on the surface examples (000 §3, Figs. 6-9): analyse --json reports the scheme,
// the maps and their spectra; points prints x,y,z; export writes PLY and OBJ files that real
// parsers (meshio, assimp) read back; render draws the shaded surface headless.

#include <QDir>
#include <QImage>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QtTest>

#include "TestMain.h"
#include "TestTime.h"

#include "CliRunner.h"

#include <cmath>

class TestSurfacesCli : public QObject {
    Q_OBJECT
private slots:
    void analyseReportsTheScheme_data();
    void analyseReportsTheScheme();
    void pointsAreThreeDimensional();
    void plyIsReadByMeshio();
    void objIsReadByMeshioAndAssimp();
    void matlabCellArrayOfTheBicubicPatch();
    void renderDrawsTheSurface_data();
    void renderDrawsTheSurface();
    void badOptions();
    void renderReportsProgress();

private:
    QString example(const QString &name) const { return awb::test::examplePath(name); }
    int run(const QString &program, const QStringList &args, QByteArray *out = nullptr,
            QByteArray *err = nullptr)
    {
        return awb::test::runProgram(program, args, out, err);
    }
    int run(const QStringList &args, QByteArray *out = nullptr, QByteArray *err = nullptr)
    {
        return awb::test::runProgram(awb::test::cliPath(), args, out, err);
    }
    // The interpreter of Debian's python3-meshio (another python3 may come first on PATH).
    QString debianPython() const
    {
        return QFile::exists("/usr/bin/python3") ? QString("/usr/bin/python3")
                                                 : QStandardPaths::findExecutable("python3");
    }
    QTemporaryDir m_dir;
};

void TestSurfacesCli::analyseReportsTheScheme_data()
{
    QTest::addColumn<QString>("file");
    QTest::addColumn<QString>("scheme");
    QTest::addColumn<int>("maps");
    QTest::addColumn<int>("used");
    QTest::addColumn<int>("points");
    QTest::addColumn<double>("sub");
    QTest::newRow("fig 6") << "000-fig06-bicubic-patch.awb" << "bicubic" << 4 << 4 << 16 << 0.5;
    QTest::newRow("fig 7") << "000-fig07-box-spline-hexagon.awb" << "loop" << 6 << 6 << 19 << 0.5;
    QTest::newRow("fig 8") << "000-fig08-sqrt3-surface.awb" << "sqrt3" << 18 << 18 << 37
                           << 1.0 / 3.0;
    QTest::newRow("fig 9") << "000-fig09-box-spline-subset.awb" << "loop" << 6 << 4 << 19 << 0.5;
}

void TestSurfacesCli::analyseReportsTheScheme()
{
    AWB_SKIP_WITHOUT_THREADS();
    QFETCH(QString, file);
    QFETCH(QString, scheme);
    QFETCH(int, maps);
    QFETCH(int, used);
    QFETCH(int, points);
    QFETCH(double, sub);
    QByteArray out, err;
    QCOMPARE(run({"analyse", example(file), "--json"}, &out, &err), 0);
    const QJsonObject item =
        QJsonDocument::fromJson(out).object()["items"].toArray().first().toObject();
    QCOMPARE(item["kind"].toString(), QString("subdivision-surface"));
    QCOMPARE(item["scheme"].toString(), scheme);
    QCOMPARE(item["map_count"].toInt(), maps);
    QCOMPARE(item["maps_used"].toArray().size(), used);
    QCOMPARE(item["control_points"].toArray().size(), points);
    QCOMPARE(item["control_points"].toArray().first().toArray().size(), 3);
    QCOMPARE(item["lattice"].toArray().size(), points);
    QCOMPARE(item["lifted_dimension"].toInt(), points - 1);
    const QJsonArray mapList = item["maps"].toArray();
    QCOMPARE(mapList.size(), maps);
    int usedCount = 0;
    for (const QJsonValue &m : mapList) {
        const QJsonArray ev = m.toObject()["eigenvalues"].toArray();
        QCOMPARE(ev.size(), points);
        // Every S_i: dominant 1, then the subdominant pair of the scheme (upright pieces).
        QVERIFY(std::abs(ev[0].toArray()[0].toDouble() - 1.0) < 1e-9);
        QVERIFY(std::abs(std::abs(ev[1].toArray()[0].toDouble()) - sub) < 1e-9);
        QVERIFY(std::abs(std::abs(ev[2].toArray()[0].toDouble()) - sub) < 1e-9);
        if (m.toObject()["used"].toBool()) {
            ++usedCount;
            QVERIFY(m.toObject()["contractive"].toBool());
            QCOMPARE(m.toObject()["fixed_point"].toArray().size(), 3);
        }
    }
    QCOMPARE(usedCount, used);
    // A surface has box-counting dimension 2 (a fractal subset of it at most 2).
    const double dim = item["box_dimension"].toDouble();
    QVERIFY2(dim > 1.6 && dim < 2.2, qPrintable(QString::number(dim)));
}

void TestSurfacesCli::pointsAreThreeDimensional()
{
    AWB_SKIP_WITHOUT_THREADS();
    QByteArray out, err;
    QCOMPARE(run({"points", example("000-fig07-box-spline-hexagon.awb"), "--item",
                  "000 Fig. 7: box-spline hexagon from a triangle", "--depth", "2", "--csv"},
                 &out, &err),
             0);
    const QList<QByteArray> lines = out.trimmed().split('\n');
    QCOMPARE(lines.first(), QByteArray("x,y,z,map,view"));
    QCOMPARE(lines.size() - 1, 6 * 6 * 3);  // 6^2 images of a triangle
    // Its start set is net points 0, 9, 18 (the rows of the lifted P): typed, the same points.
    QByteArray typed;
    QCOMPARE(run({"points", example("000-fig07-box-spline-hexagon.awb"), "--item",
                  "000 Fig. 7: box-spline hexagon from a triangle", "--depth", "2", "--start",
                  "net:0,9,18", "--csv"},
                 &typed, &err),
             0);
    QCOMPARE(typed, out);
    QCOMPARE(run({"points", example("000-fig07-box-spline-hexagon.awb"), "--item",
                  "000 Fig. 7: box-spline hexagon from a triangle", "--start", "net:0,19",
                  "--csv"},
                 &typed, &err),
             1);
    QVERIFY2(err.contains("net point 2 of the start set has the index 19; the net has 19 points"),
             err.constData());
    for (int i = 1; i < lines.size(); ++i) {
        const QList<QByteArray> f = lines[i].split(',');
        QCOMPARE(f.size(), 5);
        const int map = f[3].toInt();
        QVERIFY(map >= 1 && map <= 6);
    }
    // A start point in R^3 from the command line; a plane point is refused.
    QCOMPARE(run({"points", example("000-fig07-box-spline-hexagon.awb"), "--item",
                  "000 Fig. 7: box-spline hexagon from a triangle", "--depth", "1", "--start",
                  "point:0,0,1", "--csv"},
                 &out, &err),
             0);
    QCOMPARE(out.trimmed().split('\n').size(), 1 + 6);
    QCOMPARE(run({"points", example("000-fig07-box-spline-hexagon.awb"), "--item",
                  "000 Fig. 7: box-spline hexagon from a triangle", "--start", "point:0,0",
                  "--csv"},
                 &out, &err),
             1);
    QVERIFY2(err.contains("3 per point"), err.constData());
}

void TestSurfacesCli::plyIsReadByMeshio()
{
    AWB_SKIP_WITHOUT_THREADS();
    const QString python = debianPython();
    const QString ply = m_dir.filePath("fig9.ply");
    QByteArray out, err;
    QCOMPARE(run({"export", example("000-fig09-box-spline-subset.awb"), "--item",
                  "000 Fig. 9 (right): two of the six maps left out", "--format", "ply", "--depth",
                  "4", "--out", ply},
                 &out, &err),
             0);
    // meshio is a real PLY parser (Debian python3-meshio): points and the per-vertex map.
    const QString script = QString(R"(
import meshio, sys
m = meshio.read(sys.argv[1])
maps = sorted(set(int(v) for v in m.point_data['map']))
print(len(m.points), m.points.shape[1], ' '.join(map(str, maps)))
)");
    QCOMPARE(run(python, {"-c", script, ply}, &out, &err), 0);
    const QList<QByteArray> f = out.trimmed().split(' ');
    QVERIFY2(f.size() >= 3, (out + err).constData());
    QCOMPARE(f[0].toInt(), 4 * 4 * 4 * 4 * 3);  // 4^4 images of a triangle
    QCOMPARE(f[1].toInt(), 3);
    QCOMPARE(f.mid(2), (QList<QByteArray>{"0", "1", "2", "3"}));  // maps used, 0-based
}

void TestSurfacesCli::objIsReadByMeshioAndAssimp()
{
    AWB_SKIP_WITHOUT_THREADS();
    const QString obj = m_dir.filePath("fig6.obj");
    QByteArray out, err;
    QCOMPARE(run({"export", example("000-fig06-bicubic-patch.awb"), "--item",
                  "000 Fig. 6: bicubic B-spline patch from a triangle", "--format", "obj",
                  "--rounds", "2", "--out", obj},
                 &out, &err),
             0);
    // Two rounds of bicubic subdivision of a 4 x 4 net: 7 x 7 points, 6 x 6 quads.
    const QString python = debianPython();
    const QString script = QString(R"(
import meshio, sys
m = meshio.read(sys.argv[1])
print(len(m.points), sum(len(c.data) for c in m.cells))
)");
    QCOMPARE(run(python, {"-c", script, obj}, &out, &err), 0);
    QCOMPARE(out.trimmed(), QByteArray("49 36"));
    const QString assimp = QStandardPaths::findExecutable("assimp");
    QVERIFY2(!assimp.isEmpty(), "assimp-utils is installed by scripts/setup.sh");
    QCOMPARE(run(assimp, {"info", obj}, &out, &err), 0);
    QVERIFY2(out.contains("Vertices:") && out.contains("49"), out.constData());
}

void TestSurfacesCli::matlabCellArrayOfTheBicubicPatch()
{
    AWB_SKIP_WITHOUT_THREADS();
    // The four 16 x 16 S_i of the bicubic patch (000 Fig. 6) for MATLAB's JSR toolbox: a cell
    // array of exact fractions -- the tensor products of the cubic B-spline's 1/8, 3/4, 1/2.
    const QString m = m_dir.filePath("fig6.m");
    QByteArray out, err;
    QCOMPARE(run({"export", example("000-fig06-bicubic-patch.awb"), "--item",
                  "000 Fig. 6: bicubic B-spline patch from a triangle", "--format", "matlab",
                  "--out", m},
                 &out, &err),
             0);
    QFile f(m);
    QVERIFY(f.open(QIODevice::ReadOnly));
    const QString text = QString::fromUtf8(f.readAll());
    const QStringList lines = text.split(QLatin1Char('\n'), Qt::SkipEmptyParts);
    QVERIFY2(lines.value(0).startsWith("% 000 Fig. 6"), qPrintable(text.left(200)));
    const QString s = lines.value(1);
    QVERIFY2(s.startsWith("S = {[") && s.endsWith("]};"), qPrintable(s.left(200)));
    QCOMPARE(s.count(QLatin1Char('[')), 4);        // four maps
    QCOMPARE(s.count(QLatin1Char(';')), 4 * 15 + 1); // 16 rows each, and the statement's end
    QVERIFY(s.contains("9/16") && s.contains("1/64") && !s.contains("0.0"));
}

void TestSurfacesCli::renderDrawsTheSurface_data()
{
    QTest::addColumn<QString>("file");
    QTest::addColumn<QString>("format");
    for (const char *f : {"000-fig06-bicubic-patch.awb", "000-fig07-box-spline-hexagon.awb",
                          "000-fig08-sqrt3-surface.awb", "000-fig09-box-spline-subset.awb"})
        QTest::newRow(f) << QString(f) << "png";
    QTest::newRow("svg") << "000-fig06-bicubic-patch.awb" << "svg";
    QTest::newRow("pdf") << "000-fig06-bicubic-patch.awb" << "pdf";
}

void TestSurfacesCli::renderDrawsTheSurface()
{
    QFETCH(QString, file);
    QFETCH(QString, format);
    const QString target = m_dir.filePath(file + "." + format);
    QByteArray out, err;
    QCOMPARE(run({"render", example(file), "--out", target, "--size", "400x320"}, &out, &err), 0);
    QVERIFY(QFileInfo(target).size() > 1000);
    if (format != "png")
        return;
    const QImage image(target);
    QCOMPARE(image.size(), QSize(400, 320));
    // Coloured (shaded map colours) pixels: the surface covers a good part of the picture.
    int coloured = 0;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x) {
            const QColor c = image.pixelColor(x, y);
            if (std::max({c.red(), c.green(), c.blue()}) - std::min({c.red(), c.green(), c.blue()})
                > 40)
                ++coloured;
        }
    QVERIFY2(coloured > 2000, qPrintable(QString::number(coloured)));
}

void TestSurfacesCli::badOptions()
{
    AWB_SKIP_WITHOUT_THREADS();
    QByteArray out, err;
    const QString fig6 = example("000-fig06-bicubic-patch.awb");
    QCOMPARE(run({"render", fig6, "--out", m_dir.filePath("x.png"), "--view", "10,120"}, &out,
                 &err),
             1);
    QVERIFY(err.contains("--view"));
    QCOMPARE(run({"export", fig6, "--item", "000 Fig. 6: bicubic B-spline patch from a triangle",
                  "--format", "stl", "--out", m_dir.filePath("x.stl")},
                 &out, &err),
             2);
    QVERIFY(err.contains("ply, obj, ifs, flame or matlab"));
    const QString curve = example("000-fig02-cubic-bspline-from-point.awb");
    QCOMPARE(run({"analyse", curve, "--json"}, &out, &err), 0);
    const QString name = QJsonDocument::fromJson(out).object()["items"].toArray()[0]
                             .toObject()["name"].toString();
    QCOMPARE(run({"export", curve, "--item", name, "--format", "obj", "--out",
                  m_dir.filePath("x.obj")},
                 &out, &err),
             1);
    QVERIFY(err.contains("surface"));
    QVERIFY(!QFile::exists(m_dir.filePath("x.obj")));
    QCOMPARE(run({"export", fig6, "--item", "000 Fig. 6: bicubic B-spline patch from a triangle",
                  "--format", "ply", "--depth", "30", "--out", m_dir.filePath("x.ply")},
                 &out, &err),
             1);
    QVERIFY(err.contains("--max-points"));
}

// `render --progress` reports the iteration's fraction done on stderr, rising to 100 % -- for
// a surface (its own raster) and a plane attractor (the engine); without it and without a
// terminal (a pipe, as here) stderr stays quiet.
void TestSurfacesCli::renderReportsProgress()
{
    const QString png = m_dir.filePath("progress.png");
    for (const QStringList &args :
         {QStringList{example("000-fig07-box-spline-hexagon.awb"), "--depth", "8"},
          QStringList{example("000-fig11-sierpinski-with-control-points.awb"), "--samples",
                      "3e7", "--threads", "1"}}) {
        QByteArray err;
        QCOMPARE(run(QStringList{"render"} + args + QStringList{"--progress", "--out", png},
                     nullptr, &err),
                 0);
        const QList<QByteArray> lines = err.trimmed().split('\n');
        QVERIFY2(lines.last().startsWith("render: 100 % ("), err.constData());
        int previous = -1;
        for (const QByteArray &line : lines) {
            const int percent = line.mid(8, line.indexOf('%') - 8).trimmed().toInt();
            QVERIFY2(line.startsWith("render: ") && percent > previous, err.constData());
            previous = percent;
        }
        QCOMPARE(run(QStringList{"render"} + args + QStringList{"--out", png}, nullptr, &err), 0);
        QCOMPARE(err, QByteArray());
    }
}

AWB_TEST_MAIN(TestSurfacesCli)
#include "test_surfaces_cli.moc"
