#pragma once
// Fractal flames in and out (issue 34; layer 2, model): the XML genomes of flam3 (.flame,
// .flam3), which Apophysis, JWildfire and Fractorium read and write, as custom fractals with
// control points, and any affine item of the plane as a flame that flam3-render draws.
//
// What a flame's xform means (flam3 3.1.1, parser.c and variations.c): the pre-affine map
// coefs="a d b e c f" is x' = a x + b y + c, y' = d x + e y + f (flam3 stores it as c[3][2],
// row k = the coefficients of x, y, 1); then the variations, summed with their weights; then
// the post-affine map `post` in the same order. With the linear variation alone (weight w)
// an xform is the affine map post(w pre(p)), which is what is imported. A flame's y axis
// points down the picture (image rows), the application's up: import and export mirror y, so
// that the picture is the one flam3-render draws. The kept and the dropped fields are listed
// in docs/exchange.md; nothing is dropped without a warning naming the flame, the xform and
// the line.

#include "model/IfsExchange.h"

#include <QByteArray>
#include <QRectF>
#include <QSize>
#include <QString>
#include <QStringList>

#include <optional>

namespace awb {

class AttractorItem;

// Every <flame> of a flam3 file (under <flames>, <pick> or alone), one item each; malformed
// flames are left out with line and column. InputError when the file cannot be read.
ImportedItems importFlame(const QString &fileName);
ImportedItems importFlameText(const QByteArray &text, const QString &fileName);

// The view of a flame: the world rectangle (y up) drawn into an image of `size` pixels.
struct FlameFrame {
    QRectF world;
    QSize size;
};

// The plane maps a flame of `item` would hold: fractintEntryOf's, refused (nullopt and *why)
// for an IFS of space. The CLI asks before it frames the item.
std::optional<FractintEntry> flameEntryOf(const AttractorItem &item, QString *why);

// The item as a flam3 genome (one <flame> in <flames>). A flame item: itself, every field
// (its own camera and palette; `mapColours` and `frame` unused). Any other: its affine maps of
// the plane as xforms with the linear variation, weights = the random iteration's
// probabilities, each map its colour of `mapColours` ("#rrggbb", one per map) through a
// 256-entry palette, framed as `frame` (centre, scale in pixels per unit, size). nullopt with
// *why for an item that is neither a flame nor an affine IFS of the plane. The window's
// Export Item As and `attractor-cli export --format flame` both write this.
std::optional<QByteArray> flameOf(const AttractorItem &item, const QStringList &mapColours,
                                  const FlameFrame &frame, QString *why);

} // namespace awb
