// ItemController: the edits the views make -- the gestures of a drag (one undo step each),
// control points and start points dragged in the 2D and 3D views, a matrix cell typed in the
// Matrices dock (with the offer to keep its row affine), a map added or removed there.

#include "gui/app/ItemController.h"

#include "gui/views/AttractorView.h"
#include "model/AttractorItem.h"
#include "model/NumberFormat.h"
#include "model/Project.h"
#include "model/SubdivisionCurveItem.h"

#include <QVector3D>

#include <cmath>

namespace awb {

void ItemController::beginGesture()
{
    endGesture();
    if (!m_item || !m_item->project())
        return;
    m_gestureProject = m_item->project();
    m_gesture = m_gestureProject->beginGesture();
}

void ItemController::endGesture()
{
    if (m_gesture != 0 && m_gestureProject)
        m_gestureProject->endGesture(m_gesture);
    m_gesture = 0;
    m_gestureProject = nullptr;
}

void ItemController::onSurfacePressed()
{
    beginGesture();
}

void ItemController::onControlDragged3D(int index, const QVector3D &world)
{
    if (auto *item = qobject_cast<AttractorItem *>(m_item.data()))
        item->moveControlPoint(index, {world.x(), world.y(), world.z()}, m_gesture);
}

void ItemController::onStartDragged3D(int index, const QVector3D &world)
{
    moveStartVertex(index, {world.x(), world.y(), world.z()});
}

void ItemController::onControlPressed(int)
{
    // The view must not refit under the user's hand while the curve changes shape.
    m_attractor->setAutoFit(false);
    beginGesture();
}

void ItemController::onControlDragged(int index, const QPointF &world)
{
    // The view numbers the handles of all point sets in one sequence.
    const auto [set, i] = m_attractor->controlPointSet(index);
    if (auto *item = qobject_cast<AttractorItem *>(m_item.data()); item && set >= 0)
        item->moveControlPoint(i, {world.x(), world.y()}, m_gesture, set);
}

void ItemController::onControlReleased(int index, const QPointF &start, const QPointF &end)
{
    if (start != end)
        onControlDragged(index, end);
    endGesture();
}

void ItemController::onStartPressed(int)
{
    m_attractor->setAutoFit(false);
    beginGesture();
}

void ItemController::onStartDragged(int index, const QPointF &world)
{
    moveStartVertex(index, {world.x(), world.y()});
}

void ItemController::moveStartVertex(int index, const Point &to)
{
    auto *item = qobject_cast<AttractorItem *>(m_item.data());
    if (!item)
        return;
    StartSetSpec s = item->startSet();
    if (index < 0 || index >= int(s.points.size()))
        return;
    s.points[std::size_t(index)] = to;
    item->setStartSet(s, m_gesture);
}

void ItemController::onStartReleased(int index, const QPointF &start, const QPointF &end)
{
    if (start != end)
        onStartDragged(index, end);
    endGesture();
}

void ItemController::onCellEdited(int matrix, int row, int column, double value)
{
    auto *curve = qobject_cast<SubdivisionCurveItem *>(m_item.data());
    if (!curve || curve->scheme().kind != SchemeSpec::Kind::Matrices)
        return;
    SchemeSpec s = curve->scheme();
    if (matrix < 0 || matrix >= int(s.matrices.size()))
        return;
    Mat &S = s.matrices[std::size_t(matrix)];
    if (row < 0 || row >= S.rows() || column < 0 || column >= S.cols())
        return;
    const double old = S(row, column);
    S(row, column) = value;
    const auto problem = curve->checkScheme(s);
    if (!problem) {
        curve->setScheme(s);
        return;
    }
    const QString name = subscriptName(QStringLiteral("S_%1").arg(matrix + 1));
    // Offer to keep the row affine: the largest other entry (nearest column on a tie) absorbs
    // the difference, if that makes the matrices valid.
    const double defect = S.row(row).sum() - 1.0;
    int partner = -1;
    for (int c = 0; c < S.cols(); ++c) {
        if (c == column)
            continue;
        if (partner < 0 || std::abs(S(row, c)) > std::abs(S(row, partner)) + 1e-15
            || (std::abs(S(row, c)) >= std::abs(S(row, partner)) - 1e-15
                && std::abs(c - column) < std::abs(partner - column)))
            partner = c;
    }
    if (partner >= 0 && std::abs(defect) > 0 && std::isfinite(defect) && m_askRebalance) {
        SchemeSpec balanced = s;
        Mat &B = balanced.matrices[std::size_t(matrix)];
        B(row, partner) -= defect;
        if (!curve->checkScheme(balanced)) {
            const QString question
                = tr("Changing %1 (%2, %3) from %4 to %5 makes row %2 sum to %6, not 1: the rows "
                     "of a subdivision matrix are affine combinations.\n\nTake the difference "
                     "%7 from the entry in column %8 (%9 → %10) so that the row sums to 1?")
                      .arg(name).arg(row + 1).arg(column + 1)
                      .arg(formatNumber(old), formatNumber(value), formatNumber(1.0 + defect),
                           formatNumber(defect))
                      .arg(partner + 1)
                      .arg(formatNumber(S(row, partner)), formatNumber(B(row, partner)));
            if (m_askRebalance(question)) {
                curve->setScheme(balanced); // both cells: one undo step
                return;
            }
            refreshNow();
            return; // declined: nothing changes, nothing to report
        }
    }
    refreshNow(); // the table shows the model's value again
    emit editRefused(tr("%1 (%2, %3) = %4 was refused: %5")
                         .arg(name).arg(row + 1).arg(column + 1).arg(formatNumber(value))
                         .arg(problem->message));
}

void ItemController::onMapCountEdited(int removed)
{
    auto *curve = qobject_cast<SubdivisionCurveItem *>(m_item.data());
    if (!curve || curve->scheme().kind != SchemeSpec::Kind::Matrices
        || curve->scheme().matrices.empty())
        return;
    SchemeSpec s = curve->scheme();
    if (removed < 0) {
        s.matrices.push_back(s.matrices.back());  // a copy of the last map, to edit
    } else {
        if (removed >= int(s.matrices.size()))
            return;
        if (s.matrices.size() <= 2) {
            emit editRefused(tr("%1 cannot be removed: an IFS of own matrices needs at least "
                                "two maps")
                                 .arg(subscriptName(QStringLiteral("S_%1").arg(removed + 1))));
            return;
        }
        s.matrices.erase(s.matrices.begin() + removed);
    }
    if (const auto problem = curve->checkScheme(s)) {
        emit editRefused(removed < 0 ? tr("No map was added: %1").arg(problem->message)
                                     : tr("No map was removed: %1").arg(problem->message));
        return;
    }
    curve->setScheme(s);
}

} // namespace awb
