#pragma once
// Renders attractor figures to images the way the papers show them: a row of panels with the
// control polygon and the iterates X_0, F(X_0), F^2(X_0), ... of a start set. Used by the CLI;
// only QtGui (QImage/QPainter), no widgets.

#include "core/Attractor.h"

#include <QColor>
#include <QImage>
#include <QString>
#include <vector>

namespace awb {

struct FigurePanel {
    QString caption;
    int depth = 0;
};

struct FigureSpec {
    QString title;
    const Ifs *ifs = nullptr;
    StartSet start;
    Mat controlPoints;                 // m x 2, drawn as the control polygon (may be empty)
    std::vector<Mat> overlays;         // extra polylines (e.g. the exact curve), n x 2 each
    std::vector<FigurePanel> panels;
    int panelWidth = 420;
    int panelHeight = 360;
};

// Colour of map i (by address) — a qualitative palette that reads on white and in print.
QColor mapColor(int i);

// Draws all panels side by side. Shallow levels are drawn as vector dots/segments/polygons,
// deep ones through a RasterSink at the panel's resolution. Throws InputError on bad input.
QImage renderFigure(const FigureSpec &spec);

} // namespace awb
