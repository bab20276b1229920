// A random sequence of 2000 edits of every kind (with undo/redo and new branches mixed in),
// undone completely, serializes byte-identical to the start; redone, identical to the end.
// Qt's model checker watches the tree model all along. AWB_RANDOM_SEED picks another sequence.

#include "TestProjects.h"

#include "model/ProjectTreeModel.h"

#include <QAbstractItemModelTester>
#include <QtTest>

#include "TestMain.h"

#include <random>

using namespace awb;
using K = SchemeSpec::Kind;

namespace {

class Editor {
public:
    Editor(Project &project, quint64 seed) : m_p(project), m_rng(seed) {}

    // One random edit attempt; true when it left a new undo step.
    bool step()
    {
        const int before = m_p.undoStack()->index();
        edit(index(17));
        return m_p.undoStack()->index() == before + 1;
    }

private:
    double uniform(double a, double b) { return std::uniform_real_distribution<>(a, b)(m_rng); }
    int index(int n) { return n > 0 ? std::uniform_int_distribution<>(0, n - 1)(m_rng) : 0; }
    bool coin(double p = 0.5) { return uniform(0, 1) < p; }
    Point point() { return {uniform(-10, 10), uniform(-10, 10)}; }

    Item *anyItem()
    {
        const QList<Item *> items = m_p.items();
        return items.isEmpty() ? nullptr : items[index(int(items.size()))];
    }

    SubdivisionCurveItem *anyCurve()
    {
        QList<SubdivisionCurveItem *> curves;
        for (Item *i : m_p.items())
            if (auto *c = dynamic_cast<SubdivisionCurveItem *>(i))
                curves << c;
        return curves.isEmpty() ? nullptr : curves[index(int(curves.size()))];
    }

    SchemeSpec randomScheme(const SchemeSpec &from)
    {
        SchemeSpec s = from;
        switch (index(7)) {
        case 0: s.kind = K(index(6)); break; // any kind but matrices
        case 1: s.degree = 1 + index(6); break;
        case 2: s.t = {uniform(0.2, 0.8), coin() ? 0.0 : uniform(-0.3, 0.3)}; break;
        case 3: s.omega = uniform(-0.2, 0.2); break;
        case 4:
            s.a = uniform(0.05, 0.45);
            s.b = uniform(0.55, 0.95);
            break;
        case 5:
            s.kind = K::Matrices;
            s.matrices = test::chaikinMatrices();
            s.matrices[0].row(0) << 1 - uniform(0, 0.5), 0, 0;
            s.matrices[0](0, 1) = 1 - s.matrices[0](0, 0);
            break;
        default: s.kind = K::Bezier; break;
        }
        return s;
    }

    void edit(int what)
    {
        SubdivisionCurveItem *c = anyCurve();
        Item *item = anyItem();
        switch (what) {
        case 0: { // add a curve, maybe as a child
            PointList points;
            for (int k = 0, n = 3 + index(5); k < n; ++k)
                points.push_back(point());
            auto fresh = test::curve("curve", randomScheme(SchemeSpec()), points);
            m_p.addItem(std::move(fresh), coin(0.3) ? item : nullptr, index(4) - 1);
            break;
        }
        case 1: { // add an eigenvalue plot
            auto plot = std::make_unique<EigenvaluePlotItem>();
            plot->setSource(c ? c->name() : QString());
            m_p.addItem(std::move(plot), nullptr, -1);
            break;
        }
        case 2:
            if (item && m_p.items().size() > 10)
                m_p.removeItem(item);
            break;
        case 3:
            if (m_p.items().size() > 12)
                m_p.removeItems({anyItem(), anyItem()});
            break;
        case 4: // rename (sometimes to a taken name: refused)
            if (item)
                m_p.renameItem(item, coin(0.8) ? QString("n%1").arg(index(100000))
                                               : anyItem()->name());
            break;
        case 5: // move within or across parents (sometimes impossible: refused)
            if (item) {
                Item *parent = coin(0.3) ? anyItem() : nullptr;
                m_p.moveItem(item, parent, index(m_p.childCount(parent) + 1));
            }
            break;
        case 6: // a drag of one point
            if (c && !c->controlPoints().empty()) {
                const int drag = m_p.beginGesture(), i = index(int(c->controlPoints().size()));
                for (int k = 0, n = 1 + index(6); k < n; ++k)
                    c->moveControlPoint(i, point(), drag);
            }
            break;
        case 7: // a drag of several points
            if (c && c->controlPoints().size() > 1) {
                const int drag = m_p.beginGesture();
                for (int k = 0; k < 3; ++k)
                    c->moveControlPoints({{0, point()}, {1, point()}}, drag);
            }
            break;
        case 8:
            if (c)
                c->insertControlPoint(index(int(c->controlPoints().size()) + 1), point());
            break;
        case 9:
            if (c && c->controlPoints().size() > 2)
                c->removeControlPoint(index(int(c->controlPoints().size())));
            break;
        case 10:
            if (c && c->controlPoints().size() > 3)
                c->removeControlPoints({0, int(c->controlPoints().size()) - 1});
            break;
        case 11:
            if (c)
                c->setScheme(randomScheme(c->scheme()), coin(0.2) ? m_p.beginGesture() : 0);
            break;
        case 12:
            if (c) {
                StartSetSpec s{StartSetSpec::Kind(index(5)), {}};
                const int n[] = {1, 2, 3, 3 + index(3), 1 + index(4)};
                for (int k = 0; k < n[int(s.kind)]; ++k)
                    s.points.push_back(point());
                c->setStartSet(s);
            }
            break;
        case 13:
            if (c) {
                AlgorithmSpec a = c->algorithm();
                a.mode = AlgorithmSpec::Mode(index(2));
                a.depth = index(20);
                a.samples = 1 + index(1000000);
                a.probabilities = coin() ? std::vector<double>{} : std::vector<double>{0.3, 0.7};
                a.seed = index(1 << 30);
                c->setAlgorithm(a);
            }
            break;
        case 14:
            if (item) {
                StyleSpec s;
                s.colorBy = StyleSpec::ColorBy(index(3));
                s.prefixLength = 1 + index(3);
                s.pointSize = uniform(0.5, 8);
                if (coin())
                    s.colors = {"#12ab34", QString("#%1").arg(index(0xffffff), 6, 16, QChar('0'))};
                item->setStyle(s);
            }
            break;
        case 15: // a plot's source or matrices
            for (Item *i : m_p.items())
                if (auto *plot = dynamic_cast<EigenvaluePlotItem *>(i)) {
                    if (coin())
                        plot->setMatrixKind(EigenvaluePlotItem::MatrixKind(index(2)));
                    else
                        plot->setSource(anyItem()->name());
                    break;
                }
            break;
        default: { // a multi-item edit as one compound step
            CompoundEdit compound(&m_p, "several");
            for (int k = 0; k < 3; ++k)
                if (Item *i = anyItem()) {
                    StyleSpec s = i->style();
                    s.pointSize = uniform(0.5, 8);
                    i->setStyle(s);
                }
            if (c && !c->controlPoints().empty())
                c->moveControlPoint(0, point());
            break;
        }
        }
    }

    Project &m_p;
    std::mt19937_64 m_rng;
};

} // namespace

class TestRandomEdits : public QObject {
    Q_OBJECT

private slots:
    void undoAllRedoAll()
    {
        const quint64 seed = qEnvironmentVariableIsSet("AWB_RANDOM_SEED")
                                 ? qEnvironmentVariable("AWB_RANDOM_SEED").toULongLong()
                                 : 20240501;
        qInfo("seed %llu", seed);
        Project project;
        ProjectTreeModel model(&project);
        QAbstractItemModelTester tester(&model,
                                        QAbstractItemModelTester::FailureReportingMode::QtTest);
        test::fillSampleProject(project);
        QTemporaryDir dir;
        QVERIFY(project.saveAs(dir.filePath("start.awb")));
        Project start;
        QVERIFY(start.open(dir.filePath("start.awb"))); // the edits start from a loaded file
        project.undoStack()->clear();
        const QByteArray startBytes = project.serialize();
        QCOMPARE(startBytes, start.serialize());

        Editor editor(project, seed);
        std::mt19937 rng{unsigned(seed)};
        int edits = 0, attempts = 0;
        while (edits < 2000) {
            QVERIFY2(++attempts < 20000, "the editor keeps failing to edit");
            // Now and then undo a few steps, redo some, and edit from there (which discards
            // the rest of the redo branch).
            if (rng() % 50 == 0) {
                for (int k = int(rng() % 6); k > 0 && project.undoStack()->canUndo(); --k)
                    project.undoStack()->undo();
                for (int k = int(rng() % 3); k > 0 && project.undoStack()->canRedo(); --k)
                    project.undoStack()->redo();
            }
            if (editor.step())
                ++edits;
            if (QTest::currentTestFailed())
                return;
        }
        while (project.undoStack()->canRedo()) // a last edit that was refused
            project.undoStack()->redo();
        const QByteArray endBytes = project.serialize();
        QVERIFY(endBytes != startBytes);
        const int steps = project.undoStack()->index();
        QVERIFY(steps > 1000);
        qInfo("%d edits in %d attempts; %d undo steps on the stack; %d items at the end",
              edits, attempts, steps, int(project.items().size()));

        // The derived data of the end state, to compare with after undo/redo.
        QStringList endProblems = project.problems();

        while (project.undoStack()->canUndo())
            project.undoStack()->undo();
        QCOMPARE(project.serialize(), startBytes);
        QVERIFY(!project.isModified());
        while (project.undoStack()->canRedo())
            project.undoStack()->redo();
        QCOMPARE(project.undoStack()->index(), steps);
        QCOMPARE(project.serialize(), endBytes);
        QCOMPARE(project.problems(), endProblems);

        // And the end state saves and loads to the same bytes.
        QVERIFY(project.saveAs(dir.filePath("end.awb")));
        Project end;
        QString error;
        QVERIFY2(end.open(dir.filePath("end.awb"), &error), qPrintable(error));
        QCOMPARE(end.serialize(), endBytes);
    }
};

AWB_TEST_GUILESS_MAIN(TestRandomEdits)
#include "test_random_edits.moc"
