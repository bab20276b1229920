#include "model/AttractorItem.h"

#include "model/Commands.h"
#include "model/Project.h"
#include "model/ProjectIO.h"

#include <algorithm>
#include <cmath>

namespace awb {

AttractorItem::AttractorItem(const QString &defaultName) : Item(defaultName) {}

MaybeProblem AttractorItem::checkStartSet(const StartSetSpec &s) const
{
    if (s.kind == StartSetSpec::Kind::VertexLimits && !startsAtVertexLimits())
        return Problem{"kind", tr("the start set \"vertex-limits\" (the limit positions of a "
                                  "mesh's vertices) is for mesh items only; this item: %1")
                                   .arg(typeName())};
    return s.check();
}

bool AttractorItem::setStartSet(const StartSetSpec &startSet, int gesture)
{
    if (checkStartSet(startSet))
        return false;
    applyProperty(&AttractorItem::m_startSet, startSet, &AttractorItem::startSetChanged,
                  tr("Change start set of %1").arg(name()), gesture);
    return true;
}

bool AttractorItem::setAlgorithm(const AlgorithmSpec &algorithm, int gesture)
{
    if (checkAlgorithm(algorithm))
        return false;
    applyProperty(&AttractorItem::m_algorithm, algorithm, &AttractorItem::algorithmChanged,
                  tr("Change algorithm of %1").arg(name()), gesture);
    return true;
}

// ---- control points ---------------------------------------------------------------------------

const PointList &AttractorItem::controlPoints(int set) const
{
    static const PointList none;
    return validSet(set) ? pointStorage(set) : none;
}

bool AttractorItem::moveControlPoint(int index, const Point &to, int gesture, int set)
{
    return moveControlPoints({{index, to}}, gesture, set);
}

bool AttractorItem::moveControlPoints(const std::map<int, Point> &to, int gesture, int set)
{
    if (!validSet(set) || to.empty())
        return false;
    const PointList &points = pointStorage(set);
    std::map<int, Point> changes;
    for (const auto &[index, p] : to) {
        if (index < 0 || index >= int(points.size()) || !allFinite({p}))
            return false;
        if (!(points[size_t(index)] == p))
            changes.emplace(index, p);
    }
    if (!changes.empty())
        execute(new MoveControlPointsCommand(this, set, changes, gesture));
    return true;
}

bool AttractorItem::insertControlPoint(int index, const Point &point, int set)
{
    if (!validSet(set) || !pointCountEditable(set) || index < 0
        || index > int(pointStorage(set).size()) || !allFinite({point})
        || int(pointStorage(set).size()) >= maxControlPoints)
        return false;
    execute(new InsertControlPointCommand(this, set, index, point));
    return true;
}

bool AttractorItem::removeControlPoint(int index, int set)
{
    return removeControlPoints({index}, set);
}

bool AttractorItem::removeControlPoints(std::vector<int> indices, int set)
{
    if (!validSet(set) || !pointCountEditable(set) || indices.empty())
        return false;
    std::sort(indices.begin(), indices.end());
    indices.erase(std::unique(indices.begin(), indices.end()), indices.end());
    if (indices.front() < 0 || indices.back() >= int(pointStorage(set).size()))
        return false;
    if (indices.size() == 1) {
        execute(new RemoveControlPointCommand(this, set, indices.front()));
        return true;
    }
    // From the back, so that the indices still to remove do not shift.
    CompoundEdit edit(project(), tr("Remove %n control points of %1", nullptr,
                                    int(indices.size())).arg(name()));
    for (auto it = indices.rbegin(); it != indices.rend(); ++it)
        execute(new RemoveControlPointCommand(this, set, *it));
    return true;
}

void AttractorItem::storePoint(int set, int index, const Point &p)
{
    pointStorage(set)[size_t(index)] = p;
    inputsChanged();
    emit controlPointMoved(set, index);
    emit controlPointsChanged(set);
    emit changed();
}

void AttractorItem::storeInsertedPoint(int set, int index, const Point &p)
{
    PointList &points = pointStorage(set);
    points.insert(points.begin() + index, p);
    inputsChanged();
    emit controlPointInserted(set, index);
    emit controlPointsChanged(set);
    emit changed();
}

void AttractorItem::storeRemovedPoint(int set, int index)
{
    PointList &points = pointStorage(set);
    points.erase(points.begin() + index);
    inputsChanged();
    emit controlPointRemoved(set, index);
    emit controlPointsChanged(set);
    emit changed();
}

// ---- derived data -----------------------------------------------------------------------------

std::shared_ptr<const DerivedIfs> AttractorItem::derivedIfs() const
{
    return m_derived.get([this] {
        DerivedIfs d = computeIfs();
        // Finite inputs can still overflow (coordinates near 1e308 in P^-1 S_i P): say so
        // here rather than as a non-finite start set or an empty picture later.
        for (std::size_t i = 0; i < d.ifs.maps.size(); ++i)
            if (!d.ifs.maps[i].A.allFinite() || !d.ifs.maps[i].b.allFinite())
                throw InputError(
                    tr("map %1 is not finite: the control points' coordinates overflow in the "
                       "lifted map P⁻¹ S_i P (the largest is %2)")
                        .arg(i + 1)
                        .arg(largestCoordinate(), 0, 'g', 3)
                        .toStdString());
        return d;
    });
}

double AttractorItem::largestCoordinate() const
{
    double m = 0;
    for (int set = 0; set < controlPointSetCount(); ++set)
        for (const Point &p : controlPoints(set))
            m = std::max({m, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
    return m;
}

QString AttractorItem::derivedError() const
{
    derivedIfs();
    return m_derived.error();
}

bool AttractorItem::dropDerived()
{
    return m_derived.drop();
}

void AttractorItem::applyAlgorithm(Ifs &ifs) const
{
    if (m_algorithm.mode == AlgorithmSpec::Mode::Random)
        ifs.probabilities = m_algorithm.probabilities;
    ifs.validate();
}

StartSet AttractorItem::coreStartSet(const DerivedIfs &derived) const
{
    if (m_startSet.kind == StartSetSpec::Kind::Lifted)
        return StartSet::points(liftedStartPoints(derived, m_startSet.lifted));
    if (m_startSet.kind == StartSetSpec::Kind::VertexLimits) {
        if (const MaybeProblem p = checkStartSet(m_startSet); p || !derived.vertexLimitStart)
            throw InputError(p ? p->message.toStdString() : derived.note.toStdString());
        return StartSet::points(Mat(0, pointDimension()));
    }
    const Mat vertices = derived.toIfsSpace(toMatrix(m_startSet.points, pointDimension()));
    if (!vertices.allFinite())
        throw InputError(tr("the start set is not finite in the IFS space: the lifting "
                            "overflows (the largest control point coordinate is %1)")
                             .arg(largestCoordinate(), 0, 'g', 3)
                             .toStdString());
    switch (m_startSet.kind) {
    case StartSetSpec::Kind::Point:
    case StartSetSpec::Kind::Points:
    case StartSetSpec::Kind::Lifted:        // handled above
    case StartSetSpec::Kind::VertexLimits:  // handled above
        return StartSet::points(vertices);
    case StartSetSpec::Kind::Segment:
        return StartSet::polyline(vertices);
    case StartSetSpec::Kind::Triangle:
    case StartSetSpec::Kind::Polygon:
        break;
    }
    return StartSet::polygon(vertices);
}

Mat liftedStartPoints(const DerivedIfs &derived, const std::vector<std::vector<double>> &points)
{
    const int D = derived.ifs.dim();
    if (derived.ifs.space == "barycentric")
        throw InputError(QCoreApplication::translate("awb::AttractorItem",
                                                     "lifted start points need an invertible "
                                                     "lifting: %1")
                             .arg(derived.note)
                             .toStdString());
    Mat X(Eigen::Index(points.size()), D);
    for (size_t k = 0; k < points.size(); ++k) {
        if (int(points[k].size()) != D)
            throw InputError(QCoreApplication::translate("awb::AttractorItem",
                                                         "a lifted start point of this item has "
                                                         "%1 coordinates (x, y and the %2 extra "
                                                         "coordinates of the lifting, the "
                                                         "homogeneous 1 implied); point %3 has %4")
                                 .arg(D)
                                 .arg(std::max(0, D - 2))
                                 .arg(k + 1)
                                 .arg(points[k].size())
                                 .toStdString());
        for (int c = 0; c < D; ++c)
            X(Eigen::Index(k), c) = points[k][size_t(c)];
    }
    return X;
}

// ---- files ------------------------------------------------------------------------------------

void AttractorItem::write(QJsonObject &json) const
{
    Item::write(json);
    json["start_set"] = ProjectIO::startSetToJson(m_startSet, pointDimension());
    json["algorithm"] = ProjectIO::algorithmToJson(m_algorithm);
}

void AttractorItem::read(const FieldReader &fields)
{
    Item::read(fields);
    if (auto s = fields.object("start_set"))
        m_startSet = ProjectIO::readStartSet(*s, pointDimension());
    if (auto a = fields.object("algorithm"))
        m_algorithm = ProjectIO::readAlgorithm(*a);
}

void AttractorItem::checkLoaded(const FieldReader &fields) const
{
    Item::checkLoaded(fields);
    for (int set = 0; set < controlPointSetCount(); ++set) {
        const qsizetype n = qsizetype(controlPoints(set).size());
        if (n > maxPointCount(set))
            fields.fail(QStringLiteral("control_points"),
                        controlPointSetCount() == 1
                            ? tr("%1 points; an item takes at most %2 (its subdivision "
                                 "matrices would be %1 x %1)")
                                  .arg(n).arg(maxControlPoints)
                            : tr("point set %1 has %2 points; an item takes at most %3 per set")
                                  .arg(set + 1).arg(n).arg(maxControlPoints));
    }
    fields.require(m_algorithm.check(mapCount()), "algorithm");
    fields.require(checkStartSet(m_startSet), "start_set");
    // Lifted start points must have the lifted space's number of coordinates.
    if (m_startSet.kind == StartSetSpec::Kind::Lifted)
        if (const auto d = derivedIfs()) {
            try {
                liftedStartPoints(*d, m_startSet.lifted);
            } catch (const InputError &e) {
                fields.fail("start_set", QString::fromStdString(e.what()));
            }
        }
}

} // namespace awb
