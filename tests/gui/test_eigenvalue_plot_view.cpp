// The eigenvalue plot in the main window and the live spectrum: the plot of 000 Fig. 2 fills the
// Spectrum and Matrices panels with the eigenvalues of S_1, S_2 and the centre with its source's
// attractor; its Properties edit the source and the matrices (undoable); eigenvalue markers and
// chart points have tooltips; a click on a marker marks that map's matrices and part of the
// attractor; coinciding eigenvalues of different maps keep distinct markers.
#include "gui/app/ItemController.h"
#include "gui/app/MainWindow.h"
#include "gui/app/Messages.h"
#include "gui/app/PropertiesDock.h"
#include "gui/views/AnalysisCharts.h"
#include "gui/views/AttractorView.h"
#include "gui/views/MatrixView.h"
#include "gui/views/SpectrumView.h"
#include "model/EigenvaluePlotItem.h"
#include "model/Project.h"

#include <QChart>
#include <QComboBox>
#include <QLabel>
#include <QTableView>
#include <QXYSeries>
#include <QMenu>
#include <QtTest>

#include "TestMain.h"

#include "TestTime.h"

#include "model/Fig2Example.h"

#include "WindowTestSupport.h"

#include <qcustomplot.h>

using namespace awb;

namespace {

const QString &fig2 = test::fig2File;
const QString &plotName = test::fig2Plot;
const QString &curveName = test::fig2Curve;

} // namespace

class TestEigenvaluePlotView : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void fig2PlotFillsTheViews();
    void propertiesEditSourceAndMatrices();
    void markerTooltipsAndClicks();
    void chartPointTooltips();
    void newPlotAnalysesTheCurrentItem();

private:
    QString m_recovery;
    QTemporaryDir m_dir;
};

void TestEigenvaluePlotView::initTestCase()
{
    test::useTestSettings("test-eigenvalue-plot-view");
    m_recovery = m_dir.path() + QStringLiteral("/recovery");
}

void TestEigenvaluePlotView::fig2PlotFillsTheViews()
{
    test::ShownWindow shown(m_recovery, {1400, 900});
    QVERIFY(shown.exposed);
    MainWindow &w = shown.window;
    QVERIFY(w.openFile(fig2));
    auto *plot = qobject_cast<EigenvaluePlotItem *>(w.project()->findItem(plotName));
    QVERIFY(plot);
    w.setCurrentItem(plot);
    w.controller()->refreshNow();
    // The Spectrum panel: S_1 and S_2, five eigenvalues each (1, 1/2, 1/4, 1/8, 0).
    SpectrumView *spectrum = w.spectrumView();
    QCOMPARE(spectrum->maps().size(), 2);
    QCOMPARE(spectrum->maps()[0].label, QStringLiteral("S_1"));
    QCOMPARE(spectrum->maps()[1].label, QStringLiteral("S_2"));
    QCOMPARE(spectrum->plottedEigenvalueCount(), 10);
    QVERIFY(!spectrum->verdictText().contains(QStringLiteral("No maps")));
    for (const MapSpectrum &m : spectrum->maps()) {
        std::vector<double> re;
        for (Complex z : m.spectrum.values)
            re.push_back(z.real());
        std::sort(re.rbegin(), re.rend());
        const std::vector<double> expected{1, 0.5, 0.25, 0.125, 0};
        for (std::size_t i = 0; i < 5; ++i)
            QVERIFY(std::abs(re[i] - expected[i]) < 1e-10);
    }
    // Sensible axes: the unit circle and every eigenvalue inside, equal scale, not collapsed.
    QCoreApplication::processEvents();
    spectrum->plot()->replot();
    const QCPRange x = spectrum->plot()->xAxis->range(), y = spectrum->plot()->yAxis->range();
    QVERIFY2(x.lower <= -1 && x.upper >= 1 && y.lower <= -1 && y.upper >= 1,
             qPrintable(QStringLiteral("x %1..%2 y %3..%4")
                            .arg(x.lower).arg(x.upper).arg(y.lower).arg(y.upper)));
    QVERIFY(spectrum->plot()->axisRect()->width() > 100);
    // The Matrices panel: S_1, S_2 (5 x 5), read-only.
    QCOMPARE(w.matrixView()->matrixCount(), 2);
    QCOMPARE(w.matrixView()->table(0)->model()->rowCount(), 5);
    QVERIFY(!w.matrixView()->isEditable());
    // The centre shows the plot itself, large (the source's attractor is its own item's).
    auto *central = w.findChild<SpectrumView *>(QStringLiteral("eigenvaluePlotView"));
    QVERIFY(central);
    QVERIFY(central->isVisible());
    QVERIFY(!w.attractorView()->isVisible());
    QTRY_COMPARE(central->plottedEigenvalueCount(), 10);
    QCOMPARE(w.controller()->drawnItem(), w.project()->findItem(curveName));
    QVERIFY(w.controller()->problem().isEmpty());
    // S_1 and S_2 share their eigenvalues: a click on one offers both maps.
    QCoreApplication::processEvents();
    central->plot()->replot();
    const QList<int> both = central->mapsAt(central->pixelOf(Complex(0.5, 0)));
    QCOMPARE(both, (QList<int>{0, 1}));
    QCOMPARE(central->mapsAt(central->pixelOf(Complex(0.5, 0.9))), QList<int>{});
    // The source selected again: its attractor is in the centre.
    w.setCurrentItem(w.project()->findItem(curveName));
    QVERIFY(test::waitForFinalImage(w.attractorView()));
    QVERIFY(w.attractorView()->isVisible());
    QVERIFY(shown.messages.errors.isEmpty());
}

void TestEigenvaluePlotView::propertiesEditSourceAndMatrices()
{
    test::ShownWindow shown(m_recovery);
    QVERIFY(shown.exposed);
    MainWindow &w = shown.window;
    QVERIFY(w.openFile(fig2));
    auto *plot = qobject_cast<EigenvaluePlotItem *>(w.project()->findItem(plotName));
    w.setCurrentItem(plot);
    auto *source = qobject_cast<QComboBox *>(w.propertiesWidget()->editor("source"));
    auto *matrices = qobject_cast<QComboBox *>(w.propertiesWidget()->editor("matrices"));
    QVERIFY(source && matrices);
    QCOMPARE(source->currentText(), curveName);
    QCOMPARE(source->count(), 2); // "(none)" and the curve; a plot is not a source
    QCOMPARE(matrices->count(), 3);
    QCOMPARE(matrices->currentIndex(), 0);
    // The linear parts A_i: one undo step; the views follow.
    QUndoStack *stack = w.project()->undoStack();
    const int steps = stack->count();
    matrices->setCurrentIndex(1);
    QCOMPARE(plot->matrixKind(), EigenvaluePlotItem::MatrixKind::A);
    QCOMPARE(stack->count(), steps + 1);
    w.controller()->refreshNow();
    QCOMPARE(w.spectrumView()->maps()[0].label, QStringLiteral("A_1"));
    QCOMPARE(w.spectrumView()->plottedEigenvalueCount(), 8);
    QCOMPARE(w.matrixView()->table(0)->model()->rowCount(), 4);
    // M_i: the lifted maps, 5 x 5 with their A block.
    matrices->setCurrentIndex(2);
    w.controller()->refreshNow();
    QCOMPARE(w.spectrumView()->maps()[1].label, QStringLiteral("M_2"));
    QCOMPARE(w.matrixView()->table(0)->model()->rowCount(), 5);
    // No source: the panels are empty and the reason is given.
    source->setCurrentIndex(0);
    QVERIFY(plot->source().isEmpty());
    QCOMPARE(stack->count(), steps + 3);
    w.controller()->refreshNow();
    QCOMPARE(w.spectrumView()->plottedEigenvalueCount(), 0);
    QVERIFY2(w.controller()->problem().contains(QStringLiteral("no item")),
             qPrintable(w.controller()->problem()));
    // Undo brings the source back, and the editors show it.
    stack->undo();
    QCOMPARE(plot->source(), curveName);
    QCOMPARE(source->currentText(), curveName);
    stack->undo();
    stack->undo();
    QCOMPARE(matrices->currentIndex(), 0);
    // Renaming the source keeps the plot on it; the list shows the new name.
    QVERIFY(w.project()->findItem(curveName)->setName(QStringLiteral("Curve")));
    QCOMPARE(plot->source(), QStringLiteral("Curve"));
    QCOMPARE(source->currentText(), QStringLiteral("Curve"));
}

void TestEigenvaluePlotView::markerTooltipsAndClicks()
{
    test::ShownWindow shown(m_recovery, {1400, 900});
    QVERIFY(shown.exposed);
    MainWindow &w = shown.window;
    QVERIFY(w.openFile(fig2));
    auto *curve = w.project()->findItem(curveName);
    w.setCurrentItem(curve);
    w.controller()->refreshNow();
    SpectrumView *spectrum = w.spectrumView();
    spectrum->plot()->replot();
    QCoreApplication::processEvents();
    // 1/2 is an eigenvalue of both maps: the tooltip names each, with |λ|, arg λ and the
    // multiplicity.
    const QPointF half = spectrum->pixelOf(Complex(0.5, 0));
    const QString tip = spectrum->tooltipAt(half);
    QVERIFY2(tip.contains(QStringLiteral("S<sub>1</sub>")) && tip.contains(QStringLiteral("S<sub>2</sub>")),
             qPrintable(tip));
    QVERIFY2(tip.contains(QStringLiteral("|λ| = 1/2")), qPrintable(tip));
    QVERIFY2(tip.contains(QStringLiteral("arg λ = 0°")), qPrintable(tip));
    QVERIFY2(tip.contains(QStringLiteral("map 2")), qPrintable(tip));
    QVERIFY2(tip.contains(QStringLiteral("multiplicity 1")), qPrintable(tip));
    const QString zero = spectrum->tooltipAt(spectrum->pixelOf(Complex(0, 0)));
    QVERIFY2(zero.contains(QStringLiteral("λ = 0")), qPrintable(zero));
    // Coinciding markers of the two maps differ in shape and size.
    auto *g1 = spectrum->plot()->graph(0), *g2 = spectrum->plot()->graph(1);
    QVERIFY(g1->scatterStyle().shape() != g2->scatterStyle().shape());
    QVERIFY(g1->scatterStyle().size() > g2->scatterStyle().size());
    // A click on coinciding markers offers both maps; choosing S_2 marks S_2 and M_2 in the
    // Matrices panel and draws that map's part of the attractor in colour.
    QVERIFY(test::waitForFinalImage(w.attractorView()));
    QTest::mouseClick(spectrum->plot(), Qt::LeftButton, {}, half.toPoint());
    auto *menu = spectrum->findChild<QMenu *>(QStringLiteral("coincidingEigenvalues"));
    QVERIFY(menu);
    QCOMPARE(menu->actions().size(), 2);
    QVERIFY(menu->actions().at(0)->text().startsWith(QStringLiteral("S₁: λ = 1/2")));
    QVERIFY(menu->actions().at(1)->text().startsWith(QStringLiteral("S₂: λ = 1/2")));
    QCOMPARE(spectrum->highlightedMap(), -1); // nothing chosen yet
    menu->actions().at(1)->trigger();
    menu->close();
    QCOMPARE(spectrum->highlightedMap(), 1);
    QCOMPARE(w.matrixView()->highlightedMap(), 1);
    QVERIFY(!w.matrixView()->isHighlighted(0)); // S_1
    QVERIFY(w.matrixView()->isHighlighted(1));  // S_2
    QVERIFY(w.matrixView()->isHighlighted(3));  // M_2
    QCOMPARE(w.controller()->highlightedMap(), 1);
    const auto rs = w.attractorView()->renderSettings();
    QCOMPARE(rs.colouring.palette.value(0), QColor(205, 205, 205));
    QVERIFY(rs.colouring.palette.value(1) != QColor(205, 205, 205));
    // A click beside the markers clears the mark.
    QTest::mouseClick(spectrum->plot(), Qt::LeftButton, {},
                      spectrum->pixelOf(Complex(-0.6, 0.6)).toPoint());
    QCOMPARE(spectrum->highlightedMap(), -1);
    QCOMPARE(w.matrixView()->highlightedMap(), -1);
    QCOMPARE(w.controller()->highlightedMap(), -1);
}

void TestEigenvaluePlotView::chartPointTooltips()
{
    using T = AnalysisCharts;
    const QString d = T::pointToolTip(T::DistanceTab, QStringLiteral("F^k(X0)"), {7, 0.0125});
    QVERIFY2(d.contains(QStringLiteral("depth k = 7")) && d.contains(QStringLiteral("0.0125")),
             qPrintable(d));
    const QString b = T::pointToolTip(T::BoxCountingTab, QStringLiteral("fitted levels"),
                                      {std::log(64.0), std::log(1000.0)});
    QVERIFY2(b.contains(QStringLiteral("ε = 0.0156")) && b.contains(QStringLiteral("N = 1000")),
             qPrintable(b));
    // The charts of a real analysis show them on hover.
    test::ShownWindow shown(m_recovery);
    QVERIFY(shown.exposed);
    MainWindow &w = shown.window;
    QVERIFY(w.openFile(fig2));
    w.setCurrentItem(w.project()->findItem(curveName));
    w.controller()->refreshNow();
    QTRY_VERIFY_WITH_TIMEOUT(!w.analysisCharts()->chart(T::DistanceTab)->series().isEmpty(), awb::test::ms(20000));
    auto *series = qobject_cast<QXYSeries *>(w.analysisCharts()->chart(T::DistanceTab)->series().front());
    QVERIFY(series && series->count() > 0);
    const QPointF p = series->at(series->count() - 1);
    w.analysisCharts()->tabs()->setCurrentIndex(T::DistanceTab);
    emit series->hovered(p, true);
    QTRY_VERIFY(QToolTip::isVisible());
    QVERIFY2(QToolTip::text().contains(QStringLiteral("depth k = %1").arg(int(p.x()))),
             qPrintable(QToolTip::text()));
    emit series->hovered(p, false);
}

void TestEigenvaluePlotView::newPlotAnalysesTheCurrentItem()
{
    test::ShownWindow shown(m_recovery);
    QVERIFY(shown.exposed);
    MainWindow &w = shown.window;
    Item *curve = w.currentItem();
    QVERIFY(curve);
    QAction *add = w.action(QStringLiteral("actionAdd_eigenvalue-plot"));
    QVERIFY(add);
    add->trigger();
    auto *plot = qobject_cast<EigenvaluePlotItem *>(w.currentItem());
    QVERIFY(plot);
    QCOMPARE(plot->source(), curve->name());
    QCOMPARE(plot->parentItem(), curve);
    QCOMPARE(w.project()->undoStack()->count(), 1);
    w.controller()->refreshNow();
    QVERIFY(w.spectrumView()->plottedEigenvalueCount() > 0);
}

AWB_TEST_MAIN(TestEigenvaluePlotView)
#include "test_eigenvalue_plot_view.moc"
