// A scheme typed in the window (issue 32): Scheme -> "Own matrices" starts from the curve's own
// S_i (it was refused before: "an IFS needs at least two matrices, got 0"), the Matrices dock
// edits them cell by cell with exact fractions, adds and removes maps, each one undo step;
// Scheme -> "Mask" shows the mask as one line, typed entries (Daubechies' D4 with square roots)
// become the scheme in one undo step, the symbol's sum rules follow, a coset that does not sum
// to 1 is refused with its residue.

#include "gui/app/ItemController.h"
#include "gui/app/MainWindow.h"
#include "gui/app/Messages.h"
#include "gui/app/PropertiesDock.h"
#include "gui/views/MatrixView.h"
#include "gui/views/RegularityPanel.h"
#include "model/Project.h"
#include "model/RegularityCertificate.h"
#include "model/SubdivisionCurveItem.h"

#include <QComboBox>
#include <QFile>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSignalSpy>
#include <QTableView>
#include <QTemporaryDir>
#include <QToolButton>
#include <QtTest>

#include "TestMain.h"

#include "TestTime.h"

#include <cmath>

using namespace awb;

class TestOwnSchemes : public QObject {
    Q_OBJECT
private slots:
    void ownMatricesFromTheWindow();
    void maskTypedInProperties();

private:
    SubdivisionCurveItem *openFourPoint(MainWindow &w);
    QTemporaryDir m_dir;
};

SubdivisionCurveItem *TestOwnSchemes::openFourPoint(MainWindow &w)
{
    auto item = std::make_unique<SubdivisionCurveItem>();
    item->setName(QStringLiteral("Mine"));
    SchemeSpec s;
    s.kind = SchemeSpec::Kind::FourPoint;
    item->setScheme(s);
    while (item->controlPoints(0).size() > 1)
        item->removeControlPoint(int(item->controlPoints(0).size()) - 1);
    const PointList points{{0, 0}, {1, 1.5}, {2.5, 2}, {4, 0.5}, {5, 1}, {6.5, 2}, {8, 0}};
    item->moveControlPoint(0, points.front());
    for (std::size_t i = 1; i < points.size(); ++i)
        item->insertControlPoint(int(i), points[i]);
    auto *raw = item.get();
    w.project()->addItem(std::move(item));
    w.setCurrentItem(raw);
    w.controller()->refreshNow();
    return raw;
}

void TestOwnSchemes::ownMatricesFromTheWindow()
{
    RecordingMessages messages;
    MainWindow w(&messages, m_dir.path() + QStringLiteral("/recovery"));
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    SubdivisionCurveItem *item = openFourPoint(w);
    QUndoStack *undo = w.project()->undoStack();
    const int steps = undo->count();
    const Mat fourPointS2 = item->scheme().makeScheme()->matrices(7).S[1];

    auto *kind = qobject_cast<QComboBox *>(w.propertiesWidget()->editor("scheme.kind"));
    QVERIFY(kind);
    kind->setCurrentIndex(int(SchemeSpec::Kind::Matrices));
    QVERIFY2(messages.errors.isEmpty(), qPrintable(messages.errors.join('\n')));
    QCOMPARE(item->scheme().kind, SchemeSpec::Kind::Matrices);
    QCOMPARE(item->scheme().matrices.size(), size_t(2));
    QCOMPARE(item->scheme().matrices[1], fourPointS2);
    QCOMPARE(undo->count(), steps + 1);
    w.controller()->refreshNow();

    // Editable: the cell takes an exact fraction (the row is rebalanced on request).
    MatrixView *view = w.matrixView();
    QVERIFY(view->isEditable());
    QVERIFY(view->table(0));
    QAbstractItemModel *table = view->table(0)->model();
    QVERIFY(table->flags(table->index(0, 0)) & Qt::ItemIsEditable);

    // Add a map: a copy of S_2, one undo step; the IFS has three maps.
    auto *add = view->findChild<QPushButton *>(QStringLiteral("addMap"));
    QVERIFY(add);
    add->click();
    QCOMPARE(item->scheme().matrices.size(), size_t(3));
    QCOMPARE(item->mapCount(), 3);
    QCOMPARE(undo->count(), steps + 2);
    w.controller()->refreshNow();
    QVERIFY(item->derivedIfs());

    // Remove S_1: two maps again; removing below two is refused with the reason.
    auto *remove = view->findChild<QToolButton *>(QStringLiteral("removeMap:S_1"));
    QVERIFY(remove);
    remove->click();
    QCOMPARE(item->scheme().matrices.size(), size_t(2));
    QCOMPARE(item->scheme().matrices[0], fourPointS2);
    QCOMPARE(undo->count(), steps + 3);
    w.controller()->refreshNow();
    remove = view->findChild<QToolButton *>(QStringLiteral("removeMap:S_1"));
    QVERIFY(remove);
    remove->click();
    QCOMPARE(item->scheme().matrices.size(), size_t(2));
    QCOMPARE(undo->count(), steps + 3);
    QVERIFY(!messages.errors.isEmpty());
    QVERIFY2(messages.errors.last().contains("at least two maps"),
             qPrintable(messages.errors.last()));

    undo->undo();
    undo->undo();
    undo->undo();
    QCOMPARE(item->scheme().kind, SchemeSpec::Kind::FourPoint);
    w.controller()->refreshNow();
    QVERIFY(!w.matrixView()->isEditable());
}

void TestOwnSchemes::maskTypedInProperties()
{
    RecordingMessages messages;
    MainWindow w(&messages, m_dir.path() + QStringLiteral("/recovery"));
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    SubdivisionCurveItem *item = openFourPoint(w);
    QUndoStack *undo = w.project()->undoStack();
    const int steps = undo->count();

    auto *kind = qobject_cast<QComboBox *>(w.propertiesWidget()->editor("scheme.kind"));
    QVERIFY(kind);
    kind->setCurrentIndex(int(SchemeSpec::Kind::Mask));
    QCOMPARE(item->scheme().kind, SchemeSpec::Kind::Mask);
    auto *mask = qobject_cast<QLineEdit *>(w.propertiesWidget()->editor("scheme.mask"));
    QVERIFY(mask);
    QCOMPARE(mask->text(), QStringLiteral("-1/16, 0, 9/16, 1, 9/16, 0, -1/16"));
    auto symbol = [&] {
        for (QLabel *l : w.propertiesWidget()->findChildren<QLabel *>())
            if (l->text().contains(QStringLiteral("sum rule")))
                return l->text();
        return QString();
    };
    QVERIFY2(symbol().startsWith(QStringLiteral("4 sum rules")), qPrintable(symbol()));

    // Daubechies' D4, typed: one undo step, kept as typed, two sum rules.
    mask->setText(QStringLiteral(
        "(1 + sqrt(3))/4, (3 + sqrt(3))/4, (3 - sqrt(3))/4, (1 - sqrt(3))/4"));
    emit mask->editingFinished();
    QVERIFY2(messages.errors.isEmpty(), qPrintable(messages.errors.join('\n')));
    QCOMPARE(undo->count(), steps + 2);
    QCOMPARE(item->scheme().maskText.front(), QStringLiteral("(1 + sqrt(3))/4"));
    QVERIFY2(symbol().startsWith(QStringLiteral("2 sum rules")), qPrintable(symbol()));
    auto *offset = w.propertiesWidget()->editor("scheme.offset");
    QVERIFY(offset);
    QVERIFY(item->derivedIfs());

    // The Analysis dock: the exact Hölder exponent 2 - log2(1 + sqrt 3) (Daubechies & Lagarias
    // 1992) by an invariant polytope, its certificate saved and verified.
    auto *panel = w.findChild<RegularityPanel *>();
    QVERIFY(panel);
    w.controller()->refreshNow();
    QSignalSpy done(panel, &RegularityPanel::finished);
    QVERIFY(!panel->isRunning() || done.wait(awb::test::ms(20000)));
    QVERIFY2(panel->summary().contains(QStringLiteral("r = 0.550015686")) &&
                 panel->summary().contains(QStringLiteral("invariant polytope")),
             qPrintable(panel->summary()));
    QVERIFY2(panel->summary().contains(QStringLiteral("s₂ = 1")), qPrintable(panel->summary()));
    auto *save = panel->findChild<QToolButton *>(QStringLiteral("regularitySaveCertificate"));
    QVERIFY(save && save->isVisible());
    const QString cert = m_dir.filePath(QStringLiteral("d4.json"));
    QString why;
    QVERIFY2(w.controller()->saveCertificate(cert, &why), qPrintable(why));
    QFile in(cert);
    QVERIFY(in.open(QIODevice::ReadOnly));
    const CertificateCheck check = verifyRegularityCertificate(in.readAll());
    QVERIFY2(check.ok, qPrintable(check.message));
    const double alpha = 2 - std::log2(1 + std::sqrt(3.0));
    QVERIFY(check.lower <= alpha + 1e-12 && alpha - 1e-12 <= check.upper);

    // A coset off 1 (from k = -3, the four-point mask's first index, kept): refused with its
    // residue; the line shows the item's mask again.
    mask->setText(QStringLiteral("1/4, 3/4, 1, 1/4"));
    emit mask->editingFinished();
    QVERIFY(!messages.errors.isEmpty());
    QVERIFY2(messages.errors.last().contains(QStringLiteral("k = 1 mod 2 sum to 1.25")),
             qPrintable(messages.errors.last()));
    QCOMPARE(undo->count(), steps + 2);
    QVERIFY(mask->text().startsWith(QStringLiteral("(1 + sqrt(3))/4")));

    undo->undo();
    QCOMPARE(mask->text(), QStringLiteral("-1/16, 0, 9/16, 1, 9/16, 0, -1/16"));
}

AWB_TEST_MAIN(TestOwnSchemes)
#include "test_own_schemes.moc"
