// Parameter animation in the window (issue 16 part 2): the Animation dock shows the keys of the
// current item; a frame (slider, Play) is drawn in the views -- attractor, spectrum, matrices --
// while the document stays as it is; Set Key and Remove are undoable; Stop returns the views
// to the item.
#include "TestPaths.h"
#include "gui/app/AnimationPanel.h"
#include "gui/app/ItemController.h"
#include "gui/app/MainWindow.h"
#include "gui/views/AttractorView.h"
#include "gui/views/SpectrumView.h"
#include "core/analysis/Spectrum.h"
#include "model/Animation.h"
#include "model/AttractorItem.h"
#include "model/Project.h"

#include <QPushButton>
#include <QTreeWidget>
#include <QUndoStack>
#include <QtTest>

#include "TestMain.h"

#include "TestTime.h"

#include <numbers>

#include "WindowTestSupport.h"

using namespace awb;

namespace {

const QString fourPoint = QStringLiteral("Four-point scheme, tension ω from 0 to 1/4");
const QString levy = QStringLiteral("Complex de Casteljau t on a circle through the Lévy t = 1/2 + i/2");

QString examplePath()
{
    return awb::test::sourceDir()
           + QStringLiteral("/examples/animation-four-point-omega-and-complex-t.awb");
}

std::vector<Complex> shownEigenvalues(MainWindow &w)
{
    // The docks follow the views at the next turn of the event loop (FrameBudget).
    QCoreApplication::processEvents();
    std::vector<Complex> all;
    for (const MapSpectrum &m : w.spectrumView()->maps())
        all.insert(all.end(), m.spectrum.values.begin(), m.spectrum.values.end());
    return all;
}

// The eigenvalues of the S_i of `item`, as the Spectrum dock lists them.
std::vector<Complex> eigenvaluesOf(const AttractorItem &item)
{
    std::vector<Complex> all;
    const auto d = item.derivedIfs();
    for (std::size_t i = 0; d && i < std::size_t(d->S.count()); ++i) {
        const Spectrum s = d->S.isComplex() ? spectrum(d->S.complex[i]) : spectrum(d->S.real[i]);
        all.insert(all.end(), s.values.begin(), s.values.end());
    }
    return all;
}

bool close(const std::vector<Complex> &a, const std::vector<Complex> &b)
{
    if (a.size() != b.size() || a.empty())
        return false;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (std::abs(a[i] - b[i]) > 1e-12)
            return false;
    return true;
}

} // namespace

class TestAnimationPanel : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { test::useTestSettings("test_animation_panel"); }

    void framesDriveTheViewsNotTheDocument()
    {
        QTemporaryDir recovery;
        test::ShownWindow shown(recovery.path(), QSize(1400, 900));
        MainWindow &w = shown.window;
        QVERIFY(w.openFile(examplePath()));
        auto *item = qobject_cast<AttractorItem *>(w.project()->findItem(fourPoint));
        QVERIFY(item);
        w.setCurrentItem(item);
        AnimationPanel *panel = w.animationPanel();
        QCOMPARE(panel->item(), item);
        auto *tree = panel->findChild<QTreeWidget *>(QStringLiteral("animationTracks"));
        QCOMPARE(tree->topLevelItemCount(), 1);
        QCOMPARE(tree->topLevelItem(0)->childCount(), 3); // omega at 0, 1 and 4 s
        const std::vector<Complex> atZero = eigenvaluesOf(*item);
        QVERIFY(close(shownEigenvalues(w), atZero));
        const int steps = w.project()->undoStack()->count();
        const QByteArray saved = w.project()->serialize();

        // Frame 25 = 1 s: omega = 1/16. The spectrum is that of the frame's S_i.
        panel->setFrame(25);
        QVERIFY(panel->isPreviewing());
        const auto *frame = qobject_cast<const AttractorItem *>(w.controller()->frame());
        QVERIFY(frame);
        QCOMPARE(frame->parameter("scheme.omega").toDouble(), 0.0625);
        QCOMPARE(w.controller()->drawnItem(), frame);
        QVERIFY(close(shownEigenvalues(w), eigenvaluesOf(*frame)));
        QVERIFY(!close(shownEigenvalues(w), atZero)); // they moved
        QVERIFY(!w.attractorView()->controlPointsEditable()); // a frame is not edited
        QVERIFY(test::waitForFinalImage(w.attractorView()));
        // The document did not move.
        QCOMPARE(item->parameter("scheme.omega").toDouble(), 0.0);
        QCOMPARE(w.project()->undoStack()->count(), steps);
        QCOMPARE(w.project()->serialize(), saved);

        // Play advances the frames; Stop returns to the item.
        panel->play();
        QVERIFY(panel->isPlaying());
        QTRY_VERIFY_WITH_TIMEOUT(panel->frame() > 26, awb::test::ms(5000));
        panel->stop();
        QVERIFY(!panel->isPlaying());
        QVERIFY(!panel->isPreviewing());
        QCOMPARE(w.controller()->frame(), nullptr);
        QCOMPARE(w.controller()->drawnItem(), item);
        QVERIFY(close(shownEigenvalues(w), atZero));
        QVERIFY(w.attractorView()->controlPointsEditable());
    }

    void setKeyAndRemoveAreUndoable()
    {
        QTemporaryDir recovery;
        test::ShownWindow shown(recovery.path(), QSize(1400, 900));
        MainWindow &w = shown.window;
        QVERIFY(w.openFile(examplePath()));
        auto *item = qobject_cast<AttractorItem *>(w.project()->findItem(fourPoint));
        w.setCurrentItem(item);
        AnimationPanel *panel = w.animationPanel();
        QUndoStack *stack = w.project()->undoStack();
        const AnimationSpec before = item->animation();

        // The keying workflow: a value in Properties, a time on the slider, Set Key.
        QVERIFY(item->setParameter("scheme.omega", 0.2));
        panel->setFrame(50); // 2 s
        const int steps = stack->count();
        QString error;
        QVERIFY2(panel->setKey("scheme.omega", &error), qPrintable(error));
        QCOMPARE(stack->count(), steps + 1);
        const AnimationTrack &track = item->animation().tracks.front();
        QCOMPARE(int(track.keys.size()), 4);
        QCOMPARE(track.keys[2].time, 2.0);
        QCOMPARE(track.keys[2].value, std::vector<double>{0.2});
        // The frame shown follows the new key.
        QCOMPARE(w.controller()->frame()->parameter("scheme.omega").toDouble(), 0.2);
        stack->undo();
        QCOMPARE(int(item->animation().tracks.front().keys.size()), 3);

        // A control point keyed as a second track, then removed with the Remove button.
        QVERIFY(panel->setKey("points.0.0", &error));
        QCOMPARE(int(item->animation().tracks.size()), 2);
        auto *tree = panel->findChild<QTreeWidget *>(QStringLiteral("animationTracks"));
        tree->setCurrentItem(tree->topLevelItem(1));
        panel->findChild<QPushButton *>(QStringLiteral("animationRemove"))->click();
        QCOMPARE(int(item->animation().tracks.size()), 1);
        stack->undo();
        QCOMPARE(int(item->animation().tracks.size()), 2);
        stack->undo();
        QCOMPARE(item->animation(), before);

        // A value the item refuses is not keyed: the message says why.
        QVERIFY(!panel->setKey("scheme.nope", &error));
        QVERIFY2(error.contains("scheme.nope"), qPrintable(error));
    }

    // A complex de Casteljau t turning on a circle (004 §3.7): the eigenvalues of the complex
    // S_i move in the complex plane.
    void complexEigenvaluesMove()
    {
        QTemporaryDir recovery;
        test::ShownWindow shown(recovery.path(), QSize(1400, 900));
        MainWindow &w = shown.window;
        QVERIFY(w.openFile(examplePath()));
        auto *item = qobject_cast<AttractorItem *>(w.project()->findItem(levy));
        QVERIFY(item);
        w.setCurrentItem(item);
        AnimationPanel *panel = w.animationPanel();
        panel->setFrame(0);
        const std::vector<Complex> first = shownEigenvalues(w);
        panel->setFrame(25); // 1 s of 6: t turned by 60 degrees about 1/2
        const auto *frame = qobject_cast<const AttractorItem *>(w.controller()->frame());
        QVERIFY(frame);
        const QPointF t = frame->parameter("scheme.t").toPointF();
        const double angle = std::numbers::pi / 3;
        QVERIFY(std::abs(t.x() - (0.5 - 0.35 * std::sin(angle))) < 1e-12);
        QVERIFY(std::abs(t.y() - 0.35 * std::cos(angle)) < 1e-12);
        const std::vector<Complex> later = shownEigenvalues(w);
        QVERIFY(close(later, eigenvaluesOf(*frame)));
        QVERIFY(!close(later, first));
        bool complex = false;
        for (const Complex &z : later)
            complex = complex || std::abs(z.imag()) > 1e-3;
        QVERIFY(complex);
    }
};

AWB_TEST_MAIN(TestAnimationPanel)
#include "test_animation_panel.moc"
