#include "model/ItemValues.h"

#include <QRegularExpression>

#include <cmath>

namespace awb {

Mat toMatrix(const PointList &points, int dim)
{
    Mat P(Eigen::Index(points.size()), dim);
    for (size_t i = 0; i < points.size(); ++i)
        for (int k = 0; k < dim; ++k)
            P(Eigen::Index(i), k) = points[i][k];
    return P;
}

PointList toPointList(const Mat &P)
{
    PointList out(size_t(P.rows()));
    for (Eigen::Index i = 0; i < P.rows(); ++i)
        out[size_t(i)] = {P(i, 0), P.cols() > 1 ? P(i, 1) : 0.0, P.cols() > 2 ? P(i, 2) : 0.0};
    return out;
}

bool allFinite(const PointList &points)
{
    for (const Point &p : points)
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
            return false;
    return true;
}

// ---- start set --------------------------------------------------------------------------------

const QStringList &StartSetSpec::kindNames()
{
    static const QStringList names{"point",  "segment", "triangle",     "polygon",
                                   "points", "lifted",  "vertex-limits", "net"};
    return names;
}

MaybeProblem StartSetSpec::check() const
{
    if (kind == Kind::Lifted) {
        if (lifted.empty())
            return Problem{"points", tr("a lifted start set needs at least one point")};
        for (size_t k = 0; k < lifted.size(); ++k) {
            if (lifted[k].size() < 2 || lifted[k].size() != lifted.front().size())
                return Problem{"points", tr("lifted start point %1 has %2 coordinates: every "
                                            "point needs the same number, at least 2")
                                             .arg(k + 1)
                                             .arg(lifted[k].size())};
            for (double c : lifted[k])
                if (!std::isfinite(c))
                    return Problem{"points", tr("every point must have finite coordinates")};
        }
        return std::nullopt;
    }
    if (kind == Kind::VertexLimits)
        return std::nullopt;
    if (kind == Kind::Net) {
        if (net.empty())
            return Problem{"points", tr("a start set of net points needs at least one index")};
        if (net.size() > size_t(maxNetPoints))
            return Problem{"points", tr("a start set of net points takes at most %1 indices, "
                                        "got %2")
                                         .arg(maxNetPoints)
                                         .arg(net.size())};
        for (size_t k = 0; k < net.size(); ++k)
            if (net[k] < 0)
                return Problem{"points", tr("net point %1 of the start set has the index %2: "
                                            "indices count from 0")
                                             .arg(k + 1)
                                             .arg(net[k])};
        return std::nullopt;
    }
    if (!allFinite(points))
        return Problem{"points", tr("every point must have finite coordinates")};
    const int n = int(points.size());
    const QString kindName = kindNames().at(int(kind));
    int exact = -1, least = -1;
    switch (kind) {
    case Kind::Point: exact = 1; break;
    case Kind::Segment: exact = 2; break;
    case Kind::Triangle: exact = 3; break;
    case Kind::Polygon: least = 3; break;
    case Kind::Points: least = 1; break;
    case Kind::Lifted:
    case Kind::VertexLimits:
    case Kind::Net: break;
    }
    if (exact > 0 && n != exact)
        return Problem{"points", tr("a start set of kind \"%1\" needs exactly %2 points, got %3")
                                     .arg(kindName).arg(exact).arg(n)};
    if (least > 0 && n < least)
        return Problem{"points", tr("a start set of kind \"%1\" needs at least %2 points, got %3")
                                     .arg(kindName).arg(least).arg(n)};
    return std::nullopt;
}

// ---- algorithm --------------------------------------------------------------------------------

const QStringList &AlgorithmSpec::modeNames()
{
    static const QStringList names{"deterministic", "random"};
    return names;
}

int AlgorithmSpec::maxDepthFor(int maps)
{
    if (maps <= 1)
        return maxDepth;
    int k = 0;
    while (k < maxDepth && std::pow(double(maps), k + 1) <= maxImages)
        ++k;
    return k;
}

MaybeProblem AlgorithmSpec::check(int maps) const
{
    if (depth < 0)
        return Problem{"depth", tr("the depth cannot be negative, got %1").arg(depth)};
    if (depth > maxDepth)
        return Problem{"depth", tr("depth %1 is absurd: at most %2 is allowed")
                                    .arg(depth).arg(maxDepth)};
    // N^k in floating point: exact enough to compare with 2^31, and it cannot overflow.
    if (maps > 1 && std::pow(double(maps), depth) > maxImages)
        return Problem{"depth", tr("depth %1 with %2 maps makes %3 images of the start set, "
                                   "more than 2^31: at most depth %4 for %2 maps")
                                    .arg(depth).arg(maps)
                                    .arg(std::pow(double(maps), depth), 0, 'g', 3)
                                    .arg(maxDepthFor(maps))};
    if (samples < 1 || samples > maxSamples)
        return Problem{"samples", tr("the sample count must be between 1 and 2^31, got %1")
                                      .arg(samples)};
    if (seed < 0 || seed > maxSeed)
        return Problem{"seed", tr("the seed must be between 0 and 2^53 - 1, got %1").arg(seed)};
    double sum = 0.0;
    for (size_t i = 0; i < probabilities.size(); ++i) {
        const double p = probabilities[i];
        if (!std::isfinite(p) || p < 0.0)
            return Problem{"probabilities",
                           tr("probability %1 must be a finite number >= 0").arg(i + 1)};
        sum += p;
    }
    if (!probabilities.empty() && !(sum > 0.0))
        return Problem{"probabilities", tr("the probabilities sum to 0")};
    return std::nullopt;
}

// ---- style ------------------------------------------------------------------------------------

const QStringList &StyleSpec::colorByNames()
{
    static const QStringList names{"map", "address", "none"};
    return names;
}

const QStringList &StyleSpec::toneNames()
{
    static const QStringList names{"auto", "hits", "density"};
    return names;
}

MaybeProblem StyleSpec::check() const
{
    if (!std::isfinite(gamma) || gamma < 0.2 || gamma > 10.0)
        return Problem{"gamma", tr("the density gamma must be between 0.2 and 10, got %1")
                                    .arg(gamma)};
    if (prefixLength < 1 || prefixLength > maxPrefixLength)
        return Problem{"prefix_length", tr("the address prefix length must be between 1 and %1, "
                                           "got %2").arg(maxPrefixLength).arg(prefixLength)};
    if (!std::isfinite(pointSize) || pointSize <= 0.0 || pointSize > maxPointSize)
        return Problem{"point_size", tr("the point size must be more than 0 and at most %1 "
                                        "pixels").arg(maxPointSize)};
    static const QRegularExpression color("^#[0-9a-f]{6}$");
    for (qsizetype i = 0; i < colors.size(); ++i)
        if (!color.match(colors[i]).hasMatch())
            return Problem{"colors", tr("colour %1 is \"%2\", expected \"#rrggbb\" "
                                        "(lower-case hexadecimal)").arg(i + 1).arg(colors[i])};
    return std::nullopt;
}

} // namespace awb
