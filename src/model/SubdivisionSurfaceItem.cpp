#include "model/SubdivisionSurfaceItem.h"

#include "core/ifs/SurfaceIfs.h"
#include "model/Commands.h"
#include "model/ProjectIO.h"

#include <QJsonArray>
#include <QMutex>
#include <QMutexLocker>

#include <cmath>
#include <map>

#include <algorithm>

namespace awb {

// ---- SurfaceSchemeSpec ------------------------------------------------------------------------

const QStringList &SurfaceSchemeSpec::kindNames()
{
    static const QStringList names{"bicubic", "loop", "sqrt3"};
    return names;
}

QStringList SurfaceSchemeSpec::layoutNames(Kind kind)
{
    QStringList out;
    for (const std::string &n :
         awb::layoutNames(kind == Kind::Bicubic ? Lattice::Square : Lattice::Triangular))
        out << QString::fromStdString(n);
    return out;
}

LatticeScheme SurfaceSchemeSpec::makeScheme() const
{
    switch (kind) {
    case Kind::Bicubic: return bicubicScheme();
    case Kind::Loop: return loopScheme();
    case Kind::Sqrt3: break;
    }
    return sqrt3Scheme();
}

PatchLayout SurfaceSchemeSpec::makeLayout() const
{
    return patchLayout(makeScheme(), layout.toStdString());
}

MaybeProblem SurfaceSchemeSpec::check() const
{
    const QStringList layouts = layoutNames(kind);
    if (!layouts.contains(layout))
        return Problem{"layout", tr("the %1 scheme has the layouts %2, not '%3'")
                                     .arg(kindNames().at(int(kind)), layouts.join(", "), layout)};
    return std::nullopt;
}

// ---- SurfaceNet -------------------------------------------------------------------------------

namespace {

// The scheme, its layout and canonical net and matrices, computed once per (kind, layout):
// every check and every rebuild of the IFS (each step of a drag) reads them.
struct PatchData {
    LatticeScheme scheme;
    PatchLayout layout;
    SurfaceMatrices matrices;
};

const PatchData &patchData(const SurfaceSchemeSpec &spec)
{
    static std::map<std::pair<int, QString>, PatchData> cache;
    static QMutex mutex;
    QMutexLocker lock(&mutex);
    const auto key = std::make_pair(int(spec.kind), spec.layout);
    auto it = cache.find(key);
    if (it == cache.end()) {
        LatticeScheme scheme = spec.makeScheme();
        PatchLayout layout = patchLayout(scheme, spec.layout.toStdString());
        SurfaceMatrices matrices = surfaceMatrices(scheme, layout);
        it = cache.emplace(key, PatchData{std::move(scheme), std::move(layout),
                                          std::move(matrices)})
                 .first;
    }
    return it->second;
}

const SurfaceMatrices &canonicalMatrices(const SurfaceSchemeSpec &spec)
{
    return patchData(spec).matrices;
}

} // namespace

int SurfaceNet::layoutMapCount() const
{
    if (scheme.check())
        return -1;
    return int(canonicalMatrices(scheme).S.size());
}

int SurfaceNet::usedMapCount() const
{
    return mapsUsed.empty() ? layoutMapCount() : int(mapsUsed.size());
}

MaybeProblem SurfaceNet::check() const
{
    if (auto p = scheme.check())
        return Problem{"scheme." + p->field, p->message};
    if (!allFinite(points))
        return Problem{"control_points", tr("every control point must have finite coordinates")};
    const SurfaceMatrices &canonical = canonicalMatrices(scheme);
    if (points.size() != lattice.size())
        return Problem{"lattice", tr("%1 lattice coordinates for %2 control points: give one "
                                     "[i, j] per control point")
                                      .arg(lattice.size())
                                      .arg(points.size())};
    try {
        matchNet(canonical.net, lattice, patchData(scheme).scheme.lattice());
    } catch (const InputError &e) {
        return Problem{"lattice", tr("not the net of a %1 %2 patch: %3")
                                      .arg(scheme.kindNames().at(int(scheme.kind)), scheme.layout,
                                           QString::fromStdString(e.what()))};
    }
    const int n = int(canonical.S.size());
    if (!mapsUsed.empty()) {
        for (size_t k = 0; k < mapsUsed.size(); ++k) {
            if (mapsUsed[k] < 0 || mapsUsed[k] >= n)
                return Problem{"maps_used", tr("map %1 does not exist: the %2 layout has maps "
                                               "0 to %3")
                                                .arg(mapsUsed[k])
                                                .arg(scheme.layout)
                                                .arg(n - 1)};
            if (k > 0 && mapsUsed[k] <= mapsUsed[k - 1])
                return Problem{"maps_used",
                               tr("list each map once, in increasing order (0-based)")};
        }
    }
    return std::nullopt;
}

SurfaceNet SurfaceNet::defaultNet(const SurfaceSchemeSpec &scheme)
{
    SurfaceNet net;
    net.scheme = scheme;
    const PatchData &patch = patchData(scheme);
    const LatticeScheme &s = patch.scheme;
    const SurfaceMatrices &canonical = patch.matrices;
    // Centre the net on the patch's domain.
    const PatchLayout &layout = patch.layout;
    Eigen::Vector2d centre = Eigen::Vector2d::Zero();
    for (const auto &c : layout.domain)
        centre += latticePosition(s.lattice(), c);
    centre /= double(layout.domain.size());
    for (const LatticePoint &p : canonical.net) {
        const Eigen::Vector2d x =
            latticePosition(s.lattice(), {double(p.i), double(p.j)}) - centre;
        net.points.push_back({x.x(), x.y(), 0.25 * x.squaredNorm()});
        net.lattice.push_back(p);
    }
    return net;
}

// ---- SubdivisionSurfaceItem -------------------------------------------------------------------

SubdivisionSurfaceItem::SubdivisionSurfaceItem()
    : AttractorItem(tr("Surface")), m_net(SurfaceNet::defaultNet({}))
{
    // A triangle through three control points: 000 §3 starts every surface from a triangle.
    StartSetSpec start;
    start.kind = StartSetSpec::Kind::Triangle;
    start.points = {m_net.points[0], m_net.points[3], m_net.points[15]};
    setInitialStartSet(start);
    AlgorithmSpec algorithm;
    algorithm.depth = 6;
    setAlgorithm(algorithm);
}

std::vector<int> SubdivisionSurfaceItem::mapsUsed() const
{
    if (!m_net.mapsUsed.empty())
        return m_net.mapsUsed;
    std::vector<int> all(size_t(std::max(0, m_net.layoutMapCount())));
    for (size_t i = 0; i < all.size(); ++i)
        all[i] = int(i);
    return all;
}

MaybeProblem SubdivisionSurfaceItem::checkNet(const SurfaceNet &net) const
{
    if (auto p = net.check())
        return p;
    if (auto p = algorithm().check(net.usedMapCount()))
        return Problem{"algorithm." + p->field, p->message};
    return std::nullopt;
}

bool SubdivisionSurfaceItem::setNet(const SurfaceNet &net, int gesture)
{
    if (checkNet(net))
        return false;
    applyProperty(&SubdivisionSurfaceItem::m_net, net, &SubdivisionSurfaceItem::netChanged,
                  tr("Change net of %1").arg(name()), gesture);
    return true;
}

bool SubdivisionSurfaceItem::setScheme(const SurfaceSchemeSpec &scheme)
{
    if (scheme == m_net.scheme)
        return true;
    if (scheme.check())
        return false;
    return setNet(SurfaceNet::defaultNet(scheme));
}

bool SubdivisionSurfaceItem::setMapsUsed(std::vector<int> maps)
{
    std::sort(maps.begin(), maps.end());
    if (maps.empty())
        return false;
    SurfaceNet next = m_net;
    // All maps in use is written as "no subset".
    next.mapsUsed = int(maps.size()) == m_net.layoutMapCount() ? std::vector<int>{} : maps;
    return setNet(next);
}

bool SubdivisionSurfaceItem::setMeshRounds(int rounds, int gesture)
{
    if (rounds < 0 || rounds > maxMeshRounds)
        return false;
    applyProperty(&SubdivisionSurfaceItem::m_meshRounds, rounds,
                  &SubdivisionSurfaceItem::meshRoundsChanged,
                  tr("Change subdivision rounds of %1").arg(name()), gesture);
    return true;
}

bool SurfaceCamera::valid() const
{
    return std::isfinite(azimuth) && std::isfinite(elevation) && std::abs(elevation) <= 90.0;
}

bool SubdivisionSurfaceItem::setCamera(const SurfaceCamera &camera, int gesture)
{
    if (!camera.valid())
        return false;
    applyProperty(&SubdivisionSurfaceItem::m_camera, camera,
                  &SubdivisionSurfaceItem::cameraChanged, tr("Turn the view of %1").arg(name()),
                  gesture);
    return true;
}

std::shared_ptr<const SurfaceIfs> SubdivisionSurfaceItem::surfaceIfs() const
{
    const auto d = derivedIfs();
    return d ? d->surface : nullptr;
}

LatticeMesh SubdivisionSurfaceItem::refinedMesh(int rounds) const
{
    const LatticeScheme &scheme = patchData(m_net.scheme).scheme;
    return refineMesh(scheme, netMesh(scheme.lattice(), m_net.lattice, toMatrix(m_net.points, 3)),
                      rounds);
}

DerivedIfs SubdivisionSurfaceItem::computeIfs() const
{
    if (auto p = m_net.check())
        throw InputError((p->field + ": " + p->message).toStdString());
    const PatchData &patch = patchData(m_net.scheme);
    const auto s = std::make_shared<const SurfaceIfs>(
        buildSurfaceIfs(patch.scheme, patch.layout, patch.matrices, m_net.lattice,
                        toMatrix(m_net.points, 3), m_net.mapsUsed));
    DerivedIfs out;
    out.S.real = s->S;
    if (s->ifs.lifting.invertible) {
        for (const Mat &S : s->S)
            out.A.real.push_back(liftMatrix(s->ifs.lifting, S).A);
    } else {
        out.A.unavailable = QString::fromStdString(s->ifs.lifting.reason);
    }
    out.note = QString::fromStdString(s->ifs.lifting.note());
    out.ifs = s->ifs.ifs;
    if (int(s->mapsUsed.size()) != int(s->S.size()))
        out.mapIndex = s->mapsUsed;
    const auto sub = std::shared_ptr<const SubdivisionIfs>(s, &s->ifs);
    out.toIfsSpace = [sub](const Mat &X) { return sub->toIfsSpace(X); };
    out.subdivision = sub;
    out.surface = s;
    applyAlgorithm(out.ifs);
    return out;
}

// ---- files ------------------------------------------------------------------------------------

void SubdivisionSurfaceItem::write(QJsonObject &json) const
{
    AttractorItem::write(json);
    json["scheme"] = QJsonObject{{"kind", SurfaceSchemeSpec::kindNames().at(int(m_net.scheme.kind))},
                                 {"layout", m_net.scheme.layout}};
    json["control_points"] = ProjectIO::pointsToJson(m_net.points, 3);
    QJsonArray lattice;
    for (const LatticePoint &p : m_net.lattice)
        lattice.append(QJsonArray{p.i, p.j});
    json["lattice"] = lattice;
    if (!m_net.mapsUsed.empty()) {
        QJsonArray maps;
        for (int i : m_net.mapsUsed)
            maps.append(i);
        json["maps_used"] = maps;
    }
    json["mesh_rounds"] = m_meshRounds;
    json["camera"] = QJsonObject{{"azimuth", m_camera.azimuth}, {"elevation", m_camera.elevation}};
}

void SubdivisionSurfaceItem::read(const FieldReader &fields)
{
    AttractorItem::read(fields);
    const FieldReader s = *fields.object("scheme", true);
    SurfaceNet net;
    net.scheme.kind = SurfaceSchemeSpec::Kind(s.choice("kind", SurfaceSchemeSpec::kindNames()));
    const QStringList layouts = SurfaceSchemeSpec::layoutNames(net.scheme.kind);
    net.scheme.layout = layouts.at(s.choice("layout", layouts, 0));
    net.points = fields.points("control_points", std::nullopt, 3);
    const QJsonValue lattice = fields.value("lattice");
    if (!lattice.isArray())
        fields.fail("lattice", tr("expected an array of lattice coordinates [i, j]"));
    const QJsonArray rows = lattice.toArray();
    for (qsizetype k = 0; k < rows.size(); ++k) {
        const QJsonArray ij = rows[k].toArray();
        const QString where = fields.path("lattice") + QStringLiteral("[%1]").arg(k + 1);
        if (!rows[k].isArray() || ij.size() != 2)
            throw LoadError{where, tr("expected lattice coordinates [i, j]")};
        int v[2];
        for (int c = 0; c < 2; ++c) {
            const double x = FieldReader::toNumber(ij[c], where + QStringLiteral("[%1]").arg(c + 1));
            if (x != std::floor(x) || std::abs(x) > 1e6)
                throw LoadError{where, tr("lattice coordinates are whole numbers")};
            v[c] = int(x);
        }
        net.lattice.push_back({v[0], v[1]});
    }
    if (fields.has("maps_used")) {
        const std::vector<double> maps = fields.numbers("maps_used");
        if (maps.empty())
            fields.fail("maps_used", tr("at least one map must be used (leave the field out "
                                        "to use all)"));
        for (double m : maps) {
            if (m != std::floor(m) || std::abs(m) > 1e6)
                fields.fail("maps_used", tr("map indices are whole numbers (0-based)"));
            net.mapsUsed.push_back(int(m));
        }
    }
    fields.require(net.check());
    if (!net.mapsUsed.empty() && int(net.mapsUsed.size()) == net.layoutMapCount())
        net.mapsUsed.clear();
    m_net = net;
    m_meshRounds = int(fields.integer("mesh_rounds", m_meshRounds, 0, maxMeshRounds));
    if (const auto c = fields.object("camera")) {
        SurfaceCamera camera;
        camera.azimuth = c->number("azimuth", camera.azimuth);
        camera.elevation = c->number("elevation", camera.elevation);
        if (!camera.valid())
            c->fail("elevation", tr("the elevation must be from -90 to 90 degrees"));
        m_camera = camera;
    }
}

// ---- generic parameters -----------------------------------------------------------------------

QList<ParameterInfo> SubdivisionSurfaceItem::parameters() const
{
    using P = ParameterInfo;
    const QString group = tr("Scheme");
    QList<ParameterInfo> list;
    list << P::make("scheme.kind", tr("Scheme"), P::Type::Choice)
                .options({tr("Bicubic B-spline (Catmull–Clark)"),
                          tr("Loop (three-direction box spline)"), tr("Kobbelt √3")})
                .in(group)
                .tip(tr("A new scheme starts from its own default net (000 §3)"));
    list << P::make("scheme.layout", tr("Layout"), P::Type::Choice)
                .options(SurfaceSchemeSpec::layoutNames(m_net.scheme.kind))
                .in(group)
                .tip(tr("The patch's domain and the maps covering it"));
    const QString maps = tr("Maps");
    const std::vector<int> used = mapsUsed();
    for (int i = 0; i < m_net.layoutMapCount(); ++i)
        list << P::make(QStringLiteral("maps.%1").arg(i), tr("Map %1").arg(i + 1), P::Type::Bool)
                    .in(maps)
                    .tip(tr("Leave maps out to draw a fractal lying on the surface (000 Fig. 9)"));
    const QString view = tr("View");
    list << P::make("camera.azimuth", tr("Azimuth"), P::Type::Real)
                .slider(-180, 180)
                .in(view)
                .tip(tr("Direction of the orthographic camera around the z axis, in degrees"));
    list << P::make("camera.elevation", tr("Elevation"), P::Type::Real)
                .range(-90, 90)
                .slider(-90, 90)
                .in(view)
                .tip(tr("Height of the camera above the xy plane, in degrees"));
    list << P::make("mesh_rounds", tr("Subdivision rounds"), P::Type::Integer)
                .range(0, maxMeshRounds)
                .in(group)
                .tip(tr("Rounds of classic subdivision of the net (000 Figs. 6–8, top)"));
    return list;
}

QVariant SubdivisionSurfaceItem::parameter(const QString &key) const
{
    if (key == "scheme.kind")
        return int(m_net.scheme.kind);
    if (key == "scheme.layout")
        return int(SurfaceSchemeSpec::layoutNames(m_net.scheme.kind).indexOf(m_net.scheme.layout));
    if (key == "mesh_rounds")
        return m_meshRounds;
    if (key == "camera.azimuth")
        return m_camera.azimuth;
    if (key == "camera.elevation")
        return m_camera.elevation;
    if (key.startsWith("maps.")) {
        bool ok = false;
        const int i = key.mid(5).toInt(&ok);
        if (!ok || i < 0 || i >= m_net.layoutMapCount())
            return {};
        const std::vector<int> used = mapsUsed();
        return std::find(used.begin(), used.end(), i) != used.end();
    }
    return {};
}

bool SubdivisionSurfaceItem::setParameter(const QString &key, const QVariant &value, int gesture,
                                          QString *error)
{
    bool ok = true;
    if (key == "scheme.kind" || key == "scheme.layout") {
        SurfaceSchemeSpec next = m_net.scheme;
        const int k = value.toInt(&ok);
        if (key == "scheme.kind") {
            ok = ok && k >= 0 && k < SurfaceSchemeSpec::kindNames().size();
            if (ok) {
                next.kind = SurfaceSchemeSpec::Kind(k);
                const QStringList layouts = SurfaceSchemeSpec::layoutNames(next.kind);
                if (!layouts.contains(next.layout))
                    next.layout = layouts.front();
            }
        } else {
            const QStringList layouts = SurfaceSchemeSpec::layoutNames(next.kind);
            ok = ok && k >= 0 && k < layouts.size();
            if (ok)
                next.layout = layouts.at(k);
        }
        const SurfaceNet net = ok ? SurfaceNet::defaultNet(next) : m_net;
        return commitParameter(key, value, ok, checkNet(net),
                               [&] { return next == m_net.scheme || setNet(net, gesture); }, error);
    }
    if (key == "camera.azimuth" || key == "camera.elevation") {
        SurfaceCamera next = m_camera;
        (key == "camera.azimuth" ? next.azimuth : next.elevation) = value.toDouble(&ok);
        MaybeProblem problem;
        if (ok && !next.valid())
            problem = Problem{key, tr("the elevation must be from -90 to 90 degrees")};
        return commitParameter(key, value, ok, problem,
                               [&] { return setCamera(next, gesture); }, error);
    }
    if (key == "mesh_rounds") {
        const int r = value.toInt(&ok);
        MaybeProblem problem;
        if (ok && (r < 0 || r > maxMeshRounds))
            problem = Problem{"mesh_rounds", tr("from 0 to %1 rounds").arg(maxMeshRounds)};
        return commitParameter(key, value, ok, problem, [&] { return setMeshRounds(r, gesture); }, error);
    }
    if (key.startsWith("maps.")) {
        const int i = key.mid(5).toInt(&ok);
        ok = ok && i >= 0 && i < m_net.layoutMapCount();
        std::vector<int> used = mapsUsed();
        if (ok) {
            const bool on = value.toBool();
            used.erase(std::remove(used.begin(), used.end(), i), used.end());
            if (on)
                used.push_back(i);
            std::sort(used.begin(), used.end());
        }
        MaybeProblem problem;
        if (ok && used.empty())
            problem = Problem{"maps_used", tr("at least one map must stay on")};
        SurfaceNet next = m_net;
        next.mapsUsed = int(used.size()) == m_net.layoutMapCount() ? std::vector<int>{} : used;
        if (ok && !problem)
            problem = checkNet(next);
        return commitParameter(key, value, ok, problem,
                               [&] { return setNet(next, gesture); }, error);
    }
    return Item::setParameter(key, value, gesture, error);
}

} // namespace awb
