#pragma once
// Tables of named matrices (S_1..S_p, M_i = P^-1 S_i P with its A_i / b_i blocks), real or
// complex, with exact fractions where they are easy, and row or column sums. In editable mode a cell edit is
// validated here and reported as cellEdited(); the view does not change its own numbers: the
// owner applies the edit (one undo step) and sets the matrices again.

#include "core/Types.h"
#include "model/NamedMatrix.h"

#include <QList>
#include <QString>
#include <QWidget>

#include <utility>

class QLabel;
class QPushButton;
class QScrollArea;
class QTableView;
class QVBoxLayout;

namespace awb {

class MatrixTableModel;

class MatrixView : public QWidget {
    Q_OBJECT
public:
    enum class Sums { None, Rows, Columns };

    explicit MatrixView(QWidget *parent = nullptr);
    ~MatrixView() override;

    // Replaces the shown matrices. When names and shapes are unchanged the tables are updated
    // in place (no flicker, the scroll position and an open editor survive a live drag).
    void setMatrices(const QList<NamedMatrix> &matrices);
    // The matrices shown (for LaTeX export and the figure sheet).
    QList<NamedMatrix> matrices() const;
    int matrixCount() const { return int(m_models.size()); }
    void setSums(Sums sums);
    Sums sums() const { return m_sums; }
    // Allows editing cells of matrices marked editable.
    void setEditable(bool editable);
    bool isEditable() const { return m_editable; }
    void setDigits(int significantDigits);

    QTableView *table(int matrix) const;
    // Marks the matrices of map `map` (0-based: S_1, M_1, A_1, f_1 for map 0) and scrolls to
    // the first of them; -1 clears the mark. Kept while the shown matrices keep their names.
    void setHighlightedMap(int map);
    int highlightedMap() const { return m_highlighted; }
    // Whether matrix `matrix` is marked.
    bool isHighlighted(int matrix) const;
    // The message shown after a refused edit (empty when none).
    QString errorMessage() const;

signals:
    void cellEdited(int matrix, int row, int column, double value);
    // Editable matrices (the user's own S_i): the buttons under and beside them.
    void addMapRequested();
    void removeMapRequested(int matrix);

private:
    void rebuild(const QList<NamedMatrix> &matrices);
    void showError(const QString &message);
    void fitTable(QTableView *view, bool rows = true) const;
    void showHighlight();

    QVBoxLayout *m_tables = nullptr;
    QLabel *m_error = nullptr;
    QPushButton *m_addMap = nullptr;
    QList<MatrixTableModel *> m_models;
    QList<QTableView *> m_views;
    QList<QWidget *> m_boxes;
    Sums m_sums = Sums::Rows;
    bool m_editable = false;
    int m_digits = 6;
    int m_highlighted = -1;
    QScrollArea *m_scroll = nullptr;
};

} // namespace awb
