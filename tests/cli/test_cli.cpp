// attractor-cli end to end: the bundled figures render to real, non-empty images; bad use gives
// the exit codes and messages a command-line user expects; `render` draws an item in its own
// colours (style.color_by and style.colors), as the application's view does.

#include <QFile>
#include <QImage>
#include <QProcess>
#include <QTemporaryDir>
#include <QtTest>

#include "TestMain.h"

#include "TestPaths.h"
#include "TestTime.h"

class TestCli : public QObject {
    Q_OBJECT
private slots:
    void examplesRenderToPng();
    void usageErrors();
    void renderUsesTheItemsColours();

private:
    QString cli() const
    {
        // CTest sets AWB_BIN_DIR; run by hand, the binary is in ../bin beside tests/.
        const QString dir = qEnvironmentVariable("AWB_BIN_DIR",
                                                 QCoreApplication::applicationDirPath() + "/../bin");
        return dir + "/attractor-cli";
    }
    int run(const QStringList &args, QString *out = nullptr, QString *err = nullptr)
    {
        QProcess p;
        p.start(cli(), args);
        if (!p.waitForFinished(awb::test::ms(120000)))
            return -1;
        if (out)
            *out = QString::fromUtf8(p.readAllStandardOutput());
        if (err)
            *err = QString::fromUtf8(p.readAllStandardError());
        return p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -1;
    }
};

void TestCli::examplesRenderToPng()
{
    QTemporaryDir dir;
    QString out;
    QCOMPARE(run({"examples", "--out", dir.path()}, &out), 0);
    const QStringList ids = {"000-fig02-cubic-bspline-from-point",
                             "000-fig03-end-interpolating-cubic-from-triangle",
                             "000-fig05-four-point-from-segment"};
    for (const QString &id : ids) {
        const QString file = dir.filePath(id + ".png");
        QVERIFY2(out.contains(file), qPrintable(out));
        const QImage img(file);
        QVERIFY2(!img.isNull(), qPrintable(file));
        // Five panels of 420 x 360 plus title and captions.
        QCOMPARE(img.width(), 5 * 420);
        // Count coloured (non-grey) pixels: the attractor and the control polygon are drawn.
        int coloured = 0;
        for (int y = 0; y < img.height(); ++y)
            for (int x = 0; x < img.width(); ++x) {
                const QColor c = img.pixelColor(x, y);
                if (std::max({c.red(), c.green(), c.blue()}) - std::min({c.red(), c.green(), c.blue()}) > 60)
                    ++coloured;
            }
        QVERIFY2(coloured > 3000, qPrintable(QString("%1: %2 coloured pixels").arg(id).arg(coloured)));
    }
}

void TestCli::usageErrors()
{
    QString out, err;
    QCOMPARE(run({}, &out), 2);
    QVERIFY(out.contains("Usage: attractor-cli"));
    QCOMPARE(run({"frobnicate"}, &out, &err), 2);
    QVERIFY(err.contains("unknown command 'frobnicate'"));
    QCOMPARE(run({"examples", "--help"}, &out), 0);
    QVERIFY(out.contains("--out"));
    QCOMPARE(run({"examples", "--list"}, &out), 0);
    QCOMPARE(out.count('\n'), 3);

    // points, polygon and export take a project's only item without --item; with several
    // they ask for it and name them.
    const QString dir = awb::test::sourceDir() + "/examples/";
    const QString one = dir + "000-fig02-cubic-bspline-from-point.awb";
    QCOMPARE(run({"points", one, "--csv", "--depth", "2"}, &out, &err), 0);
    QVERIFY2(out.startsWith("x,y"), qPrintable(out.left(80) + err));
    QCOMPARE(out.count(QLatin1Char('\n')), 1 + 2 * 2); // two maps, depth 2, one start point
    QCOMPARE(run({"polygon", one, "--level", "1", "--json"}, &out, &err), 0);
    QVERIFY2(out.contains("\"points\""), qPrintable(err));
    const QString two = dir + "001-fig06-koch-type-curves.awb";
    QCOMPARE(run({"points", two, "--csv"}, &out, &err), 2);
    QVERIFY2(err.contains("--item NAME is required") && err.contains("has 2 items")
                 && err.contains("'001 Fig. 6(b): scheme (5) on a triangle, positive normals'"),
             qPrintable(err));
    QTemporaryDir tmp;
    QCOMPARE(run({"export", two, "--format", "ply", "--out", tmp.filePath("a.ply")}, &out, &err),
             2);
    QVERIFY2(err.contains("--item NAME is required"), qPrintable(err));
}

void TestCli::renderUsesTheItemsColours()
{
    // The three-map gasket (bench/sierpinski-plane.awb) by random iteration, drawn crisp (hits):
    // every lit pixel has exactly its image's colour.
    auto project = [](const QString &style) {
        return QStringLiteral(
                   R"({"format": "attractor-workbench", "version": 1, "items": [
                   {"type": "subdivision-curve", "name": "gasket",
                    "scheme": {"kind": "matrices", "matrices": [
                      [[1, 0, 0], [0.5, 0.5, 0], [0.5, 0, 0.5]],
                      [[0.5, 0.5, 0], [0, 1, 0], [0, 0.5, 0.5]],
                      [[0.5, 0, 0.5], [0, 0.5, 0.5], [0, 0, 1]]]},
                    "control_points": [[0, 0], [1, 0], [0.5, 1]],
                    "algorithm": {"mode": "random", "samples": 200000, "seed": 1},
                    "style": %1}]})")
            .arg(style)
            .toUtf8();
    };
    QTemporaryDir dir;
    auto render = [&](const QString &name, const QString &style) {
        QFile f(dir.filePath(name + ".awb"));
        f.open(QIODevice::WriteOnly);
        f.write(project(style));
        f.close();
        const QString png = dir.filePath(name + ".png");
        QString err;
        const int code = run({"render", f.fileName(), "--tone", "hits", "--out", png}, nullptr, &err);
        if (code != 0)
            qWarning("%s", qPrintable(err));
        return QImage(png).convertToFormat(QImage::Format_RGB32);
    };
    auto pixelsOf = [](const QImage &img, QRgb colour) {
        int n = 0;
        for (int y = 0; y < img.height(); ++y)
            for (int x = 0; x < img.width(); ++x)
                n += img.pixel(x, y) == colour;
        return n;
    };
    const QRgb palette[3] = {qRgb(0xe6, 0x39, 0x46), qRgb(0x2a, 0x9d, 0x8f), qRgb(0x26, 0x46, 0x53)};
    const QImage byMap = render("by-map", R"({"color_by": "map", "colors": ["#e63946", "#2a9d8f", "#264653"]})");
    QVERIFY(!byMap.isNull());
    for (QRgb c : palette)
        QVERIFY2(pixelsOf(byMap, c) > 2000, qPrintable(QString::number(pixelsOf(byMap, c))));
    const QImage one = render("one", R"({"color_by": "none", "colors": ["#2a9d8f"]})");
    QVERIFY(!one.isNull());
    QVERIFY(pixelsOf(one, palette[1]) > 6000);
    QCOMPARE(pixelsOf(one, palette[0]) + pixelsOf(one, palette[2]), 0);
    // The same lit pixels either way: the colours change, not the attractor.
    QCOMPARE(pixelsOf(one, palette[1]),
             pixelsOf(byMap, palette[0]) + pixelsOf(byMap, palette[1]) + pixelsOf(byMap, palette[2]));
}

AWB_TEST_GUILESS_MAIN(TestCli)
#include "test_cli.moc"
