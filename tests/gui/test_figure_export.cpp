// Figures fit for a paper (issue 17, part 6): an export draws the attractor at the resolution
// asked for (a raster of the target's device pixels, stored losslessly in a PDF), a curve as
// joined vector paths in SVG and PDF, the figure sheet's matrices at 8 pt or more, the
// matrices as LaTeX with exact fractions, options to hide the grid and the control points and
// to crop; and the batch mode's --export-figure that makes all of it testable offscreen.

#include "TestPaths.h"
#include "BatchRunner.h"
#include "WindowTestSupport.h"
#include "../model/Fig2Example.h"

#include "gui/app/FigureSheet.h"
#include "gui/app/ItemController.h"
#include "gui/views/MatrixView.h"
#include "model/AttractorItem.h"
#include "model/FigureMetadata.h"
#include "model/NamedMatrix.h"
#include "model/Project.h"
#include "model/ProjectIO.h"

#include <QFile>
#include <QImage>
#include <QImageReader>
#include <QPainter>
#include <QPdfWriter>
#include <QPrinter>
#include <QProcess>
#include <QRegularExpression>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QtTest>

#include "TestMain.h"

using namespace awb;

class TestFigureExport : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { test::useTestSettings("awb-test-figure-export"); }
    void latexNumbersAreExact();
    void latexOfFig2Matrices();
    void batchSvgOfACurveIsPaths();
    void batchPdfOfACurveIsPathsAndLossless();
    void batchPngIsFullResolution();
    void batchDeepSierpinskiPdfRasterAtDpi();
    void batchOptionsHideAndCrop();
    void batchMatricesAsLatex();
    void batchBadOptions();
    void sheetMatricesAreAtLeast8pt();
    void printedSheetKeepsItsTitleOnThePage();
    void pngCarriesItsItemAndReopens();

private:
    test::BatchRunner m_runner;
    int run(const QStringList &args, QString *err = nullptr) { return m_runner.run(args, err); }
    static QString example(const QString &name) { return test::BatchRunner::example(name); }
    static QByteArray readAll(const QString &file)
    {
        QFile f(file);
        return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
    }
    // "attractor drawn as ..." of the batch mode's log.
    static QString drawnAs(const QString &err)
    {
        const auto m = QRegularExpression("attractor drawn as ([^\n]+)").match(err);
        return m.hasMatch() ? m.captured(1).trimmed() : QString();
    }
};

void TestFigureExport::latexNumbersAreExact()
{
    QCOMPARE(latexNumber(0.375), QStringLiteral("\\frac{3}{8}"));
    QCOMPARE(latexNumber(-0.0625), QStringLiteral("-\\frac{1}{16}"));
    QCOMPARE(latexNumber(2.0), QStringLiteral("2"));
    QCOMPARE(latexNumber(0.0), QStringLiteral("0"));
    QCOMPARE(latexNumber(1.0 / 3.0), QStringLiteral("\\frac{1}{3}"));
    QCOMPARE(latexNumber(0.1123456789, 4), QStringLiteral("0.1123"));
    QCOMPARE(latexNumber(std::sqrt(2.0) * 1e-7, 3), QStringLiteral("1.41 \\cdot 10^{-7}"));
    QCOMPARE(latexComplex({0.5, -0.125}), QStringLiteral("\\frac{1}{2} - \\left(\\frac{1}{8}\\right)i"));
    QCOMPARE(latexComplex({0, 1}), QStringLiteral("i"));
    QCOMPARE(latexComplex({0.25, 0}), QStringLiteral("\\frac{1}{4}"));
}

// 000 Fig. 2: the cubic B-spline's S_1 on 5 points has the rows (1/2 1/2 0 0 0),
// (1/8 3/4 1/8 0 0), ... in exact fractions.
void TestFigureExport::latexOfFig2Matrices()
{
    Project project;
    QVERIFY(project.open(test::fig2File));
    auto *curve = qobject_cast<AttractorItem *>(project.findItem(test::fig2Curve));
    QVERIFY(curve);
    const auto d = curve->derivedIfs();
    QVERIFY(d);
    const QList<NamedMatrix> list = namedMatrices(*d);
    QVERIFY(list.size() >= 2);
    QCOMPARE(list[0].name, QStringLiteral("S_1"));
    const QString tex = latexMatrices(list, curve->name());
    QVERIFY(tex.startsWith(QStringLiteral("% ") + curve->name()));
    QVERIFY2(tex.contains(QStringLiteral("S_{1} = \\begin{bmatrix}\n"
                                         "  \\frac{1}{2} & \\frac{1}{2} & 0 & 0 & 0 \\\\\n"
                                         "  \\frac{1}{8} & \\frac{3}{4} & \\frac{1}{8} & 0 & 0 \\\\\n")),
             qPrintable(tex.left(400)));
    QCOMPARE(tex.count(QStringLiteral("\\begin{bmatrix}")), list.size());
    QCOMPARE(tex.count(QStringLiteral("\\[")), list.size());
}

// Four-point scheme from a segment at depth 12 (000 Fig. 5): 4 096 images become joined paths,
// no embedded picture.
void TestFigureExport::batchSvgOfACurveIsPaths()
{
    QTemporaryDir out;
    const QString svg = out.filePath("four-point.svg");
    QString err;
    const int code = run({example("000-fig05-four-point-from-segment.awb"), "--export-figure", svg,
                          "--figure-size", "1196x1646", "--dpi", "300"},
                         &err);
    QVERIFY2(code == 0, qPrintable(err));
    QCOMPARE(drawnAs(err), QStringLiteral("curve paths"));
    const QByteArray bytes = readAll(svg);
    QVERIFY(bytes.contains("<svg"));
    QVERIFY(!bytes.contains("<image"));
    // The curve's stroke: a handful of paths (one per colour run), not one per image.
    const int strokes = int(bytes.count("stroke-linecap=\"round\""));
    QVERIFY2(strokes >= 1, bytes.left(300).constData());
    QVERIFY2(bytes.count("<path") < 200, QByteArray::number(bytes.count("<path")).constData());
    QVERIFY2(bytes.size() < 600 * 1024, QByteArray::number(bytes.size()).constData());
}

void TestFigureExport::batchPdfOfACurveIsPathsAndLossless()
{
    QTemporaryDir out;
    const QString pdf = out.filePath("four-point.pdf");
    QString err;
    QVERIFY2(run({example("000-fig05-four-point-from-segment.awb"), "--export-figure", pdf,
                  "--figure-size", "1196x1646", "--dpi", "300"},
                 &err) == 0,
             qPrintable(err));
    QCOMPARE(drawnAs(err), QStringLiteral("curve paths"));
    const QByteArray bytes = readAll(pdf);
    QVERIFY(bytes.startsWith("%PDF"));
    QVERIFY(!bytes.contains("/DCTDecode"));
    QVERIFY(!bytes.contains("/Subtype /Image"));
}

// A random-iteration picture (002 Fig. 3, a union of two quadratic Bézier IFS, 400 000
// samples) exported at 1196 x 1646: the raster has exactly those pixels
// (before: the screen's half-size raster scaled up).
void TestFigureExport::batchPngIsFullResolution()
{
    QTemporaryDir out;
    const QString png = out.filePath("gasket.png");
    QString err;
    QVERIFY2(run({example("002-fig03-union-p3.awb"), "--export-figure", png,
                  "--figure-size", "1196x1646", "--dpi", "300", "--window-size", "900x700"},
                 &err) == 0,
             qPrintable(err));
    QCOMPARE(drawnAs(err), QStringLiteral("raster 1196x1646"));
    const QImage image(png);
    QCOMPARE(image.size(), QSize(1196, 1646));
    QCOMPARE(qRound(image.dotsPerMeterX() * 0.0254), 300);
}

// A Sierpinski gasket of 3^10 triangles to PDF at 300 dpi: a raster of the page's device
// pixels, stored losslessly.
void TestFigureExport::batchDeepSierpinskiPdfRasterAtDpi()
{
    QTemporaryDir out;
    QFile src(example("000-fig11-sierpinski-with-control-points.awb"));
    QVERIFY(src.open(QIODevice::ReadOnly));
    QByteArray project = src.readAll();
    project.replace("\"depth\": 8", "\"depth\": 10");
    const QString deep = out.filePath("deep.awb");
    QFile dst(deep);
    QVERIFY(dst.open(QIODevice::WriteOnly));
    dst.write(project);
    dst.close();
    const QString pdf = out.filePath("gasket.pdf");
    QString err;
    QVERIFY2(run({deep, "--item", "000 Fig. 11 (top): Sierpinski gasket from its control points",
                  "--export-figure", pdf, "--figure-size", "1200x900", "--dpi", "300"},
                 &err) == 0,
             qPrintable(err));
    QCOMPARE(drawnAs(err), QStringLiteral("raster 1200x900"));
    const QByteArray bytes = readAll(pdf);
    QVERIFY(bytes.contains("/Subtype /Image"));
    QVERIFY(!bytes.contains("/DCTDecode"));
    QVERIFY(bytes.contains("/Width 1200"));
    QVERIFY(bytes.contains("/Height 900"));
}

// --no-grid --no-handles leave no text and no control points; --crop makes the height follow
// the content (the four-point curve is wider than high).
void TestFigureExport::batchOptionsHideAndCrop()
{
    QTemporaryDir out;
    const QString full = out.filePath("full.svg"), bare = out.filePath("bare.svg"),
                  crop = out.filePath("crop.png");
    QString err;
    const QString file = example("000-fig05-four-point-from-segment.awb");
    QVERIFY2(run({file, "--export-figure", full, "--figure-size", "1200x1200"}, &err) == 0,
             qPrintable(err));
    QVERIFY2(run({file, "--export-figure", bare, "--figure-size", "1200x1200", "--no-grid",
                  "--no-handles"},
                 &err) == 0,
             qPrintable(err));
    const QByteArray withAll = readAll(full), without = readAll(bare);
    QVERIFY(withAll.count("<text") > 0);
    QCOMPARE(without.count("<text"), 0);
    QVERIFY(without.size() < withAll.size());
    QVERIFY2(run({file, "--export-figure", crop, "--figure-size", "1200x1200", "--crop",
                  "--font", "DejaVu Serif,10"},
                 &err) == 0,
             qPrintable(err));
    const QSize s = QImageReader(crop).size();
    QCOMPARE(s.width(), 1200);
    QVERIFY2(s.height() < 1000 && s.height() >= 16, qPrintable(QString::number(s.height())));
}

void TestFigureExport::batchMatricesAsLatex()
{
    QTemporaryDir out;
    const QString tex = out.filePath("fig2.tex");
    QString err;
    QVERIFY2(run({test::fig2File, "--item", test::fig2Curve, "--export-figure", tex, "--view",
                  "matrices"},
                 &err) == 0,
             qPrintable(err));
    const QString text = QString::fromUtf8(readAll(tex));
    QVERIFY(text.contains(QStringLiteral("\\frac{3}{4}")));
    QVERIFY(text.contains(QStringLiteral("S_{2} = \\begin{bmatrix}")));
    // A picture view to .tex is refused with a message, and nothing is written.
    const QString wrong = out.filePath("wrong.tex");
    QCOMPARE(run({test::fig2File, "--export-figure", wrong, "--view", "attractor"}, &err), 1);
    QVERIFY2(err.contains("matrices only"), qPrintable(err));
    QVERIFY(!QFile::exists(wrong));
}

void TestFigureExport::batchBadOptions()
{
    QString err;
    const QString file = example("000-fig05-four-point-from-segment.awb");
    QCOMPARE(run({file, "--export-figure", "/tmp/x.png", "--view", "poster"}, &err), 2);
    QVERIFY2(err.contains("--view poster"), qPrintable(err));
    QCOMPARE(run({file, "--export-figure", "/tmp/x.png", "--dpi", "9000"}, &err), 2);
    QVERIFY2(err.contains("--dpi 9000"), qPrintable(err));
    QCOMPARE(run({file, "--export-figure", "/tmp/x.png", "--figure-size", "10x10"}, &err), 2);
    QVERIFY2(err.contains("--figure-size"), qPrintable(err));
    QCOMPARE(run({file, "--export-figure", "/nonexistent-dir/x.png"}, &err), 1);
    QVERIFY2(err.contains("/nonexistent-dir/x.png"), qPrintable(err));
}

// The printed sheet (A4 landscape, 300 dpi) of 000 Fig. 2: its four 5 x 5 matrices (S_1, S_2,
// M_1, M_2) all shown, at 8 pt or more (before: shrunk until they fit, down to 4 pt).
void TestFigureExport::sheetMatricesAreAtLeast8pt()
{
    QTemporaryDir dir;
    test::ShownWindow shown(dir.path(), QSize(1200, 800));
    QVERIFY(shown.window.openFile(test::fig2File));
    Item *curve = nullptr;
    for (Item *i : shown.window.project()->items())
        if (i->name() == test::fig2Curve)
            curve = i;
    QVERIFY(curve);
    shown.window.setCurrentItem(curve);
    QVERIFY(test::waitForFinalImage(shown.window.attractorView()));
    FigureSheet sheet(curve, shown.window.attractorView(), shown.window.spectrumView());
    QString error;
    QVERIFY2(sheet.writePdf(dir.filePath("sheet.pdf"), &error), qPrintable(error));
    QCOMPARE(sheet.matricesShown(), 4);
    const double points = sheet.matrixFontPixels() * 72.0 / 300.0;
    QVERIFY2(points >= 8.0, qPrintable(QString::number(points)));

    // A mesh's five 16 x 16 and 19 x 19 matrices: every one drawn as a heat map, in a
    // picture as in print (issue 47: "… and 1 more: see the Matri…" instead).
    QVERIFY(shown.window.openFile((awb::test::sourceDir() + QStringLiteral("/examples/mesh-cube-catmull-clark.awb"))));
    Item *mesh = shown.window.project()->child(0);
    shown.window.setCurrentItem(mesh);
    shown.window.controller()->refreshNow();
    const int matrices = shown.window.matrixView()->matrixCount();
    QVERIFY2(matrices >= 5, qPrintable(QString::number(matrices)));
    FigureSheet meshSheet(mesh, shown.window.attractorView(), shown.window.spectrumView(),
                          shown.window.surfaceView());
    QVERIFY2(meshSheet.writePdf(dir.filePath("mesh-sheet.pdf"), &error), qPrintable(error));
    QCOMPARE(meshSheet.matricesShown(), matrices);
    QImage picture(1800, 1350, QImage::Format_RGB32);
    picture.fill(Qt::white);
    {
        QPainter p(&picture);
        meshSheet.paint(&p, QRectF(picture.rect()));
    }
    QCOMPARE(meshSheet.matricesShown(), matrices);
    // A margin: nothing drawn in the outer 1% of the picture.
    for (int y = 0; y < picture.height(); ++y)
        for (int x : {0, 5, 10, picture.width() - 11, picture.width() - 1})
            QVERIFY2(picture.pixel(x, y) == qRgb(255, 255, 255),
                     qPrintable(QStringLiteral("%1, %2").arg(x).arg(y)));
}

// The sheet as a printer gets it (a QPrinter, as File > Print and Print Preview paint it, here
// into a PDF file) and rasterised by poppler: a long title wraps inside the page's printable
// area, nothing is drawn in the 12 mm margins, and the title is there at the top (issue 47: in
// Print Preview the title left the frame).
void TestFigureExport::printedSheetKeepsItsTitleOnThePage()
{
    const QString pdftoppm = QStandardPaths::findExecutable(QStringLiteral("pdftoppm"));
    QVERIFY2(!pdftoppm.isEmpty(), "pdftoppm (poppler-utils, installed by scripts/setup.sh)");
    QTemporaryDir dir;
    test::ShownWindow shown(dir.path(), QSize(1200, 800));
    QVERIFY(shown.window.openFile(awb::test::sourceDir()
                                  + QStringLiteral("/examples/mesh-cube-catmull-clark.awb")));
    Item *mesh = shown.window.project()->child(0);
    QVERIFY(mesh->setName(QStringLiteral("A control mesh with a long name that a printed title "
                                         "has to wrap twice on the page of a landscape A4 sheet")));
    shown.window.setCurrentItem(mesh);
    shown.window.controller()->refreshNow();
    FigureSheet sheet(mesh, shown.window.attractorView(), shown.window.spectrumView(),
                      shown.window.surfaceView());
    QPrinter printer(QPrinter::HighResolution);
    printer.setOutputFormat(QPrinter::PdfFormat);
    printer.setOutputFileName(dir.filePath("printed.pdf"));
    printer.setPageLayout(QPageLayout(QPageSize(QPageSize::A4), QPageLayout::Landscape,
                                      QMarginsF(12, 12, 12, 12), QPageLayout::Millimeter));
    QVERIFY(sheet.print(&printer));
    QProcess poppler;
    poppler.start(pdftoppm, {QStringLiteral("-r"), QStringLiteral("40"), QStringLiteral("-png"),
                             QStringLiteral("-singlefile"), dir.filePath("printed.pdf"),
                             dir.filePath("printed")});
    QVERIFY(poppler.waitForFinished(60000));
    QCOMPARE(poppler.exitCode(), 0);
    const QImage page(dir.filePath("printed.png"));
    QVERIFY(!page.isNull());
    // A4 landscape at 40 dpi: 468 x 331 pixels; 12 mm is 18.9 pixels.
    QVERIFY2(std::abs(page.width() - 468) <= 2 && std::abs(page.height() - 331) <= 2,
             qPrintable(QStringLiteral("%1 x %2").arg(page.width()).arg(page.height())));
    const int margin = 17;
    const auto ink = [&](int x, int y) { return qGray(page.pixel(x, y)) < 200; };
    for (int y = 0; y < page.height(); ++y)
        for (int x = 0; x < page.width(); ++x) {
            const bool inMargin = x < margin || y < margin || x >= page.width() - margin
                                  || y >= page.height() - margin;
            QVERIFY2(!(inMargin && ink(x, y)), qPrintable(QStringLiteral("ink at %1, %2").arg(x).arg(y)));
        }
    // The title's first line: ink in the band just below the top margin, on the left.
    int titleInk = 0;
    for (int y = margin; y < margin + 14; ++y)
        for (int x = margin; x < page.width() / 2; ++x)
            titleInk += ink(x, y);
    QVERIFY2(titleInk > 50, qPrintable(QString::number(titleInk)));
}

// A PNG export carries the item's project (and the version) in PNG text chunks, as flam3 keeps
// its flames; opening the PNG gives back the same item, byte for byte in its JSON, untitled
// (saving never writes over the picture); attractor-cli reads it too; an SVG carries it in its
// <metadata> and reopens the same way; a PNG from elsewhere is refused with a message.
void TestFigureExport::pngCarriesItsItemAndReopens()
{
    QTemporaryDir out;
    const QString png = out.filePath("fig2.png"), svg = out.filePath("fig2.svg");
    QString err;
    QVERIFY2(run({test::fig2File, "--item", test::fig2Curve, "--export-figure", png,
                  "--figure-size", "800x600"},
                 &err) == 0,
             qPrintable(err));
    QVERIFY2(run({test::fig2File, "--item", test::fig2Curve, "--export-figure", svg,
                  "--figure-size", "800x600"},
                 &err) == 0,
             qPrintable(err));
    QImageReader reader(png);
    QVERIFY(reader.text("Software").startsWith("Attractor Workbench "));
    QString error;
    QVERIFY(embeddedProject(png, &error).contains(test::fig2Curve.toUtf8()));

    Project original, reopened;
    QVERIFY(original.open(test::fig2File));
    QVERIFY2(reopened.open(png, &error), qPrintable(error));
    // The item (with the eigenvalue plot under it), nothing else of the project.
    QCOMPARE(reopened.items().size(), 2);
    QVERIFY(reopened.findItem(test::fig2Curve));
    QVERIFY(reopened.fileName().isEmpty());
    QVERIFY(reopened.isModified());
    QCOMPARE(ProjectIO::itemToJson(*reopened.findItem(test::fig2Curve)),
             ProjectIO::itemToJson(*original.findItem(test::fig2Curve)));

    // The CLI renders the item straight from the picture.
    QProcess cli;
    cli.start(qEnvironmentVariable("AWB_BIN_DIR", QCoreApplication::applicationDirPath() + "/../bin")
                  + "/attractor-cli",
              {"analyse", png, "--json"});
    QVERIFY(cli.waitForFinished(60000));
    QCOMPARE(cli.exitCode(), 0);
    QVERIFY(cli.readAllStandardOutput().contains(test::fig2Curve.toUtf8()));

    const QByteArray svgBytes = readAll(svg);
    QVERIFY(svgBytes.contains("<metadata id=\"attractor-workbench-project\">"));
    QVERIFY(svgBytes.contains(test::fig2Curve.toUtf8()));
    // The SVG reopens to the same item.
    Project fromSvg;
    QVERIFY2(fromSvg.open(svg, &error), qPrintable(error));
    QVERIFY(fromSvg.fileName().isEmpty());
    QCOMPARE(ProjectIO::itemToJson(*fromSvg.findItem(test::fig2Curve)),
             ProjectIO::itemToJson(*original.findItem(test::fig2Curve)));

    // A PNG without an item.
    QImage plain(8, 8, QImage::Format_RGB32);
    plain.fill(Qt::white);
    const QString other = out.filePath("other.png");
    QVERIFY(plain.save(other));
    Project none;
    QVERIFY(!none.open(other, &error));
    QVERIFY2(error.contains("holds no Attractor Workbench item"), qPrintable(error));
}

AWB_TEST_MAIN(TestFigureExport)
#include "test_figure_export.moc"
