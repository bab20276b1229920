#pragma once
// Document item "subdivision-surface" (layer 2, model): a patch of a lattice subdivision surface
// (000 §3: bicubic, Loop / three-direction box spline, Kobbelt √3) given by its control net —
// control points in R^3 with their lattice coordinates — and drawn as the attractor of the
// patch's IFS over any subset of its maps (000 Fig. 9). The derived IFS comes from the core's
// buildSurfaceIfs(); the classic refinement of the net (the top rows of 000 Figs. 6–8) from
// refineMesh().

#include "model/AttractorItem.h"

#include "core/schemes/SurfacePatch.h"

namespace awb {

struct SurfaceIfs;

// The scheme of the patch and its layout (which maps cover which domain).
struct SurfaceSchemeSpec {
    Q_DECLARE_TR_FUNCTIONS(awb::SurfaceSchemeSpec)
public:
    enum class Kind { Bicubic, Loop, Sqrt3 };
    Kind kind = Kind::Bicubic;
    QString layout = QStringLiteral("square");

    bool operator==(const SurfaceSchemeSpec &) const = default;
    // Field "layout" when the scheme's lattice has no such layout.
    MaybeProblem check() const;
    LatticeScheme makeScheme() const;
    PatchLayout makeLayout() const;  // throws InputError
    // JSON spellings of the kinds, in enum order, and the layouts a kind has.
    static const QStringList &kindNames();
    static QStringList layoutNames(Kind kind);
};

// Every input that must change together when the scheme changes: the net depends on it.
struct SurfaceNet {
    Q_DECLARE_TR_FUNCTIONS(awb::SurfaceNet)
public:
    SurfaceSchemeSpec scheme;
    PointList points;                     // control points (x, y, z)
    std::vector<LatticePoint> lattice;    // lattice coordinates, parallel to points
    std::vector<int> mapsUsed;            // 0-based, ascending; empty: all maps

    bool operator==(const SurfaceNet &) const = default;
    // Problems name their field: "scheme.layout", "control_points", "lattice", "maps_used".
    MaybeProblem check() const;
    // The layout's number of maps, and the number in use.
    int layoutMapCount() const;
    int usedMapCount() const;
    // The scheme's own net, flat on the lattice and lifted onto the paraboloid
    // z = (x^2 + y^2) / 4 (a net in one plane has no lifted IFS).
    static SurfaceNet defaultNet(const SurfaceSchemeSpec &scheme);
};

// Where the surface is looked at from (a view setting, saved with the item like its style):
// an orthographic camera on the direction (azimuth, elevation), in degrees (core OrthoCamera).
struct SurfaceCamera {
    double azimuth = -60.0;
    double elevation = 30.0;
    bool operator==(const SurfaceCamera &) const = default;
    // Finite, elevation within [-90, 90].
    bool valid() const;
};

class SubdivisionSurfaceItem : public AttractorItem {
    Q_OBJECT
public:
    SubdivisionSurfaceItem();

    static QString staticType() { return QStringLiteral("subdivision-surface"); }
    static QString staticTypeName() { return tr("Subdivision surface"); }
    QString type() const override { return staticType(); }
    QString typeName() const override { return staticTypeName(); }

    const SurfaceNet &net() const { return m_net; }
    const SurfaceSchemeSpec &scheme() const { return m_net.scheme; }
    const std::vector<LatticePoint> &lattice() const { return m_net.lattice; }
    // The maps in use, 0-based (all of them when none were switched off).
    std::vector<int> mapsUsed() const;
    MaybeProblem checkNet(const SurfaceNet &net) const;
    // Undoable, one step: scheme, points, lattice and maps together. Refused when checkNet()
    // complains.
    bool setNet(const SurfaceNet &net, int gesture = 0);
    // A new scheme brings its own default net (one undo step).
    bool setScheme(const SurfaceSchemeSpec &scheme);
    // Undoable; refused for an empty subset or an index out of range.
    bool setMapsUsed(std::vector<int> maps);

    // Rounds of classic subdivision for the mesh route (0..6).
    int meshRounds() const { return m_meshRounds; }
    bool setMeshRounds(int rounds, int gesture = 0);
    static constexpr int maxMeshRounds = 6;

    const SurfaceCamera &camera() const { return m_camera; }
    // Undoable; the steps of one drag (same nonzero gesture) merge.
    bool setCamera(const SurfaceCamera &camera, int gesture = 0);

    // Declared: "scheme.kind", "scheme.layout" (a new scheme or layout starts from its own
    // default net), the net's "control_points" and "lattice", "maps_used" (shown as
    // "maps.<i>" switches), "mesh_rounds", "camera.azimuth", "camera.elevation".
    static const PropertyTable &declaration();
    const PropertyTable &properties() const override { return declaration(); }
    MaybeProblem checkMeshRounds(const int &rounds) const;
    MaybeProblem checkCamera(const SurfaceCamera &camera) const;

    int mapCount() const override { return m_net.usedMapCount(); }
    int pointDimension() const override { return 3; }
    bool startsAtNetPoints() const override { return true; }
    int controlPointSetCount() const override { return 1; }
    bool pointCountEditable(int) const override { return false; }

    // The core's surface IFS (null when it cannot be computed; see derivedError()).
    std::shared_ptr<const SurfaceIfs> surfaceIfs() const;
    // The control net after `rounds` rounds of classic subdivision (0: the net itself), as a
    // mesh with the lattice's faces. Throws InputError.
    LatticeMesh refinedMesh(int rounds) const;


signals:
    void netChanged();
    void meshRoundsChanged();
    void cameraChanged();

protected:
    DerivedIfs computeIfs() const override;
    PointList &pointStorage(int) override { return m_net.points; }

private:
    SurfaceNet m_net;
    int m_meshRounds = 3;
    SurfaceCamera m_camera;
};

} // namespace awb
