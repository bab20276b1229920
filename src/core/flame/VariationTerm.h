#pragma once
// One variation term applied to one point, as XformMap::apply runs it (VariationKernels.cpp):
// shared with the wave of orbits (XformWave.cpp), which runs the terms it has no vector kernel
// for lane by lane through the same code. Internal to src/core/flame.

#include "core/flame/Flame.h"
#include "core/ifs/Random.h"

namespace awb::flame::detail {

// The point through one xform: flam3's flam3_iter_helper.
struct Point {
    double tx, ty;              // pre(p), moved by pre_blur
    double sumsq, sqrt;         // always computed
    double atanXY = 0;          // atan2(tx, ty), if the xform needs it
    double sina = 0, cosa = 0;  // tx / sqrt, ty / sqrt, if the xform needs them
    double atanYX = 0;          // atan2(ty, tx), if the xform needs it
    double px = 0, py = 0;      // the sum of the terms

    void add(double x, double y)
    {
        px += x;
        py += y;
    }
};

// px, py += w * V_id(tx, ty), as flam3's varN_... functions. P: the xform's parameters by
// Param id, K: its constants by Const id, pre: its pre-affine (which waves, rings, fan and
// popcorn read).
void addTerm(int id, double w, Point &s, const double *P, const double *K, const Affine2 &pre,
             Xoshiro256 &rng);

} // namespace awb::flame::detail
