// The generic parameter interface (model/Parameters.h): what the properties dock and the CLI
// use to list and edit every scalar parameter of an item, through the undo stack.

#include "ItemKindTests.h"
#include "TestMain.h"

using namespace awb;

class TestParameters : public QObject {
    Q_OBJECT
private slots:
    void listFollowsSchemeKind();
    void setIsUndoableAndMergesGestures();
    void refusedValuesExplainWhy();
};

namespace {
QStringList keys(const Item &item)
{
    QStringList k;
    for (const ParameterInfo &p : test::ownParameters(item))
        k << p.key;
    return k;
}
} // namespace

void TestParameters::listFollowsSchemeKind()
{
    Project project;
    auto *c = static_cast<SubdivisionCurveItem *>(project.addItem(test::curve(
        "c", test::scheme(SchemeSpec::Kind::FourPoint),
        {{0, 0}, {1, 1}, {2, 0}, {3, 1}, {4, 0}, {5, 1}, {6, 0}})));
    QCOMPARE(keys(*c), (QStringList{"scheme.kind", "scheme.omega"}));
    const ParameterInfo omega = test::ownParameters(*c).at(1);
    QVERIFY(omega.hasSlider());
    QCOMPARE(omega.sliderMinimum, -0.5);
    QCOMPARE(c->parameter("scheme.omega").toDouble(), 1.0 / 16);
    QVERIFY(c->setParameter("scheme.kind", int(SchemeSpec::Kind::Bezier)));
    QCOMPARE(keys(*c), (QStringList{"scheme.kind", "scheme.degree", "scheme.t"}));
    QVERIFY(!c->parameter("nonsense").isValid());
}

void TestParameters::setIsUndoableAndMergesGestures()
{
    Project project;
    auto *c = static_cast<SubdivisionCurveItem *>(project.addItem(test::curve(
        "c", test::scheme(SchemeSpec::Kind::FourPoint),
        {{0, 0}, {1, 1}, {2, 0}, {3, 1}, {4, 0}, {5, 1}, {6, 0}})));
    const QByteArray before = project.serialize();
    const int steps = project.undoStack()->count();
    // A slider drag: many values, one gesture, one undo step.
    const int gesture = project.beginGesture();
    for (double w : {0.07, 0.1, 0.2, 0.3})
        QVERIFY(c->setParameter("scheme.omega", w, gesture));
    QCOMPARE(project.undoStack()->count(), steps + 1);
    QCOMPARE(c->scheme().omega, 0.3);
    project.undoStack()->undo();
    QCOMPARE(c->scheme().omega, 1.0 / 16);
    QCOMPARE(project.serialize(), before);
    project.undoStack()->redo();
    QCOMPARE(c->scheme().omega, 0.3);
}

void TestParameters::refusedValuesExplainWhy()
{
    Project project;
    auto *c = static_cast<SubdivisionCurveItem *>(project.addItem(test::curve(
        "c", test::scheme(SchemeSpec::Kind::BSpline), {{0, 0}, {1, 1}, {2, 0}, {3, 1}, {4, 0}})));
    const int steps = project.undoStack()->count();
    QString error;
    QVERIFY(!c->setParameter("scheme.degree", 0, 0, &error));
    QVERIFY2(error.contains("degree"), qPrintable(error));
    QVERIFY(!c->setParameter("scheme.degree", QString("three"), 0, &error));
    QVERIFY(error.contains("not a valid value"));
    QVERIFY(!c->setParameter("scheme.j", 0.7, 0, &error));
    QVERIFY(error.contains("no parameter"));
    QCOMPARE(project.undoStack()->count(), steps);
}

AWB_TEST_GUILESS_MAIN(TestParameters)
#include "test_parameters.moc"
