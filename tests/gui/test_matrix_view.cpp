// The matrix view: table sizes with row or column sums, fraction formatting, shaded A/b blocks
// of lifted maps, and cell edits (valid ones reported once, invalid ones refused in place).

#include "gui/views/MatrixView.h"

#include <QAbstractItemModel>
#include <QLineEdit>
#include <QSignalSpy>
#include <QTableView>
#include <QtTest>

#include "TestMain.h"

using namespace awb;

namespace {

const QString kMinus(QChar(0x2212));

Mat userMatrix()
{
    Mat S(3, 3);
    S << 0.375, 0.625, 0, 0.125, 0.75, 0.125, -0.0625, 0.5625, 0.5;
    return S;
}

QString text(QTableView *t, int r, int c)
{
    return t->model()->data(t->model()->index(r, c)).toString();
}

} // namespace

class TestMatrixView : public QObject {
    Q_OBJECT
private slots:
    void sizesAndFractions();
    void columnSumsAndBlocks();
    void liveUpdateKeepsTheTables();
    void validEditIsReportedOnce();
    void badEditIsRefusedWithAMessage();
    void readOnlyMatricesCannotBeEdited();
    void complexMatrices();
};

void TestMatrixView::sizesAndFractions()
{
    MatrixView view;
    Mat M = Mat::Identity(4, 4);
    M(3, 0) = 2.0 / 3.0;
    view.setMatrices({{QStringLiteral("S_1"), userMatrix(), -1, true},
                      {QStringLiteral("M_1"), M, 3, false}});
    QCOMPARE(view.matrixCount(), 2);
    QTableView *t = view.table(0);
    QVERIFY(t);
    QCOMPARE(t->model()->rowCount(), 3);
    QCOMPARE(t->model()->columnCount(), 4); // + the row-sum column
    QCOMPARE(t->model()->headerData(3, Qt::Horizontal).toString(), QStringLiteral("Σ"));
    QCOMPARE(text(t, 0, 0), QStringLiteral("3/8"));
    QCOMPARE(text(t, 2, 0), kMinus + QStringLiteral("1/16"));
    QCOMPARE(text(t, 0, 1), QStringLiteral("5/8"));
    QCOMPARE(text(t, 0, 3), QStringLiteral("1")); // rows sum to 1
    QCOMPARE(view.table(1)->model()->rowCount(), 4);
    QCOMPARE(view.table(1)->model()->columnCount(), 5);
    QCOMPARE(text(view.table(1), 3, 0), QStringLiteral("2/3"));
    QCOMPARE(text(view.table(1), 3, 4), QStringLiteral("5/3"));
    QVERIFY(!view.table(2));
    // Full precision in the tooltip.
    const QString tip = t->model()->data(t->model()->index(0, 0), Qt::ToolTipRole).toString();
    QCOMPARE(tip, QStringLiteral("0.375"));
}

void TestMatrixView::columnSumsAndBlocks()
{
    MatrixView view;
    Mat M = Mat::Identity(3, 3);
    M(0, 1) = 0.25;
    M(2, 0) = 0.5;
    view.setMatrices({{QStringLiteral("M_2"), M, 2, false}});
    view.setSums(MatrixView::Sums::Columns);
    QTableView *t = view.table(0);
    QCOMPARE(t->model()->rowCount(), 4);
    QCOMPARE(t->model()->columnCount(), 3);
    QCOMPARE(text(t, 3, 0), QStringLiteral("3/2"));
    QCOMPARE(text(t, 3, 1), QStringLiteral("5/4"));
    // A block, b row and the fixed column are shaded differently from each other.
    auto bg = [&](int r, int c) {
        return t->model()->data(t->model()->index(r, c), Qt::BackgroundRole).value<QColor>();
    };
    QCOMPARE(bg(0, 0), bg(1, 1));
    QVERIFY(bg(0, 0) != bg(2, 0));
    QVERIFY(bg(2, 0) != bg(0, 2));
    QVERIFY(bg(3, 0) != bg(0, 0)); // the sum row
    view.setSums(MatrixView::Sums::None);
    QCOMPARE(t->model()->rowCount(), 3);
    QCOMPARE(t->model()->columnCount(), 3);
}

void TestMatrixView::liveUpdateKeepsTheTables()
{
    MatrixView view;
    view.setMatrices({{QStringLiteral("S_1"), userMatrix(), -1, true}});
    QTableView *before = view.table(0);
    Mat S = userMatrix();
    S(1, 1) = 0.5;
    view.setMatrices({{QStringLiteral("S_1"), S, -1, true}});
    QCOMPARE(view.table(0), before); // updated in place, not rebuilt
    QCOMPARE(text(before, 1, 1), QStringLiteral("1/2"));
    QCOMPARE(text(before, 1, 3), QStringLiteral("3/4"));
    view.setMatrices({{QStringLiteral("S_1"), Mat::Identity(2, 2), -1, true}});
    QCOMPARE(view.table(0)->model()->rowCount(), 2);
}

void TestMatrixView::validEditIsReportedOnce()
{
    MatrixView view;
    view.setMatrices({{QStringLiteral("S_1"), userMatrix(), -1, true}});
    view.setEditable(true);
    view.show();
    QVERIFY(QTest::qWaitForWindowExposed(&view));
    QSignalSpy edited(&view, &MatrixView::cellEdited);
    QTableView *t = view.table(0);
    const QModelIndex idx = t->model()->index(1, 2);
    QVERIFY(t->model()->flags(idx) & Qt::ItemIsEditable);
    QVERIFY(!(t->model()->flags(t->model()->index(1, 3)) & Qt::ItemIsEditable)); // the sum
    // Type into the real editor, as a user does.
    t->setCurrentIndex(idx);
    t->edit(idx);
    auto *editor = t->findChild<QLineEdit *>();
    QVERIFY(editor);
    QCOMPARE(editor->text(), QStringLiteral("1/8")); // exact fraction to edit
    editor->selectAll();
    QTest::keyClicks(editor, QStringLiteral("-1/16"));
    QTest::keyClick(editor, Qt::Key_Return);
    // The delegate commits through a queued call.
    QTRY_COMPARE(edited.size(), 1);
    const QList<QVariant> args = edited.first();
    QCOMPARE(args.at(0).toInt(), 0);
    QCOMPARE(args.at(1).toInt(), 1);
    QCOMPARE(args.at(2).toInt(), 2);
    QCOMPARE(args.at(3).toDouble(), -0.0625);
    QVERIFY(view.errorMessage().isEmpty());
    // The view shows the owner's numbers: unchanged until the owner sets them again.
    QCOMPARE(text(t, 1, 2), QStringLiteral("1/8"));
    // Writing the same value again is no edit.
    QVERIFY(t->model()->setData(idx, QStringLiteral("0.125")));
    QCOMPARE(edited.size(), 1);
}

void TestMatrixView::badEditIsRefusedWithAMessage()
{
    MatrixView view;
    view.setMatrices({{QStringLiteral("S_1"), userMatrix(), -1, true}});
    view.setEditable(true);
    view.show();
    QVERIFY(QTest::qWaitForWindowExposed(&view));
    QSignalSpy edited(&view, &MatrixView::cellEdited);
    QTableView *t = view.table(0);
    const QModelIndex idx = t->model()->index(0, 0);
    t->setCurrentIndex(idx);
    t->edit(idx);
    auto *editor = t->findChild<QLineEdit *>();
    QVERIFY(editor);
    editor->selectAll();
    QTest::keyClicks(editor, QStringLiteral("abc"));
    QTest::keyClick(editor, Qt::Key_Return);
    QTRY_VERIFY(view.errorMessage().contains(QLatin1String("abc")));
    QCOMPARE(edited.size(), 0);
    QVERIFY(view.errorMessage().contains(QLatin1String("row 1, column 1")));
    QCOMPARE(text(t, 0, 0), QStringLiteral("3/8"));
    for (const QString &bad : {QStringLiteral("inf"), QStringLiteral("1/0"), QStringLiteral("nan"),
                               QStringLiteral(""), QStringLiteral("1e999")}) {
        QVERIFY(!t->model()->setData(idx, bad));
        QVERIFY(view.errorMessage().contains(QLatin1String("not a finite number")));
    }
    QCOMPARE(edited.size(), 0);
    // A good edit afterwards clears the message.
    QVERIFY(t->model()->setData(idx, QStringLiteral("1/4")));
    QCOMPARE(edited.size(), 1);
    QVERIFY(view.errorMessage().isEmpty());
}

void TestMatrixView::readOnlyMatricesCannotBeEdited()
{
    MatrixView view;
    view.setMatrices({{QStringLiteral("S_1"), userMatrix(), -1, false},
                      {QStringLiteral("S_2"), userMatrix(), -1, true}});
    QSignalSpy edited(&view, &MatrixView::cellEdited);
    // Not editable until the view is put in editable mode, and never for a scheme's matrix.
    QVERIFY(!(view.table(1)->model()->flags(view.table(1)->model()->index(0, 0))
              & Qt::ItemIsEditable));
    view.setEditable(true);
    QVERIFY(!(view.table(0)->model()->flags(view.table(0)->model()->index(0, 0))
              & Qt::ItemIsEditable));
    QVERIFY(!view.table(0)->model()->setData(view.table(0)->model()->index(0, 0),
                                             QStringLiteral("1")));
    QVERIFY(view.table(1)->model()->setData(view.table(1)->model()->index(0, 0),
                                            QStringLiteral("1")));
    QCOMPARE(edited.size(), 1);
    QCOMPARE(edited.first().at(0).toInt(), 1);
}

void TestMatrixView::complexMatrices()
{
    // 004 eq. (2.5) with complex t = 1/2 + i/2 (the Lévy C curve): L(t) = [[1, 0], [1 - t, t]].
    const std::complex<double> t(0.5, 0.5);
    CMat L(2, 2);
    L << 1.0, 0.0, 1.0 - t, t;
    NamedMatrix m{QStringLiteral("S_1"), L};
    m.editable = true; // even so: complex cells are not edited
    MatrixView view;
    view.setEditable(true);
    view.setMatrices({m});
    QTableView *tv = view.table(0);
    QCOMPARE(tv->model()->rowCount(), 2);
    QCOMPARE(tv->model()->columnCount(), 3);
    QCOMPARE(text(tv, 1, 0), QStringLiteral("1/2 ") + kMinus + QStringLiteral(" (1/2)i"));
    QCOMPARE(text(tv, 1, 1), QStringLiteral("1/2 + (1/2)i"));
    QCOMPARE(text(tv, 1, 2), QStringLiteral("1"));  // rows of L(t) sum to 1 for any t
    const QString tip = tv->model()->data(tv->model()->index(1, 1), Qt::ToolTipRole).toString();
    QVERIFY2(tip.contains(QStringLiteral("0.70710678118654")), qPrintable(tip)); // |t|
    // Complex matrices are never edited in the table.
    QVERIFY(!(tv->model()->flags(tv->model()->index(0, 0)) & Qt::ItemIsEditable));
    // Real -> complex with the same name and shape rebuilds the table (no stale real cells).
    view.setMatrices({{QStringLiteral("S_1"), Mat::Identity(2, 2), -1, false}});
    QCOMPARE(text(view.table(0), 1, 1), QStringLiteral("1"));
    view.setMatrices({m});
    QCOMPARE(text(view.table(0), 1, 1), QStringLiteral("1/2 + (1/2)i"));
}

AWB_TEST_MAIN(TestMatrixView)
#include "test_matrix_view.moc"
