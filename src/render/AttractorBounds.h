#pragma once
// How much of the plane an attractor takes (layer 3, render): the one rule by which a figure
// file (render/FigureRenderer) and the window's view (AttractorView's fit) frame an attractor.
// A shallow level of deterministic iteration with at most 50 000 images (an automaton: its
// start set), a chaos-game sample of at most 20 000 points in random mode, or the box of 99%
// of the invariant measure for maps that contract only on average (a flame: its tails are not
// bounded).

#include "core/ifs/Attractor.h"
#include "core/render/CustomChaos.h"

#include <QRectF>

#include <functional>
#include <optional>
#include <vector>

namespace awb {

struct AttractorExtent {
    const Ifs *ifs = nullptr;  // maps and views (may have no maps when `iterate` is set)
    std::vector<Projection> views;  // how IFS points are drawn (default: ifs->views)
    // An automaton's own iteration (CIFS, junction curves), as DerivedIfs::iterate.
    std::function<IterationStats(const StartSet &, int, const std::vector<AttractorSink *> &,
                                 const IterationControl &)>
        iterate;
    // A chaos game of the item's own (a flame): its frame, when it has one, is the extent.
    CustomChaos chaos;
    StartSet start;
    int depth = 0;     // the level drawn (the bounds use at most it)
    bool random = false;
    std::uint64_t samples = 0;
    std::uint64_t seed = 1;
};

// The plane box of the attractor's points as drawn (with the start set's vertices in
// deterministic mode); nullopt when there is no attractor or nothing finite.
std::optional<QRectF> attractorBounds(const AttractorExtent &a);

} // namespace awb
