#pragma once
// Where a one- or two-parameter family of schemes is C^k, over a grid (layer 1, no Qt): the
// regularity atlas of issue 48. The four-point scheme's tension, a corner cutting's (a, b), the
// free coefficients of a mask: each grid point gets certified Hölder bounds [lower, upper]
// (Regularity.h) and, for masks, the exact Sobolev exponent. The grid is then refined where the
// verdict "C^k" changes: in one parameter by sectioning each bracket (as regularity-interval
// bisects), in two by splitting each grid cell whose corners disagree (a quadtree).
//
// The plan does not evaluate anything itself: it hands out batches of parameter points and
// takes their rows back (AtlasPlan). Who evaluates a batch is the caller's choice -- a loop in
// this process, the machine's threads, or a Dask cluster (python/attractor_workbench/atlas.py)
// -- and the points of each batch are independent. Every evaluation runs under a budget of
// work, not of time (RegularityOptions::maxProducts), and the points of a batch depend only on
// the rows before it, so the same grid gives the same rows wherever and however it runs.

#include "core/analysis/Regularity.h"

#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace awb {

struct AtlasAxis {
    std::string name;   // the parameter's name: "omega", "w", ...
    double from = 0.0;
    double to = 1.0;
    int count = 2;      // grid values, both ends included (2..100000 in 1D, 2..2000 in 2D)
};

struct AtlasOptions {
    int smoothness = 1;            // k: the verdict asked is "C^k"
    double tolerance = 1e-6;       // 1D: a boundary's bracket narrows to this width
    int sections = 8;              // 1D: new points per bracket and round
    int maxRounds = 16;            // 1D: at most this many sectioning rounds
    int refineLevels = 3;          // 2D: cells split at most this many times
    long long work = 100000;       // JSR products per point (RegularityOptions::maxProducts)
    int polytopeVertices = 300;    // invariant polytope vertices per point
    double safetySeconds = 120.0;  // a point still running after this stops (timed_out row)
};

// The verdict on "C^k": +1 certified (lower > k), -1 certified not (upper < k, or no member
// at these parameters), 0 the bounds cannot tell (r = k, or too close within the budget).
struct AtlasRow {
    std::vector<double> params;   // one value per axis
    bool applies = false;         // a member exists and the analysis covers it
    double lower = 0.0;           // certified bounds on the Hölder exponent (inf: C^infinity)
    double upper = 0.0;
    bool exact = false;           // an invariant polytope closed: the bracket is ~1e-12 wide
    double sobolev = -1.0;        // the exact L2-Sobolev exponent s_2 (masks), -1 when none
    int smoothness = -1;          // the certified class C^n, -1 when not even C^0
    int verdict = 0;              // on C^k (above)
    bool timedOut = false;        // safetySeconds fired: this row may differ elsewhere
    double seconds = 0.0;         // wall time of the evaluation (not part of the result)
    std::string message;          // why it does not apply, or the analysis's verdict
};

int atlasVerdict(const AtlasRow &row, int k);

// The options of one point's evaluation: the work budget, the polytope's vertex limit, the
// safety clock.
RegularityOptions atlasRegularityOptions(const AtlasOptions &options);

// One point: `member(params, options)` is the family's member's regularity (a member that does
// not exist returns applies = false). Exceptions become a row that does not apply.
using AtlasMember =
    std::function<Regularity(const std::vector<double> &params, const RegularityOptions &)>;
AtlasRow evaluateAtlasPoint(const AtlasMember &member, const std::vector<double> &params,
                            const AtlasOptions &options);

// One end of a 1D run of C^k rows: `inner` certified C^k, `outer` certified not (or undecided,
// or the grid's end); the boundary lies between them.
struct AtlasBoundary {
    double inner = 0.0;
    double outer = 0.0;
    bool rangeEnd = false;
    bool undecided = false;
};
struct AtlasRun {
    AtlasBoundary from, to;
};

class AtlasPlan {
public:
    // One or two axes; throws InputError on a bad grid or option.
    AtlasPlan(std::vector<AtlasAxis> axes, AtlasOptions options);

    // The points to evaluate next (each a vector of one value per axis); empty when the atlas
    // is complete. Call accept() with their rows, in the same order, before asking again.
    std::vector<std::vector<double>> nextBatch();
    void accept(const std::vector<AtlasRow> &rows);
    bool finished() const { return m_finished; }
    int round() const { return m_round; }   // batches handed out so far

    const std::vector<AtlasAxis> &axes() const { return m_axes; }
    const AtlasOptions &options() const { return m_options; }
    // Every row so far, sorted by the first axis, then the second.
    std::vector<AtlasRow> rows() const;
    // 1D: the runs of certified C^k values, in increasing order (empty in 2D).
    std::vector<AtlasRun> runs() const;
    // 2D: the cell size (in each axis's units) of the finest level a row belongs to, for
    // drawing it as a rectangle; 1D: the distance to its nearer neighbour.
    std::vector<double> cellSize(const AtlasRow &row) const;

private:
    void plan1D();
    void plan2D();
    double value(int axis, std::int64_t lattice) const;

    std::vector<AtlasAxis> m_axes;
    AtlasOptions m_options;
    int m_round = 0;
    bool m_finished = false;
    bool m_awaiting = false;
    std::vector<std::vector<double>> m_pending;

    // 1D: rows by parameter; the open brackets (inner, outer).
    std::map<double, AtlasRow> m_line;
    std::vector<std::pair<double, double>> m_brackets;

    // 2D: rows by lattice coordinates (the grid at the finest level, 2^refineLevels per cell);
    // the cells to examine next (their lower-left corner and size in lattice units).
    std::map<std::pair<std::int64_t, std::int64_t>, AtlasRow> m_plane;
    std::map<std::pair<std::int64_t, std::int64_t>, std::int64_t> m_level;   // cell size of a row
    struct Cell {
        std::int64_t i, j, size;
    };
    std::vector<Cell> m_cells;
    std::vector<std::pair<std::int64_t, std::int64_t>> m_pendingLattice;
};

} // namespace awb
