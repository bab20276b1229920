// The main window end to end: opening projects fills every view, a mouse drag of a control
// point is one undo step that undo reverts pixel for pixel, properties edits are undoable and
// reach every view. Printing, export and files: test_main_window_files.cpp.
#include "TestPaths.h"
#include "MainWindowTests.h"
#include "TestMain.h"

using namespace awb;

using namespace awb::test;

class TestMainWindow : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void startsWithOneCurve();
    void openingFillsEveryView();
    void dragIsOneUndoStep();
    void everyPointSetIsShownAndDraggable();
    void longRenderShowsProgressAndStops();
    void propertiesEditIsUndoable();
    void dragTInTheComplexPlane();
    void takagiDistanceChart();
    void matrixCellEditRebalancesRow();

private:
    QTemporaryDir m_dir;
    QString m_file;
};

void TestMainWindow::initTestCase()
{
    QStandardPaths::setTestModeEnabled(true);
    QCoreApplication::setOrganizationName(QStringLiteral("awb-test"));
    QCoreApplication::setApplicationName(QStringLiteral("test-main-window"));
    QVERIFY(m_dir.isValid());
    // To look at the printed sheet and the exports after a run.
    if (qEnvironmentVariableIsSet("AWB_KEEP_TEST_FILES")) {
        m_dir.setAutoRemove(false);
        qInfo() << "test files in" << m_dir.path();
    }
    m_file = writeTestProject(m_dir.path());
    QVERIFY(QFile::exists(m_file));
}

void TestMainWindow::startsWithOneCurve()
{
    RecordingMessages messages;
    MainWindow w(&messages, m_dir.path() + QStringLiteral("/recovery"));
    QCOMPARE(w.project()->childCount(), 1);
    QVERIFY(w.currentItem());
    QVERIFY(!w.project()->isModified());
    QCOMPARE(w.project()->undoStack()->count(), 0);
    QVERIFY(w.matrixView()->matrixCount() > 0);
}

void TestMainWindow::openingFillsEveryView()
{
    RecordingMessages messages;
    MainWindow w(&messages, m_dir.path() + QStringLiteral("/recovery"));
    w.resize(1400, 900); // a laptop screen, the default dock layout
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    QStringList files{m_file};
    const QDir examples((awb::test::sourceDir() + QStringLiteral("/examples")));
    for (const QString &f : examples.entryList({QStringLiteral("*.awb")}, QDir::Files))
        files << examples.filePath(f);
    for (const QString &file : std::as_const(files)) {
        QVERIFY2(w.openFile(file), qPrintable(messages.errors.join('\n')));
        QVERIFY(w.project()->childCount() > 0);
        for (Item *item : w.project()->items()) {
            auto *a = qobject_cast<AttractorItem *>(item);
            // Every item of our own project can be drawn; an example may hold other kinds.
            if (file == m_file)
                QVERIFY2(a && a->derivedIfs(), qPrintable(item->name() + ": "
                                                          + item->derivedError()));
            if (!a || !a->derivedIfs())
                continue;
            w.setCurrentItem(item);
            w.controller()->refreshNow();
            const QString where = file + QStringLiteral(": ") + item->name();
            // The properties fit the dock's width (no editor clipped at the right edge).
            if (auto *scroll = w.propertiesWidget()->findChild<QScrollArea *>()) {
                QCoreApplication::processEvents();
                QVERIFY2(scroll->widget()->minimumSizeHint().width()
                             <= scroll->viewport()->width(),
                         qPrintable(where + QStringLiteral(": properties need %1 px, dock has %2")
                                        .arg(scroll->widget()->minimumSizeHint().width())
                                        .arg(scroll->viewport()->width())));
            }
            const auto d = a->derivedIfs();
            // A normal-vector curve without an equivalent IFS is drawn as its polygon only.
            if (d->ifs.size() == 0 && !d->iterate) {
                QVERIFY2(d->polygon && d->polygon->rows() > 2, qPrintable(where));
                continue;
            }
            if (a->pointDimension() == 3) {
                // Surfaces are drawn by the 3D view (the CPU renderer offscreen).
                SurfaceView *view = w.surfaceView();
                QVERIFY2(QTest::qWaitFor([view] {
                    return !view->isRendering()
                           && (!view->cpuImage().isNull() || view->mesh().size() > 0);
                }, awb::test::ms(30000)), qPrintable(where));
            } else {
                QVERIFY2(waitForFinalImage(w.attractorView()), qPrintable(where));
            }
            if (!d->S.real.empty()) {
                QCOMPARE(w.matrixView()->matrixCount(), d->S.count() + liftedCount(a));
                const int m = int(d->S.real.front().rows());
                QCOMPARE(w.matrixView()->table(0)->model()->rowCount(), m);
                QCOMPARE(w.matrixView()->table(0)->model()->columnCount() >= m, true);
            }
            if (d->S.isComplex()) { // complex L(t), R(t) and the complex lifted M_i
                QCOMPARE(w.matrixView()->matrixCount(),
                         d->S.count() + int(d->liftedComplex.size()));
                QCOMPARE(w.matrixView()->table(0)->model()->rowCount(),
                         int(d->S.complex.front().rows()));
            }
            if (d->S.count() > 0)
                QVERIFY2(w.spectrumView()->maps().size() > 0, qPrintable(where));
            // The exact-curve overlay where one is known (B-spline, Bézier, Takagi image).
            if (const auto exact = exactCurveOf(item)) {
                QCOMPARE(w.attractorView()->exactCurvePointCount(), int(exact->points.rows()));
                QCOMPARE(w.attractorView()->exactCurveLabel(), exact->label);
            } else {
                QCOMPARE(w.attractorView()->exactCurvePointCount(), 0);
            }
            if (file.contains(QStringLiteral("004-fig3.9")))
                QVERIFY2(w.attractorView()->exactCurveLabel().contains(QStringLiteral("Takagi")),
                         qPrintable(where));
            QCOMPARE(w.spectrumView()->plottedEigenvalueCount(),
                     expectedPoints(*d));
        }
    }
    QVERIFY(messages.errors.isEmpty());
}

void TestMainWindow::dragIsOneUndoStep()
{
    RecordingMessages messages;
    MainWindow w(&messages, m_dir.path() + QStringLiteral("/recovery"));
    w.resize(1300, 850);
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    QVERIFY(w.openFile(m_file));
    auto *item = qobject_cast<SubdivisionCurveItem *>(w.project()->child(0));
    QVERIFY(item);
    w.setCurrentItem(item);
    AttractorView *view = w.attractorView();
    QVERIFY(waitForFinalImage(view));
    QTest::qWait(50);
    QVERIFY(waitForFinalImage(view));
    const QImage before = view->currentImage();
    const PointList pointsBefore = item->controlPoints(0);
    const std::vector<Complex> spectrumBefore = w.spectrumView()->maps().front().spectrum.values;
    const int steps = w.project()->undoStack()->count();

    QSignalSpy finished(view, &AttractorView::renderFinished);
    const QPoint grab = view->worldToScreen(view->controlPointPosition(1)).toPoint();
    QTest::mousePress(view, Qt::LeftButton, Qt::NoModifier, grab);
    QTest::mouseMove(view, grab + QPoint(10, -5));
    QTest::mouseMove(view, grab + QPoint(25, -15));
    const QPoint end = grab + QPoint(40, -30);
    QTest::mouseMove(view, end);
    QTest::mouseRelease(view, Qt::LeftButton, Qt::NoModifier, end);

    QCOMPARE(w.project()->undoStack()->count(), steps + 1);
    QVERIFY(item->controlPoints(0) != pointsBefore);
    QCOMPARE(item->controlPoints(0)[0], pointsBefore[0]);
    // The spectrum of S_i of a B-spline does not depend on P, but the lifted M_i do: the view
    // shows the new point and a new attractor.
    QVERIFY(waitForFinalImage(view));
    QTRY_VERIFY_WITH_TIMEOUT(view->currentImage() != before, awb::test::ms(20000));
    QCOMPARE(view->controlPointPosition(1),
             QPointF(item->controlPoints(0)[1].x, item->controlPoints(0)[1].y));

    w.project()->undoStack()->undo();
    QCOMPARE(item->controlPoints(0), pointsBefore);
    QCOMPARE(w.spectrumView()->maps().front().spectrum.values, spectrumBefore);
    QTRY_VERIFY_WITH_TIMEOUT(view->currentImageInfo().final && !view->renderer()->isBusy()
                                 && view->currentImage() == before, awb::test::ms(30000));
}

void TestMainWindow::everyPointSetIsShownAndDraggable()
{
    // 002 Fig. 3: two quadratic Bézier curves, two control polygons. The second curve's points
    // follow the first's in the view's handle numbering.
    RecordingMessages messages;
    MainWindow w(&messages, m_dir.path() + QStringLiteral("/recovery"));
    w.resize(1300, 850);
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    QVERIFY(w.openFile((awb::test::sourceDir() + QStringLiteral("/examples/002-fig03-union-p3.awb"))));
    auto *item = qobject_cast<AttractorItem *>(w.project()->child(0));
    QVERIFY(item && item->controlPointSetCount() == 2);
    w.setCurrentItem(item);
    w.controller()->refreshNow();
    AttractorView *view = w.attractorView();
    QCOMPARE(view->controlPolygonCount(), 2);
    const int n0 = int(item->controlPoints(0).size());
    QCOMPARE(view->controlPointCount(), n0 + int(item->controlPoints(1).size()));
    QCOMPARE(view->controlPointSet(n0 + 1), std::make_pair(1, 1));
    QCOMPARE(view->controlPointSet(n0 - 1), std::make_pair(0, n0 - 1));
    QCOMPARE(view->controlPointSet(view->controlPointCount()), std::make_pair(-1, -1));
    // The printed caption counts both sets.
    const QString caption = FigureSheet(item, view, w.spectrumView()).caption().join(' ');
    QVERIFY2(caption.contains(QStringLiteral("control points = 3 + 3")), qPrintable(caption));
    const PointList first = item->controlPoints(0), second = item->controlPoints(1);
    const Point q1 = second[1];
    QCOMPARE(view->controlPointPosition(n0 + 1), QPointF(q1.x, q1.y));
    // Every handle lies inside the fitted view.
    for (int i = 0; i < view->controlPointCount(); ++i)
        QVERIFY(view->visibleWorldRect().contains(view->controlPointPosition(i)));

    const int steps = w.project()->undoStack()->count();
    const QPoint grab = view->worldToScreen(view->controlPointPosition(n0 + 1)).toPoint();
    QTest::mousePress(view, Qt::LeftButton, Qt::NoModifier, grab);
    QTest::mouseMove(view, grab + QPoint(10, 10));
    const QPoint end = grab + QPoint(30, 20);
    QTest::mouseMove(view, end);
    QTest::mouseRelease(view, Qt::LeftButton, Qt::NoModifier, end);
    QCOMPARE(w.project()->undoStack()->count(), steps + 1);
    QCOMPARE(item->controlPoints(0), first);           // the first curve is untouched
    QVERIFY(!(item->controlPoints(1)[1] == q1));        // the second curve's q_1 moved
    QCOMPARE(item->controlPoints(1)[0], second[0]);
    w.project()->undoStack()->undo();
    QCOMPARE(item->controlPoints(1), second);
}

void TestMainWindow::longRenderShowsProgressAndStops()
{
    RecordingMessages messages;
    MainWindow w(&messages, m_dir.path() + QStringLiteral("/recovery"));
    w.resize(1300, 850);
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    QVERIFY(w.openFile(m_file));
    auto *item = qobject_cast<SubdivisionCurveItem *>(w.project()->findItem("B-spline"));
    QVERIFY(item);
    w.setCurrentItem(item);
    QVERIFY(waitForFinalImage(w.attractorView()));
    auto *progress = w.findChild<QProgressBar *>(QStringLiteral("renderProgress"));
    auto *stop = w.findChild<QToolButton *>(QStringLiteral("renderCancel"));
    QVERIFY(progress && stop);
    QVERIFY(!progress->isVisible() && !stop->isVisible()); // quick renders show nothing
    // 2^30 images from a point: seconds of work even for the fused depth-first kernel, so the
    // progress and the button appear.
    AlgorithmSpec a = item->algorithm();
    a.depth = 30;
    QVERIFY(item->setAlgorithm(a));
    QTRY_VERIFY_WITH_TIMEOUT(stop->isVisible() && progress->isVisible(), awb::test::ms(10000));
    QVERIFY(w.attractorView()->isRendering());
    QTest::mouseClick(stop, Qt::LeftButton);
    QTRY_VERIFY_WITH_TIMEOUT(!w.attractorView()->isRendering(), awb::test::ms(5000));
    QVERIFY(!stop->isVisible() && !progress->isVisible());
    QVERIFY(!w.attractorView()->currentImage().isNull()); // the coarse picture stays
    // Draw Again (F5) starts it again; a shallower depth lets it finish.
    a.depth = 9;
    QVERIFY(item->setAlgorithm(a));
    QVERIFY(waitForFinalImage(w.attractorView()));
    QAction *again = w.action(QStringLiteral("actionRenderAgain"));
    QVERIFY(again);
    QCOMPARE(again->shortcut(), QKeySequence(QKeySequence::Refresh));
    again->trigger();
    QVERIFY(w.attractorView()->isRendering());
    QVERIFY(waitForFinalImage(w.attractorView()));
}

void TestMainWindow::propertiesEditIsUndoable()
{
    RecordingMessages messages;
    MainWindow w(&messages, m_dir.path() + QStringLiteral("/recovery"));
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    QVERIFY(w.openFile(m_file));
    auto *item = qobject_cast<SubdivisionCurveItem *>(w.project()->findItem("Four-point"));
    QVERIFY(item);
    w.setCurrentItem(item);
    QVERIFY(waitForFinalImage(w.attractorView()));
    const QImage before = w.attractorView()->currentImage();
    const auto specBefore = w.spectrumView()->maps().front().spectrum.values;
    const QStringList matBefore = firstTable(w.matrixView());

    auto *omega = qobject_cast<QDoubleSpinBox *>(w.propertiesWidget()->editor("scheme.omega"));
    QVERIFY(omega);
    QVERIFY(w.propertiesWidget()->slider("scheme.omega"));
    const int steps = w.project()->undoStack()->count();
    omega->setValue(0.03);
    QCOMPARE(item->scheme().omega, 0.03);
    QCOMPARE(w.project()->undoStack()->count(), steps + 1);
    w.controller()->refreshNow();
    QVERIFY(w.spectrumView()->maps().front().spectrum.values != specBefore);
    QVERIFY(firstTable(w.matrixView()) != matBefore);
    QVERIFY(waitForFinalImage(w.attractorView()));
    QTRY_VERIFY_WITH_TIMEOUT(w.attractorView()->currentImage() != before, awb::test::ms(20000));

    w.project()->undoStack()->undo();
    QCOMPARE(item->scheme().omega, 1.0 / 16.0);
    QCOMPARE(omega->value(), 1.0 / 16.0);
    w.controller()->refreshNow();
    QCOMPARE(w.spectrumView()->maps().front().spectrum.values, specBefore);
    QCOMPARE(firstTable(w.matrixView()), matBefore);

    // One slider drag (press, moves, release) is one undo step, and the spectrum follows it.
    auto *slider = qobject_cast<QSlider *>(w.propertiesWidget()->slider("scheme.omega"));
    QVERIFY(slider);
    const int before2 = w.project()->undoStack()->index();
    slider->setSliderDown(true);
    emit slider->sliderPressed();
    slider->setValue(slider->value() + 10);
    const double omegaMid = item->scheme().omega;
    slider->setValue(slider->value() + 10);
    QVERIFY(item->scheme().omega > omegaMid);
    QTRY_VERIFY(w.spectrumView()->maps().front().spectrum.values != specBefore);
    slider->setSliderDown(false);
    emit slider->sliderReleased();
    QCOMPARE(w.project()->undoStack()->index(), before2 + 1);
    QCOMPARE(w.project()->undoStack()->count(), before2 + 1);
    w.project()->undoStack()->undo();
    QCOMPARE(item->scheme().omega, 1.0 / 16.0);

    // A refused value is reported and the editor shows the model's value again: typed 64
    // (2^64 images) or -3, the message names the range (0 … 31 for two maps).
    auto *depth = qobject_cast<QSpinBox *>(w.propertiesWidget()->editor("algorithm.depth"));
    QVERIFY(depth);
    QCOMPARE(depth->maximum(), 31);
    const int depthBefore = item->algorithm().depth;
    auto *line = depth->findChild<QLineEdit *>();
    for (const QString &typed : {QStringLiteral("64"), QStringLiteral("-3")}) {
        depth->setFocus();
        line->setText(typed);
        QTest::keyClick(depth, Qt::Key_Return);
        QCOMPARE(item->algorithm().depth, depthBefore);
        QCOMPARE(depth->value(), depthBefore);
    }
    QCOMPARE(messages.errors.size(), 2);
    QVERIFY2(messages.errors.first().contains(QStringLiteral("64 is outside 0 … 31")),
             qPrintable(messages.errors.first()));
}

void TestMainWindow::matrixCellEditRebalancesRow()
{
    // The user's own matrices: the uniform quadratic B-spline (Chaikin) S_1, S_2 of 000 §3.
    RecordingMessages messages;
    MainWindow w(&messages, m_dir.path() + QStringLiteral("/recovery"));
    auto own = curve(QStringLiteral("Own"), SchemeSpec::Kind::Matrices,
                     {{0, 0}, {2, 3}, {4, 0}});
    SchemeSpec s = own->scheme();
    s.kind = SchemeSpec::Kind::Matrices;
    Mat S1(3, 3), S2(3, 3);
    S1 << 0.75, 0.25, 0, 0.25, 0.75, 0, 0, 0.75, 0.25;
    S2 << 0.25, 0.75, 0, 0, 0.75, 0.25, 0, 0.25, 0.75;
    s.matrices = {S1, S2};
    QVERIFY(!own->checkScheme(s));
    own->setScheme(s);
    auto *item = own.get();
    w.project()->addItem(std::move(own));
    w.setCurrentItem(item);
    w.controller()->refreshNow();
    QVERIFY2(item->derivedIfs(), qPrintable(item->derivedError()));
    QVERIFY(w.matrixView()->table(0));
    QAbstractItemModel *table = w.matrixView()->table(0)->model();
    QUndoStack *undo = w.project()->undoStack();
    const int steps = undo->count();

    // 3/4 -> 1/2 breaks row 1's sum; declined: nothing changes, no undo step, no error.
    messages.answer = QMessageBox::No;
    QVERIFY(table->setData(table->index(0, 0), QStringLiteral("1/2")));
    QCOMPARE(messages.questions.size(), 1);
    QVERIFY2(messages.questions.front().contains(QStringLiteral("sum to 3/4")),
             qPrintable(messages.questions.front()));
    QVERIFY2(messages.questions.front().contains(QStringLiteral("column 2 (1/4 → 1/2)")),
             qPrintable(messages.questions.front()));
    QCOMPARE(item->scheme().matrices[0](0, 0), 0.75);
    QCOMPARE(undo->count(), steps);
    QVERIFY(messages.errors.isEmpty());

    // Accepted: the largest other entry (column 2) takes the difference; one undo step.
    messages.answer = QMessageBox::Yes;
    QVERIFY(table->setData(table->index(0, 0), QStringLiteral("1/2")));
    QCOMPARE(item->scheme().matrices[0](0, 0), 0.5);
    QCOMPARE(item->scheme().matrices[0](0, 1), 0.5);
    QCOMPARE(item->scheme().matrices[0].row(0).sum(), 1.0);
    QCOMPARE(undo->count(), steps + 1);
    w.controller()->refreshNow();
    QCOMPARE(w.matrixView()->table(0)->model()->index(0, 1).data().toString(),
             QStringLiteral("1/2"));
    undo->undo();
    QCOMPARE(item->scheme().matrices[0], S1);

    // Typing the value a cell already has is no edit: no question, no undo step.
    const int asked = int(messages.questions.size());
    QVERIFY(w.matrixView()->table(1)->model()->setData(
        w.matrixView()->table(1)->model()->index(2, 2), QStringLiteral("3/4")));
    QCOMPARE(int(messages.questions.size()), asked);
    QCOMPARE(undo->index(), steps);
    QCOMPARE(item->scheme().matrices[1], S2);
    QVERIFY(messages.errors.isEmpty());
}

void TestMainWindow::dragTInTheComplexPlane()
{
    // 004 Fig. 3.9's t = 1/2 + i/100 dragged to 1/2 + 3i/10 in the plane of 004 Fig. 3.3: the
    // spectrum (eigenvalues 1, t, t^2 of L(t)) follows live, the whole drag is one undo step.
    RecordingMessages messages;
    MainWindow w(&messages, m_dir.path() + QStringLiteral("/recovery"));
    w.resize(1300, 850);
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    QVERIFY(w.openFile(
        (awb::test::sourceDir() + QStringLiteral("/examples/004-fig3.9-example-3.7.3-takagi-image.awb"))));
    Item *item = w.project()->child(0);
    w.setCurrentItem(item);
    w.controller()->refreshNow();
    QTest::qWait(100); // the properties dock rebuilds for the new item
    QPointer<ComplexPlanePicker> plane = w.propertiesWidget()->findChild<ComplexPlanePicker *>(
        QStringLiteral("complexPlane:t"));
    QVERIFY(plane);
    // Visible and laid out: on a loaded machine the plane may show before the dock gives it
    // its size, and a drag on a plane of no size goes nowhere.
    QTRY_VERIFY_WITH_TIMEOUT(plane->isVisible() && plane->width() >= 100 && plane->height() >= 100,
                             awb::test::ms(5000));
    QCOMPARE(plane->value(), QPointF(0.5, 0.01));
    const int steps = w.project()->undoStack()->count();
    const QPoint from = plane->toScreen({0.5, 0.01}).toPoint();
    const QPoint to = plane->toScreen({0.5, 0.3}).toPoint();
    QTest::mousePress(plane, Qt::LeftButton, Qt::NoModifier, from);
    QTest::mouseMove(plane, (from + to) / 2);
    QTest::mouseMove(plane, to);
    // Live: the item and the spectrum follow before the button is released.
    const QPointF t = item->parameter(QStringLiteral("t")).toPointF();
    const double pixel = 1.0 / (plane->toScreen({1, 0}).x() - plane->toScreen({0, 0}).x());
    QVERIFY2(pixel > 0 && pixel < 0.02, qPrintable(QString::number(pixel)));
    QVERIFY2(std::abs(t.x() - 0.5) <= pixel && std::abs(t.y() - 0.3) <= pixel,
             qPrintable(QStringLiteral("t = %1 + %2i").arg(t.x()).arg(t.y())));
    w.controller()->refreshNow();
    const Complex tc(t.x(), t.y());
    // The spectrum may arrive from a worker a little later (much later in a sanitizer build).
    const auto hasTSquared = [&] {
        if (w.spectrumView()->maps().isEmpty())
            return false;
        for (const Complex &z : w.spectrumView()->maps().front().spectrum.values)
            if (std::abs(z - tc * tc) < 1e-9)
                return true;
        return false;
    };
    const auto shown = [&] {
        QString s = QStringLiteral("t^2 = (%1, %2) is not an eigenvalue of L(t) as shown:")
                        .arg((tc * tc).real())
                        .arg((tc * tc).imag());
        for (const auto &m : w.spectrumView()->maps())
            for (const Complex &z : m.spectrum.values)
                s += QStringLiteral(" (%1, %2)").arg(z.real()).arg(z.imag());
        return s;
    };
    QTRY_VERIFY2_WITH_TIMEOUT(hasTSquared(), qPrintable(shown()), awb::test::ms(5000));
    QTest::mouseRelease(plane, Qt::LeftButton, Qt::NoModifier, to);
    QCOMPARE(w.project()->undoStack()->count(), steps + 1);
    QVERIFY(ComplexPlanePicker::inLens(plane->value()));
    QVERIFY(!ComplexPlanePicker::inLens({0.5, 0.9}));  // |t|^2 = 0.25 + 0.81 > 1
    w.project()->undoStack()->undo();
    QCOMPARE(item->parameter(QStringLiteral("t")).toPointF(), QPointF(0.5, 0.01));
    QCOMPARE(plane->value(), QPointF(0.5, 0.01));
}

void TestMainWindow::takagiDistanceChart()
{
    // 004 Fig. 3.9 / Example 3.7.3: the analysis measures F^k(X0) against the Takagi image
    // c(x + 2iy T(x)). Down to the O(y^2) gap of Conjecture 3.7.1 (~1e-4 at y = 10^-2, below
    // the item's depth 12) the distance falls by |t| = |1/2 + i/100| per level.
    RecordingMessages messages;
    MainWindow w(&messages, m_dir.path() + QStringLiteral("/recovery"));
    w.resize(1300, 850);
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    QVERIFY(w.openFile(
        (awb::test::sourceDir() + QStringLiteral("/examples/004-fig3.9-example-3.7.3-takagi-image.awb"))));
    w.setCurrentItem(w.project()->child(0));
    QTest::qWait(300); // the analysis starts after a quiet moment
    QTRY_VERIFY_WITH_TIMEOUT(!w.controller()->analysisRunning(), awb::test::ms(30000));
    QLineSeries *series = nullptr;
    QTRY_VERIFY_WITH_TIMEOUT(
        [&] {
            for (QAbstractSeries *a : w.analysisCharts()->chart(AnalysisCharts::DistanceTab)->series())
                if (a->name() == QStringLiteral("Fᵏ(X₀)"))
                    series = qobject_cast<QLineSeries *>(a);
            return series != nullptr;
        }(),
        awb::test::ms(30000));
    // The legend is short; what the distance is measured against is in the chart's tooltip.
    QVERIFY(w.analysisCharts()->chartView(AnalysisCharts::DistanceTab)->toolTip().contains(
        QStringLiteral("Takagi")));
    const QList<QPointF> pts = series->points();
    QVERIFY2(pts.size() >= 10, qPrintable(QString::number(pts.size())));
    QVERIFY(pts.last().y() < pts.first().y() / 100);
    const double t = std::abs(Complex(0.5, 0.01));
    for (int k = 6; k + 1 < int(pts.size()); ++k) {
        const double ratio = pts[k + 1].y() / pts[k].y();
        QVERIFY2(std::abs(ratio - t) < 0.03, qPrintable(QStringLiteral("k = %1: %2 vs |t| = %3")
                                                            .arg(k).arg(ratio).arg(t)));
    }
    QVERIFY2(pts.last().y() < 1.1e-3, qPrintable(QString::number(pts.last().y())));
}

AWB_TEST_MAIN(TestMainWindow)
#include "test_main_window.moc"
