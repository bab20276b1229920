#pragma once
// Document item "cifs" (layer 2, model): a controlled IFS (003 §2.2), an automaton whose states
// carry barycentric spaces (each its own control points) and whose arcs carry maps. The
// attractor of a state s is the union over its arcs t: s -> s' of T_t(A_s'), so one picture can
// mix pieces of different nature: 003 Figs. 4-5, a fern built of Sierpiński gaskets, is the
// example examples/003-fig05-fern-of-sierpinski-gaskets.awb; a flame's xaos rows import as one
// (model/FlameExchange.cpp). The item draws one state's attractor, or the union of all of them,
// through the core's CIFS iteration (core/ifs/Cifs.h): deterministic over the admissible paths,
// or random (a Markov chain on the states, by the arcs' weights).
//
// An arc keeps its matrix S_t (n_to x n_from, rows summing to 1, the core's row convention):
// like every map of the application, it acts on barycentric coordinates, so dragging a state's
// control points deforms the attractor and keeps the automaton. An arc may be given as 003's
// column form T_t = S_t^T, as a plane affine map (between the two states' frame triangles),
// or as a piece S_i of a curve scheme; it is kept as its matrix (docs/file-format.md).

#include "model/AttractorItem.h"

namespace awb {

struct Cifs;
struct CifsAnalysis;

struct CifsStateSpec {
    QString name;
    PointList points;  // the state's control points: its barycentric space has points.size()
    bool operator==(const CifsStateSpec &) const = default;
};

struct CifsArcSpec {
    QString name;
    int from = 0;  // state indices
    int to = 0;
    Mat S;          // n_to x n_from, rows summing to 1
    double weight = 1.0;  // relative probability among the arcs leaving `from`
    bool operator==(const CifsArcSpec &o) const;
};

struct CifsSpec {
    Q_DECLARE_TR_FUNCTIONS(awb::CifsSpec)
public:
    std::vector<CifsStateSpec> states;
    std::vector<CifsArcSpec> arcs;
    QString drawn = QStringLiteral("Fern");  // a state's name, or allStates

    static inline const QString allStates = QStringLiteral("all");
    static constexpr int maxStates = 64;
    static constexpr int maxStatePoints = 64;  // the dimension of one state's space

    bool operator==(const CifsSpec &) const = default;
    // Names unique and non-empty, every arc between existing states with a matrix of the right
    // size whose rows sum to 1, finite numbers, weights > 0, at most 255 arcs (addresses are
    // bytes); `drawn` a state or "all". Fields like "arcs[2].matrix", 1-based as in messages.
    // An automaton that does not contract, or a state without arcs, is accepted: the item
    // then says so where it is drawn (a user builds an automaton one arc at a time).
    MaybeProblem check() const;
    QStringList stateNames() const;
    int stateIndex(const QString &name) const;  // -1 when there is none
    // The core's automaton (check() first).
    Cifs toCore() const;
    // The most arcs leaving one state: the paths of depth k are at most this^k.
    int branching() const;
    // 003 Fig. 4: Barnsley's fern, its arc `redirected` (0..3) led into a Sierpiński state.
    static CifsSpec fernOfGaskets(int redirected = 2);
    // A new arc from -> to: (lambda + e_k)/2 between spaces of one dimension, k the number of
    // arcs already leaving `from` (a Sierpiński map); else lambda |-> the centroid's mix.
    static Mat defaultArcMatrix(int nTo, int nFrom, int k);
    // Fresh names: "S1", "S2", ... and "t1", "t2", ... not yet used.
    QString freshStateName() const;
    QString freshArcName() const;
};

class CifsItem : public AttractorItem {
    Q_OBJECT
public:
    CifsItem();

    static QString staticType() { return QStringLiteral("cifs"); }
    static QString staticTypeName() { return tr("Controlled IFS"); }
    QString type() const override { return staticType(); }
    QString typeName() const override { return staticTypeName(); }

    const CifsSpec &spec() const { return m_spec; }
    // The spec's own check, then the algorithm's depth bound with its branching.
    MaybeProblem checkSpec(const CifsSpec &spec) const;
    // Undoable, one step (a gesture merges the steps of a drag); false (and *error says why)
    // when checkSpec() refuses.
    bool setSpec(const CifsSpec &spec, int gesture = 0, QString *error = nullptr);

    // Declared: "states" (names and control points), "arcs" (from, to, matrix, weight), the
    // drawn "state".
    static const PropertyTable &declaration();
    const PropertyTable &properties() const override { return declaration(); }
    // Files of versions before the general automaton: {"preset": "fern-sierpinski",
    // "redirected": k, "control_points": frame} become its states and arcs.
    QJsonObject upgradedFields(const QJsonObject &json) const override;

    // The arcs: an address symbol each, a colour each.
    int mapCount() const override { return int(m_spec.arcs.size()); }
    int branching() const override { return m_spec.branching(); }
    // Point set i is state i's control points; their number is the state's dimension, fixed
    // by its arcs' matrices.
    int controlPointSetCount() const override { return int(m_spec.states.size()); }
    bool pointCountEditable(int) const override { return false; }
    bool controlPointSetClosed(int set) const override
    {
        return m_spec.states[size_t(set)].points.size() > 2;
    }

    // What the automaton contracts by (core/analysis/CifsAnalysis.h): its constrained JSR,
    // cycles and Lyapunov exponent. They depend on the arcs only, not on the control points:
    // kept until the arcs change. Null (and *error says why) for an invalid automaton.
    std::shared_ptr<const CifsAnalysis> automatonAnalysis(QString *error = nullptr) const;

signals:
    void specChanged();

protected:
    DerivedIfs computeIfs() const override;
    PointList &pointStorage(int set) override { return m_spec.states[size_t(set)].points; }

private:
    CifsSpec m_spec;
    mutable std::vector<CifsArcSpec> m_analysedArcs;
    mutable std::vector<int> m_analysedDimensions;
    mutable std::shared_ptr<const CifsAnalysis> m_analysis;
    mutable QString m_analysisError;
};

// An arc's map as the file, Python and `attractor-cli set` may give it, into its matrix:
// {"matrix": S} (n_to x n_from, row convention), {"columns": T} (003's form, T = S^T),
// {"affine": {"A": [[a11, a12], [a21, a22]], "b": [b1, b2]}} (x |-> x A + b taking the
// to-state's frame triangle into the plane of the from-state's, both 3 points), or
// {"scheme": {...a curve scheme...}, "piece": i} (S_i for the states' number of points).
// Throws LoadError naming the field below `where`.
Mat cifsArcMatrixFromJson(const QJsonObject &arc, const CifsStateSpec &from,
                          const CifsStateSpec &to, const QString &where);

} // namespace awb
