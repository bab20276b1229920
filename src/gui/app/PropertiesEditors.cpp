// PropertiesWidget: the editors of the structured inputs -- the control point table (with the
// point set chooser and the add / insert / delete buttons and context menu), the map colour
// button -- and the eigenvalue plot's state. Point insertions and deletions go through ControlPointEdits: one undo step each.
#include "gui/app/PropertiesDock.h"

#include "gui/app/ControlPointEdits.h"
#include "gui/app/PaletteDialog.h"
#include "gui/views/AttractorRenderer.h"
#include "gui/views/ThemeColours.h"
#include "model/AttractorItem.h"
#include "model/EigenvaluePlotItem.h"
#include "model/Project.h"
#include "model/SubdivisionMeshItem.h"

#include "core/mesh/MeshAnalysis.h"

#include <QAction>
#include <QComboBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPoint>
#include <QMenu>
#include <QPushButton>
#include <QTableWidget>
#include <QToolButton>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace awb {

void PropertiesWidget::setDefaultPalette(const QList<QColor> &palette)
{
    m_defaultPalette = palette;
    updateValues();
}

std::vector<int> PropertiesWidget::selectedPointRows() const
{
    std::vector<int> rows;
    if (!m_points)
        return rows;
    for (const QModelIndex &index : m_points->selectionModel()->selectedIndexes())
        rows.push_back(index.row());
    if (rows.empty() && m_points->currentRow() >= 0)
        rows.push_back(m_points->currentRow());
    std::sort(rows.begin(), rows.end());
    rows.erase(std::unique(rows.begin(), rows.end()), rows.end());
    return rows;
}

void PropertiesWidget::addPointEditors()
{
    auto *item = qobject_cast<AttractorItem *>(m_item.data());
    auto *content = static_cast<QVBoxLayout *>(m_content->layout());
    if (item->controlPointSetCount() < 1)
        return;
    m_pointSet = std::clamp(m_pointSet, 0, item->controlPointSetCount() - 1);
    auto *pointsBox = new QGroupBox(tr("Control points"));
    auto *pointsLayout = new QVBoxLayout(pointsBox);
    // Items with several point sets (a union of curves, a junction) edit one set at a time,
    // lettered as the attractor view labels them.
    if (item->controlPointSetCount() > 1) {
        auto *sets = new QComboBox;
        for (int k = 0; k < item->controlPointSetCount(); ++k)
            sets->addItem(tr("Set %1 (%2)").arg(k + 1).arg(QChar(u'p' + k)));
        sets->setCurrentIndex(m_pointSet);
        m_editors.insert(QStringLiteral("points.set"), sets);
        connect(sets, &QComboBox::currentIndexChanged, this, [this](int k) {
            m_pointSet = k;
            updateValues();
        });
        pointsLayout->addWidget(sets);
    }
    // A surface's net has z too (pointDimension() == 3): one column per coordinate.
    const int dim = std::clamp(item->pointDimension(), 2, 3);
    m_points = new QTableWidget(0, dim);
    m_points->setHorizontalHeaderLabels(QStringList{tr("x"), tr("y"), tr("z")}.mid(0, dim));
    m_points->horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
    m_points->setMinimumHeight(120);
    m_points->setContextMenuPolicy(Qt::ActionsContextMenu);
    pointsLayout->addWidget(m_points);
    m_editors.insert(QStringLiteral("points"), m_points);
    auto *table = m_points;
    connect(table, &QTableWidget::cellChanged, this, [this, item, table](int r, int c) {
        if (m_updating)
            return;
        bool ok = false;
        const double v = table->item(r, c)->text().toDouble(&ok);
        Point p = item->controlPoints(m_pointSet)[std::size_t(r)];
        (c == 0 ? p.x : c == 1 ? p.y : p.z) = v;
        if (!ok || !std::isfinite(v) || !item->moveControlPoint(r, p, 0, m_pointSet)) {
            updateValues();
            report(tr("\"%1\" is not a finite number.").arg(table->item(r, c)->text()));
        }
    });

    // Add (after the last), insert (before the selected) and delete (the selected rows).
    const auto insertAt = [this, item](int index) {
        QString error;
        if (!control_points::insert(item, m_pointSet, index,
                                    control_points::defaultPoint(item, m_pointSet, index),
                                    &error))
            report(error);
        else if (m_points)
            m_points->selectRow(index);
    };
    auto *buttons = new QHBoxLayout;
    const auto button = [&](const char *key, const QString &text, const QString &icon,
                            const QString &tip, auto slot) {
        auto *b = new QToolButton;
        b->setObjectName(QString::fromLatin1(key));
        b->setIcon(QIcon::fromTheme(icon));
        b->setText(text);
        b->setToolTip(tip);
        b->setToolButtonStyle(Qt::ToolButtonTextOnly); // narrow: the dock may be
        connect(b, &QToolButton::clicked, this, slot);
        m_editors.insert(QString::fromLatin1(key), b);
        buttons->addWidget(b);
        auto *a = new QAction(QIcon::fromTheme(icon), text, table);
        connect(a, &QAction::triggered, this, slot);
        table->addAction(a);
        return b;
    };
    auto *add = button("points.add", tr("Add"), QStringLiteral("list-add"),
                       tr("Append a point after the last one"), [this, item, insertAt] {
                           insertAt(int(item->controlPoints(m_pointSet).size()));
                       });
    auto *insert = button("points.insert", tr("Insert"), QStringLiteral("insert-object"),
                          tr("Insert a point before the selected one (halfway to its "
                             "predecessor)"),
                          [this, insertAt] {
                              const auto rows = selectedPointRows();
                              insertAt(rows.empty() ? 0 : rows.front());
                          });
    auto *remove = button("points.delete", tr("Delete"), QStringLiteral("list-remove"),
                          tr("Delete the selected points (one undo step)"), [this, item] {
                              QString error;
                              if (!control_points::remove(item, m_pointSet, selectedPointRows(),
                                                          &error))
                                  report(error);
                          });
    buttons->addStretch();
    pointsLayout->addLayout(buttons);
    auto *fixed = new QLabel;
    fixed->setWordWrap(true);
    pointsLayout->addWidget(fixed);

    m_bindings.append({QStringLiteral("points"),
                       [this, item, table, dim, add, insert, remove, fixed](const Infos &) {
        const QSignalBlocker block(table);
        const PointList &pts = item->controlPoints(m_pointSet);
        table->setRowCount(int(pts.size()));
        for (int i = 0; i < int(pts.size()); ++i) {
            table->setVerticalHeaderItem(i, new QTableWidgetItem(QString::number(i + 1)));
            for (int k = 0; k < dim; ++k)
                table->setItem(i, k, new QTableWidgetItem(
                                         QString::number(pts[std::size_t(i)][k], 'g', 10)));
        }
        const QString why = control_points::whyFixed(item, m_pointSet);
        for (QWidget *w : {static_cast<QWidget *>(add), static_cast<QWidget *>(insert),
                           static_cast<QWidget *>(remove)})
            w->setEnabled(why.isEmpty());
        for (QAction *a : table->actions())
            a->setEnabled(why.isEmpty());
        fixed->setText(why);
        fixed->setVisible(!why.isEmpty());
    }});
    content->addWidget(pointsBox);
}

void PropertiesWidget::addPaletteEditor(QFormLayout *form)
{
    auto *item = qobject_cast<AttractorItem *>(m_item.data());
    auto *button = new QPushButton;
    button->setToolTip(tr("The colour of each map's points: click to choose"));
    m_editors.insert(QStringLiteral("style.colors"), button);
    const auto shown = [item] {
        QList<QColor> colors;
        for (const QString &c : item->style().colors)
            colors << QColor(c);
        return colors;
    };
    const auto defaults = [this] {
        QList<QColor> d = m_defaultPalette;
        if (d.isEmpty())
            for (int i = 0; i < 8; ++i)
                d << AttractorRenderer::mapColor(i);
        return d;
    };
    connect(button, &QPushButton::clicked, this, [this, item, shown, defaults] {
        PaletteDialog dialog(shown(), defaults(), std::max(1, item->mapCount()), this);
        if (dialog.exec() != QDialog::Accepted)
            return;
        StyleSpec s = item->style();
        s.colors.clear();
        for (const QColor &c : dialog.colors())
            s.colors << c.name(QColor::HexRgb).toLower();
        if (auto p = item->checkStyle(s)) {
            report(p->message);
            return;
        }
        item->setStyle(s); // one undo step; nothing when unchanged
    });
    m_bindings.append({QStringLiteral("style.colors"), [item, button, shown, defaults](const Infos &) {
        const QList<QColor> own = shown();
        const int n = std::clamp(item->mapCount(), 1, 8);
        QList<QColor> colors;
        for (int i = 0; i < n; ++i)
            colors << paletteColor(own.isEmpty() ? defaults() : own, i, Qt::black);
        button->setIcon(PaletteDialog::swatchIcon(colors));
        button->setIconSize(QSize(14 * n, 14));
        button->setText(own.isEmpty() ? tr("Default…") : tr("Own…"));
    }});
    form->addRow(tr("Map colours:"), button);
}

void PropertiesWidget::addEigenvaluePlotStatus(QFormLayout *form)
{
    auto *plot = qobject_cast<EigenvaluePlotItem *>(m_item.data());
    auto *status = new QLabel;
    status->setWordWrap(true);
    form->addRow(status);
    m_bindings.append({QStringLiteral("plot"), [plot, status](const Infos &) {
        if (const auto data = plot->eigenvalues()) {
            std::size_t n = 0;
            for (const auto &s : data->spectra)
                n += s.values.size();
            status->setText(tr("%1 matrices %2_i, %3 eigenvalues, plotted in the centre; "
                               "click an eigenvalue to mark its map (its matrices in the "
                               "Matrices dock).")
                                .arg(data->spectra.size()).arg(data->symbol).arg(n));
            status->setStyleSheet(QString());
        } else {
            status->setText(plot->derivedError());
            status->setStyleSheet(
                QStringLiteral("color: %1").arg(errorTextColour(status->palette()).name()));
        }
    }});
}

} // namespace awb
