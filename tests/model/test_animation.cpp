// Parameter animation (issue 16 part 2): keyframed tracks of an item's numbers, saved and
// undoable, and frames that are copies of the item at a time.
#include "TestProjects.h"

#include "model/Animation.h"
#include "model/ProjectIO.h"
#include "TestMain.h"

#include <QTest>

#include <cmath>
#include <numbers>

using namespace awb;
using namespace awb::test;

namespace {

AnimationTrack track(const QString &target, std::vector<AnimationKey> keys)
{
    AnimationTrack t;
    t.target = target;
    t.keys = std::move(keys);
    return t;
}

AnimationSpec spec(double duration, double fps, std::vector<AnimationTrack> tracks)
{
    AnimationSpec s;
    s.duration = duration;
    s.fps = fps;
    s.tracks = std::move(tracks);
    return s;
}

// The four-point curve of 000 Fig. 5 (six points: the scheme needs at least six).
std::unique_ptr<SubdivisionCurveItem> fourPoint(double omega)
{
    SchemeSpec s = scheme(SchemeSpec::Kind::FourPoint);
    s.omega = omega;
    return curve("Four-point", s, {{0, 0}, {1, 2}, {2.5, 2.25}, {4, 1}, {5.125, -0.5}, {6, 1}});
}

} // namespace

class TestAnimation : public QObject {
    Q_OBJECT
private slots:
    void interpolatesLinearlyAndHoldsOutside()
    {
        const AnimationTrack t = track("x", {{1.0, {0.0, 10.0}}, {3.0, {1.0, 30.0}}});
        QCOMPARE(t.valueAt(0.0, 4.0), (std::vector<double>{0.0, 10.0}));
        QCOMPARE(t.valueAt(2.0, 4.0), (std::vector<double>{0.5, 20.0}));
        QCOMPARE(t.valueAt(2.5, 4.0), (std::vector<double>{0.75, 25.0}));
        QCOMPARE(t.valueAt(4.0, 4.0), (std::vector<double>{1.0, 30.0}));
    }

    void smoothEasingIsSmoothstep()
    {
        AnimationTrack t = track("x", {{0.0, {0.0}}, {1.0, {1.0}}});
        t.easing = AnimationTrack::Easing::Smooth;
        QCOMPARE(t.valueAt(0.5, 1.0).front(), 0.5);
        QCOMPARE(t.valueAt(0.25, 1.0).front(), 0.15625); // 3/16 - 2/64
    }

    void circleTurnsAboutItsCentre()
    {
        AnimationTrack t = track("points.0.0", {{0.0, {2.0, 1.0}}});
        t.path = AnimationTrack::Path::Circle;
        t.center = {1.0, 1.0};
        t.turns = 1.0;
        const auto quarter = t.valueAt(1.0, 4.0);
        QVERIFY(std::abs(quarter[0] - 1.0) < 1e-15 && std::abs(quarter[1] - 2.0) < 1e-15);
        const auto whole = t.valueAt(4.0, 4.0);
        QVERIFY(std::abs(whole[0] - 2.0) < 1e-14 && std::abs(whole[1] - 1.0) < 1e-14);
    }

    void framesIncludeBothEnds()
    {
        const AnimationSpec s = spec(1.0, 4.0, {});
        QCOMPARE(s.frameCount(), 5);
        QCOMPARE(s.frameTime(2), 0.5);
        QCOMPARE(s.frameTime(4), 1.0);
        QCOMPARE(spec(2.0, 25.0, {}).frameCount(), 51);
    }

    // A frame is the item with its parameters set: the four-point mask at omega = 1/16 is
    // (-1/16, 9/16, 9/16, -1/16) (004 eq. 2.14), reached half-way from omega = 0 to 1/8.
    void frameIsTheItemWithTheValuesAtItsTime()
    {
        Project project;
        auto *item = static_cast<SubdivisionCurveItem *>(project.addItem(fourPoint(0.0)));
        QString error;
        QVERIFY2(item->setAnimation(
                     spec(1.0, 4.0, {track("scheme.omega", {{0.0, {0.0}}, {1.0, {0.125}}})}),
                     &error),
                 qPrintable(error));
        const auto frame = animatedCopy(*item, 0.5, &error);
        QVERIFY2(frame, qPrintable(error));
        QVERIFY(!frame->project());
        QCOMPARE(frame->parameter("scheme.omega").toDouble(), 0.0625);
        QCOMPARE(item->parameter("scheme.omega").toDouble(), 0.0); // the document stays

        auto reference = fourPoint(0.0625);
        const auto d = static_cast<AttractorItem *>(frame.get())->derivedIfs();
        const auto r = reference->derivedIfs();
        QVERIFY(d && r);
        QCOMPARE(d->S.real.size(), r->S.real.size());
        for (std::size_t i = 0; i < r->S.real.size(); ++i)
            QCOMPARE(d->S.real[i], r->S.real[i]);
        bool found = false; // the mask's 9/16 and -1/16 stand in a row of S_1
        for (int row = 0; row < r->S.real[0].rows(); ++row) {
            const auto v = r->S.real[0].row(row);
            if (std::abs(v.maxCoeff() - 9.0 / 16) < 1e-15 && std::abs(v.minCoeff() + 1.0 / 16) < 1e-15)
                found = true;
        }
        QVERIFY(found);
    }

    void editIsOneUndoStepAndSaves()
    {
        Project project;
        auto *item = static_cast<SubdivisionCurveItem *>(project.addItem(fourPoint(0.0)));
        const AnimationSpec s =
            spec(2.0, 10.0, {track("scheme.omega", {{0.0, {0.0}}, {2.0, {0.125}}})});
        roundTrip(
            project, [&] { QVERIFY(item->setAnimation(s)); },
            [&] { QCOMPARE(item->animation(), s); },
            [&] { QVERIFY(item->animation().isEmpty()); });
        // Saved and read back: the same animation and the same bytes.
        const QByteArray bytes = project.serialize();
        QVERIFY(bytes.contains("\"animation\""));
        ProjectData data;
        QString error;
        QVERIFY2(ProjectIO::parse(bytes, "saved.awb", &data, &error), qPrintable(error));
        QCOMPARE(data.items.front()->animation(), s);
        // Removing the animation removes the field (files without one stay as they were).
        QVERIFY(item->setAnimation(AnimationSpec{}));
        QVERIFY(!project.serialize().contains("\"animation\""));
    }

    void refusesWhatTheItemRefuses()
    {
        Project project;
        SchemeSpec cut = scheme(SchemeSpec::Kind::CornerCutting);
        auto *item = project.addItem(curve("Cut", cut, fivePoints()));
        const int steps = project.undoStack()->count();
        QString error;
        // a outside [0, 1] at the second key.
        QVERIFY(!item->setAnimation(spec(1.0, 25.0, {track("scheme.a", {{0.0, {0.25}}, {1.0, {2.0}}})}),
                                    &error));
        QVERIFY2(error.contains("scheme.a") && error.contains("1 s"), qPrintable(error));
        QVERIFY(!item->setAnimation(spec(1.0, 25.0, {track("scheme.nope", {{0.0, {1.0}}})}), &error));
        QVERIFY2(error.contains("scheme.nope"), qPrintable(error));
        QVERIFY(!item->setAnimation(
            spec(1.0, 25.0, {track("scheme.a", {{0.5, {0.2}}, {0.25, {0.3}}})}), &error));
        QVERIFY2(error.contains("increase"), qPrintable(error));
        QVERIFY(!item->setAnimation(spec(1.0, 25.0, {track("points.0.9", {{0.0, {1.0, 2.0}}})}),
                                    &error));
        QVERIFY2(error.contains("control point 10"), qPrintable(error));
        QVERIFY(!item->setAnimation(spec(1.0, 25.0, {track("points.0.1", {{0.0, {1.0}}})}), &error));
        QVERIFY2(error.contains("coordinates"), qPrintable(error));
        QVERIFY(!item->setAnimation(spec(0.0, 25.0, {track("scheme.a", {{0.0, {0.2}}})}), &error));
        QVERIFY2(error.contains("duration"), qPrintable(error));
        QCOMPARE(project.undoStack()->count(), steps); // nothing refused became an edit
        QVERIFY(item->animation().isEmpty());
    }

    void loaderNamesTheBadField()
    {
        Project project;
        auto *item = project.addItem(fourPoint(0.0));
        QVERIFY(item->setAnimation(spec(1.0, 25.0, {track("scheme.omega", {{0.0, {0.0}}, {1.0, {0.1}}})})));
        const QByteArray good = project.serialize();
        const auto refused = [&](QByteArray bytes, const char *expected) {
            ProjectData data;
            QString error;
            QVERIFY(!ProjectIO::parse(bytes, "bad.awb", &data, &error));
            QVERIFY2(error.contains(expected), qPrintable(error));
        };
        QByteArray bad = good;
        refused(bad.replace("\"fps\": 25", "\"fps\": 0.5"), "animation.fps");
        bad = good;
        refused(bad.replace("\"fps\": 25", "\"fps\": 1000"), "animation.fps");
        bad = good;
        refused(bad.replace("\"time\": 1", "\"time\": 5"), "animation.tracks[1].keys[2].time");
        bad = good;
        refused(bad.replace("\"time\": 1", "\"tme\": 1"), "animation.tracks[1].keys[2]");
    }

    // A track whose input the item does not have now (omega once the scheme is no longer the
    // four-point scheme) is inactive: the edit that removed omega is not refused, the file still
    // saves and loads, frames skip the track, and keying omega again needs the four-point scheme.
    void tracksOfVanishedInputsAreInactive()
    {
        Project project;
        auto *item = static_cast<SubdivisionCurveItem *>(project.addItem(fourPoint(0.0)));
        QVERIFY(item->setAnimation(spec(1.0, 25.0, {track("scheme.omega", {{0.0, {0.0}}, {1.0, {0.1}}}),
                                                    track("points.0.5", {{0.0, {6.0, 1.0}}, {1.0, {6.0, 2.0}}})})));
        SchemeSpec s = item->scheme();
        s.kind = SchemeSpec::Kind::BSpline;
        QVERIFY(item->setScheme(s));
        QVERIFY(item->removeControlPoint(5));
        QCOMPARE(inactiveAnimationTargets(*item), (QStringList{"scheme.omega", "points.0.5"}));
        // Saved and loaded with the inactive tracks kept.
        ProjectData data;
        QString error;
        QVERIFY2(ProjectIO::parse(project.serialize(), "saved.awb", &data, &error), qPrintable(error));
        QCOMPARE(data.items.front()->animation(), item->animation());
        // Frames skip them; another key can still be set.
        const auto frame = animatedCopy(*item, 0.5, &error);
        QVERIFY2(frame, qPrintable(error));
        AnimationSpec more = item->animation();
        more.tracks.push_back(track("points.0.0", {{0.0, {0.0, 0.0}}, {1.0, {0.5, 0.0}}}));
        QVERIFY2(item->setAnimation(more, &error), qPrintable(error));
        // A new track on an input that does not exist is refused.
        more.tracks.push_back(track("scheme.a", {{0.0, {0.2}}}));
        QVERIFY(!item->setAnimation(more, &error));
        QVERIFY2(error.contains("scheme.a"), qPrintable(error));
        // Back to the four-point scheme with six points: the tracks drive again.
        QVERIFY(item->insertControlPoint(5, {6, 1}));
        s.kind = SchemeSpec::Kind::FourPoint;
        QVERIFY(item->setScheme(s));
        QVERIFY(inactiveAnimationTargets(*item).isEmpty());
        const auto again = animatedCopy(*item, 0.5, &error);
        QVERIFY2(again, qPrintable(error));
        QCOMPARE(again->parameter("scheme.omega").toDouble(), 0.05);
    }

    void probabilitiesKeepTheirSum()
    {
        Project project;
        auto *item = static_cast<SubdivisionCurveItem *>(
            project.addItem(curve("B", scheme(SchemeSpec::Kind::BSpline), fivePoints())));
        AlgorithmSpec a = item->algorithm();
        a.mode = AlgorithmSpec::Mode::Random;
        QVERIFY(item->setAlgorithm(a));
        const int maps = item->mapCount();
        QCOMPARE(maps, 2);
        QString error;
        QVERIFY2(item->setAnimation(spec(2.0, 25.0, {track("probabilities", {{0.0, {0.8, 0.2}},
                                                                             {2.0, {0.2, 0.8}}})}),
                                    &error),
                 qPrintable(error));
        const auto frame = animatedCopy(*item, 0.5, &error);
        QVERIFY2(frame, qPrintable(error));
        const auto p = static_cast<AttractorItem *>(frame.get())->algorithm().probabilities;
        QCOMPARE(p.size(), std::size_t(2));
        QVERIFY(std::abs(p[0] - 0.65) < 1e-15 && std::abs(p[0] + p[1] - 1.0) < 1e-15);
    }

    // A control point turning about a centre, and a complex de Casteljau t along a path
    // (004 §3.7: the Lévy curve at t = 1/2 + i/2).
    void pointsAndComplexParameters()
    {
        Project project;
        SchemeSpec bezier = scheme(SchemeSpec::Kind::Bezier);
        bezier.degree = 2;
        bezier.t = {0.5, 0.5};
        auto *item = static_cast<SubdivisionCurveItem *>(
            project.addItem(curve("Levy", bezier, {{0, 0}, {0.5, 1.0 / 3.0}, {1, 0}})));
        AnimationTrack circle = track("points.0.2", {{0.0, {1.0, 0.0}}});
        circle.path = AnimationTrack::Path::Circle;
        circle.center = {0.5, 0.0};
        circle.turns = 0.5;
        const AnimationTrack t =
            track("scheme.t", {{0.0, {0.5, 0.5}}, {1.0, {0.5, 0.25}}});
        QString error;
        QVERIFY2(item->setAnimation(spec(1.0, 25.0, {circle, t}), &error), qPrintable(error));
        const QList<AnimationTarget> targets = animationTargets(*item);
        QVERIFY(std::any_of(targets.begin(), targets.end(),
                            [](const AnimationTarget &x) { return x.key == "scheme.t" && x.complex; }));
        const auto frame = animatedCopy(*item, 1.0, &error);
        QVERIFY2(frame, qPrintable(error));
        const auto *a = static_cast<AttractorItem *>(frame.get());
        QVERIFY(std::abs(a->controlPoints()[2].x - 0.0) < 1e-15); // half a turn about (0.5, 0)
        QVERIFY(std::abs(a->controlPoints()[2].y) < 1e-15);
        QCOMPARE(frame->parameter("scheme.t").toPointF(), QPointF(0.5, 0.25));
        // The animation travels with the copy: a frame knows where it came from.
        QCOMPARE(frame->animation(), item->animation());
    }
};

AWB_TEST_GUILESS_MAIN(TestAnimation)
#include "test_animation.moc"
