#pragma once
// Writing an item's attractor points (layer 2, model): F^depth(X0) as CSV text or as a binary
// PLY point cloud, each point with the map applied last (numbered as the item numbers its
// maps). Shared by attractor-cli (`points --csv`, `export --format ply`) and the GUI's
// File > Export Points. The iteration runs on the calling thread and can be cancelled through
// the IterationControl.

#include "core/ifs/Address.h"
#include "core/ifs/Attractor.h"

#include <QColor>
#include <QString>

#include <cstdint>
#include <functional>
#include <vector>

class QIODevice;

namespace awb {

struct DerivedIfs;

// Points F^depth(X0) gives: images x start vertices x views. Unknown (-1) for an automaton
// (DerivedIfs::iterate), whose images are not N^depth.
double exportPointCount(const DerivedIfs &d, const StartSet &start, int depth);
// Whether the points have three coordinates (a surface's view), not two.
bool exportsSpacePoints(const DerivedIfs &d);

// CSV: the header "x,y,map,view" (or "x,y,z,map,view"), then one line per point with 17
// significant digits, the map 1-based (0 for X0 itself) and the view 1-based. Returns the
// number of points; throws InputError when the device refuses to write. A non-empty `address`
// w (ifs/Address.h) writes the sub-copy f_w(F^depth(X0)) instead: the same number of points,
// each the image under f_w of the point written without it, its map that of w's first symbol.
std::uint64_t writePointsCsv(QIODevice &out, const DerivedIfs &d, const StartSet &start,
                             int depth, const IterationControl &control = {},
                             const Address &address = {});

// The same points in memory (attractor_workbench's Item.points): one row per point (2 or 3
// columns, as the CSV's coordinates), and per point its 0-based map (-1 for X0 itself) and its
// 0-based view. Stops early, with what it has, when `control` cancels.
struct CollectedPoints {
    Mat points;
    std::vector<int> maps;
    std::vector<int> views;
};
CollectedPoints collectPoints(const DerivedIfs &d, const StartSet &start, int depth,
                              const IterationControl &control = {}, const Address &address = {});

// Binary little-endian PLY: x, y, z as float (z = 0 for plane points), red, green, blue of
// `color(map)` and the 0-based map as uchar; `title` goes into a comment. Readable by MeshLab,
// Blender and any PLY parser. Refuses (InputError) an item drawn by an automaton: the vertex
// count must be known before the points.
std::uint64_t writePointsPly(QIODevice &out, const QString &title, const DerivedIfs &d,
                             const StartSet &start, int depth,
                             const std::function<QColor(int map)> &color,
                             const IterationControl &control = {});

} // namespace awb
