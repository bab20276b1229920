#pragma once
// ControlPointEdits (layer 3, GUI): adding, inserting and deleting control points, shared by
// the attractor view's context menu and double click and the Properties point table. Each edit
// is one undo step; a Bézier curve's degree follows its number of points in the same step (a
// Bézier of degree n has exactly n + 1 points). Kinds whose point count is fixed
// (AttractorItem::pointCountEditable() false) are refused with a reason for the user.
#include "model/ItemValues.h"

#include <QString>
#include <vector>

namespace awb {

class AttractorItem;

namespace control_points {

// Why points of set `set` cannot be added or removed ("" when they can).
QString whyFixed(const AttractorItem *item, int set);
// Inserts `point` before index `index` (== count: appends). False with *error saying why.
bool insert(AttractorItem *item, int set, int index, const Point &point, QString *error);
// Removes the points `indices` of set `set` together. False with *error saying why.
bool remove(AttractorItem *item, int set, const std::vector<int> &indices, QString *error);
// Where a point inserted before `index` goes by default: halfway between its neighbours, or
// beyond the first / last point by half the end edge.
Point defaultPoint(const AttractorItem *item, int set, int index);

} // namespace control_points
} // namespace awb
