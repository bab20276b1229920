#pragma once
// flam3's XML genomes (.flame, .flam3: flam3 3.1.1's parser.c and flam3_print, which
// Apophysis, JWildfire and Fractorium read and write) to and from core flames (flame/Flame.h),
// field by field (layer 2, model). What flam3 draws is kept: the xforms with their variations
// and parameters, pre and post affine maps, weights, colours, colour speeds, opacities and
// xaos rows, the final xform, the palette (sparse <color> entries filled in as flam3 does,
// <palette> and <colors> hex), <symmetry> (its xforms added as flam3's parser adds them), the
// camera and the tone. Animation (time, <motion>, motion_*, interpolation), the spatial and
// temporal filter shapes, <edit> histories and a few others are not: each is named in a
// warning with the flame, the xform and the line. Attributes of other programs that flam3
// ignores (JWildfire's variations beyond flam3's) are named the same way; JWildfire's
// linear3D is flam3's linear in the plane.
//
// The reader is linear in the file and bounded: at most flame::kMaxXforms xforms per flame
// (symmetry's included), 256 palette entries, whole-number attributes range-checked before
// anything is allocated; a malformed flame is left out with its line and column, the others
// are kept. The writer gives every number its shortest exact text: a flame written and read
// back is the same flame.

#include "core/flame/Flame.h"

#include <QByteArray>
#include <QString>
#include <QStringList>

#include <vector>

namespace awb {

struct FlameRead {
    flame::Flame flame;
    int symmetry = 0;         // the <symmetry kind> read (its xforms are in flame.xforms)
    qint64 line = 0, column = 0;
};

struct FlameFileRead {
    std::vector<FlameRead> flames;
    QStringList problems;  // flames left out, with line and column
    QStringList warnings;  // what was read with a loss
};

FlameFileRead readFlameText(const QByteArray &text, const QString &fileName);

// One <flame> element (flam3's layout: attributes, xforms, final xform, palette as <color>
// entries) and a file of several under <flames>.
QByteArray flameElement(const flame::Flame &flame);
QByteArray flameFileText(const std::vector<flame::Flame> &flames);

} // namespace awb
