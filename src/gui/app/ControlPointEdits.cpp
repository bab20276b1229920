#include "gui/app/ControlPointEdits.h"

#include "model/AttractorItem.h"
#include "model/Project.h"
#include "model/SubdivisionCurveItem.h"

#include <QCoreApplication>
#include <QUndoStack>

#include <algorithm>
#include <functional>
#include <optional>

namespace awb::control_points {

namespace {

// lupdate takes the context of ControlPointEditsTr::tr() from the macro (a free tr() would get the
// enclosing namespace as its context).
struct ControlPointEditsTr {
    Q_DECLARE_TR_FUNCTIONS(awb::ControlPointEdits)
};

// Fewer points than this leave no polygon to speak of (and no curve of any kind).
constexpr int minPoints = 2;

// The scheme a real Bézier curve gets with `count` points (degree count - 1), or none when the
// item is not one.
std::optional<SchemeSpec> bezierFor(const AttractorItem *item, int count)
{
    const auto *curve = qobject_cast<const SubdivisionCurveItem *>(item);
    if (!curve || curve->scheme().kind != SchemeSpec::Kind::Bezier)
        return std::nullopt;
    SchemeSpec s = curve->scheme();
    s.degree = count - 1;
    return s;
}

// Runs `edit` as one undo step named `text` (a macro when it pushes several commands).
bool asOneStep(AttractorItem *item, const QString &text, const std::function<bool()> &edit)
{
    QUndoStack *stack = item->project() ? item->project()->undoStack() : nullptr;
    if (!stack)
        return edit();
    const int before = stack->index();
    stack->beginMacro(text);
    const bool ok = edit();
    stack->endMacro();
    if (!ok && stack->index() > before)
        stack->undo(); // half an edit is no edit (checked beforehand, so hardly ever)
    return ok;
}

} // namespace

QString whyFixed(const AttractorItem *item, int set)
{
    if (!item || set < 0 || set >= item->controlPointSetCount())
        return ControlPointEditsTr::tr("There is no such point set.");
    if (!item->pointCountEditable(set))
        return ControlPointEditsTr::tr("%1 (%2) has a fixed number of control points.")
            .arg(item->name(), item->typeName());
    return {};
}

bool insert(AttractorItem *item, int set, int index, const Point &point, QString *error)
{
    QString why = whyFixed(item, set);
    const int count = why.isEmpty() ? int(item->controlPoints(set).size()) : 0;
    const auto bezier = why.isEmpty() ? bezierFor(item, count + 1) : std::nullopt;
    if (why.isEmpty() && bezier)
        if (const auto p = qobject_cast<SubdivisionCurveItem *>(item)->checkScheme(*bezier))
            why = ControlPointEditsTr::tr("A Bézier curve of degree %1 is refused: %2")
                      .arg(bezier->degree).arg(p->message);
    if (why.isEmpty() && (index < 0 || index > count))
        why = ControlPointEditsTr::tr("There is no point %1.").arg(index + 1);
    if (!why.isEmpty()) {
        if (error)
            *error = why;
        return false;
    }
    return asOneStep(item,
                     ControlPointEditsTr::tr("Insert control point %1 into %2").arg(index + 1).arg(item->name()),
                     [&] {
                         if (!item->insertControlPoint(index, point, set))
                             return false;
                         auto *curve = qobject_cast<SubdivisionCurveItem *>(item);
                         return !bezier || curve->setScheme(*bezier);
                     });
}

bool remove(AttractorItem *item, int set, const std::vector<int> &indices, QString *error)
{
    QString why = whyFixed(item, set);
    const int count = why.isEmpty() ? int(item->controlPoints(set).size()) : 0;
    std::vector<int> unique = indices;
    std::sort(unique.begin(), unique.end());
    unique.erase(std::unique(unique.begin(), unique.end()), unique.end());
    if (why.isEmpty() && unique.empty())
        why = ControlPointEditsTr::tr("No control point is selected.");
    if (why.isEmpty() && (unique.front() < 0 || unique.back() >= count))
        why = ControlPointEditsTr::tr("There is no point %1.").arg(unique.back() + 1);
    if (why.isEmpty() && count - int(unique.size()) < minPoints)
        why = ControlPointEditsTr::tr("%1 needs at least %2 control points.").arg(item->name()).arg(minPoints);
    const auto bezier = why.isEmpty() ? bezierFor(item, count - int(unique.size()))
                                      : std::nullopt;
    if (!why.isEmpty()) {
        if (error)
            *error = why;
        return false;
    }
    const QString text = unique.size() == 1
                             ? ControlPointEditsTr::tr("Delete control point %1 of %2").arg(unique.front() + 1)
                                   .arg(item->name())
                             : ControlPointEditsTr::tr("Delete %1 control points of %2").arg(unique.size())
                                   .arg(item->name());
    return asOneStep(item, text, [&] {
        if (!item->removeControlPoints(unique, set))
            return false;
        auto *curve = qobject_cast<SubdivisionCurveItem *>(item);
        return !bezier || curve->setScheme(*bezier);
    });
}

Point defaultPoint(const AttractorItem *item, int set, int index)
{
    const PointList &p = item->controlPoints(set);
    const int n = int(p.size());
    const auto mix = [](const Point &a, const Point &b, double t) {
        return Point{a.x + t * (b.x - a.x), a.y + t * (b.y - a.y), a.z + t * (b.z - a.z)};
    };
    if (n == 0)
        return {};
    if (n == 1)
        return mix(p[0], Point{p[0].x + 1, p[0].y, p[0].z}, 1.0);
    if (index <= 0)
        return mix(p[0], p[1], -0.5);
    if (index >= n) {
        if (item->controlPointSetClosed(set)) // the closing edge's midpoint
            return mix(p[std::size_t(n - 1)], p[0], 0.5);
        return mix(p[std::size_t(n - 1)], p[std::size_t(n - 2)], -0.5);
    }
    return mix(p[std::size_t(index - 1)], p[std::size_t(index)], 0.5);
}

} // namespace awb::control_points
