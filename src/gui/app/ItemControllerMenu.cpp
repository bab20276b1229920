// ItemController: control point editing in the attractor view (its context menu and the
// double click on an edge of the control polygon), through ControlPointEdits: each insertion
// or deletion is one undo step.
#include "gui/app/ControlPointEdits.h"
#include "gui/app/ItemController.h"
#include "gui/views/AttractorView.h"
#include "model/AttractorItem.h"

#include <QAction>
#include <QMenu>

#include <cmath>

namespace awb {

namespace {

QAction *addAction(QMenu *menu, const char *name, const QString &text, const QString &why)
{
    QAction *a = menu->addAction(text);
    a->setObjectName(QString::fromLatin1(name));
    a->setEnabled(why.isEmpty());
    a->setToolTip(why); // why it is disabled
    return a;
}

} // namespace

void ItemController::fillContextMenu(QMenu *menu, const QPointF &screen)
{
    menu->setToolTipsVisible(true);
    auto *item = qobject_cast<AttractorItem *>(m_item.data());
    const auto edit = [this, item](auto &&apply) {
        QString error;
        if (!item || !apply(&error))
            emit editRefused(error);
    };
    const QPointF world = m_attractor->screenToWorld(screen);
    const Point at{world.x(), world.y()};
    if (item && item->controlPointSetCount() > 0 && item->pointDimension() == 2) {
        QPointF onEdge;
        const int handle = m_attractor->controlPointAt(screen);
        const int edge = handle < 0 ? m_attractor->controlEdgeAt(screen, &onEdge) : -1;
        if (handle >= 0) {
            const auto [set, i] = m_attractor->controlPointSet(handle);
            const QString why = control_points::whyFixed(item, set);
            connect(addAction(menu, "actionInsertPointBefore", tr("Insert Point &Before %1")
                                  .arg(i + 1), why),
                    &QAction::triggered, this, [=, set = set, i = i] {
                        edit([&](QString *e) {
                            return control_points::insert(
                                item, set, i, control_points::defaultPoint(item, set, i), e);
                        });
                    });
            connect(addAction(menu, "actionInsertPointAfter", tr("Insert Point &After %1")
                                  .arg(i + 1), why),
                    &QAction::triggered, this, [=, set = set, i = i] {
                        edit([&](QString *e) {
                            return control_points::insert(
                                item, set, i + 1,
                                control_points::defaultPoint(item, set, i + 1), e);
                        });
                    });
            connect(addAction(menu, "actionDeletePoint", tr("&Delete Point %1").arg(i + 1), why),
                    &QAction::triggered, this, [=, set = set, i = i] {
                        edit([&](QString *e) { return control_points::remove(item, set, {i}, e); });
                    });
        } else if (edge >= 0) {
            const auto [set, i] = m_attractor->controlPointSet(edge);
            const Point p{onEdge.x(), onEdge.y()};
            connect(addAction(menu, "actionInsertPointHere", tr("&Insert Point Here"),
                              control_points::whyFixed(item, set)),
                    &QAction::triggered, this, [=, set = set, i = i] {
                        edit([&](QString *e) {
                            return control_points::insert(item, set, i + 1, p, e);
                        });
                    });
        } else {
            // Appended to the set whose end is nearest to the click.
            int set = 0;
            double best = -1;
            for (int k = 0; k < item->controlPointSetCount(); ++k) {
                if (item->controlPoints(k).empty())
                    continue;
                const Point &last = item->controlPoints(k).back();
                const double d = std::hypot(last.x - at.x, last.y - at.y);
                if (best < 0 || d < best) {
                    best = d;
                    set = k;
                }
            }
            connect(addAction(menu, "actionAppendPoint", tr("&Append Point Here"),
                              control_points::whyFixed(item, set)),
                    &QAction::triggered, this, [=] {
                        edit([&](QString *e) {
                            return control_points::insert(
                                item, set, int(item->controlPoints(set).size()), at, e);
                        });
                    });
        }
        menu->addSeparator();
    }
    QAction *fit = menu->addAction(tr("&Fit View"));
    fit->setObjectName(QStringLiteral("actionFitView"));
    connect(fit, &QAction::triggered, m_attractor, &AttractorView::fitToContents);
}

void ItemController::onEdgeDoubleClicked(int flatIndex, const QPointF &world)
{
    auto *item = qobject_cast<AttractorItem *>(m_item.data());
    const auto [set, i] = m_attractor->controlPointSet(flatIndex);
    if (!item || set < 0)
        return;
    QString error;
    if (!control_points::insert(item, set, i + 1, {world.x(), world.y()}, &error))
        emit editRefused(error);
}

} // namespace awb
