// attractor-cli and other tools' IFS files (issue 34): import makes a project of a Fractint
// .ifs library -- every well-formed entry a fractal with control points, 2D and 3D, the
// malformed ones named with their line and column (exit 1) -- and export --format ifs writes an
// item's maps back: the round trip keeps every coefficient, the imported Sierpinski triangle
// has the box-counting dimension log 3 / log 2, and its points lie on the triangle's attractor.

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QtTest>

#include "TestFiles.h"
#include "TestMain.h"
#include "TestTime.h"

#include "CliRunner.h"

#include "core/exchange/FractintIfs.h"

#include <cmath>
#include <sstream>

using namespace awb;

namespace {

const char *library = R"(; two classics and a tetrahedron
fern {
  0     0    0     .16 0 0    .01
  .85  .04 -.04  .85  0 1.6  .85
  .2  -.26  .23  .22  0 1.6  .07
 -.15  .28  .26  .24  0 .44  .07
}
sierpinski { .5 0 0 .5 0 0 .333, .5 0 0 .5 .5 0 .333, .5 0 0 .5 .25 .5 .334 }
tetra (3D) {
 .5 0 0 0 .5 0 0 0 .5 0 0 0 .25
 .5 0 0 0 .5 0 0 0 .5 1 0 0 .25
 .5 0 0 0 .5 0 0 0 .5 0 1 0 .25
 .5 0 0 0 .5 0 0 0 .5 0 0 1 .25
}
typo { .5 0 0 .5 0 0 .5 .5 0 0 .5 .5 }
)";

} // namespace

class TestImportCli : public QObject {
    Q_OBJECT
private slots:
    void importKeepsTheGoodEntries();
    void bundledLibrary();
    void exportRoundTrip();
    void contractiveOnAverage();
    void refusals();
    void legacyFilesAndLimits();

private:
    int run(const QStringList &args, QByteArray *out = nullptr, QByteArray *err = nullptr)
    {
        return awb::test::runProgram(awb::test::cliPath(), args, out, err);
    }
    QString write(const QString &name, const QByteArray &text)
    {
        return awb::test::writeFile(m_dir, name, text);
    }
    QJsonObject analyse(const QString &project, const QString &item)
    {
        QByteArray out;
        if (run({"analyse", project, "--item", item, "--json"}, &out) != 0)
            return {};
        return QJsonDocument::fromJson(out).object()["items"].toArray().first().toObject();
    }
    QTemporaryDir m_dir;
};

void TestImportCli::importKeepsTheGoodEntries()
{
    const QString lib = write("lib.ifs", library);
    const QString awb = m_dir.filePath("lib.awb");
    QByteArray out, err;
    QCOMPARE(run({"import", lib, "--out", awb}, &out, &err), 1);  // one entry was refused
    QVERIFY2(err.contains("lib.ifs, line 15, column 25: entry typo: 12 numbers: a 2D entry has "
                          "rows of 7"),
             err.constData());
    QVERIFY2(out.contains("3 item(s): fern, sierpinski, tetra"), out.constData());
    // The Sierpinski triangle: random iteration with the file's probabilities, and the
    // box-counting dimension of the paper's gasket, log 3 / log 2 = 1.585.
    const QJsonObject s = analyse(awb, "sierpinski");
    QCOMPARE(s["type"].toString(), QString("fractal"));
    const double dimension = s["box_dimension"].toDouble();
    QVERIFY2(std::abs(dimension - std::log(3.0) / std::log(2.0)) < 0.05,
             qPrintable(QString::number(dimension)));
    // Its points lie on the gasket: each one's coordinates in the triangle's frame have
    // disjoint binary digits (u AND v = 0 for (u, v) on the dyadic grid of the corners).
    QCOMPARE(run({"points", awb, "--item", "sierpinski", "--depth", "6", "--start",
                  "point:0,0", "--csv"},
                 &out, &err),
             0);
    const QList<QByteArray> lines = out.trimmed().split('\n');
    QCOMPARE(lines.size(), 1 + 729);  // a header, 3^6 images of the corner
    for (int k = 1; k < lines.size(); ++k) {
        const QList<QByteArray> xy = lines[k].split(',');  // x,y,map,view
        const double x = xy.value(0).toDouble(), y = xy.value(1).toDouble();
        const long v = std::lround(y * 128), u = std::lround((x - 0.5 * y) * 128);
        QVERIFY2(u >= 0 && v >= 0 && (u & v) == 0, lines[k].constData());
    }
    // The tetrahedron is an item of space, rendered in 3D.
    const QJsonObject t = analyse(awb, "tetra");
    QCOMPARE(t["type"].toString(), QString("fractal"));
    const QString png = m_dir.filePath("tetra.png");
    QCOMPARE(run({"render", awb, "--item", "tetra", "--out", png, "--size", "300x300"}, &out,
                 &err),
             0);
    QVERIFY(QImage(png).width() == 300);
}

void TestImportCli::bundledLibrary()
{
    AWB_SKIP_WITHOUT_THREADS();
    // examples/fractint-classics.ifs: every entry imports (exit 0), 2D and 3D.
    QByteArray out, err;
    const QString awb = m_dir.filePath("classics.awb");
    QCOMPARE(run({"import", awb::test::examplePath("fractint-classics.ifs"), "--out", awb}, &out,
                 &err),
             0);
    QVERIFY2(out.contains("5 item(s): fern, triangle, levy, 3dfern, tetrahedron"),
             out.constData());
    QVERIFY2(err.isEmpty(), err.constData());
    // The triangle is Sierpinski's (dimension log 3 / log 2), the 3D entries items of space.
    const double d = analyse(awb, "triangle")["box_dimension"].toDouble();
    QVERIFY2(std::abs(d - std::log(3.0) / std::log(2.0)) < 0.05, qPrintable(QString::number(d)));
    QCOMPARE(run({"points", awb, "--item", "tetrahedron", "--csv"}, &out, &err), 0);
    QVERIFY2(out.startsWith("x,y,z,"), out.left(40).constData());
    // --start and --depth mean what they say on an item of space that the 3D view draws by
    // random iteration: F^0 of a point is the point, F^1 its four images.
    QCOMPARE(run({"points", awb, "--item", "tetrahedron", "--csv", "--depth", "0", "--start",
                  "point:1,2,3"},
                 &out, &err),
             0);
    const QList<QByteArray> rows = out.trimmed().split('\n');
    QCOMPARE(rows.size(), 2);
    const QList<QByteArray> p = rows[1].split(',');
    QVERIFY2(std::abs(p.value(0).toDouble() - 1) < 1e-9 && std::abs(p.value(1).toDouble() - 2) < 1e-9
                 && std::abs(p.value(2).toDouble() - 3) < 1e-9,
             rows[1].constData());
    QCOMPARE(run({"points", awb, "--item", "tetrahedron", "--csv", "--depth", "1", "--start",
                  "point:1,2,3"},
                 &out, &err),
             0);
    QCOMPARE(out.trimmed().split('\n').size(), 5);
}

void TestImportCli::exportRoundTrip()
{
    AWB_SKIP_WITHOUT_THREADS();
    const QString awb = m_dir.filePath("round.awb");
    QByteArray out, err;
    run({"import", write("round.ifs", library), "--out", awb}, &out, &err);
    for (const char *name : {"fern", "tetra"}) {
        const QString ifs = m_dir.filePath(QString(name) + "-out.ifs");
        QCOMPARE(run({"export", awb, "--item", name, "--format", "ifs", "--out", ifs}, &out,
                     &err),
                 0);
        QFile f(ifs);
        QVERIFY(f.open(QIODevice::ReadOnly));
        std::istringstream in(f.readAll().toStdString());
        const FractintFile back = readFractintIfs(in);
        std::istringstream original(library);
        const FractintFile file = readFractintIfs(original);
        const FractintEntry &want = std::string(name) == "fern" ? file.entries[0]
                                                                : file.entries[2];
        QCOMPARE(int(back.entries.size()), 1);
        QCOMPARE(back.entries[0].name, want.name);
        QCOMPARE(back.entries[0].probabilities, want.probabilities);
        for (std::size_t i = 0; i < want.maps.size(); ++i)
            QVERIFY((back.entries[0].maps[i].A - want.maps[i].A).norm() < 1e-12
                    && (back.entries[0].maps[i].b - want.maps[i].b).norm() < 1e-12);
    }
}

void TestImportCli::contractiveOnAverage()
{
    // A map that grows (1.2 x) among one that shrinks: random iteration still converges, the
    // IFS contracts on average (Lyapunov exponent .3 log 1.2 + .7 log .3 = -0.788): imported,
    // reported, rendered; deterministic iteration of the same maps is refused.
    const QString awb = m_dir.filePath("avg.awb");
    QByteArray out, err;
    QCOMPARE(run({"import", write("avg.ifs", "avg { 1.2 0 0 1.2 0 0 .3  .3 0 0 .3 1 1 .7 }\n"),
                  "--out", awb},
                 &out, &err),
             0);
    const QJsonObject a = analyse(awb, "avg");
    QVERIFY(a["contractive_on_average"].toBool());
    QVERIFY2(std::abs(a["lyapunov_exponent"].toDouble() - (.3 * std::log(1.2) + .7 * std::log(.3)))
                 < 0.03,
             qPrintable(QString::number(a["lyapunov_exponent"].toDouble())));
    QCOMPARE(run({"render", awb, "--out", m_dir.filePath("avg.png"), "--size", "200x200"}, &out,
                 &err),
             0);
    QCOMPARE(run({"render", awb, "--out", m_dir.filePath("avg-d.png"), "--depth", "6"}, &out,
                 &err),
             1);
    QVERIFY2(err.contains("not contractive"), err.constData());
    // Chosen 99 times in 100, the growing map wins (Lyapunov exponent > 0): random iteration is
    // refused too, by its message alone (no painter left with a saved state on the way out).
    QFile f(awb);
    QVERIFY(f.open(QIODevice::ReadOnly));
    QJsonObject root = QJsonDocument::fromJson(f.readAll()).object();
    f.close();
    QJsonArray items = root["items"].toArray();
    QJsonObject item = items[0].toObject();
    QJsonObject algorithm = item["algorithm"].toObject();
    algorithm["probabilities"] = QJsonArray{0.99, 0.01};
    item["algorithm"] = algorithm;
    items[0] = item;
    root["items"] = items;
    const QString grow = write("grow.awb", QJsonDocument(root).toJson());
    QCOMPARE(run({"render", grow, "--out", m_dir.filePath("grow.png")}, &out, &err), 1);
    QVERIFY2(err.contains("not contractive") && !err.contains("contracts on average")
                 && !err.contains("QPainter"),
             err.constData());
}

void TestImportCli::refusals()
{
    AWB_SKIP_WITHOUT_THREADS();
    QByteArray out, err;
    QCOMPARE(run({"import", write("none.ifs", "; nothing\nonly {\n"), "--out",
                  m_dir.filePath("none.awb")},
                 &out, &err),
             1);
    QVERIFY2(err.contains("none.ifs, line 2, column 6: entry only: the file ends before the "
                          "entry's '}'")
                 && err.contains("no entry could be imported"),
             err.constData());
    QVERIFY(!QFile::exists(m_dir.filePath("none.awb")));
    // A flame whose field lies outside what a project holds (quality 1e12, the declared range
    // 1e-6 to 1e6) is not imported: import never writes what the program then refuses.
    QCOMPARE(run({"import",
                  write("q.flame", "<flame name=\"q\" size=\"64 64\" scale=\"16\" "
                                   "quality=\"1e12\"><xform weight=\"1\" spherical=\"1\" "
                                   "coefs=\"0.5 0 0 0.5 0 0\"/></flame>"),
                  "--out", m_dir.filePath("q.awb")},
                 &out, &err),
             1);
    QVERIFY2(err.contains("q.flame: flame 'q' not imported: field \"tone.quality\": 1e+12 is "
                          "outside the range")
                 && err.contains("no entry could be imported"),
             err.constData());
    QVERIFY(!QFile::exists(m_dir.filePath("q.awb")));
    QCOMPARE(run({"import", write("x.txt", "a { }"), "--out", m_dir.filePath("x.awb")}, &out,
                 &err),
             2);
    QVERIFY(err.contains("Fractint .ifs"));
    // A B-spline curve's IFS acts in the lifted space of 000 §2: no Fractint entry.
    const QString curve = awb::test::examplePath("000-fig02-cubic-bspline-from-point.awb");
    QCOMPARE(run({"export", curve, "--item", "000 Fig. 2: cubic B-spline from a point",
                  "--format", "ifs", "--out", m_dir.filePath("c.ifs")},
                 &out, &err),
             1);
    QVERIFY2(err.contains("drawn through a projection"), err.constData());
    // 000 Fig. 11 (top): the Sierpinski gasket from its control points acts in a lifted space
    // of dimension 5 whose plane block is decoupled, x' = x A + b in the plane: it goes out as
    // its three plane maps, halvings towards the triangle's corners.
    const QString gasket = awb::test::examplePath("000-fig11-sierpinski-with-control-points.awb");
    const QString top = "000 Fig. 11 (top): Sierpinski gasket from its control points";
    QCOMPARE(run({"export", gasket, "--item", top, "--format", "ifs", "--out",
                  m_dir.filePath("g.ifs")},
                 &out, &err),
             0);
    QFile g(m_dir.filePath("g.ifs"));
    QVERIFY(g.open(QIODevice::ReadOnly));
    std::istringstream gin(g.readAll().toStdString());
    const FractintFile gf = readFractintIfs(gin);
    QCOMPARE(int(gf.entries.size()), 1);
    QCOMPARE(gf.entries[0].name, top.toStdString());
    QCOMPARE(int(gf.entries[0].maps.size()), 3);
    for (const AffineMap &f : gf.entries[0].maps)
        QVERIFY((f.A - 0.5 * Mat::Identity(2, 2)).norm() < 1e-12);
    QCOMPARE(run({"export", gasket, "--item", top, "--format", "flame", "--out",
                  m_dir.filePath("g.flame")},
                 &out, &err),
             0);
    // A 3D item is no flame: the message says so and names the format that holds it.
    const QString tetra = m_dir.filePath("tetra.awb");
    QCOMPARE(run({"import", write("tetra.ifs", "tetra (3D) { .5 0 0 0 .5 0 0 0 .5 0 0 0 .5 "
                                               ".5 0 0 0 .5 0 0 0 .5 1 0 0 .5 }"),
                  "--out", tetra},
                 &out, &err),
             0);
    QCOMPARE(run({"export", tetra, "--item", "tetra", "--format", "flame", "--out",
                  m_dir.filePath("t.flame")},
                 &out, &err),
             1);
    QVERIFY2(err.contains("tetra is an IFS of space: a flam3 flame holds maps of the plane"),
             err.constData());
}

void TestImportCli::legacyFilesAndLimits()
{
    AWB_SKIP_WITHOUT_THREADS();
    QByteArray out, err;
    // Fractint 15's one-IFS files: bare rows, one entry named after the file.
    const QString fern = write("fern.ifs", "0 0 0 .16 0 0 .01\n.85 .04 -.04 .85 0 1.6 .85\n"
                                           ".2 -.26 .23 .22 0 1.6 .07\n"
                                           "-.15 .28 .26 .24 0 .44 .07\n");
    QCOMPARE(run({"import", fern, "--out", m_dir.filePath("fern.awb")}, &out, &err), 0);
    QVERIFY2(out.contains("1 item(s): fern"), out.constData());
    // Probabilities that are no distribution: imported, with a warning.
    QCOMPARE(run({"import", write("w.ifs", "low { .5 0 0 .5 0 0 .1 .5 0 0 .5 .5 0 .2 }"),
                  "--out", m_dir.filePath("w.awb")},
                 &out, &err),
             0);
    QVERIFY2(err.contains("warning: w.ifs, line 1, column 1: entry low: the probabilities sum "
                          "to 0.3, not 1"),
             err.constData());
    // More maps than the engine iterates: refused at import, not written for render to refuse.
    QByteArray many = "many {\n";
    for (int r = 0; r < 1000; ++r)
        many += ".01 0 0 .01 0 0 1\n";
    QCOMPARE(run({"import", write("many.ifs", many + "}\n"), "--out",
                  m_dir.filePath("many.awb")},
                 &out, &err),
             1);
    QVERIFY2(err.contains("entry many: 1000 maps: at most 255 maps are supported"),
             err.constData());
    QVERIFY(!QFile::exists(m_dir.filePath("many.awb")));
    // Names of several words come back as written.
    QCOMPARE(run({"import", write("n.ifs", "Barnsley fern { .5 0 0 .5 0 0 .5 .5 0 0 .5 .5 0 .5 }"),
                  "--out", m_dir.filePath("n.awb")},
                 &out, &err),
             0);
    QCOMPARE(run({"export", m_dir.filePath("n.awb"), "--item", "Barnsley fern", "--format", "ifs",
                  "--out", m_dir.filePath("n2.ifs")},
                 &out, &err),
             0);
    QFile n2(m_dir.filePath("n2.ifs"));
    QVERIFY(n2.open(QIODevice::ReadOnly));
    QVERIFY(n2.readAll().startsWith("Barnsley fern {"));
}

AWB_TEST_MAIN(TestImportCli)
#include "test_import_cli.moc"
