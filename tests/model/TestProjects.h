#pragma once
// Shared fixtures of the model tests: sample items and projects built the same way in every
// test (and in the child processes of the crash tests, which must reproduce them exactly), and
// the apply / undo / redo round trip every command is put through.

#include "model/EigenvaluePlotItem.h"
#include "model/Project.h"
#include "model/SubdivisionCurveItem.h"

#include <QDir>
#include <QFile>
#include <QTemporaryDir>
#include <QTest>

namespace awb::test {

inline std::unique_ptr<SubdivisionCurveItem> curve(const QString &name, const SchemeSpec &scheme,
                                                   const PointList &points)
{
    auto item = std::make_unique<SubdivisionCurveItem>();
    item->setName(name);
    // The points first: the user's own matrices fix their number.
    for (int i = int(item->controlPoints().size()) - 1; i >= 0; --i)
        item->removeControlPoint(i);
    for (size_t i = 0; i < points.size(); ++i)
        item->insertControlPoint(int(i), points[i]);
    item->setScheme(scheme);
    return item;
}

inline SchemeSpec scheme(SchemeSpec::Kind kind)
{
    SchemeSpec s;
    s.kind = kind;
    return s;
}

inline std::vector<Mat> chaikinMatrices()
{
    // The overlapping-rows split of Chaikin on 3 points (000 §2, 004 eq. (3.27)).
    Mat S1(3, 3), S2(3, 3);
    S1 << 0.75, 0.25, 0, 0.25, 0.75, 0, 0, 0.75, 0.25;
    S2 << 0.25, 0.75, 0, 0, 0.75, 0.25, 0, 0.25, 0.75;
    return {S1, S2};
}

inline const PointList &fivePoints()
{
    static const PointList p{{0, 0}, {1, 2}, {2.5, 2.25}, {4, 1}, {5.125, -0.5}};
    return p;
}

// One item of every scheme kind, a child, an eigenvalue plot and odd numbers.
inline void fillSampleProject(Project &project)
{
    using K = SchemeSpec::Kind;
    project.addItem(curve("B-spline", scheme(K::BSpline), fivePoints()));
    SchemeSpec endInterp = scheme(K::EndInterpolatingBSpline);
    endInterp.degree = 2;
    Item *parent = project.addItem(curve("End-interpolating", endInterp, fivePoints()));
    project.addItem(curve("Chaikin", scheme(K::Chaikin), fivePoints()), parent);
    SchemeSpec cut = scheme(K::CornerCutting);
    cut.a = 0.1;
    cut.b = 0.7000000000000001;
    project.addItem(curve("Corner cutting", cut, fivePoints()));
    // Five points are too few for the four-point scheme (it needs six): the sample also holds
    // an item whose IFS cannot be computed, which must save and load all the same.
    SchemeSpec four = scheme(K::FourPoint);
    four.omega = -0.1;
    project.addItem(curve("Four-point", four, fivePoints()));
    SchemeSpec bezier = scheme(K::Bezier);
    bezier.degree = 2;
    bezier.t = {0.5, 0.5};
    project.addItem(curve("Lévy-like", bezier, {{0, 0}, {0.5, 1.0 / 3.0}, {1, 0}}));
    SchemeSpec matrices = scheme(K::Matrices);
    matrices.matrices = chaikinMatrices();
    project.addItem(curve("Matrices", matrices, {{0, 0}, {1, 1}, {2, 0}}));
    auto plot = std::make_unique<EigenvaluePlotItem>();
    plot->setName("Spectrum");
    plot->setSource("B-spline");
    plot->setMatrixKind(EigenvaluePlotItem::MatrixKind::A);
    project.addItem(std::move(plot));
}

// A fixed sequence of edits (used by the crash test in the parent and in the child).
inline void applyScriptedEdits(Project &project)
{
    auto *c = static_cast<SubdivisionCurveItem *>(project.findItem("B-spline"));
    const int drag = project.beginGesture();
    for (int k = 1; k <= 20; ++k)
        c->moveControlPoint(2, {2.5 + 0.01 * k, 2.25 - 0.02 * k}, drag);
    c->insertControlPoint(5, {6.5, 0.25});
    SchemeSpec s = c->scheme();
    s.degree = 4;
    c->setScheme(s);
    project.renameItem(c, "B-spline (edited)");
    project.removeItem(project.findItem("Four-point"));
    AlgorithmSpec a = c->algorithm();
    a.depth = 12;
    a.mode = AlgorithmSpec::Mode::Random;
    a.probabilities = {0.25, 0.75};
    c->setAlgorithm(a);
}

inline bool writeBytes(const QString &path, const QByteArray &bytes)
{
    QFile f(path);
    return f.open(QIODevice::WriteOnly) && f.write(bytes) == bytes.size();
}

// Runs `edit` on `project` and checks the round trip: exactly one new undo step, undo gives
// the original bytes back (everything saved), redo the edited ones. `check` asserts the
// edited state; `checkOriginal` the original one (state that is not saved, object identity).
template <class Edit, class Check, class CheckOriginal>
void roundTrip(Project &project, Edit edit, Check check, CheckOriginal checkOriginal)
{
    QUndoStack *stack = project.undoStack();
    const QByteArray before = project.serialize();
    const int index = stack->index();
    checkOriginal();
    edit();
    QCOMPARE(stack->index(), index + 1);
    QCOMPARE(stack->count(), index + 1);
    check();
    const QByteArray after = project.serialize();
    QVERIFY(after != before);
    stack->undo();
    QCOMPARE(project.serialize(), before);
    checkOriginal();
    stack->redo();
    QCOMPARE(project.serialize(), after);
    check();
    stack->undo();
    QCOMPARE(project.serialize(), before);
    checkOriginal();
    stack->redo();
    check();
}

inline SubdivisionCurveItem *curveNamed(Project &p, const QString &name)
{
    return dynamic_cast<SubdivisionCurveItem *>(p.findItem(name));
}

} // namespace awb::test
