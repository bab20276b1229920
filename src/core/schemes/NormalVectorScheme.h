#pragma once
// The normal-vector p-ary subdivision scheme of 001 eq. (1), its presets (001 §3) and its
// analysis (001 §4). Unlike the schemes of Scheme.h it is not linear in the control points (the
// normal d_i depends on the edge), so it is a subdivision in its own right rather than a
// CurveScheme; where a preset's rules are the same on every edge, equivalentIfs() gives the plane
// IFS whose attractor is its limit curve.
//
// Rule j of edge i at level k (the polygon being subdivided; the first step has k = 0):
//   P^{k+1}_{p i + j} = (1 - α_j) P^k_i + α_j P^k_{i+1} + s_j(k, i) β_j d^k_i,   j = 0..p-1,
// d^k_i = |P^k_i P^k_{i+1}| n^k_i with n^k_i the edge direction rotated 90° counter-clockwise
// (Positive) or clockwise (Negative); s_j(k, i) = ±1 is the β sign rule (i: 0-based edge index).
// Points are rows (m x 2), as everywhere in awb::core.
//
// Which presets have an equivalent IFS of p similarities (one per new edge of a unit edge):
// every interpolatory one (α_0 = β_0 = 0). With one β sign everywhere (Lévy, Koch, snowflake,
// tigerhead, crown, 7-ary) each new edge carries a plain copy of the unit edge's limit; where
// the sign changes with the edge or the level (dragon (-1)^i, Sierpiński arrowhead (-1)^(k+i),
// human-like (-1)^(k+1)) an edge subdivided with the other sign carries a reversed or mirrored
// copy: the dragon is f1(z) = (1+i) z/2, f2(z) = 1 - (1-i) z/2. equivalentIfs() finds the
// orientations by search (4^p patterns, each checked against the scheme's own polygons). The
// approximating curve (α_0 ≠ 0) has none: it makes an edge across each old vertex that is no
// image of one edge.

#include "core/ifs/Ifs.h"
#include "core/Types.h"

#include <optional>

namespace awb {

enum class NormalDirection { Positive, Negative };
// s_j(k, i) of 001 §3: 1, (-1)^i, (-1)^(k+i), (-1)^(k+1) (NOTES.md fixes k and i).
enum class BetaSign { Constant, EdgeAlternating, LevelEdgeAlternating, LevelAlternating };
std::string toString(NormalDirection normal);
std::string toString(BetaSign sign);
int betaSignValue(BetaSign sign, int level, long long edge);
// The conventions above in one paragraph, for the application to show next to the parameters.
std::string normalVectorConventions();

struct ControlPolygon {
    Mat points;           // (n + 1) x 2 for an open polygon of n edges, n x 2 when closed
    bool closed = false;  // closed: edge n-1 joins the last point to the first
    Eigen::Index edgeCount() const { return closed ? points.rows() : points.rows() - 1; }
};
ControlPolygon unitSegment();          // (0,0) -> (1,0), open: Fig. 2(a), 3(a)
ControlPolygon equilateralTriangle();  // (0,0), (1,0), (1/2,√3/2), closed, counter-clockwise
ControlPolygon unitSquare();           // (0,0), (1,0), (1,1), (0,1), closed, counter-clockwise

class NormalVectorScheme {
public:
    // alpha, beta: p values each (p >= 2, finite). signs: empty (all constant), one sign for
    // every rule, or p signs (one per rule). Throws InputError naming the bad argument.
    NormalVectorScheme(std::vector<double> alpha, std::vector<double> beta,
                       NormalDirection normal = NormalDirection::Positive,
                       std::vector<BetaSign> signs = {});

    int arity() const { return int(m_alpha.size()); }
    const std::vector<double> &alpha() const { return m_alpha; }
    const std::vector<double> &beta() const { return m_beta; }
    const std::vector<BetaSign> &signs() const { return m_signs; }  // p entries
    NormalDirection normal() const { return m_normal; }
    // α_0 = β_0 = 0: the old points stay (the scheme is interpolatory).
    bool interpolatory() const;
    // Some rule with β_j ≠ 0 changes sign with the level (non-stationary) / the edge index.
    bool levelDependent() const;
    bool edgeDependent() const;
    // s_j(k, i) β_j.
    double signedBeta(int j, int level, long long edge) const;
    std::string describe() const;

    // Throws InputError unless poly can be subdivided: 2 coordinates, finite, at least 2
    // points (3 when closed); open polygons need α_0 = β_0 = 0, because rule 0 at the last
    // point i = p^k n of eq. (1) would use a point after the end.
    void validate(const ControlPolygon &poly) const;
    // Points after `steps` steps: p^steps n + 1 (open) or p^steps n (closed), as a double.
    double pointCount(const ControlPolygon &poly, int steps) const;
    // One step of eq. (1) applied to the polygon of level `level` (>= 0): m x 2 -> (p n [+1]) x 2.
    // Same checks as subdivide(poly, 1, level).
    ControlPolygon step(const ControlPolygon &poly, int level) const;
    // `steps` steps from level firstLevel. Throws InputError for steps < 0, or when the result
    // would hold more than maxPoints() points.
    ControlPolygon subdivide(const ControlPolygon &poly, int steps, int firstLevel = 0) const;
    // Levels 0..steps (element k is the polygon at level k).
    std::vector<ControlPolygon> levels(const ControlPolygon &poly, int steps) const;
    static constexpr double maxPoints() { return 5e7; }

private:
    std::vector<double> m_alpha, m_beta;
    NormalDirection m_normal;
    std::vector<BetaSign> m_signs;
};

// 001 §4 for any parameters. On the unit edge rule j sits at a_j = (α_j, ±s_j β_j) (the sign of
// the normal), a_p = (1, 0); a new edge is Δ_j = a_{j+1} - a_j in the frame (e, d) of the old
// edge, and |d| = |e|, d ⊥ e.
struct NormalVectorAnalysis {
    // Theorem 1's factor: max_j (|Δα_j| + |Δβ_j|) by the triangle inequality, over all β signs.
    // For a non-interpolatory scheme the edge across an old vertex adds
    // |1 - α_{p-1}| + |α_0| + |β_{p-1}| + |β_0|. Scheme (5): (√3 + 1)/6.
    double paperContractionBound = 0.0;
    // max_j |Δ_j|: the exact worst ratio new/old edge length (interpolatory only, NaN otherwise).
    // Scheme (5): 1/3.
    double edgeContraction = 0.0;
    // δ = max_j |(α_j - j/p, β_j)|: ||F^{k+1} - F^k||∞ = δ max_i |P^k_{i+1} - P^k_i| (scheme (5):
    // √3/6, the first line of the proof of Theorem 1).
    double displacementFactor = 0.0;
    // Σ_j |Δ_j|: the polygon length ratio per step, min and max over the β signs
    // (interpolatory only, NaN otherwise). Scheme (5): 4/3 (Theorem 2).
    double lengthRatioMin = 0.0, lengthRatioMax = 0.0;
    bool convergent = false;      // a contraction factor < 1 was found
    bool nonRectifiable = false;  // the length ratio is > 1 for every sign
    std::string verdict;
};
NormalVectorAnalysis analyse(const NormalVectorScheme &scheme);

// Measures of each level of a subdivision (levels 0..steps).
struct LevelMeasure {
    int level = 0;
    Eigen::Index points = 0;
    double length = 0.0;   // polygon length (closing edge included when closed)
    double maxEdge = 0.0;  // longest edge
    double area = 0.0;     // signed shoelace area when closed, NaN when open
};
std::vector<LevelMeasure> measureLevels(const NormalVectorScheme &scheme,
                                        const ControlPolygon &poly, int steps);

// Why the scheme has no equivalent IFS of similarities (see the header comment), or nullopt.
std::optional<std::string> whyNoEquivalentIfs(const NormalVectorScheme &scheme);
// The p maps taking the unit edge onto the new edges a_j -> a_{j+1} of the unit edge, each
// forward (z |-> a_j + Δ_j z) or reversed (a_{j+1} - Δ_j z), plain or mirrored (conj z), the
// orientations found by search: the first pattern whose level-n vertices equal the scheme's
// polygon after n steps for every n up to ~4000 vertices. Row form: A = [[u, v], [-v, u]]
// (plain) or [[u, v], [v, -u]] (mirrored), c = u + iv. Identity view. Throws InputError with
// whyNoEquivalentIfs(), e.g. when a new edge is not shorter than the old one.
Ifs equivalentIfs(const NormalVectorScheme &scheme);
// The same IFS with one view per edge of poly (view = the similarity taking the unit edge onto
// that edge), so drawing all views gives the limit curve of the whole polygon.
Ifs equivalentIfs(const NormalVectorScheme &scheme, const ControlPolygon &poly);

enum class NormalVectorPresetId {
    Levy, Dragon, SierpinskiArrowhead, Koch, KochSnowflake, Tigerhead, HumanLike,
    Approximating, Crown, SevenAry
};
struct NormalVectorPreset {
    NormalVectorPresetId id;
    std::string key;      // stable identifier for files ("koch", "snowflake", ...)
    std::string name;
    std::string source;   // paper section, scheme number, figure
    std::string note;     // what the paper says about it, or where our reading differs
    NormalVectorScheme scheme;
    ControlPolygon polygon;  // the figure's initial control polygon
    int figureSteps = 0;     // subdivision steps shown in the figure
};
std::vector<NormalVectorPreset> normalVectorPresets();
NormalVectorPreset normalVectorPreset(NormalVectorPresetId id);
// The preset's polygon after `steps` steps (e.g. Koch at 7 steps: 4^7 + 1 points).
ControlPolygon subdividePreset(NormalVectorPresetId id, int steps);

} // namespace awb
