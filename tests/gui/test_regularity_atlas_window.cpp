// View > Regularity Atlas (issue 48): the window runs the Python module's atlas as a process
// and draws the rows as they arrive. The four-point family in one process gives the C^1 region
// up to omega* = 0.19273 (Hechler, Mößner & Reif 2009); the six-point family in two parameters
// runs on a local Dask cluster of two workers and shows as a map; a click adds an item at that
// member (one undo step); a bad form, a missing Python and Cancel each say what happened.

#include "gui/app/RegularityAtlasWindow.h"
#include "gui/views/AtlasPlot.h"
#include "model/Project.h"
#include "model/ProjectIO.h"
#include "model/SubdivisionCurveItem.h"

#include <QJsonDocument>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QtTest>

#include "TestMain.h"
#include "TestPaths.h"
#include "TestTime.h"

#include <qcustomplot.h>

#include <cmath>

using namespace awb;

namespace {

const char *kFourPoint = "000 Fig. 5: four-point scheme from a segment";
const char *kSixPointMask = "v, 0, w, 0, 1/2 - w - v, 1, 1/2 - w - v, 0, w, 0, v";

SubdivisionCurveItem *openFourPoint(Project &project)
{
    QString why;
    if (!project.open(awb::test::sourceDir() + "/examples/000-fig05-four-point-from-segment.awb",
                      &why))
        qWarning("%s", qPrintable(why));
    return qobject_cast<SubdivisionCurveItem *>(project.findItem(kFourPoint));
}

} // namespace

class TestRegularityAtlasWindow : public QObject {
    Q_OBJECT
private slots:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        if (qEnvironmentVariableIsSet("AWB_PYTHON_UNUSABLE"))
            QSKIP("the Python module cannot run in this build");
        QVERIFY2(!RegularityAtlasWindow::modulePath().isEmpty(),
                 "the package attractor_workbench is not built beside the tests");
        QSettings().remove(QStringLiteral("preferences"));
    }

    void fourPointInOneProcess()
    {
        Project project;
        auto *curve = openFourPoint(project);
        QVERIFY(curve);
        RegularityAtlasWindow window(&project);
        window.setItem(curve);
        // The form follows the scheme: omega of the four-point scheme.
        QCOMPARE(window.axes().size(), size_t(1));
        QCOMPARE(window.axes()[0].name, std::string("omega"));
        window.setAxes({{"omega", 0.1, 0.25, 7}});
        window.setTolerance(1e-4);
        window.setWhere(RegularityAtlasWindow::Where::InProcess);
        QSignalSpy done(&window, &RegularityAtlasWindow::finished);
        QVERIFY(window.start());
        QVERIFY(window.isRunning());
        QVERIFY(!window.start());   // one run at a time
        QVERIFY(done.wait(awb::test::ms(120000)));
        QVERIFY2(done.first().first().toBool(), qPrintable(window.statusText()));
        QVERIFY2(window.statusText().contains("C^1 from 0.1 to [0.192"),
                 qPrintable(window.statusText()));
        const AtlasPlot *plot = window.plot();
        QVERIFY(plot->rows().size() > 7);
        QCOMPARE(plot->plot()->graphCount(), 2);   // lower and upper bounds on r
        // Hover: the row under its own marker, and its certified bracket.
        for (size_t i : {size_t(0), plot->rows().size() - 1}) {
            const auto at = plot->rowAt(plot->rowPosition(i));
            QVERIFY(at.has_value());
            QCOMPARE(plot->rows()[*at].params, plot->rows()[i].params);
        }
        const QString tip = plot->rowText(plot->rows().front());
        QVERIFY2(tip.contains("omega = 0.1") && tip.contains("Hölder exponent r in [") &&
                     tip.contains("C¹ as asked: yes"),
                 qPrintable(tip));

        // A click's item: the member's scheme, one undo step.
        const int before = project.undoStack()->count();
        Item *added = window.addItemAt({0.125});
        QVERIFY2(added, qPrintable(window.statusText()));
        QCOMPARE(qobject_cast<SubdivisionCurveItem *>(added)->scheme().omega, 0.125);
        QVERIFY(added->name().contains("omega = 0.125"));
        QCOMPARE(project.undoStack()->count(), before + 1);
        project.undoStack()->undo();
        QVERIFY(!project.findItem(added->name()));
    }

    void sixPointPlaneOnALocalCluster()
    {
        QSettings().setValue(QStringLiteral("preferences/atlasWorkers"), 2);
        Project project;
        QString why;
        std::unique_ptr<Item> item = ProjectIO::itemFromJson(
            QJsonDocument::fromJson(R"({"type": "subdivision-curve", "name": "six-point",
                "scheme": {"kind": "mask", "arity": 2, "offset": -5,
                           "mask": ["3/256", 0, "-25/256", 0, "75/128", 1, "75/128", 0,
                                    "-25/256", 0, "3/256"]},
                "control_points": [[0, 0], [1, 2], [2, 1], [3, 3], [4, 0], [5, 1], [6, 2],
                                   [7, 0], [8, 1], [9, 0], [10, 2], [11, 1]]})")
                .object(),
            &why);
        QVERIFY2(item, qPrintable(why));
        auto *curve = qobject_cast<SubdivisionCurveItem *>(project.addItem(std::move(item)));
        RegularityAtlasWindow window(&project);
        window.setItem(curve);
        QCOMPARE(window.where(), RegularityAtlasWindow::Where::LocalCluster);
        window.setMask(QString::fromLatin1(kSixPointMask));
        window.setAxes({{"w", -0.5, 0.0, 3}, {"v", -0.02, 0.02, 3}});
        window.setRefinement(1);
        QSignalSpy done(&window, &RegularityAtlasWindow::finished);
        QVERIFY(window.start());
        QVERIFY(done.wait(awb::test::ms(180000)));
        QVERIFY2(done.first().first().toBool(), qPrintable(window.statusText()));
        QVERIFY2(window.statusText().contains("on 2 worker(s) (tcp://"),
                 qPrintable(window.statusText()));
        const AtlasPlot *plot = window.plot();
        QVERIFY(plot->rows().size() > 9);
        // The map: the four-point member (w = -1/8, v = 0) certified C^1, drawn in C^1's
        // colour where it sits.
        std::optional<size_t> four;
        for (size_t i = 0; i < plot->rows().size(); ++i)
            if (plot->rows()[i].params == std::vector<double>{-0.125, 0.0})
                four = i;
        QVERIFY(four.has_value());
        QCOMPARE(plot->rows()[*four].smoothness, 1);
        const QImage image = plot->plot()->toPixmap(0, 0, 1.0).toImage();
        const QPointF p = plot->rowPosition(*four);
        QCOMPARE(image.pixelColor(p.toPoint()).rgb(), AtlasPlot::classColour(1).rgb());
        QVERIFY(plot->rowText(plot->rows()[*four]).contains("w = -0.125, v = 0"));
        // An item at a member of the mask family.
        Item *added = window.addItemAt({-25.0 / 256, 3.0 / 256});
        QVERIFY2(added, qPrintable(window.statusText()));
        QVERIFY(qobject_cast<SubdivisionCurveItem *>(added)->scheme().mask.size() == 11);
        QSettings().remove(QStringLiteral("preferences"));
    }

    void refusalsAndCancel()
    {
        Project project;
        auto *curve = openFourPoint(project);
        QVERIFY(curve);
        RegularityAtlasWindow window(&project);
        QVERIFY(!window.start());
        QVERIFY(window.statusText().contains("Select a subdivision curve"));
        window.setItem(curve);
        window.setAxes({{"w", 0.0, 0.25, 5}});
        QVERIFY(!window.start());
        QVERIFY2(window.statusText().contains("has no parameter 'w'"),
                 qPrintable(window.statusText()));
        window.setAxes({{"omega", 0.3, 0.1, 5}});
        QVERIFY(!window.start());
        QVERIFY2(window.statusText().contains("from < to"), qPrintable(window.statusText()));
        window.setWhere(RegularityAtlasWindow::Where::Scheduler);
        window.setAxes({{"omega", 0.0, 0.25, 5}});
        QVERIFY(!window.start());
        QVERIFY2(window.statusText().contains("No Dask scheduler is set"),
                 qPrintable(window.statusText()));

        // No Python where the preferences say.
        window.setWhere(RegularityAtlasWindow::Where::InProcess);
        QSettings().setValue(QStringLiteral("preferences/python"),
                             QStringLiteral("/nonexistent/python3"));
        QSignalSpy done(&window, &RegularityAtlasWindow::finished);
        QVERIFY(window.start());
        QVERIFY(done.count() == 1 || done.wait(awb::test::ms(20000)));
        QVERIFY(!done.last().first().toBool());
        QVERIFY2(window.statusText().contains("could not start /nonexistent/python3"),
                 qPrintable(window.statusText()));
        QSettings().remove(QStringLiteral("preferences/python"));

        // Cancel during a long run: it stops, says so, and keeps the points so far.
        window.setAxes({{"omega", 0.0, 0.01, 400}});
        QVERIFY(window.start());
        QTRY_VERIFY_WITH_TIMEOUT(window.plot()->rows().size() > 0, awb::test::ms(60000));
        window.cancel();
        QVERIFY(done.wait(awb::test::ms(60000)));
        QVERIFY(!done.last().first().toBool());
        QVERIFY2(window.statusText().contains("Cancelled"), qPrintable(window.statusText()));
        QVERIFY(!window.isRunning());
        QVERIFY(window.plot()->rows().size() < 400);
    }
};

AWB_TEST_MAIN(TestRegularityAtlasWindow)
#include "test_regularity_atlas_window.moc"
