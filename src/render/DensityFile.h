#pragma once
// The raw density of an attractor's picture in files (issue 34), so that it can be tone-mapped
// again elsewhere without rendering again (`attractor-cli render --out F.exr`, `--bits 16`):
// - OpenEXR: four float32 channels R, G, B, A per pixel, A = the pixel's hits and R, G, B =
//   the hits times their colour (core densityChannels), with the frame's world window, the
//   number of samples and the item's project as header attributes. Only DensityExr.cpp sees
//   OpenEXR's headers.
// - 16-bit PNG (RGBA64, straight alpha): A = log(1 + n) / log(1 + n_max), the log density the
//   density tone starts from, at 1/65535; R, G, B the pixel's mean colour; the text chunk
//   "attractor-workbench:max-count" holds n_max, so n = (1 + n_max)^A - 1 comes back; the
//   project's chunks as every PNG figure.
// Layer: render (QtGui).

#include "render/AttractorImage.h"
#include "render/FigureFile.h"

#include <QRectF>
#include <QString>

namespace awb {

struct DensityFileInfo {
    QRectF world;      // the frame's world rectangle (y up)
    QString what;      // e.g. "Fern: 1000000 random points"
    FigureMetadata metadata;
};

inline constexpr const char *kDensityMaxCountKey = "attractor-workbench:max-count";

// False with *error ("cannot write FILE: ...") on failure; an existing file is replaced whole
// or left as it was (model/FileWriting.h).
bool writeDensityExr(const QString &fileName, const AttractorDensity &density,
                     const DensityFileInfo &info, QString *error);
bool writeDensityPng16(const QString &fileName, const AttractorDensity &density,
                       const DensityFileInfo &info, QString *error);

// An EXR written by writeDensityExr (or any with float or half R, G, B, A channels): the
// channels as rgba (row 0 at the top) and the frame's size; the world window when the file
// has ours. Empty rgba with *error for a file that cannot be read.
AttractorDensity readDensityExr(const QString &fileName, QRectF *world, QString *error);

} // namespace awb
