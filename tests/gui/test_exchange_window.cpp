// Other tools' files in the window (issue 34): File > Import adds every entry of a Fractint
// .ifs file in one undo step and says which entries were left out (line and column); File >
// Export Item As writes the current item as a Fractint entry or its matrices as MATLAB cell
// arrays, and refuses an item whose IFS is not one of the plane or of space, by name.
#include "gui/app/ItemController.h"
#include "gui/app/MainWindow.h"
#include "gui/app/Dialogs.h"
#include "gui/views/AttractorView.h"
#include "gui/views/SpectrumView.h"
#include "render/DensityFile.h"
#include "gui/app/Messages.h"
#include "model/FlameItem.h"
#include "model/FractalItem.h"
#include "model/Project.h"

#include <QAction>
#include <QDragEnterEvent>
#include <QDropEvent>
#include <QMimeData>
#include <QUrl>
#include <QFile>
#include <QTemporaryDir>
#include <QtTest>

#include "TestFiles.h"
#include "TestMain.h"

using namespace awb;

class TestExchangeWindow : public QObject {
    Q_OBJECT
private slots:
    void importIsOneUndoStep();
    void exportItemAs();
    void flamesInAndOut();
    void openMakesAnUntitledProject();
    void rawDensityOfTheView();
    void droppedFiles();

private:
    QString write(const QString &name, const QByteArray &text)
    {
        return awb::test::writeFile(m_dir, name, text);
    }
    QTemporaryDir m_dir;
};

void TestExchangeWindow::importIsOneUndoStep()
{
    RecordingMessages messages;
    MainWindow w(&messages, m_dir.filePath("recovery"));
    const int before = w.project()->childCount();
    const QString file = write("two.ifs", "; two entries and a typo\n"
                                          "half { .5 0 0 .5 0 0 .5  .5 0 0 .5 .5 .5 .5 }\n"
                                          "space (3D) { .5 0 0 0 .5 0 0 0 .5 0 0 0 1 }\n"
                                          "typo { .5 0 0 .5 0 }\n");
    QStringList problems;
    QString error;
    QVERIFY2(w.importIfs(file, &problems, &error), qPrintable(error));
    QCOMPARE(w.project()->childCount(), before + 2);
    QCOMPARE(problems.size(), 1);
    QVERIFY2(problems[0].startsWith("two.ifs, line 4, column 8: entry typo"),
             qPrintable(problems[0]));
    auto *half = qobject_cast<FractalItem *>(w.project()->findItem("half"));
    auto *space = qobject_cast<FractalItem *>(w.project()->findItem("space"));
    QVERIFY(half && space);
    QCOMPARE(half->pointDimension(), 2);
    QCOMPARE(space->pointDimension(), 3);
    QCOMPARE(half->algorithm().mode, AlgorithmSpec::Mode::Random);
    QCOMPARE(w.currentItem(), half);
    w.project()->undoStack()->undo();
    QCOMPARE(w.project()->childCount(), before);
    // Nothing to import: the reason, nothing added.
    QVERIFY(!w.importIfs(write("bad.ifs", "typo { .5 0 0 .5 0 }\n"), &problems, &error));
    QVERIFY2(error.contains("no entry could be imported"), qPrintable(error));
    QCOMPARE(w.project()->childCount(), before);
    QVERIFY(w.findChild<QAction *>("actionImport"));
    QVERIFY(w.findChild<QAction *>("actionExportItemAs"));
}

void TestExchangeWindow::exportItemAs()
{
    RecordingMessages messages;
    MainWindow w(&messages, m_dir.filePath("recovery"));
    QString error;
    QVERIFY(w.importIfs(write("half.ifs", "half { .5 0 0 .5 0 0 .5  .5 0 0 .5 .5 .5 .5 }\n"),
                        nullptr, &error));
    const QString ifs = m_dir.filePath("out.ifs");
    QVERIFY2(w.exportItemAs(ifs, &error), qPrintable(error));
    QFile f(ifs);
    QVERIFY(f.open(QIODevice::ReadOnly));
    const QByteArray text = f.readAll();
    QVERIFY2(text.startsWith("half {\n  0.5 0 0 0.5 0 0  0.5\n  0.5 0 0 0.5 0.5 0.5  0.5\n}"),
             text.constData());
    const QString m = m_dir.filePath("out.m");
    QVERIFY2(w.exportItemAs(m, &error), qPrintable(error));
    QFile mf(m);
    QVERIFY(mf.open(QIODevice::ReadOnly));
    QVERIFY(mf.readAll().contains("S = {["));
    QVERIFY(!w.exportItemAs(m_dir.filePath("out.txt"), &error));
    QVERIFY2(error.contains(".ifs (Fractint), .flame (flam3) or .m (MATLAB)"), qPrintable(error));
    // The cubic B-spline of a new project acts in the lifted space of 000 §2.
    w.newProject();
    QVERIFY(!w.exportItemAs(ifs, &error));
    QVERIFY2(error.contains("drawn through a projection"), qPrintable(error));
}

void TestExchangeWindow::flamesInAndOut()
{
    // Two flames, one undo step: an affine one becomes a fractal, one with a non-linear
    // variation (julia) a flame item; what flam3 does not draw (JWildfire's spherical3D) is
    // named for the window to show.
    RecordingMessages messages;
    MainWindow w(&messages, m_dir.filePath("recovery"));
    w.resize(900, 700);
    const int before = w.project()->childCount();
    const QString file =
        write("two.flame", "<flames>\n"
                           "<flame name=\"halves\"><xform weight=\"1\" linear=\"1\" "
                           "coefs=\"0.5 0 0 0.5 0 0\"/>\n"
                           "<xform weight=\"1\" linear=\"1\" julia=\"0.2\" "
                           "spherical3D=\"0.1\" coefs=\"0.5 0 0 0.5 0.5 0.5\"/></flame>\n"
                           "<flame name=\"thirds\"><xform weight=\"1\" linear=\"1\" "
                           "coefs=\"0.3 0 0 0.3 0 0\"/><xform weight=\"2\" linear=\"1\" "
                           "coefs=\"0.3 0 0 0.3 0.7 0\"/></flame>\n</flames>\n");
    QStringList problems, warnings;
    QString error;
    QVERIFY2(w.importIfs(file, &problems, &error, &warnings), qPrintable(error));
    QVERIFY(problems.isEmpty());
    QCOMPARE(warnings.size(), 1);
    QVERIFY2(warnings[0].startsWith("two.flame, line 3, column ")
                 && warnings[0].contains("flame 'halves': xform 2: attributes flam3 does not "
                                         "draw, ignored: spherical3D"),
             qPrintable(warnings[0]));
    QCOMPARE(w.project()->childCount(), before + 2);
    auto *halves = qobject_cast<FlameItem *>(w.project()->findItem("halves"));
    QVERIFY(halves);
    QCOMPARE(halves->flame().xforms[1].variations.size(), std::size_t(2));  // linear, julia
    // The window draws it by its own chaos game, without a problem to report.
    w.setCurrentItem(halves);
    w.controller()->refreshNow();
    QVERIFY(QTest::qWaitFor([&] { return !w.attractorView()->isRendering(); }, 20000));
    QVERIFY2(w.attractorView()->lastError().isEmpty(), qPrintable(w.attractorView()->lastError()));
    auto *thirds = qobject_cast<FractalItem *>(w.project()->findItem("thirds"));
    QVERIFY(thirds);
    QCOMPARE(thirds->algorithm().probabilities, (std::vector<double>{1.0, 2.0}));
    w.project()->undoStack()->undo();
    QCOMPARE(w.project()->childCount(), before);
    w.project()->undoStack()->redo();

    // Out again, framed as the view shows the current item.
    w.setCurrentItem(w.project()->findItem("thirds"));
    const QString out = m_dir.filePath("thirds.flame");
    QVERIFY2(w.exportItemAs(out, &error), qPrintable(error));
    QFile f(out);
    QVERIFY(f.open(QIODevice::ReadOnly));
    const QByteArray text = f.readAll();
    QVERIFY2(text.contains("coefs=\"0.3 0 0 0.3 0.7 0\"") && text.contains("weight=\"2\""),
             text.constData());
    QVERIFY(text.contains("<color index=\"255\""));
    // A flame item out as itself, every field (issue 47's trial: the window refused it,
    // naming the flam3 flame it was asked to write).
    w.setCurrentItem(w.project()->findItem("halves"));
    const QString halvesOut = m_dir.filePath("halves.flame");
    QVERIFY2(w.exportItemAs(halvesOut, &error), qPrintable(error));
    QFile h(halvesOut);
    QVERIFY(h.open(QIODevice::ReadOnly));
    const QByteArray flameText = h.readAll();
    QVERIFY2(flameText.contains("julia=") && flameText.contains("name=\"halves\""),
             flameText.constData());
    // Its Spectrum panel speaks of the xforms' affine parts and of the game's own orbit, not
    // of an IFS of those parts.
    w.controller()->refreshNow();
    const QString flameVerdict = w.spectrumView()->verdictText();
    QVERIFY2(flameVerdict.contains("Lyapunov exponent of its chaos game")
                 && flameVerdict.contains("affine (pre) maps")
                 && !flameVerdict.contains("unique attractor"),
             qPrintable(flameVerdict));

    // A flame with flam3's symmetry: a reflection (spectral radius 1) among its maps. The
    // Spectrum panel says that the IFS contracts on average instead of refusing it.
    QVERIFY2(w.importIfs(write("sym.flame", "<flame name=\"sym\"><symmetry kind=\"-2\"/>"
                                           "<xform weight=\"1\" linear=\"1\" "
                                           "coefs=\"0.5 0 0 0.5 0.5 0\"/></flame>\n"),
                        &problems, &error, &warnings),
            qPrintable(error));
    QVERIFY(warnings.isEmpty());
    w.setCurrentItem(w.project()->findItem("sym"));
    w.controller()->refreshNow();
    const QString verdict = w.spectrumView()->verdictText();
    QVERIFY2(verdict.contains("but the IFS contracts on average"), qPrintable(verdict));
}

void TestExchangeWindow::openMakesAnUntitledProject()
{
    // File > Open of a flame (or a Fractint library, or one given on the command line): an
    // untitled, modified project of its entries; a file without one changes nothing.
    RecordingMessages messages;
    MainWindow w(&messages, m_dir.filePath("recovery"));
    const QString bad = write("none.flame", "<flames></flames>\n");
    const int before = w.project()->childCount();
    QVERIFY(!w.openFile(bad));
    QCOMPARE(w.project()->childCount(), before);
    QVERIFY2(!messages.errors.isEmpty() && messages.errors[0].contains("no <flame>"),
             qPrintable(messages.errors.join("; ")));
    const QString file =
        write("one.flame", "<flame name=\"one\"><xform weight=\"1\" linear=\"1\" "
                           "coefs=\"0.5 0 0 0.5 0 0\"/><xform weight=\"1\" linear=\"1\" "
                           "coefs=\"0.5 0 0 0.5 0.5 0\"/></flame>\n");
    QVERIFY(w.openFile(file));
    QCOMPARE(w.project()->childCount(), 1);
    QVERIFY(w.project()->findItem("one"));
    QVERIFY(w.project()->fileName().isEmpty());
    QVERIFY(w.project()->isModified());
}

void TestExchangeWindow::rawDensityOfTheView()
{
    // File > Export Figure to .exr: the view's attractor as float32 hits per pixel. The
    // Sierpinski triangle by random iteration, fitted in the view: every sample is counted.
    RecordingMessages messages;
    MainWindow w(&messages, m_dir.filePath("recovery"));
    w.resize(1000, 700);
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    QString error;
    QVERIFY(w.importIfs(write("tri.ifs", "tri { .5 0 0 .5 0 0 1  .5 0 0 .5 1 0 1  "
                                         ".5 0 0 .5 .5 1 1 }\n"),
                        nullptr, &error));
    w.controller()->refreshNow();
    w.attractorView()->fitToContents();
    ExportDialog::Options o;
    o.target = ExportDialog::Target::Attractor;
    o.fileName = m_dir.filePath("tri.exr");
    o.size = QSize(300, 200);
    QVERIFY2(w.exportView(o, &error), qPrintable(error));
    QRectF world;
    const AttractorDensity d = readDensityExr(o.fileName, &world, &error);
    QVERIFY2(error.isEmpty(), qPrintable(error));
    QCOMPARE(d.frame.width, 300);
    QCOMPARE(d.frame.height, 200);
    double total = 0;
    for (std::size_t i = 3; i < d.rgba.size(); i += 4)
        total += d.rgba[i];
    const double samples = double(qobject_cast<AttractorItem *>(w.currentItem())
                                      ->algorithm().samples);
    QVERIFY2(total > 0.999 * samples && total <= samples,
             qPrintable(QStringLiteral("%1 of %2").arg(total).arg(samples)));
    // Proportions of the export, one scale on both axes.
    QVERIFY(std::abs(world.width() / world.height() - 1.5) < 1e-9);
    // The Spectrum is not an attractor.
    o.target = ExportDialog::Target::Spectrum;
    QVERIFY(!w.exportView(o, &error));
    QVERIFY2(error.contains("raw density of an attractor"), qPrintable(error));
}

void TestExchangeWindow::droppedFiles()
{
    // A flame and a Fractint library dropped on the window are imported into the project (one
    // undo step each); a file of another kind is not accepted.
    RecordingMessages messages;
    MainWindow w(&messages, m_dir.filePath("recovery"));
    QVERIFY(w.acceptDrops());
    const int before = w.project()->childCount();
    QMimeData mime;
    mime.setUrls({QUrl::fromLocalFile(write("d.flame", "<flame name=\"d\"><xform weight=\"1\" "
                                                       "linear=\"1\" coefs=\"0.5 0 0 0.5 0 0\"/>"
                                                       "<xform weight=\"1\" linear=\"1\" "
                                                       "coefs=\"0.5 0 0 0.5 1 0\"/></flame>\n")),
                  QUrl::fromLocalFile(write("e.ifs", "e { .5 0 0 .5 0 0 1  .5 0 0 .5 1 1 1 }\n"))});
    QDragEnterEvent enter(QPoint(10, 10), Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
    enter.setAccepted(false);
    QCoreApplication::sendEvent(&w, &enter);
    QVERIFY(enter.isAccepted());
    QDropEvent drop(QPointF(10, 10), Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
    QCoreApplication::sendEvent(&w, &drop);
    QCOMPARE(w.project()->childCount(), before + 2);
    QVERIFY(w.project()->findItem("d") && w.project()->findItem("e"));
    QMimeData text;
    text.setUrls({QUrl::fromLocalFile(write("notes.txt", "hello\n"))});
    QDragEnterEvent other(QPoint(10, 10), Qt::CopyAction, &text, Qt::LeftButton, Qt::NoModifier);
    other.setAccepted(false);
    QCoreApplication::sendEvent(&w, &other);
    QVERIFY(!other.isAccepted());
}

AWB_TEST_MAIN(TestExchangeWindow)
#include "test_exchange_window.moc"
