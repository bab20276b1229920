#include "model/SubdivisionSurfaceItem.h"

#include "core/ifs/SurfaceIfs.h"
#include "model/Commands.h"
#include "model/ProjectIO.h"
#include "model/PropertyDeclaration.h"

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
    return checkWithMaps(net.check(), net.usedMapCount());
}

bool SubdivisionSurfaceItem::setNet(const SurfaceNet &net, int gesture)
{
    return setDeclared(*this, net, gesture);
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

MaybeProblem SubdivisionSurfaceItem::checkMeshRounds(const int &rounds) const
{
    if (rounds < 0 || rounds > maxMeshRounds)
        return Problem{"mesh_rounds", tr("from 0 to %1 rounds").arg(maxMeshRounds)};
    return std::nullopt;
}

bool SubdivisionSurfaceItem::setMeshRounds(int rounds, int gesture)
{
    return setDeclared(*this, rounds, gesture);
}

bool SurfaceCamera::valid() const
{
    return std::isfinite(azimuth) && std::isfinite(elevation) && std::abs(elevation) <= 90.0;
}

MaybeProblem SubdivisionSurfaceItem::checkCamera(const SurfaceCamera &camera) const
{
    if (!camera.valid())
        return Problem{"elevation", tr("the elevation must be from -90 to 90 degrees")};
    return std::nullopt;
}

bool SubdivisionSurfaceItem::setCamera(const SurfaceCamera &camera, int gesture)
{
    return setDeclared(*this, camera, gesture);
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

// ---- declared properties ----------------------------------------------------------------------

const PropertyTable &SubdivisionSurfaceItem::declaration()
{
    static const PropertyTable table = [] {
        using I = SubdivisionSurfaceItem;
        using K = SurfaceSchemeSpec::Kind;
        Declaration<I> d(&AttractorItem::attractorProperties());
        auto net = d.part(&I::m_net, &I::checkNet, &I::netChanged,
                          QT_TR_NOOP("Change net of %1"));
        net.checkedOnRead([](const I &, const SurfaceNet &n) { return n.check(); });
        // All maps in use is written as "no subset".
        net.normalizedOnRead([](const I &, SurfaceNet &n) {
            if (!n.mapsUsed.empty() && int(n.mapsUsed.size()) == n.layoutMapCount())
                n.mapsUsed.clear();
        });
        // A new scheme or layout starts from its own default net (000 §3).
        const auto defaultNet = [](const I &item, SurfaceNet &next) -> MaybeProblem {
            const QStringList layouts = SurfaceSchemeSpec::layoutNames(next.scheme.kind);
            if (!layouts.contains(next.scheme.layout))
                next.scheme.layout = layouts.front();
            if (next.scheme != item.m_net.scheme)
                next = SurfaceNet::defaultNet(next.scheme);
            return std::nullopt;
        };
        net.choice("scheme.kind", [](SurfaceNet &n) -> K & { return n.scheme.kind; },
                   SurfaceSchemeSpec::kindNames(),
                   {QT_TR_NOOP("Bicubic B-spline (Catmull–Clark)"),
                    QT_TR_NOOP("Loop (three-direction box spline)"), QT_TR_NOOP("Kobbelt √3")})
            .label(QT_TR_NOOP("Scheme"))
            .group(QT_TR_NOOP("Scheme"))
            .tip(QT_TR_NOOP("A new scheme starts from its own default net (000 §3)"))
            .required()
            .onEdit(defaultNet);
        auto layout =
            net.choiceBy(
                   "scheme.layout", {}, {},
                   [](const SurfaceNet &n) {
                       return int(SurfaceSchemeSpec::layoutNames(n.scheme.kind)
                                      .indexOf(n.scheme.layout));
                   },
                   [](SurfaceNet &n, int i) {
                       n.scheme.layout = SurfaceSchemeSpec::layoutNames(n.scheme.kind).at(i);
                   })
                .label(QT_TR_NOOP("Layout"))
                .group(QT_TR_NOOP("Scheme"))
                .tip(QT_TR_NOOP("The patch's domain and the maps covering it"))
                .whenMissing([](const I &, SurfaceNet &n) {
                    n.scheme.layout = SurfaceSchemeSpec::layoutNames(n.scheme.kind).front();
                })
                .onEdit(defaultNet)
                .choicesFrom([](const I &, const SurfaceNet &n) {
                    return SurfaceSchemeSpec::layoutNames(n.scheme.kind);
                });
        layout.spellingsFrom([](const I &, const SurfaceNet &n) {
            return SurfaceSchemeSpec::layoutNames(n.scheme.kind);
        });
        net.points("control_points", &SurfaceNet::points, [](const I &) { return 3; })
            .label(QT_TR_NOOP("Control points"))
            .required();
        net.structured(
               "lattice", QStringLiteral("lattice points"),
               [](const I &, const SurfaceNet &n) {
                   QJsonArray lattice;
                   for (const LatticePoint &p : n.lattice)
                       lattice.append(QJsonArray{p.i, p.j});
                   return QJsonValue(lattice);
               },
               [](const I &, SurfaceNet &n, const QJsonValue &v, const QString &where) {
                   if (!v.isArray())
                       throw LoadError{where, tr("expected an array of lattice coordinates "
                                                 "[i, j]")};
                   n.lattice.clear();
                   const QJsonArray rows = v.toArray();
                   for (qsizetype k = 0; k < rows.size(); ++k) {
                       const QJsonArray ij = rows[k].toArray();
                       const QString at = where + QStringLiteral("[%1]").arg(k + 1);
                       if (!rows[k].isArray() || ij.size() != 2)
                           throw LoadError{at, tr("expected lattice coordinates [i, j]")};
                       int c[2];
                       for (int q = 0; q < 2; ++q) {
                           const double x = FieldReader::toNumber(
                               ij[q], at + QStringLiteral("[%1]").arg(q + 1));
                           if (x != std::floor(x) || std::abs(x) > 1e6)
                               throw LoadError{at, tr("lattice coordinates are whole numbers")};
                           c[q] = int(x);
                       }
                       n.lattice.push_back({c[0], c[1]});
                   }
               })
            .label(QT_TR_NOOP("Lattice coordinates"))
            .tip(QT_TR_NOOP("Each control point's place [i, j] on the scheme's lattice"))
            .required(QT_TR_NOOP("expected an array of lattice coordinates [i, j]"));
        net.structured(
               "maps_used", QStringLiteral("map numbers"),
               [](const I &, const SurfaceNet &n) {
                   QJsonArray maps;
                   for (int i : n.mapsUsed)
                       maps.append(i);
                   return QJsonValue(maps);
               },
               [](const I &, SurfaceNet &n, const QJsonValue &v, const QString &where) {
                   const std::vector<double> maps = property::numbersFromJson(v, where);
                   if (maps.empty())
                       throw LoadError{where, tr("at least one map must be used (leave the "
                                                 "field out to use all)")};
                   n.mapsUsed.clear();
                   for (double m : maps) {
                       if (m != std::floor(m) || std::abs(m) > 1e6)
                           throw LoadError{where, tr("map indices are whole numbers (0-based)")};
                       n.mapsUsed.push_back(int(m));
                   }
               })
            .label(QT_TR_NOOP("Maps used"))
            .omitWhenDefault()
            .elements(
                QStringLiteral("maps.%1"), QT_TR_NOOP("Map %1"), ParameterInfo::Type::Bool,
                [](const SurfaceNet &n) { return std::max(0, n.layoutMapCount()); },
                [](const SurfaceNet &n, int i) {
                    return QVariant(n.mapsUsed.empty()
                                    || std::find(n.mapsUsed.begin(), n.mapsUsed.end(), i)
                                           != n.mapsUsed.end());
                },
                [](SurfaceNet &n, int i, const QVariant &v) -> MaybeProblem {
                    const auto on = property::toBool(v);
                    if (!on)
                        return Problem{"maps_used",
                                       property::notValid(v, QStringLiteral("maps.%1").arg(i))};
                    std::vector<int> used;
                    for (int k = 0; k < n.layoutMapCount(); ++k)
                        if (k == i ? *on
                                   : n.mapsUsed.empty()
                                         || std::find(n.mapsUsed.begin(), n.mapsUsed.end(), k)
                                                != n.mapsUsed.end())
                            used.push_back(k);
                    if (used.empty())
                        return Problem{"maps_used", tr("at least one map must stay on")};
                    n.mapsUsed = int(used.size()) == n.layoutMapCount() ? std::vector<int>{}
                                                                         : used;
                    return std::nullopt;
                },
                QT_TR_NOOP("Maps"))
            .tip(QT_TR_NOOP("Leave maps out to draw a fractal lying on the surface (000 Fig. 9)"));
        auto rounds = d.part(&I::m_meshRounds, &I::checkMeshRounds, &I::meshRoundsChanged,
                             QT_TR_NOOP("Change subdivision rounds of %1"));
        rounds.startsFrom([](const I &) { return 3; });  // a file without it: 3 rounds
        rounds.integer("mesh_rounds", [](int &r) -> int & { return r; })
            .label(QT_TR_NOOP("Subdivision rounds"))
            .group(QT_TR_NOOP("Scheme"))
            .range(0, maxMeshRounds)
            .tip(QT_TR_NOOP("Rounds of classic subdivision of the net (000 Figs. 6–8, top)"));
        auto camera = d.part(&I::m_camera, &I::checkCamera, &I::cameraChanged,
                             QT_TR_NOOP("Turn the view of %1"));
        camera.checkedOnRead([](const I &item, const SurfaceCamera &c) {
            return item.checkCamera(c);
        }, QStringLiteral("camera"));
        camera.real("camera.azimuth", &SurfaceCamera::azimuth)
            .label(QT_TR_NOOP("Azimuth"))
            .group(QT_TR_NOOP("View"))
            .slider(-180, 180)
            .tip(QT_TR_NOOP("Direction of the orthographic camera around the z axis, in "
                            "degrees"));
        camera.real("camera.elevation", &SurfaceCamera::elevation)
            .label(QT_TR_NOOP("Elevation"))
            .group(QT_TR_NOOP("View"))
            .range(-90, 90)
            .slider(-90, 90)
            .tip(QT_TR_NOOP("Height of the camera above the xy plane, in degrees"));
        return d.table();
    }();
    return table;
}

} // namespace awb
