#pragma once
// Start sets written as text (layer 2, model): `attractor-cli points --start TEXT` and Python's
// Item.points(start=TEXT) read the same forms through this one reader --
//   point:x,y  segment:x1,y1,x2,y2  triangle:x1,y1,...  polygon:...  points:...
//   (x,y,z per point for items of space), lifted:x,y,c1,..;x,y,c1,.. (points of the lifted
//   space, 000 §2), net:i,j,.. (control points by index: the rows of the lifted P),
//   vertex-limits (a mesh item's vertices' limit positions).

#include "core/ifs/Attractor.h"

#include <QString>

#include <vector>

namespace awb {

class AttractorItem;
struct DerivedIfs;

// Why a text is no start set: `malformed` when it is none of the forms at all (a usage error
// on a command line), otherwise a form with wrong numbers.
struct StartSetTextError {
    QString message;
    bool malformed = false;
};

// The kind and points (n x dim, one per row) of "point:x,y", "segment:...", "triangle:...",
// "polygon:..." or "points:...". Throws StartSetTextError.
StartSet::Kind parseStartSetText(const QString &text, Mat *points, int dim = 2);

// Net point indices written as text, "0, 9, 18" (commas, semicolons or spaces between them):
// the Properties dock's field and the "net:" form below. Throws StartSetTextError naming the
// first word that is no index (an integer from 0), or for no index at all.
std::vector<int> netIndicesFromText(const QString &text);

// The start set `text` gives for `item` in the IFS space of `d` (its derived IFS). Throws
// StartSetTextError.
StartSet startSetFromText(const AttractorItem &item, const DerivedIfs &d, const QString &text);

} // namespace awb
