#pragma once
// The base of every item that is drawn as the attractor of an IFS (layer 2, model): subdivision
// curves now; fractals, Bézier unions, normal-vector curves, ... later. It adds the common
// inputs (start set, algorithm), editable control point sets with their undo commands, and the
// derived IFS, built lazily from the inputs by the subclass and cached until the next edit.

#include "core/ifs/Attractor.h"
#include "core/ifs/Ifs.h"
#include "core/render/CustomChaos.h"
#include "model/Item.h"

#include <functional>
#include <map>
#include <optional>

namespace awb {

struct SurfaceIfs;

// Matrices an eigenvalue plot can analyse: real, or complex (a complex Bézier parameter).
struct AnalysisMatrices {
    std::vector<Mat> real;
    std::vector<CMat> complex;
    QString unavailable;  // why there are none (e.g. M_i is undefined for a singular P)
    int count() const { return int(real.empty() ? complex.size() : real.size()); }
    bool isComplex() const { return !complex.empty(); }
};

// What an attractor item derives from its inputs. Never saved.
struct DerivedIfs {
    Ifs ifs;            // validated; probabilities set in random mode
    AnalysisMatrices S; // subdivision matrices S_1..S_p (m x m)
    AnalysisMatrices A; // linear parts A_i of M_i = P^-1 S_i P ((m-1) x (m-1))
    // The whole lifted maps M_i = P^-1 S_i P = [[A_i, 0], [b_i, 1]] of a complex lifting (a
    // Bézier curve split at a complex t, 004 §3.7); real liftings are in `subdivision`.
    std::vector<CMat> liftedComplex;
    // The core's full result when the item is a real subdivision scheme (lifting, M_i, ...).
    std::shared_ptr<const SubdivisionIfs> subdivision;
    // The core's surface IFS when the item is a subdivision surface patch (000 §3).
    std::shared_ptr<const SurfaceIfs> surface;
    // Map k of `ifs` is map mapIndex[k] of the analysis matrices S, A (an IFS over a subset of
    // the maps, 000 Fig. 9); empty: the same index.
    std::vector<int> mapIndex;
    int analysisIndex(int k) const { return mapIndex.empty() ? k : mapIndex[size_t(k)]; }
    QString note;       // e.g. why the barycentric form is used
    // Plane points (n x 2) to points of the IFS space (n x D).
    std::function<Mat(const Mat &)> toIfsSpace;

    // Items whose attractor is not that of the single IFS `ifs` (a CIFS state, a junction
    // automaton) set `iterate`: it streams the images of depth `depth` to the sinks (one per
    // thread) like awb::iterateParallel, addresses included; `ifs.views` still say how a point
    // of its space is drawn. Renderers call it when set, awb::iterateParallel(ifs, ...)
    // otherwise.
    std::function<IterationStats(const StartSet &, int depth, const std::vector<AttractorSink *> &,
                                 const IterationControl &)>
        iterate;
    // `iterate` only draws `ifs` another way (a random-mode fractal of space streams its chaos
    // game to the 3D view): F^depth(start) is still awb::iterate(ifs, ...), which `points` and
    // the point exports take, so that their --start and --depth mean what they say.
    bool iterateDrawsIfs = false;
    // Items whose random iteration is a chaos game of their own (a fractal flame's non-affine
    // xforms): renderers play it in random mode instead of the engine's on `ifs`, which then
    // holds only what is analysed (the affine parts).
    CustomChaos chaos;
    // Items that start from the limit positions of their vertices (mesh items, start set kind
    // "vertex-limits"): `iterate` takes an empty start set as that start.
    bool vertexLimitStart = false;
    // Items with `iterate` that know how many points a start set makes at a depth (mesh
    // items; -1 or unset: unknown).
    std::function<double(const StartSet &, int depth)> pointCount;
    // Items whose figure is a polygon rather than (only) an attractor: the normal-vector
    // scheme's polygon at the item's number of steps (n x 2; closed when polygonClosed).
    std::optional<Mat> polygon;
    bool polygonClosed = false;
};

// Lifted start points (each with the IFS space's dim() coordinates) as rows; throws InputError
// naming the expected count, or when the IFS is in barycentric form (no lifting).
Mat liftedStartPoints(const DerivedIfs &derived, const std::vector<std::vector<double>> &points);
// Control points of `s` by index as points of its IFS space: the rows of the lifted P, or unit
// vectors in barycentric form. Throws InputError.
Mat netPointRows(const SubdivisionIfs &s, const std::vector<int> &net);
// The start set of kind "net" (the item's `subdivision`): one index a point, two a segment,
// more a polygon. Throws InputError.
StartSet netStartSet(const DerivedIfs &derived, const std::vector<int> &net);

class AttractorItem : public Item {
    Q_OBJECT
public:
    const StartSetSpec &startSet() const { return m_startSet; }
    // The spec's own check, and "vertex-limits" only for items with vertices (meshes).
    MaybeProblem checkStartSet(const StartSetSpec &s) const;
    MaybeProblem checkNetStart(const std::vector<int> &net) const;
    // A start set of net points or of lifted points changes meaning with the net's count.
    bool startSetFollowsCount() const;
    // After a change of point set `set`'s count (old index -> new, -1 when removed): net
    // indices follow their points, lifted points get the new lifting's coordinate count.
    // Without `remap` (an edit that changed the net as a whole: a new scheme or layout, a new
    // lifting), a net start set whose indices no longer fit starts again from the net's largest
    // triangle.
    void refitStartSet(int set, const std::function<int(int)> &remap);
    bool hasDependents() const override { return startSetFollowsCount(); }
    void refitDependents() override { refitStartSet(0, nullptr); }
    virtual bool startsAtVertexLimits() const { return false; }
    // Items whose IFS is built from one control net take the start set kind "net".
    virtual bool startsAtNetPoints() const { return false; }
    // False for an item whose game starts from points of its own (a flame: random points of
    // [-1, 1]^2, as flam3's): no start set to edit or to show.
    virtual bool hasStartSet() const { return true; }
    bool setStartSet(const StartSetSpec &startSet, int gesture = 0);

    const AlgorithmSpec &algorithm() const { return m_algorithm; }
    MaybeProblem checkAlgorithm(const AlgorithmSpec &a) const { return a.check(branching()); }
    // The checks of every kind's spec: its own (`own`, its field under `prefix`), then the
    // algorithm's depth bound with the number of maps the spec makes.
    MaybeProblem checkWithMaps(const MaybeProblem &own, int maps, const QString &prefix = {}) const
    {
        if (own)
            return Problem{prefix + own->field, own->message};
        if (auto p = m_algorithm.check(maps))
            return Problem{"algorithm." + p->field, p->message};
        return std::nullopt;
    }
    bool setAlgorithm(const AlgorithmSpec &algorithm, int gesture = 0);

    // The number of maps the inputs ask for, known without building the IFS (-1: unknown).
    virtual int mapCount() const = 0;
    // The most images one image makes per level, which bounds the depth: the maps, or the
    // most arcs leaving one state of an automaton (CifsItem).
    virtual int branching() const { return mapCount(); }
    // Coordinates of control points and start-set vertices: 2 (plane curves) or 3 (surfaces).
    virtual int pointDimension() const { return 2; }
    // Whether points may be inserted into or removed from point set `set` (a surface's net is
    // fixed by its scheme).
    virtual bool pointCountEditable(int set) const { Q_UNUSED(set); return true; }
    // The most points a point set may have: an n-point set makes n x n subdivision matrices
    // (lifting, spectra, fixed points cost n^3), so a file or an edit beyond this is refused
    // with a message rather than left to exhaust the time or the memory.
    static constexpr int maxControlPoints = 256;
    // The most points point set `set` may have (maxControlPoints; a mesh's vertices more).
    virtual int maxPointCount(int set) const { Q_UNUSED(set); return maxControlPoints; }

    // ---- control points: an item has controlPointSetCount() ordered lists of plane points.
    virtual int controlPointSetCount() const { return 0; }
    // Whether point set `set` is a closed polygon (its last point joins the first): drawn closed
    // by every view and figure.
    virtual bool controlPointSetClosed(int set) const { Q_UNUSED(set); return false; }
    const PointList &controlPoints(int set = 0) const;
    // Undoable; false for a bad set/index or non-finite coordinates. Moves within one drag
    // share a gesture id (Project::beginGesture) and become one undo step.
    bool moveControlPoint(int index, const Point &to, int gesture = 0, int set = 0);
    // Several points at once: one undo step (merging by gesture like a single point).
    bool moveControlPoints(const std::map<int, Point> &to, int gesture = 0, int set = 0);
    bool insertControlPoint(int index, const Point &point, int set = 0);
    bool removeControlPoint(int index, int set = 0);
    // Removes several points as one undo step.
    bool removeControlPoints(std::vector<int> indices, int set = 0);
    // The whole set as one undo step (moves, then inserts or removes at the end); false with
    // *error when the count is fixed, too large, or a point is not finite.
    bool setControlPoints(int set, const PointList &points, QString *error = nullptr);

    // The derived IFS, computed on first use after an edit; null when it cannot be computed,
    // with the reason in derivedError().
    std::shared_ptr<const DerivedIfs> derivedIfs() const;
    QString derivedError() const override;
    // The largest absolute coordinate of any control point (0 without points).
    double largestCoordinate() const;
    // The start set mapped into the IFS space of `derived`, ready for core::iterate().
    // Throws InputError.
    StartSet coreStartSet(const DerivedIfs &derived) const;

    void checkLoaded(const FieldReader &fields) const override;

    // The declared start set and algorithm, after Item's (PropertyTable.h): the base of every
    // attractor kind's declaration.
    static const PropertyTable &attractorProperties();

signals:
    void startSetChanged();
    void algorithmChanged();
    // Any change of a point set (then also one of the finer signals below).
    void controlPointsChanged(int set);
    void controlPointMoved(int set, int index);
    void controlPointInserted(int set, int index);
    void controlPointRemoved(int set, int index);

protected:
    explicit AttractorItem(const QString &defaultName);
    // Builds the IFS from the inputs; throws InputError with a message for the user.
    virtual DerivedIfs computeIfs() const = 0;
    bool dropDerived() override;
    // The storage of point set `set` (0 <= set < controlPointSetCount()).
    virtual PointList &pointStorage(int set) = 0;
    // Called when an edit (or its undo) has stored into point set `set`, before the derived
    // data is dropped: an item whose points stand for other inputs (a flame's xform triangles)
    // updates them here.
    virtual void pointsStored(int set) { Q_UNUSED(set); }
    const PointList &pointStorage(int set) const
    {
        return const_cast<AttractorItem *>(this)->pointStorage(set);
    }
    // Random mode: the probabilities go into the IFS (validated with it).
    void applyAlgorithm(Ifs &ifs) const;
    // The start set a new item of the kind begins with (not an edit: no undo step).
    void setInitialStartSet(const StartSetSpec &startSet) { m_startSet = startSet; }

private:
    // Runs a command that changes point set `set`'s count, and refitStartSet(set, remap) in
    // the same undo step when the start set follows the count.
    void executeCounted(QUndoCommand *command, int set, const std::function<int(int)> &remap);
    friend class PointSetPart;  // stores the points read from a file
    friend class MoveControlPointsCommand;
    friend class InsertControlPointCommand;
    friend class RemoveControlPointCommand;
    // Raw edits for the commands: store, invalidate, notify.
    void storePoint(int set, int index, const Point &p);
    void storeInsertedPoint(int set, int index, const Point &p);
    void storeRemovedPoint(int set, int index);
    bool validSet(int set) const { return set >= 0 && set < controlPointSetCount(); }

    StartSetSpec m_startSet;
    AlgorithmSpec m_algorithm;
    DerivedCache<DerivedIfs> m_derived;
};

} // namespace awb
