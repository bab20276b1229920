// ProjectTreeModel: Qt's own model checker watches it through inserts, removals, moves (within
// and across parents), renames, undo/redo and resets; the tree it shows mirrors the project;
// edits made through the model are single undo steps.

#include "TestProjects.h"

#include "model/ProjectTreeModel.h"

#include <QAbstractItemModelTester>
#include <QSignalSpy>
#include <QtTest>

#include "TestMain.h"

using namespace awb;
using awb::test::curve;
using awb::test::scheme;

namespace {

// The tree as the model shows it: "name(child, child)" ...
QString shape(const QAbstractItemModel &m, const QModelIndex &parent = {})
{
    QStringList parts;
    for (int r = 0; r < m.rowCount(parent); ++r) {
        const QModelIndex i = m.index(r, 0, parent);
        QString s = i.data().toString();
        if (m.rowCount(i) > 0)
            s += "(" + shape(m, i) + ")";
        parts << s;
    }
    return parts.join(", ");
}

// The same from the project itself.
QString shape(const Project &p, const Item *parent = nullptr)
{
    QStringList parts;
    for (int r = 0; r < p.childCount(parent); ++r) {
        const Item *i = p.child(parent, r);
        QString s = i->name();
        if (p.childCount(i) > 0)
            s += "(" + shape(p, i) + ")";
        parts << s;
    }
    return parts.join(", ");
}

} // namespace

class TestTreeModel : public QObject {
    Q_OBJECT

private slots:
    void init()
    {
        m_project = std::make_unique<Project>();
        m_model = std::make_unique<ProjectTreeModel>(m_project.get());
        m_tester = std::make_unique<QAbstractItemModelTester>(
            m_model.get(), QAbstractItemModelTester::FailureReportingMode::QtTest);
        test::fillSampleProject(*m_project);
    }

    void cleanup()
    {
        m_tester.reset();
        m_model.reset();
        m_project.reset();
    }

    void mirrorsTheProject()
    {
        QCOMPARE(shape(*m_model), shape(*m_project));
        QCOMPARE(shape(*m_model),
                 QString("B-spline, End-interpolating(Chaikin), Corner cutting, Four-point, "
                         "Lévy-like, Matrices, Spectrum"));
        const QModelIndex chaikin = m_model->indexOf(m_project->findItem("Chaikin"));
        QCOMPARE(chaikin.row(), 0);
        QCOMPARE(m_model->itemAt(chaikin.parent()), m_project->findItem("End-interpolating"));
        QCOMPARE(m_model->index(0, ProjectTreeModel::TypeColumn, chaikin.parent()).data(),
                 QVariant("Subdivision curve"));
        QCOMPARE(chaikin.data(ProjectTreeModel::ItemTypeRole), QVariant("subdivision-curve"));
        QCOMPARE(m_model->columnCount(), 2);
        QVERIFY(m_model->flags(chaikin) & Qt::ItemIsEditable);
        const QModelIndex four = m_model->indexOf(m_project->findItem("Four-point"));
        QVERIFY(four.data(ProjectTreeModel::DerivedErrorRole).toString().contains("needs"));
        // The tooltip: the whole name (the column elides it), the kind, the problem.
        const QString tip = four.data(Qt::ToolTipRole).toString();
        QVERIFY(tip.startsWith(QStringLiteral("Four-point\nSubdivision curve\n")));
        QVERIFY(tip.endsWith(four.data(ProjectTreeModel::DerivedErrorRole).toString()));
    }

    void followsEveryStructuralEdit()
    {
        Item *parent = m_project->findItem("Matrices");
        m_project->addItem(curve("x", scheme(SchemeSpec::Kind::Chaikin), {}), parent);
        m_project->addItem(curve("y", scheme(SchemeSpec::Kind::Chaikin), {}), parent, 0);
        m_project->addItem(curve("z", scheme(SchemeSpec::Kind::Chaikin), {}), nullptr, 0);
        QCOMPARE(shape(*m_model), shape(*m_project));
        m_project->moveItem(m_project->findItem("z"), nullptr, 5);             // down
        m_project->moveItem(m_project->findItem("Spectrum"), nullptr, 0);      // up
        m_project->moveItem(m_project->findItem("y"), parent, 1);              // within a child
        m_project->moveItem(m_project->findItem("Chaikin"), parent, 0);        // across parents
        m_project->moveItem(parent, m_project->findItem("B-spline"), 0);       // a subtree
        QCOMPARE(shape(*m_model), shape(*m_project));
        QCOMPARE(shape(*m_model),
                 QString("Spectrum, B-spline(Matrices(Chaikin, x, y)), End-interpolating, "
                         "Corner cutting, Four-point, Lévy-like, z"));
        m_project->renameItem(m_project->findItem("x"), "renamed");
        m_project->removeItems({m_project->findItem("y"), m_project->findItem("Lévy-like")});
        QCOMPARE(shape(*m_model), shape(*m_project));
        while (m_project->undoStack()->canUndo()) {
            m_project->undoStack()->undo();
            QCOMPARE(shape(*m_model), shape(*m_project));
        }
        QCOMPARE(m_model->rowCount(), 0);
        while (m_project->undoStack()->canRedo()) {
            m_project->undoStack()->redo();
            QCOMPARE(shape(*m_model), shape(*m_project));
        }
    }

    void resetsOnOpenAndClear()
    {
        QTemporaryDir dir;
        const QString file = dir.filePath("t.awb");
        QVERIFY(m_project->saveAs(file));
        QSignalSpy reset(m_model.get(), &QAbstractItemModel::modelReset);
        m_project->clear();
        QCOMPARE(reset.count(), 1);
        QCOMPARE(m_model->rowCount(), 0);
        QVERIFY(m_project->open(file));
        QCOMPARE(reset.count(), 2);
        QCOMPARE(shape(*m_model), shape(*m_project));
        QCOMPARE(m_model->rowCount(), 7);
    }

    void renameThroughTheModel()
    {
        const QModelIndex i = m_model->indexOf(m_project->findItem("Chaikin"));
        const int index = m_project->undoStack()->index();
        QSignalSpy changed(m_model.get(), &QAbstractItemModel::dataChanged);
        QVERIFY(m_model->setData(i, "Corner"));
        QCOMPARE(i.data().toString(), QString("Corner"));
        QCOMPARE(m_project->undoStack()->index(), index + 1);
        QVERIFY(changed.count() >= 1);
        QVERIFY(!m_model->setData(i, "B-spline")); // taken
        QVERIFY(!m_model->setData(i, ""));
        QVERIFY(!m_model->setData(m_model->index(0, 1, i.parent()), "kind column"));
        QCOMPARE(m_project->undoStack()->index(), index + 1);
        m_project->undoStack()->undo();
        QCOMPARE(i.data().toString(), QString("Chaikin"));
    }

    void removeRowsIsOneStep()
    {
        const int index = m_project->undoStack()->index();
        QVERIFY(m_model->removeRows(1, 3));
        QCOMPARE(m_project->undoStack()->index(), index + 1);
        QCOMPARE(shape(*m_model), QString("B-spline, Lévy-like, Matrices, Spectrum"));
        QVERIFY(!m_model->removeRows(3, 2));
        m_project->undoStack()->undo();
        QCOMPARE(m_model->rowCount(), 7);
    }

    void moveRowsIsOneStep()
    {
        const int index = m_project->undoStack()->index();
        // B-spline and End-interpolating to before Lévy-like (row 4): Qt counts rows before
        // the move.
        QVERIFY(m_model->moveRows({}, 0, 2, {}, 4));
        QCOMPARE(shape(*m_model), QString("Corner cutting, Four-point, B-spline, "
                                          "End-interpolating(Chaikin), Lévy-like, Matrices, "
                                          "Spectrum"));
        QCOMPARE(m_project->undoStack()->index(), index + 1);
        QVERIFY(m_model->moveRows({}, 4, 2, {}, 1)); // up
        QCOMPARE(shape(*m_model), QString("Corner cutting, Lévy-like, Matrices, Four-point, "
                                          "B-spline, End-interpolating(Chaikin), Spectrum"));
        const QModelIndex matrices = m_model->indexOf(m_project->findItem("Matrices"));
        QVERIFY(m_model->moveRows({}, 0, 1, matrices, 0)); // into another item
        QCOMPARE(shape(*m_model), QString("Lévy-like, Matrices(Corner cutting), Four-point, "
                                          "B-spline, End-interpolating(Chaikin), Spectrum"));
        QVERIFY(!m_model->moveRows({}, 0, 2, {}, 1)); // onto itself
        const QModelIndex m2 = m_model->indexOf(m_project->findItem("Matrices"));
        QVERIFY(!m_model->moveRows({}, m2.row(), 1, m2, 0)); // into itself
        QCOMPARE(m_project->undoStack()->index(), index + 3);
        m_project->undoStack()->undo();
        m_project->undoStack()->undo();
        m_project->undoStack()->undo();
        QCOMPARE(shape(*m_model), QString("B-spline, End-interpolating(Chaikin), Corner "
                                          "cutting, Four-point, Lévy-like, Matrices, Spectrum"));
    }

    void propertyEditsAreDataChanges()
    {
        auto *c = static_cast<SubdivisionCurveItem *>(m_project->findItem("B-spline"));
        QSignalSpy changed(m_model.get(), &QAbstractItemModel::dataChanged);
        c->moveControlPoint(0, {0.5, 0.5});
        QVERIFY(changed.count() >= 1);
        const QModelIndex i = m_model->indexOf(c);
        bool seen = false;
        for (const auto &args : changed)
            seen = seen || args.at(0).value<QModelIndex>() == i;
        QVERIFY(seen);
    }

private:
    std::unique_ptr<Project> m_project;
    std::unique_ptr<ProjectTreeModel> m_model;
    std::unique_ptr<QAbstractItemModelTester> m_tester;
};

AWB_TEST_GUILESS_MAIN(TestTreeModel)
#include "test_tree_model.moc"
