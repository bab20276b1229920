#pragma once
// Controlled IFS (003 §2.2): an automaton whose states carry barycentric spaces and whose arcs
// carry the maps. The attractor of a state s is the union over its arcs t: s -> s' of
// T_t(A_s'), so one attractor can mix pieces of different nature (003 Figs. 4-5: a fern built of
// Sierpinski triangles). The BCIFS curves of Bcifs.h are drawn through this automaton.
//
// Conventions (the core's row convention, see Types.h):
//  * A barycentric point of a state of dimension n is a ROW lambda (1 x n) summing to 1; it is
//    drawn at lambda * controlPoints (controlPoints: n x d, one point per row).
//  * A transition t: from -> to stores S_t (n_to x n_from), rows summing to 1. It maps the
//    to-state's space INTO the from-state's space: lambda_from = lambda_to * S_t.
//  * 003 writes the same map on COLUMNS: T_t (n_from x n_to), columns summing to 1, with
//    T_t = S_t^T. addColumnTransition() takes that form and stores its transpose.
// A path t_1 t_2 .. t_k from s (t_1 leaves s) maps the end state's space into s's space by
// lambda |-> lambda S_{t_k} ... S_{t_1}; its address is (t_1, .., t_k), address[0] = t_1 being
// the outermost map, as for awb::iterate().

#include "core/ifs/Attractor.h"

namespace awb {

struct CifsState {
    std::string name;
    Mat controlPoints;  // n x d (d = 2 or 3); n is the dimension of the barycentric space
    int dim() const { return int(controlPoints.rows()); }
};

struct CifsTransition {
    std::string name;
    int from = 0;
    int to = 0;
    Mat S;                // n_to x n_from, rows sum to 1 (row convention)
    double weight = 1.0;  // relative probability among the from-state's arcs (random iteration)
};

struct Cifs {
    std::vector<CifsState> states;
    std::vector<CifsTransition> transitions;

    int addState(std::string name, const Mat &controlPoints);
    // Row convention: S is n_to x n_from. Returns the transition index (its address symbol).
    int addTransition(std::string name, int from, int to, const Mat &S, double weight = 1.0);
    // 003's column convention: T is n_from x n_to; stored as S = T^T.
    int addColumnTransition(std::string name, int from, int to, const Mat &T,
                            double weight = 1.0);

    // Index of the named state / transition; InputError when there is none.
    int stateIndex(const std::string &name) const;
    int transitionIndex(const std::string &name) const;
    // Indices of the transitions leaving `state`, in insertion order.
    std::vector<int> outgoing(int state) const;
    // lambda (1 x n) |-> lambda * controlPoints: the view for a state's attractor.
    Projection view(int state) const;

    // Throws InputError naming the problem: no states, a state without control points or
    // with non-finite ones, an arc to a missing state, a matrix of the wrong size (S must be
    // n_to x n_from), non-finite entries, a row not summing to 1 (the map would leave the
    // barycentric hyperplane), a weight <= 0, a state with no outgoing arc (its attractor
    // would be empty), more than 255 arcs (addresses are bytes).
    void validate() const;
};

// The linear part of a row-stochastic S (n x n) on the barycentric directions (row vectors
// summing to 0), in the basis e_k - e_{n-1}: (n-1) x (n-1). Its eigenvalues are those of S
// with one eigenvalue 1 removed; it decides contraction.
Mat barycentricPart(const Mat &S);

// Contractivity of the cycles of the automaton: every simple cycle s -t_1-> .. -t_m-> s must
// have a product S_{t_m} .. S_{t_1} (n_s x n_s) whose barycentricPart has spectral radius < 1.
// This is necessary for the attractors to exist (each cycle repeated is a path of the
// iteration); it is not sufficient in general (products mixing cycles are not checked).
struct CycleCheck {
    std::vector<int> transitions;  // t_1 .. t_m; the cycle starts at its lowest-index state
    double spectralRadius = 0.0;
};
struct CifsCheck {
    std::vector<CycleCheck> cycles;
    bool contractive = true;  // all enumerated cycles have spectral radius < 1
    bool complete = true;     // false past maxCycles simple cycles, or 2e6 steps of the walk
    std::string message;      // names the first offending cycle; empty when contractive
};
// Validates first (InputError as in Cifs::validate()).
CifsCheck checkCifs(const Cifs &cifs, int maxCycles = 10000);
// "Fern -T1-> Sierpinski -S0-> ..." for messages.
std::string describePath(const Cifs &cifs, int from, const std::vector<int> &transitions);

// Fixed point (1 x n, summing to 1) of a row-stochastic S (n x n): lambda = lambda S. Throws
// InputError when it is not unique (1 is a repeated eigenvalue).
RowVec barycentricFixedPoint(const Mat &S);

// Start sets lying on the attractors, one per state in its own space (Points): the fixed
// points of the state's self-loops, else of the shortest cycle through it, else the images
// of its first arc's target seeds. Every image of them is then a point of the attractor, so
// depth-k point sets converge from the inside. InputError unless checkCifs(cifs).contractive.
std::vector<StartSet> attractorSeeds(const Cifs &cifs);
// The simplex vertices of every state (the identity, drawn as its control polygon).
std::vector<StartSet> controlPolygonStarts(const Cifs &cifs);

// The stacked space of an automaton item: every state's barycentric coordinates side by side
// (state s in columns offsets[s] .. offsets[s] + n_s - 1), drawn by the stacked control points
// (dimension x d), so that one view draws the points of every state.
struct CifsStacking {
    std::vector<int> offsets;
    int dimension = 0;
    Mat points;
};
CifsStacking stackingOf(const Cifs &cifs);

// Passes a state's images on, written into that state's block of the stacked space.
class StackedSink : public AttractorSink {
public:
    StackedSink(AttractorSink &target, int dimension) : m_target(target), m_dim(dimension) {}
    int offset = 0;  // the block of the state being drawn
    void consume(const Mat &vertices, StartSet::Kind kind, const std::uint8_t *address,
                 int length) override;

private:
    AttractorSink &m_target;
    int m_dim;
    Mat m_buffer;
};

// Number of paths of length `depth` leaving `state` (as a double, it may be huge).
double pathCount(const Cifs &cifs, int state, int depth);

// Deterministic iteration: for every path t_1 .. t_k of length k = depth leaving `state`, the
// image of the end state's start set (starts[end]: m x n_end) mapped into `state`'s space
// (m x n_state rows) goes to the sink, with address (t_1, .., t_k). Draw it with
// cifs.view(state). depth 0 emits starts[state]. Throws InputError for an invalid automaton,
// depth outside [0, 64], start sets of the wrong size or non-finite.
IterationStats iterate(const Cifs &cifs, int state, const std::vector<StartSet> &starts,
                       int depth, AttractorSink &sink, const IterationControl &control = {});

// Random iteration. Every state keeps a current point (starting at its simplex centroid);
// each round replaces, for every state q reachable from `state`, its point by x_{to(t)} S_t
// for a random arc t leaving q (by weight), all from the previous round's points. After r
// rounds x_state is the image of a random path of length r, so it lies within rho^r of the
// attractor. After options.skip rounds, x_state (1 x n_state) is emitted every round with
// the latest options.addressLength arcs of its path as address.
IterationStats chaosGame(const Cifs &cifs, int state, const ChaosOptions &options,
                         AttractorSink &sink, const IterationControl &control = {});

// ---- the example of 003 §2.2 -------------------------------------------------------------

// Barnsley's fern (Barnsley, "Fractals Everywhere", the classic table; 003 shows only the
// picture): stem, main frond (0.85), left leaflet, right leaflet, in that order, in the core's
// row convention x |-> x A + b. probabilities: 0.01, 0.85, 0.07, 0.07.
std::vector<AffineMap> barnsleyFernMaps();
std::vector<double> barnsleyFernProbabilities();

// The barycentric matrix (row convention, (d+1) x (d+1)) of the affine map f of R^d between
// two frames: a point lambda of the frame `domain` ((d+1) x d, drawn lambda * domain) goes to
// f(lambda * domain), written in barycentric coordinates of the frame `image`. Throws
// InputError when a frame is not d+1 affinely independent points.
Mat barycentricMatrix(const AffineMap &f, const Mat &domain, const Mat &image);

// The frame both states of the example use: the triangle (-3,0), (3,0), (0,10) around the fern.
Mat fernFrame();
// 003 Fig. 4 left: one state "Fern" with the four fern maps as arcs T0..T3.
Cifs barnsleyFernCifs(const Mat &frame = fernFrame());
// 003 Fig. 4 right: the fern state's arc `redirected` (0..3) leads into a new state
// "Sierpinski" with the three maps lambda |-> (lambda + e_k)/2 (arcs S0..S2), so the fern is
// built of Sierpinski triangles (Fig. 5 bottom). 003 redirects the arc its figure labels T1;
// its maps are only drawn, so which fern map that is cannot be read from the text. With the
// classic order above, index 1 is the 0.85 main-frond map, whose redirection turns the whole
// frond into one big gasket; the default 2 (left leaflet) gives the fern of Fig. 5 bottom.
Cifs fernSierpinskiCifs(int redirected = 2, const Mat &frame = fernFrame());

} // namespace awb
