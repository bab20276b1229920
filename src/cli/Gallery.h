#pragma once
// The bundled figures the first CLI renders: 000 Figs. 2, 3 and 5 (cubic B-spline from a
// single point, end-interpolating cubic from a triangle, four-point scheme from a segment).

#include "core/ifs/Attractor.h"

#include <QString>
#include <memory>
#include <vector>

namespace awb {

struct GalleryExample {
    QString id;       // file name stem, named after the paper figure
    QString title;
    std::shared_ptr<CurveScheme> scheme;
    Mat controlPoints;    // m x 2
    Mat start;            // start set in the plane (or lifted coordinates)
    StartSet::Kind startKind = StartSet::Kind::Points;
    int depth = 14;
};

std::vector<GalleryExample> builtinGallery();

} // namespace awb
