#pragma once
// The start set an attractor item takes by default (layer 2, model): shared by the item's
// edits (AttractorItem.cpp) and its declared properties (AttractorProperties.cpp).

#include "model/ItemValues.h"

#include <vector>

namespace awb {

// The net start set a net begins with: its largest triangle (the lifting's first free rows,
// 000 §2), the start of 000 Fig. 7.
std::vector<int> largestNetTriangle(const PointList &control, int dimension);

// The start set's default points when its kind changes: taken from the control polygon so that
// the new set lies where the curve is.
PointList startPointsFor(StartSetSpec::Kind kind, const PointList &control);

} // namespace awb
