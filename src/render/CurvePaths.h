#pragma once
// Vector paths of a curve drawn by deterministic iteration, for SVG and PDF figures.
//
// F^depth(X0) of a polyline start set is N^depth small polylines; at depth 13 a B-spline is
// 8 192 of them, a ternary scheme 1.6 million. Drawn one by one they make a file of megabytes
// that no journal takes. Streamed in address order (the order awb::iterate emits), consecutive
// images of a curve meet (or nearly: the pieces f_w(X0) and f_w'(X0) of neighbouring addresses
// both converge to the curve), so they join into one path; and vertices closer than a fraction
// of a device pixel to the last one kept are dropped (radial-distance simplification): the path
// stays within `tolerance` device pixels of every image, far below what print resolves. A
// B-spline at depth 13 becomes one path of a few thousand vertices at 300 dpi.
//
// Layer: render (QtGui). Used by the attractor view's export and print and by the CLI's figures.
#include "core/ifs/Attractor.h"
#include "core/ifs/Ifs.h"

#include <QColor>
#include <QPainterPath>
#include <QTransform>

#include <atomic>
#include <functional>
#include <vector>

class QPainter;

namespace awb {

class CurvePathSink : public AttractorSink {
public:
    struct Path {
        QColor colour;
        QPainterPath path;        // painter (logical) coordinates
        std::size_t vertices = 0;
    };
    using ColourFn = std::function<QColor(const std::uint8_t *address, int length)>;

    // `toLogical` maps plane (view) coordinates to the painter's logical coordinates;
    // `devicePixelsPerLogical` scales the tolerances, given in device pixels.
    CurvePathSink(std::vector<Projection> views, QTransform toLogical,
                  double devicePixelsPerLogical, ColourFn colour,
                  std::size_t maxVertices = 1'000'000, double tolerance = 0.3);

    // Polylines are joined and simplified; images of any other kind set overflowed() (the
    // caller draws those as a raster or as shapes).
    void consume(const Mat &vertices, StartSet::Kind kind, const std::uint8_t *address,
                 int length) override;

    // More than maxVertices would be kept, or an image was not a polyline: draw a raster.
    bool overflowed() const { return m_overflow; }
    // Set to true on overflow: pass it as IterationControl::cancel to stop the iteration.
    void setOverflowFlag(std::atomic<bool> *flag) { m_overflowFlag = flag; }
    std::size_t vertices() const { return m_kept; }
    // Ends the open subpaths and hands the paths over (one per colour run and view).
    std::vector<Path> finish();

private:
    struct Track {             // the open subpath of one view
        int path = -1;         // index into m_paths
        QPointF last;          // last vertex kept
        QPointF pending;       // last vertex seen but dropped (ends the subpath)
        bool hasPending = false;
        bool open = false;
    };
    void setOverflow();
    void flush(Track &t);
    void lineTo(Track &t, QPointF q);

    std::vector<Projection> m_views;
    QTransform m_toLogical;
    double m_tolerance;        // logical units
    double m_join;             // logical units
    ColourFn m_colour;
    std::size_t m_maxVertices;
    std::size_t m_kept = 0;
    bool m_overflow = false;
    std::atomic<bool> *m_overflowFlag = nullptr;
    std::vector<Track> m_tracks;
    std::vector<Path> m_paths;
};

// Draws the paths with a pen of `width` logical units (round caps and joins).
void drawCurvePaths(QPainter &painter, const std::vector<CurvePathSink::Path> &paths,
                    double width);

// Device pixels per logical unit of the painter (its device transform's scale): how finely a
// raster drawn into it must be resolved, and what a device pixel is in logical units.
double devicePixelsPerLogical(const QPainter &painter);
// Whether the painter writes vectors (SVG, PDF, a printer, a QPicture) rather than pixels.
bool isVectorDevice(const QPainter &painter);

} // namespace awb
