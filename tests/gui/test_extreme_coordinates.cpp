// Coordinates no window should choke on (issue 28): a control point at 1e300 once spun the GUI
// thread for good in the grid's loop (x += step never moved past 1e300). Each project below is
// opened in the main window, shown, drawn, zoomed and panned under a watchdog that fails the
// test instead of hanging it; it opens with the view saying why nothing is drawn, draws, or is
// refused with the CLI's message. And the grid's line counts are bounded for any extent.

#include "TestPaths.h"
#include "gui/app/ItemController.h"
#include "gui/app/MainWindow.h"
#include "gui/views/AttractorView.h"
#include "gui/views/AttractorViewDetail.h"
#include "gui/views/SurfaceView.h"
#include "model/Project.h"

#include "WindowTestSupport.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QtTest>

#include "TestMain.h"

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <mutex>
#include <thread>

using namespace awb;

namespace {

// Ends the process with a message if not disarmed within `seconds`: a frozen GUI thread never
// returns to the test, so the check must come from another thread.
class Watchdog {
public:
    Watchdog(const QString &what, int seconds)
        : m_what(what.toStdString()), m_thread([this, seconds] {
              std::unique_lock lock(m_mutex);
              if (!m_done.wait_for(lock, std::chrono::seconds(seconds), [this] { return m_disarmed; })) {
                  std::fprintf(stderr, "FAIL: the window froze on %s (no return within %d s)\n",
                               m_what.c_str(), seconds);
                  std::_Exit(3);
              }
          })
    {
    }
    ~Watchdog()
    {
        {
            std::lock_guard lock(m_mutex);
            m_disarmed = true;
        }
        m_done.notify_all();
        m_thread.join();
    }

private:
    std::string m_what;
    std::mutex m_mutex;
    std::condition_variable m_done;
    bool m_disarmed = false;
    std::thread m_thread;
};

// 000 Fig. 11 (top) with control point p4's y (and more) replaced.
QJsonObject gasket()
{
    QFile f(awb::test::sourceDir()
            + QStringLiteral("/examples/000-fig11-sierpinski-with-control-points.awb"));
    if (!f.open(QIODevice::ReadOnly))
        return {};
    QJsonObject root = QJsonDocument::fromJson(f.readAll()).object();
    QJsonArray items = root.value(QStringLiteral("items")).toArray();
    while (items.size() > 1)
        items.removeLast();
    root.insert(QStringLiteral("items"), items);
    return root;
}

QJsonObject withPoints(const std::function<QJsonArray(QJsonArray)> &edit)
{
    QJsonObject root = gasket();
    QJsonArray items = root.value(QStringLiteral("items")).toArray();
    QJsonObject item = items[0].toObject();
    item.insert(QStringLiteral("control_points"),
                edit(item.value(QStringLiteral("control_points")).toArray()));
    items[0] = item;
    root.insert(QStringLiteral("items"), items);
    return root;
}

QJsonArray scaled(QJsonArray points, double k, double dx)
{
    for (int i = 0; i < points.size(); ++i) {
        const QJsonArray p = points[i].toArray();
        points[i] = QJsonArray{p[0].toDouble() * k + dx, p[1].toDouble() * k};
    }
    return points;
}

} // namespace

class TestExtremeCoordinates : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { test::useTestSettings("test-extreme-coordinates"); }

    void gridIsBoundedForAnyExtent()
    {
        using attractor_view::gridLines;
        // The ordinary case: lines at 0, 0.1, ..., 1.
        const auto g = gridLines(-0.05, 1.05, 0.1, 400);
        QVERIFY(g);
        QCOMPARE(g->first, 0.0);
        QCOMPARE(g->count, 11);
        // Far from 0 the step is below the coordinates' precision: no grid, no endless loop.
        QVERIFY(!gridLines(1e300, 1e300 + 1e286, 1e284, 400));
        QVERIFY(!gridLines(-1e300, 1e300, 1e299, 10)); // too many
        QVERIFY(!gridLines(0, 1, 0.0, 400));
        QVERIFY(!gridLines(0, qInf(), 1.0, 400));
        QVERIFY(!gridLines(qQNaN(), 1, 1.0, 400));
        QVERIFY(!gridLines(0, 1, 1e-320, 400)); // a denormal step: too many
        // Tiny extents are fine when the step fits them.
        const auto t = gridLines(1e-300, 9e-300, 1e-300, 400);
        QVERIFY(t);
        QCOMPARE(t->count, 9);
    }

    void projectsOpenDrawOrAreRefused_data()
    {
        QTest::addColumn<QByteArray>("json");
        QTest::addColumn<QString>("expect"); // "drawn", "problem: TEXT", "refused: TEXT"
        const auto bytes = [](const QJsonObject &o) { return QJsonDocument(o).toJson(); };
        const auto setY = [](double y) {
            return [y](QJsonArray p) {
                QJsonArray q = p[4].toArray();
                q[1] = y;
                p[4] = q;
                return p;
            };
        };
        QTest::newRow("y = 1e300") << bytes(withPoints(setY(1e300)))
                                   << QStringLiteral("problem: the lifting overflows");
        QTest::newRow("y = -1e300") << bytes(withPoints(setY(-1e300)))
                                    << QStringLiteral("problem: the lifting overflows");
        QTest::newRow("y = 1e-300") << bytes(withPoints(setY(1e-300))) << QStringLiteral("drawn");
        QTest::newRow("all at 1e300 scale")
            << bytes(withPoints([](QJsonArray p) { return scaled(p, 1e300, 0); }))
            << QStringLiteral("problem: the lifting overflows");
        QTest::newRow("1e-300 wide at x = 1e300")
            << bytes(withPoints([](QJsonArray p) { return scaled(p, 1e-300, 1e300); }))
            << QStringLiteral("problem: the lifting overflows");
        QTest::newRow("1e-12 wide at x = 1e6")
            << bytes(withPoints([](QJsonArray p) { return scaled(p, 1e-12, 1e6); }))
            << QStringLiteral("drawn");
        // JSON has no NaN or infinity: the reader refuses the words, and a number too large.
        QByteArray nan = bytes(withPoints(setY(12345.678)));
        QByteArray inf = nan;
        nan.replace("12345.678", "NaN");
        inf.replace("12345.678", "1e400");
        QTest::newRow("NaN") << nan << QStringLiteral("refused: NaN is not a finite number");
        QTest::newRow("1e400") << inf << QStringLiteral("refused: 1e400 is not a finite number");
    }

    void projectsOpenDrawOrAreRefused()
    {
        QFETCH(QByteArray, json);
        QFETCH(QString, expect);
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("extreme.awb"));
        QFile f(path);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(json);
        f.close();
        test::ShownWindow shown(dir.filePath(QStringLiteral("recovery")), QSize(1200, 800));
        MainWindow &w = shown.window;
        AttractorView *view = w.attractorView();
        Watchdog watchdog(QString::fromLatin1(QTest::currentDataTag()), 60 * test::ms(1));
        const bool opened = w.openFile(path);
        if (expect.startsWith(QLatin1String("refused: "))) {
            QVERIFY(!opened);
            QVERIFY2(shown.messages.errors.join(' ').contains(expect.mid(9)),
                     qPrintable(shown.messages.errors.join(' ')));
            return;
        }
        QVERIFY(opened);
        // Painted, zoomed, panned and fitted: every paint returns.
        for (int k = 0; k < 3; ++k) {
            view->repaint();
            view->zoomBy(k == 1 ? 1e6 : 1e-6, QPointF(10, 10));
            view->repaint();
            QTest::keyClick(view, Qt::Key_Home);
            QCoreApplication::processEvents();
        }
        QVERIFY(!w.grab().isNull());
        if (expect == QLatin1String("drawn")) {
            QVERIFY(test::waitForFinalImage(view)); // with lit pixels
        } else {
            // The CLI's words for it (attractor-cli check), in the view and the status bar.
            QVERIFY2(view->problem().contains(expect.mid(9)), qPrintable(view->problem()));
            QVERIFY(w.controller()->problem().contains(expect.mid(9)));
        }
    }

    // The 3D view (000 Fig. 7, a net point far out): opens, draws or says why, never hangs.
    void surfacesOpen_data()
    {
        QTest::addColumn<double>("z");
        QTest::newRow("z = 1e300") << 1e300;
        QTest::newRow("z = -1e300") << -1e300;
        QTest::newRow("z = 1e-300") << 1e-300;
        QTest::newRow("z = 1e12") << 1e12;
    }

    void surfacesOpen()
    {
        QFETCH(double, z);
        QFile in(awb::test::sourceDir()
                 + QStringLiteral("/examples/000-fig07-box-spline-hexagon.awb"));
        QVERIFY(in.open(QIODevice::ReadOnly));
        QJsonObject root = QJsonDocument::fromJson(in.readAll()).object();
        QJsonArray items = root.value(QStringLiteral("items")).toArray();
        QJsonObject item = items[0].toObject();
        QJsonArray points = item.value(QStringLiteral("control_points")).toArray();
        QJsonArray p = points[9].toArray();
        p[2] = z;
        points[9] = p;
        item.insert(QStringLiteral("control_points"), points);
        items[0] = item;
        root.insert(QStringLiteral("items"), items);
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("surface.awb"));
        QFile f(path);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(QJsonDocument(root).toJson());
        f.close();
        test::ShownWindow shown(dir.filePath(QStringLiteral("recovery")), QSize(1200, 800));
        MainWindow &w = shown.window;
        Watchdog watchdog(QString::fromLatin1(QTest::currentDataTag()), 120 * test::ms(1));
        QVERIFY(w.openFile(path));
        SurfaceView *view = w.surfaceView();
        QVERIFY(QTest::qWaitFor([&] { return !view->isRendering(); }, test::ms(60000)));
        for (int k = 0; k < 3; ++k) {
            view->orbit(40, 10);
            view->zoomBy(k == 1 ? 1e6 : 1e-6);
            view->repaint();
            QTest::keyClick(view, Qt::Key_Home);
            QCoreApplication::processEvents();
        }
        QVERIFY(QTest::qWaitFor([&] { return !view->isRendering(); }, test::ms(60000)));
        QVERIFY(!w.grab().isNull());
        QVERIFY(!view->renderImage(QSize(300, 200)).isNull());
        // Drawn, or the reason is in the status bar.
        QVERIFY(view->mesh().size() > 0 || !w.controller()->problem().isEmpty());
    }
};

AWB_TEST_MAIN(TestExtremeCoordinates)
#include "test_extreme_coordinates.moc"
