// The property commands (the one template behind every parameter edit: scheme and each of its
// parameters, start set, algorithm, style, eigenvalue plot settings), compound edits and the
// modified state: apply, assert, undo, assert the original state exactly, redo (STYLE.md §11).
// No-op edits leave no step; refused values change nothing.

#include "TestProjects.h"

#include "model/Commands.h"

#include <QSignalSpy>
#include <QtTest>

#include "TestMain.h"

using namespace awb;
using awb::test::curve;
using awb::test::curveNamed;
using awb::test::roundTrip;
using awb::test::scheme;

class TestPropertyCommands : public QObject {
    Q_OBJECT

private slots:
    void init()
    {
        m_project = std::make_unique<Project>();
        test::fillSampleProject(*m_project);
        m_project->undoStack()->clear();
        m_c = curveNamed(*m_project, "B-spline");
        QVERIFY(m_c);
    }

    // ---- parameters (the property template) -------------------------------------------------

    void changeScheme_data()
    {
        QTest::addColumn<int>("kind");
        QTest::addColumn<QString>("parameter");
        using K = SchemeSpec::Kind;
        QTest::newRow("kind") << int(K::FourPoint) << "";
        QTest::newRow("bspline degree") << int(K::BSpline) << "degree";
        QTest::newRow("end-interpolating degree") << int(K::EndInterpolatingBSpline) << "degree";
        QTest::newRow("bezier degree") << int(K::Bezier) << "degree";
        QTest::newRow("bezier real t") << int(K::Bezier) << "t";
        QTest::newRow("bezier complex t") << int(K::Bezier) << "complex t";
        QTest::newRow("omega") << int(K::FourPoint) << "omega";
        QTest::newRow("a") << int(K::CornerCutting) << "a";
        QTest::newRow("b") << int(K::CornerCutting) << "b";
        QTest::newRow("matrices") << int(K::Matrices) << "matrices";
    }

    void changeScheme()
    {
        QFETCH(int, kind);
        QFETCH(QString, parameter);
        // Start from the kind itself so that only the one parameter changes.
        SchemeSpec start = m_c->scheme();
        start.kind = SchemeSpec::Kind(kind);
        if (start.kind == SchemeSpec::Kind::Matrices)
            start.matrices = test::chaikinMatrices();
        if (!parameter.isEmpty()) {
            QVERIFY(m_c->setScheme(start));
            m_project->undoStack()->clear();
        }
        const SchemeSpec original = m_c->scheme();
        SchemeSpec next = original;
        if (parameter.isEmpty())
            next.kind = SchemeSpec::Kind(kind);
        else if (parameter == "degree")
            next.degree = 5;
        else if (parameter == "t")
            next.t = 0.3;
        else if (parameter == "complex t")
            next.t = {0.5, 0.2886751345948129};
        else if (parameter == "omega")
            next.omega = -0.125;
        else if (parameter == "a")
            next.a = 0.2;
        else if (parameter == "b")
            next.b = 0.9;
        else if (parameter == "matrices")
            next.matrices[1].row(0) << 0.5, 0.5, 0.0;
        QVERIFY(!next.check());
        QSignalSpy spy(m_c, &SubdivisionCurveItem::schemeChanged);
        QSignalSpy derived(m_c, &Item::derivedChanged);
        roundTrip(
            *m_project, [&] { QVERIFY(m_c->setScheme(next)); },
            [&] { QVERIFY(m_c->scheme() == next); },
            [&] { QVERIFY(m_c->scheme() == original); });
        QCOMPARE(spy.count(), 5);
        QCOMPARE(derived.count(), 5);
    }

    void schemeSliderDragIsOneStep()
    {
        SchemeSpec s = scheme(SchemeSpec::Kind::FourPoint);
        QVERIFY(m_c->setScheme(s));
        const int index = m_project->undoStack()->index();
        const int drag = m_project->beginGesture();
        for (int k = 1; k <= 30; ++k) {
            s.omega = 0.0625 + k * 0.001;
            QVERIFY(m_c->setScheme(s, drag));
        }
        QCOMPARE(m_project->undoStack()->index(), index + 1);
        m_project->undoStack()->undo();
        QCOMPARE(m_c->scheme().omega, 1.0 / 16.0);
    }

    void schemeRefusals()
    {
        const int index = m_project->undoStack()->index();
        SchemeSpec s = scheme(SchemeSpec::Kind::BSpline);
        s.degree = 0;
        QVERIFY(m_c->checkScheme(s));
        QCOMPARE(m_c->checkScheme(s)->field, QString("scheme.degree"));
        QVERIFY(!m_c->setScheme(s));
        s = scheme(SchemeSpec::Kind::CornerCutting);
        s.a = 0.8;
        s.b = 0.6;
        QVERIFY(!m_c->setScheme(s));
        QCOMPARE(s.check()->field, QString("b"));
        s = scheme(SchemeSpec::Kind::Bezier);
        s.t = {0.5, 0.9}; // |t| > 1
        QVERIFY(!m_c->setScheme(s));
        s.t = 1.5;
        QVERIFY(!m_c->setScheme(s));
        s = scheme(SchemeSpec::Kind::Matrices);
        s.matrices = test::chaikinMatrices();
        s.matrices[0](1, 1) = 0.5; // row 2 of S_1 no longer sums to 1
        QVERIFY(!m_c->setScheme(s));
        QVERIFY(s.check()->message.contains("row 2 sums to"));
        // Eight maps at depth 12 would make 8^12 = 2^36 images: the scheme is refused.
        AlgorithmSpec a = m_c->algorithm();
        a.depth = 12;
        QVERIFY(m_c->setAlgorithm(a));
        s.matrices = std::vector<Mat>(8, Mat::Identity(3, 3));
        QCOMPARE(m_c->checkScheme(s)->field, QString("algorithm.depth"));
        QVERIFY(!m_c->setScheme(s));
        QCOMPARE(m_project->undoStack()->index(), index + 1);
        QCOMPARE(m_c->scheme().kind, SchemeSpec::Kind::BSpline);
    }

    void changeStartSet()
    {
        const StartSetSpec original = m_c->startSet();
        StartSetSpec s{StartSetSpec::Kind::Triangle, {{0, 0}, {1, 0}, {0, 1}}};
        QSignalSpy spy(m_c, &AttractorItem::startSetChanged);
        roundTrip(
            *m_project, [&] { QVERIFY(m_c->setStartSet(s)); },
            [&] { QVERIFY(m_c->startSet() == s); },
            [&] { QVERIFY(m_c->startSet() == original); });
        QCOMPARE(spy.count(), 5);
        QVERIFY(!m_c->setStartSet({StartSetSpec::Kind::Segment, {{0, 0}}}));
        QVERIFY(!m_c->setStartSet({StartSetSpec::Kind::Polygon, {{0, 0}, {1, 1}}}));
        QVERIFY(!m_c->setStartSet({StartSetSpec::Kind::Points, {}}));
    }

    void changeAlgorithm_data()
    {
        QTest::addColumn<QString>("field");
        for (const char *f : {"mode", "depth", "samples", "probabilities", "seed"})
            QTest::newRow(f) << f;
    }

    void changeAlgorithm()
    {
        QFETCH(QString, field);
        const AlgorithmSpec original = m_c->algorithm();
        AlgorithmSpec next = original;
        if (field == "mode")
            next.mode = AlgorithmSpec::Mode::Random;
        else if (field == "depth")
            next.depth = 14;
        else if (field == "samples")
            next.samples = 123456;
        else if (field == "probabilities")
            next.probabilities = {0.2, 0.8};
        else
            next.seed = 987654321;
        QSignalSpy spy(m_c, &AttractorItem::algorithmChanged);
        roundTrip(
            *m_project, [&] { QVERIFY(m_c->setAlgorithm(next)); },
            [&] { QVERIFY(m_c->algorithm() == next); },
            [&] { QVERIFY(m_c->algorithm() == original); });
        QCOMPARE(spy.count(), 5);
    }

    void algorithmRefusals()
    {
        AlgorithmSpec a = m_c->algorithm();
        a.depth = 65;
        QVERIFY(!m_c->setAlgorithm(a));
        a.depth = 32; // 2^32 images
        QVERIFY(m_c->checkAlgorithm(a)->message.contains("2^31"));
        QVERIFY(!m_c->setAlgorithm(a));
        a.depth = 31;
        QVERIFY(m_c->setAlgorithm(a));
        a.samples = 0;
        QVERIFY(!m_c->setAlgorithm(a));
        a.samples = 10;
        a.probabilities = {-0.5, 1.5};
        QVERIFY(!m_c->setAlgorithm(a));
        a.probabilities = {0, 0};
        QVERIFY(!m_c->setAlgorithm(a));
    }

    void changeStyle_data()
    {
        QTest::addColumn<QString>("field");
        for (const char *f : {"color_by", "prefix_length", "point_size", "colors"})
            QTest::newRow(f) << f;
    }

    void changeStyle()
    {
        QFETCH(QString, field);
        auto *plot = m_project->findItem("Spectrum"); // any item kind has a style
        for (Item *item : {static_cast<Item *>(m_c), plot}) {
            const StyleSpec original = item->style();
            StyleSpec next = original;
            if (field == "color_by")
                next.colorBy = StyleSpec::ColorBy::Address;
            else if (field == "prefix_length")
                next.prefixLength = 3;
            else if (field == "point_size")
                next.pointSize = 4.5;
            else
                next.colors = {"#ff0000", "#00ff7f"};
            roundTrip(
                *m_project, [&] { QVERIFY(item->setStyle(next)); },
                [&] { QVERIFY(item->style() == next); },
                [&] { QVERIFY(item->style() == original); });
        }
        StyleSpec bad;
        bad.colors = {"red"};
        QVERIFY(!m_c->setStyle(bad));
        bad.colors = {"#FF0000"};
        QVERIFY(!m_c->setStyle(bad));
        bad = {};
        bad.prefixLength = 4;
        QVERIFY(!m_c->setStyle(bad));
        bad = {};
        bad.pointSize = 0;
        QVERIFY(!m_c->setStyle(bad));
    }

    void changePlotSourceAndMatrices()
    {
        auto *plot = dynamic_cast<EigenvaluePlotItem *>(m_project->findItem("Spectrum"));
        roundTrip(
            *m_project, [&] { QVERIFY(plot->setSource("Chaikin")); },
            [&] { QCOMPARE(plot->source(), QString("Chaikin")); },
            [&] { QCOMPARE(plot->source(), QString("B-spline")); });
        roundTrip(
            *m_project, [&] { QVERIFY(plot->setMatrixKind(EigenvaluePlotItem::MatrixKind::S)); },
            [&] { QCOMPARE(plot->matrixKind(), EigenvaluePlotItem::MatrixKind::S); },
            [&] { QCOMPARE(plot->matrixKind(), EigenvaluePlotItem::MatrixKind::A); });
    }

    void noOpEditsLeaveNoStep()
    {
        const int index = m_project->undoStack()->index();
        QSignalSpy changed(m_c, &Item::changed);
        QVERIFY(m_c->setScheme(m_c->scheme()));
        QVERIFY(m_c->setStartSet(m_c->startSet()));
        QVERIFY(m_c->setAlgorithm(m_c->algorithm()));
        QVERIFY(m_c->setStyle(m_c->style()));
        QCOMPARE(m_project->undoStack()->index(), index);
        QCOMPARE(changed.count(), 0);
        QVERIFY(!m_project->isModified());
    }

    // ---- compound edits and the modified state ----------------------------------------------

    void compoundEditIsOneStep()
    {
        const QList<Item *> items = m_project->items();
        StyleSpec style;
        style.pointSize = 7;
        roundTrip(
            *m_project,
            [&] {
                CompoundEdit edit(m_project.get(), "Style all");
                for (Item *item : items) {
                    CompoundEdit nested(m_project.get(), "nested");
                    QVERIFY(item->setStyle(style));
                }
                QVERIFY(m_c->moveControlPoint(0, {3, 3}));
            },
            [&] {
                for (Item *item : items)
                    QCOMPARE(item->style().pointSize, 7.0);
            },
            [&] {
                for (Item *item : items)
                    QCOMPARE(item->style().pointSize, 2.0);
            });
        QCOMPARE(m_project->undoStack()->text(m_project->undoStack()->index() - 1),
                 QString("Style all"));
        const int index = m_project->undoStack()->index();
        { CompoundEdit empty(m_project.get(), "nothing"); }
        QCOMPARE(m_project->undoStack()->index(), index);
    }

    void modifiedFollowsTheStack()
    {
        QTemporaryDir dir;
        const QString file = dir.filePath("m.awb");
        QVERIFY(m_project->saveAs(file));
        QVERIFY(!m_project->isModified());
        QSignalSpy spy(m_project.get(), &Project::modifiedChanged);
        m_c->moveControlPoint(0, {1, 1});
        QVERIFY(m_project->isModified());
        QCOMPARE(spy.count(), 1);
        QCOMPARE(spy.last().at(0).toBool(), true);
        m_project->undoStack()->undo();
        QVERIFY(!m_project->isModified());
        QCOMPARE(spy.last().at(0).toBool(), false);
        m_project->undoStack()->redo();
        QVERIFY(m_project->isModified());
        QVERIFY(m_project->save());
        QVERIFY(!m_project->isModified());
        m_project->undoStack()->undo(); // before the save: modified again
        QVERIFY(m_project->isModified());
    }

    void detachedItemsApplyDirectly()
    {
        SubdivisionCurveItem item;
        QSignalSpy spy(&item, &SubdivisionCurveItem::schemeChanged);
        SchemeSpec s = scheme(SchemeSpec::Kind::Chaikin);
        QVERIFY(item.setScheme(s));
        QVERIFY(item.scheme() == s);
        QCOMPARE(spy.count(), 1);
        QVERIFY(item.setName("Free"));
        QCOMPARE(item.name(), QString("Free"));
        QVERIFY(item.moveControlPoint(0, {-3, -3}));
        QCOMPARE(item.controlPoints()[0], (Point{-3, -3}));
    }

private:
    std::unique_ptr<Project> m_project;
    SubdivisionCurveItem *m_c = nullptr;
};

AWB_TEST_GUILESS_MAIN(TestPropertyCommands)
#include "test_property_commands.moc"
