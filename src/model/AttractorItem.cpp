#include "model/AttractorItem.h"

#include "model/Commands.h"
#include "model/NumberFormat.h"
#include "model/PointSetProperty.h"
#include "model/Project.h"
#include "model/ProjectIO.h"
#include "model/StartSetDefaults.h"
#include "model/StartSetText.h"

#include <algorithm>
#include <cmath>
#include <optional>

namespace awb {

std::vector<int> largestNetTriangle(const PointList &control, int dimension)
{
    if (control.empty())
        return {};
    std::vector<int> rows = affineBasisRows(toMatrix(control, dimension));
    rows.resize(std::min<size_t>(rows.size(), 3));
    return rows;
}

AttractorItem::AttractorItem(const QString &defaultName) : Item(defaultName) {}

MaybeProblem AttractorItem::checkStartSet(const StartSetSpec &s) const
{
    if (s.kind == StartSetSpec::Kind::VertexLimits && !startsAtVertexLimits())
        return Problem{"kind", tr("the start set \"vertex-limits\" (the limit positions of a "
                                  "mesh's vertices) is for mesh items only; this item: %1")
                                   .arg(typeName())};
    if (MaybeProblem p = s.check())
        return p;
    if (s.kind == StartSetSpec::Kind::Net)
        if (MaybeProblem p = checkNetStart(s.net))
            return p;
    // Lifted points need the lifted space's number of coordinates.
    if (s.kind == StartSetSpec::Kind::Lifted && s != m_startSet)
        if (const auto d = derivedIfs()) {
            try {
                liftedStartPoints(*d, s.lifted);
            } catch (const InputError &e) {
                return Problem{"points", QString::fromStdString(e.what())};
            }
        }
    return std::nullopt;
}

MaybeProblem AttractorItem::checkNetStart(const std::vector<int> &net) const
{
    const int m = controlPointSetCount() ? int(controlPoints(0).size()) : 0;
    if (!startsAtNetPoints())
        return Problem{"kind", tr("the start set \"net\" (control points of the net by index) is "
                                  "for items whose IFS is built from one control net (curves, "
                                  "surfaces, fractals with control points); this item: %1")
                                   .arg(typeName())};
    for (size_t k = 0; k < net.size(); ++k)
        if (net[k] >= m)
            return Problem{"points", tr("net point %1 of the start set has the index %2; this "
                                        "item has %3 control points (indices 0 to %4)")
                                         .arg(k + 1)
                                         .arg(net[k])
                                         .arg(m)
                                         .arg(m - 1)};
    return std::nullopt;
}

bool AttractorItem::setStartSet(const StartSetSpec &startSet, int gesture)
{
    return setDeclared(*this, startSet, gesture);
}

bool AttractorItem::setAlgorithm(const AlgorithmSpec &algorithm, int gesture)
{
    return setDeclared(*this, algorithm, gesture);
}

PointList startPointsFor(StartSetSpec::Kind kind, const PointList &control)
{
    PointList c = control.empty() ? PointList{{0, 0}, {1, 0}, {0.5, 1}} : control;
    const Point first = c.front(), last = c.back(), middle = c[c.size() / 2];
    switch (kind) {
    case StartSetSpec::Kind::Point: {
        Point m;
        for (const auto &p : c)
            m = {m.x + p.x / double(c.size()), m.y + p.y / double(c.size()),
                 m.z + p.z / double(c.size())};
        return {m};
    }
    case StartSetSpec::Kind::Segment: return {first, last};
    case StartSetSpec::Kind::Triangle:
        if (c.size() < 3)
            return {{0, 0}, {1, 0}, {0.5, 1}};
        return {first, middle, last};
    case StartSetSpec::Kind::Polygon:
        if (c.size() < 3)
            return {{0, 0}, {1, 0}, {0.5, 1}};
        return c;
    case StartSetSpec::Kind::Points: return c;
    case StartSetSpec::Kind::Lifted: return c;
    case StartSetSpec::Kind::VertexLimits: return {};  // mesh items
    case StartSetSpec::Kind::Net: return {};           // indices, no points
    }
    return c;
}

bool AttractorItem::setControlPoints(int set, const PointList &points, QString *error)
{
    const auto refuse = [error](const QString &message) {
        if (error)
            *error = message;
        return false;
    };
    if (!validSet(set))
        return refuse(tr("%1 has no point set %2").arg(name()).arg(set));
    const int old = int(pointStorage(set).size());
    const int n = int(points.size());
    if (n != old && !pointCountEditable(set))
        return refuse(tr("%1: its scheme fixes the number of points at %2, got %3")
                          .arg(name()).arg(old).arg(n));
    if (n > maxPointCount(set))
        return refuse(tr("%1: %2 points is more than the %3 a point set may have")
                          .arg(name()).arg(n).arg(maxPointCount(set)));
    if (!allFinite(points))
        return refuse(tr("every point must have finite coordinates"));
    CompoundEdit edit(project(), tr("Set the points of %1").arg(name()));
    std::map<int, Point> moves;
    for (int i = 0; i < std::min(n, old); ++i)
        moves[i] = points[size_t(i)];
    if (!moves.empty() && !moveControlPoints(moves, 0, set))
        return refuse(tr("the points of %1 were refused").arg(name()));
    for (int i = old; i < n; ++i)
        if (!insertControlPoint(i, points[size_t(i)], set))
            return refuse(tr("the points of %1 were refused").arg(name()));
    if (n < old) {
        std::vector<int> gone;
        for (int i = n; i < old; ++i)
            gone.push_back(i);
        if (!removeControlPoints(gone, set))
            return refuse(tr("the points of %1 were refused").arg(name()));
    }
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
    executeCounted(new InsertControlPointCommand(this, set, index, point), set,
                   [index](int i) { return i >= index ? i + 1 : i; });
    return true;
}

void AttractorItem::executeCounted(QUndoCommand *command, int set,
                                   const std::function<int(int)> &remap)
{
    // A start set of net points or of lifted points depends on the net's count: kept valid in
    // the same undo step, so that a saved file always reads back.
    if (!startSetFollowsCount()) {
        execute(command);
        return;
    }
    const CompoundEdit edit(project(), command->text());
    execute(command);
    refitStartSet(set, remap);
}

bool AttractorItem::startSetFollowsCount() const
{
    return m_startSet.kind == StartSetSpec::Kind::Net
           || m_startSet.kind == StartSetSpec::Kind::Lifted;
}

void AttractorItem::refitStartSet(int set, const std::function<int(int)> &remap)
{
    StartSetSpec s = m_startSet;
    if (s.kind == StartSetSpec::Kind::Net && set == 0 && remap) {
        // Indices follow their points; a removed point leaves the set.
        std::vector<int> kept;
        for (int i : s.net)
            if (const int j = remap(i); j >= 0)
                kept.push_back(j);
        s.net = kept;
    }
    const PointList &control = controlPointSetCount() ? controlPoints(0) : PointList{};
    if (s.kind == StartSetSpec::Kind::Net) {
        // All its points removed: the centroid of the net as a point; indices past a new net:
        // that net's largest triangle.
        if (!s.net.empty() && checkNetStart(s.net))
            s.net = largestNetTriangle(control, pointDimension());
        if (s.net.empty()) {
            s.kind = StartSetSpec::Kind::Point;
            s.points = startPointsFor(s.kind, control);
        }
    } else if (s.kind == StartSetSpec::Kind::Lifted) {
        // x, y (and z) and as many extra coordinates as the lifting has: zeros added, or the
        // last ones dropped.
        if (const auto d = derivedIfs())
            for (auto &p : s.lifted)
                p.resize(std::size_t(std::max(d->ifs.dim(), 2)), 0.0);
    }
    if (s != m_startSet)
        setStartSet(s);
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
    const auto remap = [indices](int i) {
        const auto at = std::lower_bound(indices.begin(), indices.end(), i);
        return at != indices.end() && *at == i ? -1 : i - int(at - indices.begin());
    };
    if (indices.size() == 1) {
        executeCounted(new RemoveControlPointCommand(this, set, indices.front()), set, remap);
        return true;
    }
    // From the back, so that the indices still to remove do not shift.
    CompoundEdit edit(project(), tr("Remove %n control points of %1", nullptr,
                                    int(indices.size())).arg(name()));
    for (auto it = indices.rbegin(); it != indices.rend(); ++it)
        execute(new RemoveControlPointCommand(this, set, *it));
    if (startSetFollowsCount())
        refitStartSet(set, remap);
    return true;
}

void AttractorItem::storePoint(int set, int index, const Point &p)
{
    pointStorage(set)[size_t(index)] = p;
    pointsStored(set);
    inputsChanged();
    emit controlPointMoved(set, index);
    emit controlPointsChanged(set);
    emit changed();
}

void AttractorItem::storeInsertedPoint(int set, int index, const Point &p)
{
    PointList &points = pointStorage(set);
    points.insert(points.begin() + index, p);
    pointsStored(set);
    inputsChanged();
    emit controlPointInserted(set, index);
    emit controlPointsChanged(set);
    emit changed();
}

void AttractorItem::storeRemovedPoint(int set, int index)
{
    PointList &points = pointStorage(set);
    points.erase(points.begin() + index);
    pointsStored(set);
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
    if (m_startSet.kind == StartSetSpec::Kind::Net)
        return netStartSet(derived, m_startSet.net);
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
    case StartSetSpec::Kind::Net:           // handled above
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

Mat netPointRows(const SubdivisionIfs &s, const std::vector<int> &net)
{
    const int m = int(s.controlPoints.rows());
    const int D = s.ifs.dim();
    if (!s.barycentric() && !s.lifting.invertible)
        throw InputError(s.lifting.reason);
    Mat X(Eigen::Index(net.size()), D);
    for (size_t k = 0; k < net.size(); ++k) {
        if (net[k] < 0 || net[k] >= m)
            throw InputError(QCoreApplication::translate("awb::AttractorItem",
                                                         "net point %1 of the start set has the "
                                                         "index %2; the net has %3 points")
                                 .arg(k + 1)
                                 .arg(net[k])
                                 .arg(m)
                                 .toStdString());
        // Barycentric form: the unit vector; lifted: the row of the lifted P, its trailing 1
        // dropped.
        X.row(Eigen::Index(k)) = s.barycentric()
                                     ? RowVec(RowVec::Unit(m, net[k]))
                                     : RowVec(s.lifting.lifted.row(net[k]).head(D));
    }
    return X;
}

StartSet netStartSet(const DerivedIfs &derived, const std::vector<int> &net)
{
    if (!derived.subdivision)
        throw InputError(QCoreApplication::translate("awb::AttractorItem",
                                                     "this item has no control net to start "
                                                     "from")
                             .toStdString());
    const Mat X = netPointRows(*derived.subdivision, net);
    if (net.size() == 1)
        return StartSet::points(X);
    if (net.size() == 2)
        return StartSet::polyline(X);
    return StartSet::polygon(X);
}

// ---- files ------------------------------------------------------------------------------------

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
    fields.require(m_algorithm.check(branching()), "algorithm");
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

// ---- PointSetPart ------------------------------------------------------------------------------

bool PointSetPart::applies(const Item &item) const
{
    const auto &a = static_cast<const AttractorItem &>(item);
    return pointSet < a.controlPointSetCount() && (!present || present(a));
}

std::optional<bool> PointSetPart::setJson(Item &item, const QString &k, const QJsonValue &v,
                                          QString *error) const
{
    if (k != key || !applies(item))
        return std::nullopt;
    auto &a = static_cast<AttractorItem &>(item);
    try {
        return a.setControlPoints(pointSet, property::pointsFromJson(v, key, a.pointDimension()),
                                  error);
    } catch (const LoadError &e) {
        if (error)
            *error = QStringLiteral("%1: %2").arg(e.field, e.message);
        return false;
    }
}

void PointSetPart::write(const Item &item, QJsonObject &json) const
{
    if (!applies(item))
        return;
    const auto &a = static_cast<const AttractorItem &>(item);
    json[key] = ProjectIO::pointsToJson(a.controlPoints(pointSet), a.pointDimension());
}

void PointSetPart::read(Item &item, const FieldReader &fields) const
{
    auto &a = static_cast<AttractorItem &>(item);
    if (!applies(item))
        return;
    a.pointStorage(pointSet) =
        fields.points(key, fallback ? std::optional<PointList>(fallback(a)) : std::nullopt,
                      a.pointDimension());
}

bool PointSetPart::transfer(const Item &from, Item &to, QString *error) const
{
    if (!applies(from) || !applies(to))
        return true;
    return static_cast<AttractorItem &>(to).setControlPoints(
        pointSet, static_cast<const AttractorItem &>(from).controlPoints(pointSet), error);
}

void PointSetPart::describe(const Item &item, QList<PropertyDescription> &out) const
{
    if (!applies(item))
        return;
    const auto &a = static_cast<const AttractorItem &>(item);
    PropertyDescription d;
    d.info.key = key;
    d.info.label = texts.label ? texts.translate(texts.label) : key;
    d.typeName = QStringLiteral("points");
    d.json = key;
    d.value = ProjectIO::pointsToJson(a.controlPoints(pointSet), a.pointDimension());
    d.scalar = false;
    out << d;
}

} // namespace awb
