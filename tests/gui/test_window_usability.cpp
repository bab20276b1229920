// The main window as a user meets it (issue 17): the wheel scrolls the Properties dock instead
// of changing values; Esc stops a drawing from any panel; the toolbar keeps its width while the
// undo text changes; at 1000 x 650 the attractor view gets most of the width and long notes are
// readable; points export as CSV and PLY; the map colours are chosen in a dialog (undoable);
// Help > User Guide shows the bundled guide.
#include "gui/app/ExampleGallery.h"
#include "gui/app/ItemController.h"
#include "gui/app/MainWindow.h"
#include "gui/app/Messages.h"
#include "gui/app/PaletteDialog.h"
#include "gui/app/PointExportDialog.h"
#include "gui/app/PropertiesDock.h"
#include "gui/app/StatusText.h"
#include "gui/app/UserGuideDialog.h"
#include "gui/views/AnalysisCharts.h"
#include "gui/views/AttractorView.h"
#include "gui/views/RegularityPanel.h"
#include "model/Project.h"
#include "model/SubdivisionCurveItem.h"
#include "model/SubdivisionSurfaceItem.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QComboBox>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QMenu>
#include <QMenuBar>
#include <QPushButton>
#include <QScrollArea>
#include <QScrollBar>
#include <QStackedWidget>
#include <QTextBrowser>
#include <QToolBar>
#include <QToolButton>
#include <QtTest>

#include "TestMain.h"

#include "TestTime.h"

#include "ImageCompare.h"
#include "WindowTestSupport.h"

using namespace awb;

namespace {

// A wheel turn of one notch over `w` at its centre, delivered as QApplication delivers the
// window system's: to the widget under the pointer, then to its parents while they ignore it.
// (QApplication::sendEvent alone does not propagate: the event is not spontaneous.)
void wheel(QWidget *w, int notches = -1)
{
    QPointF local = QRectF(w->rect()).center();
    for (QWidget *target = w; target; target = target->parentWidget()) {
        QWheelEvent e(local, target->mapToGlobal(local), QPoint(), QPoint(0, 120 * notches),
                      Qt::NoButton, Qt::NoModifier, Qt::NoScrollPhase, false);
        const bool handled = QApplication::sendEvent(target, &e);
        if ((handled && e.isAccepted()) || target->isWindow())
            break;
        local += target->pos();
    }
}

SubdivisionCurveItem *firstCurve(MainWindow &w)
{
    return qobject_cast<SubdivisionCurveItem *>(w.project()->child(0));
}

} // namespace

class TestWindowUsability : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void wheelScrollsInsteadOfEditing();
    void escapeStopsDrawingFromAnyPanel();
    void toolbarKeepsItsWidth();
    void smallWindowGivesTheViewMostOfTheWidth();
    void exportPointsCsvAndPly();
    void paletteIsUndoable();
    void userGuideShowsShortcutsAndExamples();
    void damagedRecoveryCopyIsKeptAside();
    void examplesOutputsAndShortcuts();
    void everyShortcutIsBoundOnce();

private:
    QTemporaryDir m_dir;
    QString m_recovery;
};

void TestWindowUsability::initTestCase()
{
    test::useTestSettings("test-window-usability");
    m_recovery = m_dir.path() + QStringLiteral("/recovery");
}

void TestWindowUsability::wheelScrollsInsteadOfEditing()
{
    test::ShownWindow shown(m_recovery, {1000, 650});
    QVERIFY(shown.exposed);
    MainWindow &w = shown.window;
    w.activateWindow();
    QVERIFY(QTest::qWaitForWindowActive(&w));
    auto *combo = qobject_cast<QComboBox *>(w.propertiesWidget()->editor("scheme.kind"));
    auto *depth = qobject_cast<QAbstractSpinBox *>(w.propertiesWidget()->editor("algorithm.depth"));
    QVERIFY(combo && depth);
    QCOMPARE(combo->focusPolicy(), Qt::StrongFocus);
    const int index = combo->currentIndex();
    const int steps = w.project()->undoStack()->count();
    auto *scroll = w.propertiesWidget()->findChild<QScrollArea *>();
    QVERIFY(scroll && scroll->verticalScrollBar()->maximum() > 0);
    const int scrolled = scroll->verticalScrollBar()->value();
    QVERIFY(!combo->hasFocus());
    wheel(combo);
    wheel(depth);
    QCOMPARE(combo->currentIndex(), index);
    QCOMPARE(w.project()->undoStack()->count(), steps);
    QVERIFY2(scroll->verticalScrollBar()->value() > scrolled, "the dock did not scroll");
    // A focused editor takes the wheel: that is an edit, with its undo step.
    combo->setFocus();
    QTRY_VERIFY(combo->hasFocus());
    wheel(combo, -1);
    QVERIFY(combo->currentIndex() != index);
    QCOMPARE(w.project()->undoStack()->count(), steps + 1);
}

void TestWindowUsability::escapeStopsDrawingFromAnyPanel()
{
    test::ShownWindow shown(m_recovery, {1300, 850});
    QVERIFY(shown.exposed);
    MainWindow &w = shown.window;
    w.activateWindow();
    QVERIFY(QTest::qWaitForWindowActive(&w));
    SubdivisionCurveItem *item = firstCurve(w);
    QVERIFY(test::waitForFinalImage(w.attractorView()));
    QAction *stop = w.action(QStringLiteral("actionStopRender"));
    QCOMPARE(stop->shortcut(), QKeySequence(Qt::Key_Escape));
    QVERIFY(!stop->isEnabled()); // Esc is free while nothing is drawn
    // 2^26 images: seconds of work.
    AlgorithmSpec a = item->algorithm();
    a.depth = 26;
    QVERIFY(item->setAlgorithm(a));
    QTRY_VERIFY_WITH_TIMEOUT(w.attractorView()->isRendering(), awb::test::ms(5000));
    QTRY_VERIFY(stop->isEnabled());
    // Esc from the Properties dock, where the focus is on an editor.
    auto *depth = w.propertiesWidget()->editor("algorithm.depth");
    depth->setFocus();
    QTRY_VERIFY(depth->hasFocus());
    QTest::keyClick(QApplication::focusWidget(), Qt::Key_Escape);
    QTRY_VERIFY_WITH_TIMEOUT(!w.attractorView()->isRendering(), awb::test::ms(5000));
    QVERIFY(!stop->isEnabled());
    // The View menu lists it with its key.
    bool listed = false;
    for (QAction *m : w.menuBar()->actions())
        if (m->menu() && m->menu()->actions().contains(stop))
            listed = true;
    QVERIFY(listed);
    a.depth = 8;
    QVERIFY(item->setAlgorithm(a));
    QVERIFY(test::waitForFinalImage(w.attractorView()));
}

void TestWindowUsability::toolbarKeepsItsWidth()
{
    test::ShownWindow shown(m_recovery, {1000, 650});
    QVERIFY(shown.exposed);
    MainWindow &w = shown.window;
    auto *bar = w.findChild<QToolBar *>(QStringLiteral("toolBarMain"));
    QAction *undo = w.action(QStringLiteral("actionUndo"));
    auto *button = qobject_cast<QToolButton *>(bar->widgetForAction(undo));
    QVERIFY(button);
    QCOMPARE(button->toolButtonStyle(), Qt::ToolButtonIconOnly);
    QVERIFY(!undo->icon().isNull());
    QVERIFY(bar->widgetForAction(w.action(QStringLiteral("actionFit")))->isVisible());
    const int width = button->sizeHint().width();
    const QRect fitBefore = bar->widgetForAction(w.action(QStringLiteral("actionFit")))->geometry();
    // An edit with a long text: the menu and the tooltip say what undo undoes, the toolbar
    // does not move.
    SubdivisionCurveItem *item = firstCurve(w);
    QVERIFY(item->moveControlPoint(2, {3.5, 2.75}));
    QVERIFY(undo->text().contains(item->name()));
    QVERIFY2(undo->toolTip().contains(w.project()->undoStack()->undoText()),
             qPrintable(undo->toolTip()));
    QCoreApplication::processEvents();
    QCOMPARE(button->sizeHint().width(), width);
    QCOMPARE(bar->widgetForAction(w.action(QStringLiteral("actionFit")))->geometry(), fitBefore);
    QVERIFY(bar->widgetForAction(w.action(QStringLiteral("actionFit")))->isVisible());
}

void TestWindowUsability::smallWindowGivesTheViewMostOfTheWidth()
{
    test::ShownWindow shown(m_recovery, {1000, 650});
    QVERIFY(shown.exposed);
    MainWindow &w = shown.window;
    QTRY_VERIFY2(w.centralWidget()->width() >= 500,
                 qPrintable(QStringLiteral("central view %1 px of %2")
                                .arg(w.centralWidget()->width()).arg(w.width())));
    QCOMPARE(w.width(), 1000);
    // A long note does not widen the window: elided in the status bar, whole in its tooltip
    // and in the Analysis panel.
    SubdivisionCurveItem *item = firstCurve(w);
    SchemeSpec s = item->scheme();
    s.kind = SchemeSpec::Kind::Bezier;
    s.degree = 7; // needs 8 points, the item has 5: a long reason
    QVERIFY(item->setScheme(s));
    w.controller()->refreshNow();
    QCoreApplication::processEvents();
    const QString problem = w.controller()->problem();
    QVERIFY(!problem.isEmpty());
    auto *label = w.findChild<QLabel *>(QStringLiteral("problemLabel"));
    QVERIFY(label);
    QCOMPARE(w.width(), 1000);
    QVERIFY(label->toolTip() == mathText(problem) || label->text() == mathText(problem));
    QCOMPARE(w.analysisCharts()->note(), problem);
    QVERIFY(w.centralWidget()->width() >= 500);
    // The status bar cuts at a word, never mid-word, and writes formulas as the papers do
    // (issue 47: "‖F^{k+1} − F^k‖ <= … Cauchy s…" for the dragon).
    const QString verdict = QStringLiteral(
        "convergent: every edge shrinks by a factor of at most 0.707107 per step, so "
        "||F^{k+1} - F^k|| <= 0.5 * 0.707107^k * (longest initial edge) and F^k is a Cauchy "
        "sequence (the argument of 001 Theorem 1)");
    const QString math = mathText(verdict);
    QVERIFY2(math.contains(QStringLiteral("‖Fᵏ⁺¹ − Fᵏ‖ ≤ 0.5 · 0.707107ᵏ")), qPrintable(math));
    const QFontMetrics fm(label->font());
    for (int width : {120, 300, 517, 800}) {
        const QString cut = elidedAtWord(fm, math, width);
        QVERIFY2(fm.horizontalAdvance(cut) <= width, qPrintable(cut));
        QVERIFY2(cut.endsWith(QStringLiteral(" …")), qPrintable(cut));
        const QString kept = cut.chopped(2);
        QVERIFY2(math.startsWith(kept), qPrintable(cut));
        QVERIFY2(!math.at(kept.size()).isLetterOrNumber(), qPrintable(cut));
    }
    QCOMPARE(elidedAtWord(fm, math, 100000), math);
}

void TestWindowUsability::exportPointsCsvAndPly()
{
    RecordingMessages messages;
    MainWindow w(&messages, m_recovery);
    SubdivisionCurveItem *item = firstCurve(w);
    QVERIFY(item->derivedIfs());
    // CSV: x, y, map, view; F^3 of a triangle with 2 maps = 8 images x 3 vertices.
    const QString csv = m_dir.path() + QStringLiteral("/points.csv");
    QString error;
    QVERIFY2(w.exportPoints(csv, 3, &error), qPrintable(error));
    QFile f(csv);
    QVERIFY(f.open(QIODevice::ReadOnly));
    const QList<QByteArray> lines = f.readAll().trimmed().split('\n');
    QCOMPARE(lines.front(), QByteArray("x,y,map,view"));
    QCOMPARE(lines.size(), 1 + 8 * 3);
    QCOMPARE(lines[1].split(',').size(), 4);
    // PLY of the same points: header and 8 * 3 binary vertices of 16 bytes.
    const QString ply = m_dir.path() + QStringLiteral("/points.ply");
    QVERIFY2(w.exportPoints(ply, 3, &error), qPrintable(error));
    QFile g(ply);
    QVERIFY(g.open(QIODevice::ReadOnly));
    const QByteArray bytes = g.readAll();
    QVERIFY(bytes.startsWith("ply\nformat binary_little_endian 1.0\n"));
    QVERIFY(bytes.contains("element vertex 24\n"));
    const qsizetype body = bytes.indexOf("end_header\n") + qsizetype(strlen("end_header\n"));
    QCOMPARE(bytes.size() - body, qsizetype(24 * 16));
    // Too many points are refused with a reason, and nothing is written.
    const QString big = m_dir.path() + QStringLiteral("/big.csv");
    QVERIFY(!w.exportPoints(big, 40, &error));
    QVERIFY2(error.contains(QStringLiteral("smaller depth")), qPrintable(error));
    QVERIFY(!QFile::exists(big));
    // The dialog counts the points of the chosen depth and follows the suffix.
    PointExportDialog dialog(item, csv);
    dialog.setDepth(3);
    QCOMPARE(dialog.pointCount(), 24.0);
    QCOMPARE(dialog.findChild<QComboBox *>()->currentIndex(), 0);
    dialog.setFileName(ply);
    QCOMPARE(dialog.findChild<QComboBox *>()->currentIndex(), 1);
    // A surface exports 3D points (x, y, z).
    auto surface = std::make_unique<SubdivisionSurfaceItem>();
    auto *raw = surface.get();
    w.project()->addItem(std::move(surface));
    w.setCurrentItem(raw);
    const QString csv3 = m_dir.path() + QStringLiteral("/surface.csv");
    QVERIFY2(w.exportPoints(csv3, 1, &error), qPrintable(error));
    QFile h(csv3);
    QVERIFY(h.open(QIODevice::ReadOnly));
    QCOMPARE(h.readLine(), QByteArray("x,y,z,map,view\n"));
    QVERIFY(w.action(QStringLiteral("actionExportPoints")));
}

void TestWindowUsability::paletteIsUndoable()
{
    test::ShownWindow shown(m_recovery);
    QVERIFY(shown.exposed);
    MainWindow &w = shown.window;
    SubdivisionCurveItem *item = firstCurve(w);
    QVERIFY(item->style().colors.isEmpty());
    auto *button = qobject_cast<QPushButton *>(w.propertiesWidget()->editor("style.colors"));
    QVERIFY(button);
    const int steps = w.project()->undoStack()->count();
    // The dialog is modal: answer it from the event loop.
    QTimer::singleShot(0, [] {
        auto *dialog = qobject_cast<PaletteDialog *>(QApplication::activeModalWidget());
        QVERIFY(dialog);
        QCOMPARE(dialog->mapCount(), 2);
        dialog->setColor(1, QColor(10, 200, 30));
        dialog->accept();
    });
    button->click();
    QCOMPARE(w.project()->undoStack()->count(), steps + 1);
    QCOMPARE(item->style().colors.size(), 2);
    QCOMPARE(item->style().colors[1], QStringLiteral("#0ac81e"));
    w.controller()->refreshNow();
    QCOMPARE(w.attractorView()->renderSettings().colouring.palette.value(1), QColor(10, 200, 30));
    w.project()->undoStack()->undo();
    QVERIFY(item->style().colors.isEmpty());
    // "Use the default colours" clears the item's own colours again.
    w.project()->undoStack()->redo();
    QTimer::singleShot(0, [] {
        auto *dialog = qobject_cast<PaletteDialog *>(QApplication::activeModalWidget());
        QVERIFY(dialog);
        dialog->useDefaults();
        dialog->accept();
    });
    button->click();
    QVERIFY(item->style().colors.isEmpty());
}

void TestWindowUsability::userGuideShowsShortcutsAndExamples()
{
    RecordingMessages messages;
    MainWindow w(&messages, m_recovery);
    QAction *guide = w.action(QStringLiteral("actionUserGuide"));
    QVERIFY(guide);
    QCOMPARE(guide->shortcut(), QKeySequence(QKeySequence::HelpContents));
    guide->trigger();
    auto *dialog = w.findChild<UserGuideDialog *>();
    QVERIFY(dialog);
    const QString text = dialog->browser()->toPlainText();
    QVERIFY2(text.contains(QStringLiteral("Keyboard shortcuts")), qPrintable(text.left(200)));
    QVERIFY(text.contains(QStringLiteral("Stop Drawing")));
    QVERIFY(text.contains(QKeySequence(Qt::Key_Escape).toString(QKeySequence::NativeText)));
    QVERIFY(text.contains(QStringLiteral("Export Points")));
    QVERIFY(text.contains(QStringLiteral("000-fig02")));
    QVERIFY(text.contains(QStringLiteral("004-fig3.9")));
    dialog->close();
    // The desktop adds the application's name: the title does not repeat it.
    QCOMPARE(dialog->windowTitle(), QStringLiteral("User Guide"));
}

// File > Open Example lists the papers' figures and opens a copy; outputs are proposed where
// they can be written, named after the project; Save As has its shortcut everywhere.
void TestWindowUsability::examplesOutputsAndShortcuts()
{
    RecordingMessages messages;
    MainWindow w(&messages, m_recovery);
    QCOMPARE(w.action(QStringLiteral("actionSaveAs"))->shortcut(),
             QKeySequence(QStringLiteral("Ctrl+Shift+S")));
    const QString examples = MainWindow::examplesDirectory();
    QVERIFY(QFileInfo::exists(examples + QStringLiteral("/000-fig02-cubic-bspline-from-point.awb")));
    auto *menu = w.findChild<QMenu *>(QStringLiteral("menuExamples"));
    QVERIFY(menu);
    QMetaObject::invokeMethod(menu, "aboutToShow");
    // The gallery first, then one submenu per paper (and meshes, the rest): no menu taller
    // than a screen (issue 47: 42 entries in one).
    QCOMPARE(menu->actions().first(), w.action(QStringLiteral("actionExampleGallery")));
    QList<QAction *> entries;
    for (QAction *a : menu->actions())
        if (a->menu()) {
            QVERIFY2(a->menu()->actions().size() <= 16,
                     qPrintable(a->text() + QString::number(a->menu()->actions().size())));
            entries += a->menu()->actions();
        }
    QVERIFY2(entries.size() >= 40, qPrintable(QString::number(entries.size())));
    bool found = false;
    for (QAction *a : entries)
        found = found || a->text().startsWith(QStringLiteral("000 Fig. 2: cubic B-spline"));
    QVERIFY(found);
    // The gallery: every example with its thumbnail (drawn in the background, as the CLI
    // renders), a filter, and Open opens a copy.
    {
        ExampleGallery gallery(examples, &w);
        gallery.show();
        QVERIFY2(gallery.list()->count() >= 40, qPrintable(QString::number(gallery.list()->count())));
        QTRY_VERIFY_WITH_TIMEOUT(gallery.thumbnailsReady() >= 3, test::ms(60000));
        // The first example's thumbnail is in the cache: its figure, without its caption.
        const QImage thumb(ExampleGallery::thumbnailFile(
            gallery.list()->item(0)->data(Qt::UserRole).toString()));
        QCOMPARE(thumb.size(), QSize(240, 180));
        QVERIFY2(test::drawnPixels(thumb) > 300, qPrintable(QString::number(test::drawnPixels(thumb))));
        gallery.filter()->setText(QStringLiteral("koch 000"));
        int shown = 0;
        for (int row = 0; row < gallery.list()->count(); ++row)
            shown += gallery.list()->item(row)->isHidden() ? 0 : 1;
        QCOMPARE(shown, 1);
        for (int row = 0; row < gallery.list()->count(); ++row)
            if (!gallery.list()->item(row)->isHidden())
                gallery.list()->setCurrentRow(row);
        gallery.accept();
        QCOMPARE(gallery.result(), int(QDialog::Accepted));
        QVERIFY2(gallery.chosenFile().endsWith(QStringLiteral("000-fig10-koch-with-control-points.awb")),
                 qPrintable(gallery.chosenFile()));
    }
    // An example opens as a copy: no file name, not modified; saving asks where.
    QVERIFY(w.openExample(examples + QStringLiteral("/000-fig11-sierpinski-with-control-points.awb")));
    QCOMPARE(w.project()->fileName(), QString());
    QVERIFY(!w.project()->isModified());
    QVERIFY(w.project()->childCount() >= 2);
    // Outputs of a project without a file go to the documents, named after the item.
    const QString documents = QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation);
    const QString pdf = w.outputPath(QStringLiteral("pdf"));
    QVERIFY2(pdf.startsWith(documents) && pdf.endsWith(QStringLiteral(".pdf")), qPrintable(pdf));
    QVERIFY2(pdf.contains(QStringLiteral("Sierpinski")), qPrintable(pdf));
    // A project in a folder that cannot be written to (an installed example): the same.
    QTemporaryDir dir;
    const QString readOnly = dir.filePath(QStringLiteral("ro"));
    QVERIFY(QDir().mkpath(readOnly));
    const QString copy = readOnly + QStringLiteral("/fig11.awb");
    QVERIFY(QFile::copy(examples + QStringLiteral("/000-fig11-sierpinski-with-control-points.awb"), copy));
    QVERIFY(w.openFile(copy));
    QVERIFY(QFile::setPermissions(readOnly, QFileDevice::ReadOwner | QFileDevice::ExeOwner));
    if (!QFileInfo(readOnly).isWritable()) // root writes anywhere: nothing to test then
        QVERIFY2(w.outputPath(QStringLiteral("png")).startsWith(documents),
                 qPrintable(w.outputPath(QStringLiteral("png"))));
    QFile::setPermissions(readOnly, QFileDevice::ReadOwner | QFileDevice::WriteOwner
                                        | QFileDevice::ExeOwner);
    // A writable project folder: beside the project, "<project>-<item>.png".
    const QString png = w.outputPath(QStringLiteral("png"));
    QVERIFY2(png.startsWith(readOnly + QStringLiteral("/fig11-")), qPrintable(png));
    // An example opened with File > Open from the gallery's folder (writable in a source
    // tree): its figures go to the documents, not among the examples (issue 47).
    QVERIFY(w.openFile(examples + QStringLiteral("/000-fig11-sierpinski-with-control-points.awb")));
    const QString inDocuments = w.outputPath(QStringLiteral("png"));
    QVERIFY2(inDocuments.startsWith(documents), qPrintable(inDocuments));
}

// No key is bound to two actions of the window: Qt then triggers neither ("Ambiguous shortcut
// overload", issue 47: Ctrl+Shift+P was Print Preview's and the Python Console's). The console's
// key is the one the README and docs/python.md give.
void TestWindowUsability::everyShortcutIsBoundOnce()
{
    test::ShownWindow shown(m_recovery);
    QHash<QString, QString> owner;
    QStringList clashes;
    for (QAction *a : shown.window.findChildren<QAction *>()) {
        for (const QKeySequence &key : a->shortcuts()) {
            const QString k = key.toString(QKeySequence::PortableText);
            const QString name = a->objectName().isEmpty() ? a->text() : a->objectName();
            if (owner.contains(k) && owner.value(k) != name)
                clashes << k + QStringLiteral(": ") + owner.value(k) + QStringLiteral(", ") + name;
            owner.insert(k, name);
        }
    }
    QVERIFY2(clashes.isEmpty(), qPrintable(clashes.join(QStringLiteral("; "))));
    QAction *console = shown.window.action(QStringLiteral("actionPythonConsole"));
    QVERIFY(console);
    QCOMPARE(console->shortcut(), QKeySequence(QStringLiteral("Ctrl+Shift+P")));
    auto *dock = shown.window.findChild<QDockWidget *>(QStringLiteral("dockPython"));
    QVERIFY(dock);
    QVERIFY(!dock->isVisible());
    QTest::keyClick(&shown.window, Qt::Key_P, Qt::ControlModifier | Qt::ShiftModifier);
    QTRY_VERIFY(dock->isVisible());
}

// A crashed session left a recovery copy that is itself damaged: the next start offers it,
// cannot read it, says so, and keeps it in recovery/damaged (never deleted, not offered again).
void TestWindowUsability::damagedRecoveryCopyIsKeptAside()
{
    QTemporaryDir recovery;
    const QString damaged = recovery.filePath("1234-cut-off.awb-recovery");
    {
        QFile f(damaged);
        QVERIFY(f.open(QIODevice::WriteOnly));
        // Not a raw string: moc miscounts the braces of an unbalanced one.
        f.write("{\"format\": \"attractor-workbench-recovery\", \"version\": 1, \"project\": {\"form");
    }
    {
        test::ShownWindow shown(recovery.path());
        shown.messages.answer = QMessageBox::Yes;
        QVERIFY(!shown.window.offerRecovery());
        QCOMPARE(shown.messages.questions.size(), 1);
        QCOMPARE(shown.messages.errors.size(), 1);
        const QString error = shown.messages.errors.first();
        QVERIFY2(error.contains("cannot be read") && error.contains("not valid JSON")
                     && error.contains("It was kept as") && error.contains("damaged"),
                 qPrintable(error));
    }
    QVERIFY(!QFile::exists(damaged));
    const QStringList kept = QDir(recovery.filePath("damaged")).entryList(QDir::Files);
    QCOMPARE(kept.size(), 1);
    test::ShownWindow again(recovery.path());
    again.messages.answer = QMessageBox::Yes;
    QVERIFY(!again.window.offerRecovery());
    QVERIFY(again.messages.questions.isEmpty());
}

AWB_TEST_MAIN(TestWindowUsability)
#include "test_window_usability.moc"
