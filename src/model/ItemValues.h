#pragma once
// Value types of the inputs every attractor item shares (start set, algorithm, display style),
// and the plane point used for control points. Layer 2 (model): plain values with exact
// equality, because the undo template compares them to skip no-op edits and the tests compare
// them to prove that undo restores a state exactly. Each value checks itself with the same
// function for the setters and for the file loader, so whatever can be set can be saved and
// loaded again.

#include "core/Types.h"

#include <QCoreApplication>
#include <QString>
#include <QStringList>

#include <optional>
#include <vector>

namespace awb {

// A control point or start-set vertex. Items of plane curves use x, y (z stays 0); surface
// items use all three (AttractorItem::pointDimension()).
struct Point {
    double x = 0.0;
    double y = 0.0;
    double z = 0.0;
    bool operator==(const Point &) const = default;
    double operator[](int k) const { return k == 0 ? x : k == 1 ? y : z; }
};
using PointList = std::vector<Point>;

// The points as the core wants them: n x dim (2 or 3), one point per row.
Mat toMatrix(const PointList &points, int dim = 2);
PointList toPointList(const Mat &P);
bool allFinite(const PointList &points);

// Why a value cannot be stored: the field inside the value's JSON object ("points",
// "depth", ...; empty for the value as a whole) and a translated message. The loader prefixes
// the file, the item and the enclosing field.
struct Problem {
    QString field;
    QString message;
};
using MaybeProblem = std::optional<Problem>;

// The set X_0 that deterministic iteration starts from, in plane coordinates — or, for kind
// Lifted, points of the IFS's own (lifted) space: x, y, then the extra coordinates of the
// lifting of 000 §2 (the homogeneous 1 implied), as 000 Fig. 2 starts "from a random
// homogeneous point in five dimensions".
struct StartSetSpec {
    Q_DECLARE_TR_FUNCTIONS(awb::StartSetSpec)
public:
    // VertexLimits: the limit positions of a mesh item's vertices (exact at every depth); no
    // points. Net: control points of the item's net by index (0-based), as the lifted space
    // has them -- the rows of the lifted P (000 §2) -- so the set follows the net when a point
    // moves; one index is a point, two a segment, more a polygon. No points.
    enum class Kind { Point, Segment, Triangle, Polygon, Points, Lifted, VertexLimits, Net };
    Kind kind = Kind::Point;
    PointList points{{0.0, 0.0}};
    // Kind Lifted: the points, each with the lifted space's number of coordinates (the item
    // checks the count against its IFS when it is computed).
    std::vector<std::vector<double>> lifted{};
    // Kind Net: the indices (the item checks them against its number of control points).
    std::vector<int> net{};
    static constexpr int maxNetPoints = 4096;

    bool operator==(const StartSetSpec &) const = default;
    // Right number of finite points for the kind (1, 2, 3, >= 3, >= 1).
    MaybeProblem check() const;
    // JSON spellings, in enum order.
    static const QStringList &kindNames();
};

// How the attractor is drawn: deterministic iteration to a depth, or random iteration.
struct AlgorithmSpec {
    Q_DECLARE_TR_FUNCTIONS(awb::AlgorithmSpec)
public:
    enum class Mode { Deterministic, Random };
    Mode mode = Mode::Deterministic;
    int depth = 8;
    qint64 samples = 100000;
    std::vector<double> probabilities;  // one per map; empty means uniform
    qint64 seed = 1;

    // Deterministic depth k makes N^k images of the start set: more than this is refused.
    static constexpr double maxImages = 2147483648.0;  // 2^31
    static constexpr int maxDepth = 64;                 // the core's own limit
    // The deepest level whose N^k images of the start set stay within 2^31 (maxDepth for
    // one map or none).
    static int maxDepthFor(int maps);
    static constexpr qint64 maxSamples = qint64(1) << 31;
    static constexpr qint64 maxSeed = (qint64(1) << 53) - 1;  // exact in a JSON number

    bool operator==(const AlgorithmSpec &) const = default;
    // `maps` is the item's number of maps (-1 when unknown): it bounds the depth.
    MaybeProblem check(int maps) const;
    static const QStringList &modeNames();
};

// How an attractor is coloured and drawn. Kept apart from the geometry (STYLE.md §4).
struct StyleSpec {
    Q_DECLARE_TR_FUNCTIONS(awb::StyleSpec)
public:
    enum class ColorBy { Map, Address, None };
    ColorBy colorBy = ColorBy::Map;
    int prefixLength = 1;     // address symbols that pick the colour (ColorBy::Address)
    double pointSize = 2.0;   // pixels
    QStringList colors;       // "#rrggbb" in lower case; empty: the views' own palette
    // The raster's tone: hits (every lit pixel opaque, the papers' look), density (log density
    // of the invariant measure, flame-style) or auto (hits for deterministic iteration,
    // density for random iteration). Gamma of the density tone.
    enum class Tone { Auto, Hits, Density };
    Tone tone = Tone::Auto;
    double gamma = 2.2;

    // Colour labels of the raster engine: at most 3 address symbols.
    static constexpr int maxPrefixLength = 3;
    static constexpr double maxPointSize = 100.0;

    bool operator==(const StyleSpec &) const = default;
    MaybeProblem check() const;
    static const QStringList &colorByNames();
    static const QStringList &toneNames();
    // Density when tone is Density, or Auto with random iteration.
    bool densityTone(bool random) const { return tone == Tone::Density || (tone == Tone::Auto && random); }
};

} // namespace awb
