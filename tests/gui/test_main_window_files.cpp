// The main window's files end to end: the figure sheet prints to PDF (a cancelled print writes
// nothing), SVG export keeps the control polygon as vector paths, a corrupt file is reported
// without touching the open project, unsaved changes are asked about, the title shows the
// file, and a recovery file is offered.
#include "MainWindowTests.h"
#include "TestMain.h"

using namespace awb;
using namespace awb::test;

class TestMainWindowFiles : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void printToPdf();
    void cancelledPrintWritesNothing();
    void svgExportHasControlPolygon();
    void corruptFileIsReported();
    void unsavedChangesPrompt();
    void titleShowsFileAndModified();
    void recoveryIsOffered();

private:
    QTemporaryDir m_dir;
    QString m_file;
};

void TestMainWindowFiles::initTestCase()
{
    QStandardPaths::setTestModeEnabled(true);
    QCoreApplication::setOrganizationName(QStringLiteral("awb-test"));
    QCoreApplication::setApplicationName(QStringLiteral("test-main-window-files"));
    QVERIFY(m_dir.isValid());
    // To look at the printed sheet and the exports after a run.
    if (qEnvironmentVariableIsSet("AWB_KEEP_TEST_FILES")) {
        m_dir.setAutoRemove(false);
        qInfo() << "test files in" << m_dir.path();
    }
    m_file = writeTestProject(m_dir.path());
    QVERIFY(QFile::exists(m_file));
}

void TestMainWindowFiles::printToPdf()
{
    RecordingMessages messages;
    MainWindow w(&messages, m_dir.path() + QStringLiteral("/recovery"));
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    QVERIFY(w.openFile(m_file));
    QVERIFY(waitForFinalImage(w.attractorView()));
    const QString pdf = m_dir.path() + QStringLiteral("/sheet.pdf");
    QString error;
    QVERIFY2(w.printToPdf(pdf, &error), qPrintable(error));
    QFile f(pdf);
    QVERIFY(f.open(QIODevice::ReadOnly));
    const QByteArray bytes = f.readAll();
    QVERIFY(bytes.startsWith("%PDF"));
    QCOMPARE(bytes.count("/Type /Page\n") + bytes.count("/Type /Page\r")
                 + bytes.count("/Type /Page "), 1);
    QVERIFY(bytes.size() > 5000);  // the figure, not an empty page
}

void TestMainWindowFiles::cancelledPrintWritesNothing()
{
    RecordingMessages messages;
    MainWindow w(&messages, m_dir.path() + QStringLiteral("/recovery"));
    w.resize(1300, 850);
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    QVERIFY(w.openFile(m_file));
    auto *item = qobject_cast<SubdivisionCurveItem *>(w.project()->findItem("B-spline"));
    w.setCurrentItem(item);
    QVERIFY(waitForFinalImage(w.attractorView()));
    // Zoomed far in, the screen's raster does not cover the page's fitted framing: the sheet
    // draws its own, 2^30 images deep, which takes seconds and shows a progress dialog.
    AlgorithmSpec a = item->algorithm();
    a.depth = 30;
    QVERIFY(item->setAlgorithm(a));
    w.controller()->refreshNow();
    QCOMPARE(w.attractorView()->renderSettings().depth, 30);
    w.attractorView()->setView(QPointF(3, 2), w.attractorView()->pixelsPerUnit() * 20);
    w.attractorView()->cancelRender();
    bool sawDialog = false;
    QTimer::singleShot(900, &w, [&] {
        if (auto *d = w.findChild<QProgressDialog *>(QStringLiteral("exportProgress"))) {
            sawDialog = d->isVisible();
            d->cancel();
        }
    });
    const QString pdf = m_dir.path() + QStringLiteral("/cancelled.pdf");
    QString error;
    QElapsedTimer timer;
    timer.start();
    QVERIFY(!w.printToPdf(pdf, &error));
    QVERIFY2(error.contains(QStringLiteral("cancelled")), qPrintable(error));
    QVERIFY(sawDialog);
    QVERIFY(!QFile::exists(pdf));
    QVERIFY(!w.findChild<QProgressDialog *>(QStringLiteral("exportProgress")));
    qInfo("cancelled after %lld ms", timer.elapsed());
    // A shallow item prints again (the cancel does not stick).
    a.depth = 9;
    QVERIFY(item->setAlgorithm(a));
    w.controller()->refreshNow();
    QVERIFY2(w.printToPdf(pdf, &error), qPrintable(error));
    QVERIFY(QFile::exists(pdf));
}

void TestMainWindowFiles::svgExportHasControlPolygon()
{
    RecordingMessages messages;
    MainWindow w(&messages, m_dir.path() + QStringLiteral("/recovery"));
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    QVERIFY(w.openFile(m_file));
    QVERIFY(waitForFinalImage(w.attractorView()));
    ExportDialog::Options o;
    o.target = ExportDialog::Target::Attractor;
    o.fileName = m_dir.path() + QStringLiteral("/attractor.svg");
    o.size = QSize(800, 600);
    o.dpi = 96;
    QString error;
    QVERIFY2(w.exportView(o, &error), qPrintable(error));
    QFile f(o.fileName);
    QVERIFY(f.open(QIODevice::ReadOnly));
    const QString svg = QString::fromUtf8(f.readAll());
    // The control polygon: one vector element (polyline or path) through its five vertices,
    // where the export maps them (the screen's world rectangle fitted into 800 x 600).
    AttractorView *view = w.attractorView();
    const QRectF vis = view->visibleWorldRect();
    const double k = std::min(800 / vis.width(), 600 / vis.height());
    const QPointF c = view->viewCenter();
    QList<QPointF> expected;
    for (int i = 0; i < view->controlPointCount(); ++i) {
        const QPointF p = view->controlPointPosition(i);
        expected << QPointF(400 + (p.x() - c.x()) * k, 300 - (p.y() - c.y()) * k);
    }
    QCOMPARE(expected.size(), 5);
    static const QRegularExpression elementRe(
        QStringLiteral("<(?:polyline[^>]*points|path[^>]*\\bd)=\"([^\"]*)\""));
    static const QRegularExpression numberRe(QStringLiteral("-?[0-9.]+(?:e-?[0-9]+)?"));
    bool found = false;
    for (auto it = elementRe.globalMatch(svg); it.hasNext() && !found;) {
        QList<double> numbers;
        for (auto n = numberRe.globalMatch(it.next().captured(1)); n.hasNext();)
            numbers << n.next().captured().toDouble();
        int hits = 0;
        for (const QPointF &e : expected)
            for (int i = 0; i + 1 < numbers.size(); i += 2)
                if (QLineF(e, QPointF(numbers[i], numbers[i + 1])).length() < 1.0) {
                    ++hits;
                    break;
                }
        found = hits == expected.size();
    }
    QVERIFY2(found, "no vector path through the control points");

    // PNG at a chosen size and DPI.
    o.fileName = m_dir.path() + QStringLiteral("/spectrum.png");
    o.target = ExportDialog::Target::Spectrum;
    o.dpi = 200;
    QVERIFY2(w.exportView(o, &error), qPrintable(error));
    QImage png(o.fileName);
    QCOMPARE(png.size(), QSize(800, 600));
    QCOMPARE(qRound(png.dotsPerMeterX() * 0.0254), 200);

    // The analysis charts, computed off the GUI thread, export like any view.
    QTRY_VERIFY_WITH_TIMEOUT(!w.controller()->analysisRunning(), awb::test::ms(30000));
    QTest::qWait(300);
    QTRY_VERIFY_WITH_TIMEOUT(!w.controller()->analysisRunning(), awb::test::ms(30000));
    o.fileName = m_dir.path() + QStringLiteral("/analysis.png");
    o.target = ExportDialog::Target::Analysis;
    QVERIFY2(w.exportView(o, &error), qPrintable(error));
    o.fileName = m_dir.path() + QStringLiteral("/sheet.png");
    o.target = ExportDialog::Target::FigureSheet;
    o.size = QSize(1400, 1000);
    QVERIFY2(w.exportView(o, &error), qPrintable(error));
    QImage sheet(o.fileName);
    QCOMPARE(sheet.size(), QSize(1400, 1000));
    // The caption is at the top left, the figure below: both leave ink.
    int dark = 0;
    for (int y = 0; y < 60; ++y)
        for (int x = 0; x < 400; ++x)
            dark += qGray(sheet.pixel(x, y)) < 128;
    QVERIFY(dark > 50);
}

void TestMainWindowFiles::corruptFileIsReported()
{
    RecordingMessages messages;
    MainWindow w(&messages, m_dir.path() + QStringLiteral("/recovery"));
    QVERIFY(w.openFile(m_file));
    const QByteArray before = w.project()->serialize();
    const QString bad = m_dir.path() + QStringLiteral("/corrupt.awb");
    QFile f(bad);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write("{\"format\": \"attractor-workbench\", \"version\": 1, \"items\": [{\"type\": ");
    f.close();
    QString loaderMessage;
    {
        Project probe;
        QVERIFY(!probe.open(bad, &loaderMessage));
    }
    QVERIFY(!w.openFile(bad));
    QCOMPARE(messages.errors.size(), 1);
    QVERIFY(messages.errors.first().contains(loaderMessage));
    QCOMPARE(w.project()->serialize(), before);
    QCOMPARE(w.project()->fileName(), m_file);
}

void TestMainWindowFiles::unsavedChangesPrompt()
{
    RecordingMessages messages;
    MainWindow w(&messages, m_dir.path() + QStringLiteral("/recovery"));
    auto *item = qobject_cast<AttractorItem *>(w.currentItem());
    QVERIFY(item);
    QVERIFY(item->moveControlPoint(0, {0.5, 0.5}));
    QVERIFY(w.project()->isModified());
    messages.answer = QMessageBox::Cancel;
    w.action(QStringLiteral("actionNew"))->trigger();
    QCOMPARE(messages.questions.size(), 1);
    QCOMPARE(item->controlPoints(0)[0], (Point{0.5, 0.5}));  // cancelled: still there
    messages.answer = QMessageBox::Discard;
    w.action(QStringLiteral("actionNew"))->trigger();
    QCOMPARE(messages.questions.size(), 2);
    QVERIFY(!w.project()->isModified());
    QCOMPARE(w.project()->childCount(), 1);
}

void TestMainWindowFiles::titleShowsFileAndModified()
{
    RecordingMessages messages;
    MainWindow w(&messages, m_dir.path() + QStringLiteral("/recovery"));
    QVERIFY(w.openFile(m_file));
    QVERIFY(w.windowTitle().contains(QStringLiteral("test.awb")));
    QVERIFY(!w.isWindowModified());
    auto *item = qobject_cast<AttractorItem *>(w.project()->child(0));
    QVERIFY(item->moveControlPoint(0, {0.25, 0.0}));
    QVERIFY(w.isWindowModified());
    w.project()->undoStack()->undo();
    QVERIFY(!w.isWindowModified());
}

void TestMainWindowFiles::recoveryIsOffered()
{
    const QString dir = m_dir.path() + QStringLiteral("/recovery-offer");
    QString crashed;
    QByteArray edited;
    {
        // A session with an unsaved edit writes its recovery file; copying it under another
        // name leaves a file whose process (lock) is gone, as after a crash.
        Project project;
        Recovery recovery(&project, dir);
        QVERIFY(project.open(m_file));
        auto *item = qobject_cast<AttractorItem *>(project.child(0));
        QVERIFY(item->moveControlPoint(0, {-1.0, 0.5}));
        QVERIFY(recovery.autosave());
        const QFileInfo info(recovery.filePath());
        crashed = info.path() + QStringLiteral("/crashed-") + info.fileName();
        QVERIFY(QFile::copy(recovery.filePath(), crashed));
        edited = project.serialize();
    }
    RecordingMessages messages;
    messages.answer = QMessageBox::Yes;
    MainWindow w(&messages, dir);
    QVERIFY(w.offerRecovery());
    QCOMPARE(messages.questions.size(), 1);
    QVERIFY(messages.questions.first().contains(QStringLiteral("test.awb")));
    QCOMPARE(w.project()->serialize(), edited);
    QVERIFY(w.project()->isModified());
    QCOMPARE(w.project()->fileName(), m_file);
    QVERIFY(w.isWindowModified());
    QVERIFY(!QFile::exists(crashed));  // recovered: the copy is gone
    QVERIFY(!w.offerRecovery());
}


AWB_TEST_MAIN(TestMainWindowFiles)
#include "test_main_window_files.moc"
