#pragma once
// Shared fixtures of the main window's tests (test_main_window.cpp,
// test_main_window_files.cpp): a project of three curves, waiting for a final raster, counts
// of what the views show.

#include "core/analysis/Spectrum.h"
#include "gui/app/FigureSheet.h"
#include "gui/app/ItemController.h"
#include "gui/app/MainWindow.h"
#include "gui/app/Messages.h"
#include "gui/app/PropertiesDock.h"
#include "gui/views/AnalysisCharts.h"
#include "gui/views/AttractorView.h"
#include "gui/views/ComplexPlanePicker.h"
#include "gui/views/MatrixView.h"
#include "gui/views/SpectrumView.h"
#include "gui/views/SurfaceView.h"
#include "model/ExactCurve.h"
#include "model/Project.h"
#include "model/Recovery.h"
#include "model/SubdivisionCurveItem.h"

#include <QDir>
#include <QDoubleSpinBox>
#include <QFile>
#include <QComboBox>
#include <QChart>
#include <QChartView>
#include <QLineSeries>
#include <QProgressBar>
#include <QElapsedTimer>
#include <QTimer>
#include <QProgressDialog>
#include <QScrollArea>
#include <QToolButton>
#include <QSignalSpy>
#include <QSlider>
#include <QStandardPaths>
#include <QTableView>
#include <QTemporaryDir>
#include <QLineEdit>
#include <QtTest>

#include "TestTime.h"

namespace awb::test {

inline std::unique_ptr<SubdivisionCurveItem> curve(const QString &name, SchemeSpec::Kind kind,
                                            const PointList &points)
{
    auto item = std::make_unique<SubdivisionCurveItem>();
    item->setName(name);
    SchemeSpec s = item->scheme();
    s.kind = kind;
    item->setScheme(s);
    // Replace the default points by `points`.
    while (item->controlPoints(0).size() > 1)
        item->removeControlPoint(int(item->controlPoints(0).size()) - 1);
    item->moveControlPoint(0, points.front());
    for (std::size_t i = 1; i < points.size(); ++i)
        item->insertControlPoint(int(i), points[i]);
    AlgorithmSpec a = item->algorithm();
    a.depth = 9;
    item->setAlgorithm(a);
    return item;
}

// A project file with a cubic B-spline on 5 points, a four-point curve and a cubic Bézier.
inline QString writeTestProject(const QString &dir)
{
    Project project;
    project.addItem(curve(QStringLiteral("B-spline"), SchemeSpec::Kind::BSpline,
                          {{0, 0}, {1, 2}, {3, 2.5}, {4.5, 1}, {6, 2}}));
    project.addItem(curve(QStringLiteral("Four-point"), SchemeSpec::Kind::FourPoint,
                          {{0, 0}, {1, 1.5}, {2.5, 2}, {4, 0.5}, {5, 1}, {6.5, 2}}));
    project.addItem(curve(QStringLiteral("Bezier"), SchemeSpec::Kind::Bezier,
                          {{0, 0}, {1, 3}, {3, 3}, {4, 0}}));
    const QString file = dir + QStringLiteral("/test.awb");
    QString error;
    if (!project.saveAs(file, &error))
        qWarning() << error;
    return file;
}

// Waits for a final raster with lit pixels.
inline bool waitForFinalImage(AttractorView *view)
{
    const bool ok = QTest::qWaitFor([view] {
        return view->currentImageInfo().final && view->currentImageInfo().litPixels > 0
               && !view->renderer()->isBusy();
    }, awb::test::ms(30000));
    if (!ok)
        qWarning() << "no final image: final" << view->currentImageInfo().final << "lit"
                   << view->currentImageInfo().litPixels << "busy" << view->renderer()->isBusy()
                   << "error" << view->lastError() << "visible" << view->isVisible();
    return ok;
}

// One point per eigenvalue of each map: m per m x m matrix S_i (or A_i).
inline int expectedPoints(const DerivedIfs &d)
{
    int n = 0;
    for (const Mat &S : d.S.real)
        n += int(S.rows());
    for (const CMat &S : d.S.complex)
        n += int(S.rows());
    if (n == 0)
        for (int i = 0; i < d.ifs.size(); ++i)
            n += int(d.ifs.effectiveLinearPart(i).rows());
    return n;
}

// Every cell of the first matrix table, as shown.
inline QStringList firstTable(MatrixView *view)
{
    QStringList cells;
    const QAbstractItemModel *m = view->table(0)->model();
    for (int r = 0; r < m->rowCount(); ++r)
        for (int c = 0; c < m->columnCount(); ++c)
            cells << m->index(r, c).data().toString();
    return cells;
}

inline int liftedCount(const AttractorItem *item)
{
    const auto d = item->derivedIfs();
    return d && d->subdivision ? int(d->subdivision->lifted.size()) : 0;
}

} // namespace awb::test
