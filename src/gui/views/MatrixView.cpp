#include "gui/views/MatrixView.h"

#include "gui/views/ThemeColours.h"
#include "gui/views/MatrixHeatMap.h"

#include "model/NumberFormat.h"

#include <QAbstractTableModel>
#include <QFont>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QRegularExpression>
#include <QScrollArea>
#include <QTableView>
#include <QToolButton>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <functional>
#include <utility>

namespace awb {

namespace {

const QColor kABlock(226, 236, 250);
// Matrices with more rows than this also get a heat map (a surface's S_i: 16 x 16 and up).
constexpr int heatMapRows = 12;
const QColor kBRow(252, 236, 214);
const QColor kFixed(240, 240, 240);
const QColor kSum(232, 232, 232);

// "S_1" -> "S<sub>1</sub>" for the table titles.
QString richName(const QString &name)
{
    QString s = name.toHtmlEscaped();
    static const QRegularExpression sub(QStringLiteral("_\\{?([A-Za-z0-9]+)\\}?"));
    s.replace(sub, QStringLiteral("<sub>\\1</sub>"));
    return s;
}

} // namespace

// One matrix as a table: formatted cells, shaded blocks, an extra sum row or column. Edits
// are validated here and handed to callbacks; the stored numbers change only via setMatrix.
class MatrixTableModel : public QAbstractTableModel {
public:
    std::function<void(int row, int col, double value)> onEdited;
    std::function<void(const QString &message)> onRejected;

    // Replaces the numbers. Cells whose value did not change keep their text (formatting an
    // exact fraction is the costly part) and emit nothing; true when a cell's text changed.
    bool setMatrix(const NamedMatrix &m)
    {
        const bool reshape = m.rows() != m_m.rows() || m.cols() != m_m.cols()
                             || m.isComplex() != m_m.isComplex()
                             || m.affineBlock != m_m.affineBlock;
        if (reshape) {
            beginResetModel();
            m_m = m;
            m_text.clear();
            endResetModel();
            return true;
        }
        const NamedMatrix old = std::exchange(m_m, m);
        int r0 = rowCount(), r1 = -1, c0 = columnCount(), c1 = -1;
        for (int r = 0; r < rowCount(); ++r)
            for (int c = 0; c < columnCount(); ++c) {
                const bool same = m_m.isComplex()
                                      ? complexValue(m_m, r, c) == complexValue(old, r, c)
                                      : value(m_m, r, c) == value(old, r, c);
                if (same)
                    continue;
                if (!m_text.isEmpty())
                    m_text[r * columnCount() + c].clear(); // formatted again when shown
                r0 = std::min(r0, r), r1 = std::max(r1, r);
                c0 = std::min(c0, c), c1 = std::max(c1, c);
            }
        if (r1 < 0)
            return false;
        emit dataChanged(index(r0, c0), index(r1, c1),
                         {Qt::DisplayRole, Qt::EditRole, Qt::ToolTipRole});
        return true;
    }
    const NamedMatrix &matrix() const { return m_m; }
    void setSums(MatrixView::Sums s)
    {
        beginResetModel();
        m_sums = s;
        m_text.clear();
        endResetModel();
    }
    void setEditable(bool e)
    {
        m_editable = e;
        if (rowCount() > 0 && columnCount() > 0)
            emit dataChanged(index(0, 0), index(rowCount() - 1, columnCount() - 1));
    }
    void setDigits(int d)
    {
        m_digits = d;
        m_text.clear();
        if (rowCount() > 0 && columnCount() > 0)
            emit dataChanged(index(0, 0), index(rowCount() - 1, columnCount() - 1));
    }

    int rowCount(const QModelIndex &parent = {}) const override
    {
        if (parent.isValid())
            return 0;
        return int(m_m.rows()) + (m_sums == MatrixView::Sums::Columns ? 1 : 0);
    }
    int columnCount(const QModelIndex &parent = {}) const override
    {
        if (parent.isValid())
            return 0;
        return int(m_m.cols()) + (m_sums == MatrixView::Sums::Rows ? 1 : 0);
    }

    QVariant data(const QModelIndex &index, int role) const override
    {
        if (!index.isValid())
            return {};
        const int r = index.row(), c = index.column();
        const bool sum = isSum(r, c);
        switch (role) {
        case Qt::DisplayRole:
            return displayText(r, c);
        case Qt::EditRole:
            return m_m.isComplex() ? formatComplex(complexValue(r, c), 17)
                                   : editableNumber(value(r, c));
        case Qt::ToolTipRole: {
            QString exact = QString::number(value(r, c), 'g', 17);
            if (m_m.isComplex()) {
                const std::complex<double> z = complexValue(r, c);
                exact = MatrixView::tr("%1 %2 %3i (modulus %4)")
                            .arg(QString::number(z.real(), 'g', 17),
                                 z.imag() < 0 ? QStringLiteral("−") : QStringLiteral("+"),
                                 QString::number(std::abs(z.imag()), 'g', 17),
                                 QString::number(std::abs(z), 'g', 17));
            }
            if (sum)
                return m_sums == MatrixView::Sums::Rows
                           ? MatrixView::tr("Sum of row %1: %2").arg(r + 1).arg(exact)
                           : MatrixView::tr("Sum of column %1: %2").arg(c + 1).arg(exact);
            const QString block = blockName(r, c);
            return block.isEmpty() ? exact : QStringLiteral("%1 (%2)").arg(exact, block);
        }
        case Qt::TextAlignmentRole:
            return QVariant::fromValue(Qt::AlignRight | Qt::AlignVCenter);
        case Qt::ForegroundRole:
            // The tinted cells are light in any theme: their text stays dark.
            if (sum || m_m.affineBlock >= 0)
                return QColor(20, 20, 20);
            return {};
        case Qt::BackgroundRole:
            if (sum)
                return kSum;
            if (m_m.affineBlock >= 0) {
                const int a = m_m.affineBlock;
                if (r < a && c < a)
                    return kABlock;
                if (r == a && c < a)
                    return kBRow;
                return kFixed;
            }
            return {};
        case Qt::FontRole:
            if (sum) {
                QFont f;
                f.setItalic(true);
                return f;
            }
            return {};
        default:
            return {};
        }
    }

    QVariant headerData(int section, Qt::Orientation o, int role) const override
    {
        if (role != Qt::DisplayRole)
            return QAbstractTableModel::headerData(section, o, role);
        const bool sum = o == Qt::Horizontal ? section == int(m_m.cols())
                                             : section == int(m_m.rows());
        return sum ? QStringLiteral("Σ") : QString::number(section + 1);
    }

    Qt::ItemFlags flags(const QModelIndex &index) const override
    {
        Qt::ItemFlags f = Qt::ItemIsEnabled | Qt::ItemIsSelectable;
        if (m_editable && m_m.editable && !m_m.isComplex() && !isSum(index.row(), index.column()))
            f |= Qt::ItemIsEditable;
        return f;
    }

    bool setData(const QModelIndex &index, const QVariant &v, int role) override
    {
        if (role != Qt::EditRole || !(flags(index) & Qt::ItemIsEditable))
            return false;
        const QString text = v.toString();
        const std::optional<double> x = parseNumber(text);
        if (!x) {
            if (onRejected)
                onRejected(MatrixView::tr("“%1” is not a finite number: %2, row %3, column %4 "
                                          "was not changed.")
                               .arg(text.trimmed(), m_m.name)
                               .arg(index.row() + 1)
                               .arg(index.column() + 1));
            return false;
        }
        // No-op edits make no undo step.
        if (*x != m_m.values(index.row(), index.column()) && onEdited)
            onEdited(index.row(), index.column(), *x);
        return true;
    }

private:
    bool isSum(int r, int c) const
    {
        return r >= m_m.rows() || c >= m_m.cols();
    }
    // The shown text of a cell, formatted once per value (the cache is cleared per cell when
    // its value changes, wholly when the shape, the sums or the digits change).
    QString displayText(int r, int c) const
    {
        const int n = rowCount() * columnCount();
        if (m_text.size() != n)
            m_text = QList<QString>(n);
        QString &text = m_text[r * columnCount() + c];
        if (text.isNull())
            text = m_m.isComplex() ? formatComplex(complexValue(r, c), m_digits)
                                   : formatNumber(value(r, c), m_digits);
        return text;
    }
    std::complex<double> complexValue(int r, int c) const { return complexValue(m_m, r, c); }
    double value(int r, int c) const { return value(m_m, r, c); }
    static std::complex<double> complexValue(const NamedMatrix &m, int r, int c)
    {
        const CMat &M = m.complexValues;
        if (c >= M.cols())
            return M.row(r).sum();
        if (r >= M.rows())
            return M.col(c).sum();
        return M(r, c);
    }
    static double value(const NamedMatrix &m, int r, int c)
    {
        if (m.isComplex())
            return complexValue(m, r, c).real();
        if (c >= m.values.cols())
            return m.values.row(r).sum();
        if (r >= m.values.rows())
            return m.values.col(c).sum();
        return m.values(r, c);
    }
    QString blockName(int r, int c) const
    {
        const int a = m_m.affineBlock;
        if (a < 0)
            return {};
        if (r < a && c < a)
            return MatrixView::tr("A block");
        if (r == a && c < a)
            return MatrixView::tr("b row");
        return MatrixView::tr("fixed part of the lifted map");
    }

    NamedMatrix m_m;
    mutable QList<QString> m_text;  // DisplayRole per cell, row-major; null: not formatted
    MatrixView::Sums m_sums = MatrixView::Sums::Rows;
    bool m_editable = false;
    int m_digits = 6;
};

MatrixView::MatrixView(QWidget *parent) : QWidget(parent)
{
    auto *outer = new QVBoxLayout(this);
    outer->setContentsMargins(0, 0, 0, 0);
    auto *scroll = new QScrollArea(this);
    m_scroll = scroll;
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    auto *content = new QWidget(scroll);
    m_tables = new QVBoxLayout(content);
    m_tables->setContentsMargins(6, 6, 6, 6);
    m_tables->addStretch(1);
    scroll->setWidget(content);
    outer->addWidget(scroll, 1);
    // The refusal message sits outside the scroll area: it stays visible whatever is scrolled.
    m_error = new QLabel(this);
    m_error->setWordWrap(true);
    m_error->setStyleSheet(QStringLiteral("QLabel { color: %1; padding: 4px; }")
                               .arg(errorTextColour(palette()).name()));
    m_error->hide();
    outer->addWidget(m_error);
}

MatrixView::~MatrixView() = default;

bool MatrixView::isHighlighted(int matrix) const
{
    if (m_highlighted < 0 || matrix < 0 || matrix >= m_models.size())
        return false;
    const QString &name = m_models[matrix]->matrix().name;
    return name.endsWith(QStringLiteral("_%1").arg(m_highlighted + 1));
}

void MatrixView::setHighlightedMap(int map)
{
    m_highlighted = map;
    showHighlight();
    for (int i = 0; i < m_boxes.size(); ++i)
        if (isHighlighted(i)) {
            m_scroll->ensureWidgetVisible(m_boxes[i], 0, 0);
            break;
        }
}

void MatrixView::showHighlight()
{
    for (int i = 0; i < m_boxes.size(); ++i) {
        m_boxes[i]->setAutoFillBackground(isHighlighted(i));
        // The box's own colours follow the theme: its title must stay legible on the
        // highlight, whose colour does not.
        QPalette p = palette();
        if (isHighlighted(i)) {
            p.setColor(QPalette::Window, highlightBackground(palette()));
            p.setColor(QPalette::WindowText, highlightText(palette()));
        }
        m_boxes[i]->setPalette(p);
    }
}

QList<NamedMatrix> MatrixView::matrices() const
{
    QList<NamedMatrix> list;
    for (const MatrixTableModel *m : m_models)
        list.append(m->matrix());
    return list;
}

void MatrixView::setMatrices(const QList<NamedMatrix> &matrices)
{
    bool same = matrices.size() == m_models.size();
    for (int i = 0; same && i < matrices.size(); ++i) {
        const NamedMatrix &a = matrices[i], &b = m_models[i]->matrix();
        same = a.name == b.name && a.rows() == b.rows() && a.cols() == b.cols()
               && a.isComplex() == b.isComplex() && a.affineBlock == b.affineBlock
               && a.editable == b.editable;
    }
    if (!same) {
        rebuild(matrices);
        return;
    }
    for (int i = 0; i < matrices.size(); ++i) {
        // Only tables whose numbers changed are measured again (a drag changes the M_i, not
        // the S_i), and only cells that changed are formatted and repainted.
        if (!m_models[i]->setMatrix(matrices[i]))
            continue;
        if (auto *heat = m_boxes[i]->findChild<MatrixHeatMap *>())
            heat->setMatrix(matrices[i].name, matrices[i].values);
        fitTable(m_views[i], false);
    }
}

void MatrixView::rebuild(const QList<NamedMatrix> &matrices)
{
    // Each box owns its title, table and (through the table) model.
    qDeleteAll(m_boxes);
    delete m_addMap;
    m_addMap = nullptr;
    m_boxes.clear();
    m_views.clear();
    m_models.clear();
    for (int i = 0; i < matrices.size(); ++i) {
        const NamedMatrix &nm = matrices[i];
        auto *model = new MatrixTableModel;
        model->setSums(m_sums);
        model->setDigits(m_digits);
        model->setMatrix(nm);
        model->setEditable(m_editable);
        model->onEdited = [this, i](int r, int c, double v) {
            m_error->hide();
            m_error->clear();
            emit cellEdited(i, r, c, v);
        };
        model->onRejected = [this](const QString &message) { showError(message); };

        QString title = QStringLiteral("<b>%1</b>").arg(richName(nm.name));
        if (nm.affineBlock >= 0)
            title += QStringLiteral(" <span style='color:#555'>%1</span>")
                         .arg(tr("— <span style='background:#e2ecfa'>&nbsp;A&nbsp;</span> "
                                 "block, <span style='background:#fcecd6'>&nbsp;b&nbsp;</span> "
                                 "row"));
        if (nm.isComplex())
            title += QStringLiteral(" <span style='color:#555'>%1</span>")
                         .arg(tr("(complex entries)"));
        auto *box = new QWidget;
        auto *boxLayout = new QVBoxLayout(box);
        boxLayout->setContentsMargins(0, 0, 0, 8);
        boxLayout->setSpacing(3);
        auto *label = new QLabel(title, box);
        label->setTextFormat(Qt::RichText);
        auto *view = new QTableView(box);
        view->setModel(model);
        model->setParent(view);
        view->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
        view->setVerticalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
        view->setSizeAdjustPolicy(QAbstractScrollArea::AdjustToContents);
        view->setEditTriggers(QAbstractItemView::DoubleClicked | QAbstractItemView::EditKeyPressed
                              | QAbstractItemView::AnyKeyPressed);
        // Sized by fitTable when numbers change (ResizeToContents would measure every cell of
        // the table again on every dataChanged).
        view->horizontalHeader()->setSectionResizeMode(QHeaderView::Fixed);
        view->verticalHeader()->setSectionResizeMode(QHeaderView::Fixed);
        // Narrow columns: a 6 x 6 matrix and its sums fit the dock's first width.
        view->horizontalHeader()->setMinimumSectionSize(26);
        if (m_editable && nm.editable && !nm.isComplex()) {
            // The user's own maps: each can be removed (the owner refuses the last two).
            auto *remove = new QToolButton(box);
            remove->setObjectName(QStringLiteral("removeMap:") + nm.name);
            remove->setText(tr("Remove"));
            remove->setToolTip(tr("Remove the map %1 from the IFS (one undo step)")
                                   .arg(subscriptName(nm.name)));
            remove->setAutoRaise(true);
            connect(remove, &QToolButton::clicked, this, [this, i] {
                emit removeMapRequested(i);
            });
            auto *title = new QHBoxLayout;
            title->setContentsMargins(0, 0, 0, 0);
            title->addWidget(label);
            title->addWidget(remove);
            title->addStretch(1);
            boxLayout->addLayout(title);
        } else {
            boxLayout->addWidget(label);
        }
        // Large real matrices (a surface's S_i) get a heat map above the table: the table is
        // too wide to read, the pattern of weights is not.
        if (!nm.isComplex() && nm.rows() > heatMapRows) {
            auto *heat = new MatrixHeatMap(box);
            heat->setObjectName(QStringLiteral("heatMap:") + nm.name);
            heat->setMatrix(nm.name, nm.values);
            boxLayout->addWidget(heat, 0, Qt::AlignLeft);
        }
        boxLayout->addWidget(view, 0, Qt::AlignLeft);
        m_tables->insertWidget(m_tables->count() - 1, box); // before the stretch
        m_boxes << box;
        m_views << view;
        m_models << model;
        fitTable(view);
    }
    if (m_editable && std::any_of(matrices.begin(), matrices.end(),
                    [](const NamedMatrix &m) { return m.editable && !m.isComplex(); })) {
        m_addMap = new QPushButton(tr("Add a Map"));
        m_addMap->setObjectName(QStringLiteral("addMap"));
        m_addMap->setToolTip(tr("A new map S_(p+1), a copy of the last one to edit cell by "
                                "cell (one undo step)"));
        connect(m_addMap, &QPushButton::clicked, this, &MatrixView::addMapRequested);
        m_tables->insertWidget(m_tables->count() - 1, m_addMap, 0, Qt::AlignLeft);
    }
    showHighlight();
}

void MatrixView::fitTable(QTableView *view, bool rows) const
{
    // Whole tables, no inner scroll bars: the outer scroll area scrolls them all together.
    // New numbers change the columns' widths, not the rows' heights (one line each).
    view->resizeColumnsToContents();
    if (rows)
        view->resizeRowsToContents();
    int w = view->verticalHeader()->sizeHint().width() + 2 * view->frameWidth();
    for (int c = 0; c < view->model()->columnCount(); ++c)
        w += view->columnWidth(c);
    int h = view->horizontalHeader()->sizeHint().height() + 2 * view->frameWidth();
    for (int r = 0; r < view->model()->rowCount(); ++r)
        h += view->rowHeight(r);
    view->setFixedSize(w, h);
}

void MatrixView::setSums(Sums sums)
{
    m_sums = sums;
    for (MatrixTableModel *m : m_models)
        m->setSums(sums);
    for (QTableView *v : m_views)
        fitTable(v);
}

void MatrixView::setEditable(bool editable)
{
    m_editable = editable;
    for (MatrixTableModel *m : m_models)
        m->setEditable(editable);
}

void MatrixView::setDigits(int significantDigits)
{
    m_digits = std::clamp(significantDigits, 1, 17);
    for (MatrixTableModel *m : m_models)
        m->setDigits(m_digits);
    for (QTableView *v : m_views)
        fitTable(v);
}

QTableView *MatrixView::table(int matrix) const
{
    return matrix >= 0 && matrix < m_views.size() ? m_views[matrix] : nullptr;
}

QString MatrixView::errorMessage() const
{
    return m_error->isHidden() ? QString() : m_error->text();
}

void MatrixView::showError(const QString &message)
{
    m_error->setText(message);
    m_error->show();
}

} // namespace awb
