// The Properties dock's xform editor of a flame (gui/app/FlameXformEditor.h), used as a person
// uses it: pick an xform, change its weight and colour, a variation's weight, add a variation
// from the list, change a parameter, add, duplicate and delete xforms, edit the final xform --
// each one undo step that the item's flame shows, undone exactly; a word typed as a weight is
// refused with a message and the table shows the model again.

#include "gui/app/FlameXformEditor.h"
#include "gui/app/Messages.h"
#include "gui/app/PropertiesDock.h"
#include "model/FlameItem.h"
#include "model/Project.h"
#include "model/ProjectIO.h"

#include "core/flame/Variations.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QPushButton>
#include <QTableWidget>
#include <QtTest>

#include "TestMain.h"

using namespace awb;

namespace {

const char *kFlame = R"({"type": "flame", "name": "F",
    "xforms": [{"weight": 1, "color": 0, "coefs": [0.5, 0, 0, 0.5, 0, 0],
                "variations": {"linear": 0.4, "julian": 0.6},
                "parameters": {"julian_power": 3, "julian_dist": 1}},
               {"weight": 2, "color": 1, "coefs": [0.5, 0, 0, 0.5, 0.5, 0],
                "variations": {"swirl": 1}}],
    "final_xform": {"color": 0.5, "coefs": [1, 0, 0, 1, 0, 0], "variations": {"linear": 1}},
    "algorithm": {"mode": "random", "samples": 10000}})";

bool load(Project &project, const char *item, QString *error)
{
    ProjectData data;
    const QByteArray json =
        QByteArray(R"({"format": "attractor-workbench", "version": 1, "items": [)") + item + "]}";
    if (!ProjectIO::parse(json, "t.awb", &data, error))
        return false;
    project.adopt(std::move(data), {}, false);
    return true;
}

int row(QTableWidget *t, const QString &name)
{
    for (int r = 0; r < t->rowCount(); ++r)
        if (t->item(r, 0)->text() == name)
            return r;
    return -1;
}

} // namespace

class TestFlameXforms : public QObject {
    Q_OBJECT
private slots:
    void editsAreUndoSteps();
};

void TestFlameXforms::editsAreUndoSteps()
{
    Project p;
    QString error;
    QVERIFY2(load(p, kFlame, &error), qPrintable(error));
    auto *item = qobject_cast<FlameItem *>(p.findItem("F"));
    QVERIFY(item);
    RecordingMessages messages;
    PropertiesWidget dock(&messages);
    dock.setItem(item);
    auto *which = qobject_cast<QComboBox *>(dock.editor("xforms.xform"));
    auto *weight = qobject_cast<QDoubleSpinBox *>(dock.editor("xforms.weight"));
    auto *colour = qobject_cast<QDoubleSpinBox *>(dock.editor("xforms.color"));
    auto *variations = qobject_cast<QTableWidget *>(dock.editor("xforms.variations"));
    auto *addVariation = qobject_cast<QComboBox *>(dock.editor("xforms.add_variation"));
    auto *parameters = qobject_cast<QTableWidget *>(dock.editor("xforms.parameters"));
    auto *add = qobject_cast<QPushButton *>(dock.editor("xforms.add"));
    auto *duplicate = qobject_cast<QPushButton *>(dock.editor("xforms.duplicate"));
    auto *remove = qobject_cast<QPushButton *>(dock.editor("xforms.delete"));
    QVERIFY(which && weight && colour && variations && addVariation && parameters && add
            && duplicate && remove);
    QCOMPARE(which->count(), 3);  // two xforms and the final one
    QCOMPARE(variations->rowCount(), 2);
    QCOMPARE(parameters->rowCount(), 2);  // julian_power, julian_dist
    QUndoStack *stack = p.undoStack();
    const flame::Flame original = item->flame();

    // The second xform's weight and colour: an undo step each.
    which->setCurrentIndex(1);
    QCOMPARE(weight->value(), 2.0);
    weight->setValue(3.5);
    colour->setValue(0.25);
    QCOMPARE(item->flame().xforms[1].weight, 3.5);
    QCOMPARE(item->flame().xforms[1].colour, 0.25);
    QCOMPARE(stack->count(), 2);

    // A variation's weight typed in the table; a word is refused and the model shown again.
    QTableWidgetItem *swirl = variations->item(row(variations, "swirl"), 1);
    swirl->setText("0.75");
    QCOMPARE(item->flame().xforms[1].variations.front().weight, 0.75);
    swirl = variations->item(row(variations, "swirl"), 1);
    swirl->setText("lots");
    QCOMPARE(messages.errors.size(), 1);
    QVERIFY2(messages.errors.front().contains("'lots' is not a number"),
             qPrintable(messages.errors.front()));
    QCOMPARE(variations->item(row(variations, "swirl"), 1)->text(), QString("0.75"));
    QCOMPARE(stack->count(), 3);

    // A variation added from the list, with its parameters shown; its parameter set.
    addVariation->setCurrentIndex(addVariation->findText("blob"));
    emit addVariation->activated(addVariation->currentIndex());
    QCOMPARE(variations->rowCount(), 2);
    QCOMPARE(item->flame().xforms[1].variations.size(), std::size_t(2));
    QVERIFY(row(parameters, "blob_low") >= 0);
    parameters->item(row(parameters, "blob_waves"), 1)->setText("5");
    QCOMPARE(item->flame().xforms[1].parameters[std::size_t(flame::parameterId("blob_waves"))], 5.0);
    // A weight of 0 removes a variation.
    variations->item(row(variations, "swirl"), 1)->setText("0");
    QCOMPARE(variations->rowCount(), 1);
    QCOMPARE(stack->count(), 6);

    // Add, duplicate, delete xforms; the final xform is edited and deleted like the others.
    add->click();
    QCOMPARE(item->flame().xforms.size(), std::size_t(3));
    QCOMPARE(which->currentIndex(), 2);
    which->setCurrentIndex(0);
    duplicate->click();
    QCOMPARE(item->flame().xforms.size(), std::size_t(4));
    QCOMPARE(item->flame().xforms[3].variations, original.xforms[0].variations);
    remove->click();
    QCOMPARE(item->flame().xforms.size(), std::size_t(3));
    which->setCurrentIndex(which->count() - 1);
    QVERIFY(!weight->isEnabled());  // the final xform has no weight
    colour->setValue(0.75);
    QCOMPARE(item->flame().finalXform->colour, 0.75);
    remove->click();
    QVERIFY(!item->flame().finalXform);
    QCOMPARE(which->count(), 3);
    QCOMPARE(stack->count(), 11);

    // Every step undone: the flame as it was, number for number.
    while (stack->canUndo())
        stack->undo();
    QCOMPARE(item->flame(), original);
    QCOMPARE(which->count(), 3);
}

AWB_TEST_MAIN(TestFlameXforms)
#include "test_flame_xforms.moc"
