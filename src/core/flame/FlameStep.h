#pragma once
// The flame game's step after an xform (FlameChaos.cpp's runWave): each orbit of the xform's
// stack moves its colour, counts its sample, is drawn through the camera and chooses its next
// xform, onto whose stack it goes. Written once in scalar code in runWave, and here on AVX-512
// registers, eight orbits at a time (FlameStepAvx512.cpp): the colour, counters, opacity draws,
// final xform's choice, camera and next-xform pick as lanes, the orbits pushed onto their next
// stacks and the hits written by compress instructions -- no orbit goes through scalar code
// unless it is one of the rare ones (a bad value to retry, the last sample of its batch), which
// the vector step leaves to the scalar one (a fuse step -- the first 15 of a batch -- counts
// down in the lanes). Plain structs and one function: the
// AVX-512 file includes nothing else of the program (no AVX-512 copy of a shared inline
// function may reach the rest of it). Internal to src/core/flame.

#include "core/flame/FlameHits.h"

#include <cstddef>
#include <cstdint>

namespace awb::flame::detail {

// An orbit's counters, which go with its point from stack to stack (one 64-bit word: togo in
// bits 0-15, fuse 16-23, bad 24-31, last 32-47, share 48-63).
struct OrbitCounters {
    std::uint16_t togo;   // samples its batch has still to draw
    std::uint8_t fuse;    // steps before it is drawn
    std::uint8_t bad;     // consecutive bad values
    std::uint16_t last;   // the xform it last went through + 1 (its xaos row); 0 on a restart
    std::uint16_t share;  // its share of the stream's samples
};
static_assert(sizeof(OrbitCounters) == 8);

// The xforms' stacks of orbits (runWave): xform k's orbits at k cap .. k cap + top[k], their
// points, colours and counters side by side, with room for every orbit and a register's
// padding (kStackPadding: the vector code reads and writes whole registers). Raw pointers,
// copied into the game's loops: the compiler keeps them in registers there.
struct Stacks {
    double *x, *y, *c;
    OrbitCounters *n;
    std::uint32_t *top;
    std::size_t cap;

    void push(std::size_t to, double px, double py, double pc, OrbitCounters pn) const
    {
        const std::size_t at = to * cap + top[to]++;
        x[at] = px;
        y[at] = py;
        c[at] = pc;
        n[at] = pn;
    }
};
inline constexpr std::size_t kStackPadding = 8;

// One stack after its xform: m orbits, their new points (and the final xform's, when there is
// one), whether each was a bad value, their colours and counters as they came.
struct StepOrbits {
    const double *qx, *qy;
    const std::uint8_t *bad;
    const double *fx, *fy;  // null without a final xform
    const double *colour;
    const OrbitCounters *counters;
    std::size_t m;
};

// The camera as numbers (FlameGame.h's Plot: world to cells, rotated about the centre).
struct StepCamera {
    double x0, y1, sx, sy;
    int w, h;
    bool rotated;
    double cx, cy, r00, r01, r10, r11;
};

// An alias table (Random.h's AliasTable: n columns, uniform or by thresholds and aliases).
struct StepTable {
    int n;
    bool uniform;
    const std::uint64_t *threshold;
    const int *alias;
};

// What the step does with them: xform k's colour move and opacity, the sink's rule for an
// opacity (drawn with that probability, or drawn whenever it is not 0 and weighed by it), its
// table of whole deltas, the final xform's colour move and opacity, the next-xform table (xform
// k's xaos row, or the weights; any number of columns), the camera, and the sink's cells to
// prefetch.
struct StepRule {
    double towards, keep, opacity;
    bool opacityByChance;
    std::uint32_t table;  // xform k's first row of whole deltas, where the hits are rows
                          // (FlameHits::entry)
    std::uint16_t last;  // k + 1
    bool final;
    double finalTowards, finalKeep, finalOpacity;
    StepTable next;
    StepCamera camera;
    const char *prefetch;  // the sink's cells (hit cell i at prefetch + i stride), or null
    std::size_t stride;    // a power of two
};

// Where the step writes: the hits, and the orbits it leaves to the scalar step (their index,
// colour and counters as they came: their places in the stack may be overwritten by then).
struct StepOut {
    FlameHits hits;
    std::uint32_t *deferred;
    double *deferredColour;
    OrbitCounters *deferredCounters;
    std::size_t drawn = 0, offscreen = 0, deferredCount = 0;
};

// The step on AVX-512 registers; call only where XformWave::wide() (FlameStepAvx512.cpp).
// `state` is the eight lanes' xoshiro256+ (word w of lane j at state[w][j]).
void stepAvx512(const StepOrbits &orbits, const StepRule &rule, const Stacks &stacks,
                std::uint64_t (&state)[4][8], StepOut &out);

} // namespace awb::flame::detail
