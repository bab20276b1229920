// Every registered item kind as "Add item" creates it (model/ItemRegistry.h): the default item
// computes, saves and loads byte-identically, and every parameter it lists can be read and set
// back to its own value without an undo step.

#include "ItemKindTests.h"
#include "TestMain.h"

#include "model/ItemRegistry.h"

using namespace awb;

class TestItemKinds : public QObject {
    Q_OBJECT
private slots:
    void defaultItemsWork_data();
    void defaultItemsWork();
};

void TestItemKinds::defaultItemsWork_data()
{
    QTest::addColumn<QString>("type");
    for (const QString &type : ItemRegistry::instance().types())
        QTest::newRow(qPrintable(type)) << type;
}

void TestItemKinds::defaultItemsWork()
{
    QFETCH(QString, type);
    Project p;
    std::unique_ptr<Item> created = ItemRegistry::instance().create(type);
    QVERIFY(created);
    QCOMPARE(created->type(), type);
    QVERIFY(!created->typeName().isEmpty());
    Item *item = p.addItem(std::move(created));
    if (auto *a = dynamic_cast<AttractorItem *>(item)) {
        QVERIFY2(a->derivedIfs(), qPrintable(a->derivedError()));
        QVERIFY(!a->checkAlgorithm(a->algorithm()));
        QCOMPARE(int(a->controlPoints(a->controlPointSetCount()).size()), 0);
    }
    QVERIFY(test::reloadsIdentically(p));
    const int steps = p.undoStack()->count();
    for (const ParameterInfo &info : item->parameters()) {
        const QVariant value = item->parameter(info.key);
        QVERIFY2(value.isValid(), qPrintable(info.key));
        QVERIFY(!info.label.isEmpty());
        QString error;
        QVERIFY2(item->setParameter(info.key, value, 0, &error),
                 qPrintable(info.key + ": " + error));
    }
    QCOMPARE(p.undoStack()->count(), steps);
}

AWB_TEST_GUILESS_MAIN(TestItemKinds)
#include "test_item_kinds.moc"
