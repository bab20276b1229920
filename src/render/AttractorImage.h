#pragma once
// The picture of a curve attractor as a QImage: the one raster path of the application. The
// attractor view (asynchronously, through gui/views/AttractorRenderer), `attractor-cli render`,
// export, print, the figure sheet and the benches all call renderAttractorImage(), which runs
// the core engine (core/render/Engine.h) into a density histogram and tone-maps it
// (core/render/Density.h). Layer: render (QtGui, no widgets).

#include "core/ifs/Attractor.h"
#include "core/render/CustomChaos.h"
#include "core/render/Density.h"

#include <QColor>
#include <QImage>
#include <QList>
#include <QRectF>
#include <QSize>

#include <functional>
#include <memory>

namespace awb {

enum class AttractorColorMode {
    ByMap,      // colour of the outermost map (which of the N pieces a pixel lies in)
    ByAddress,  // gradient over the address prefix of length prefixLength (curve order)
    Single      // one colour
};

// How an attractor's images are coloured: the one description the raster (RenderRequest), the
// views' settings, export and `attractor-cli render` share, read from an item's style by
// attractorColouring(). An empty palette means the application's own colours.
struct AttractorColouring {
    AttractorColorMode mode = AttractorColorMode::ByMap;
    int prefixLength = 1;  // 1..3 address symbols, for ByAddress
    QList<QColor> palette; // ByMap: one per map; ByAddress: gradient stops; Single: [0]
    bool operator==(const AttractorColouring &) const = default;
};

// Streams F^k of an attractor that is not that of one IFS (an automaton's state) to the
// sinks, like awb::iterateParallel (model/AttractorItem.h, DerivedIfs::iterate).
using CustomIterate = std::function<IterationStats(const StartSet &, int,
                                                   const std::vector<AttractorSink *> &,
                                                   const IterationControl &)>;

struct RenderRequest {
    enum class Mode { Deterministic, Random };

    std::shared_ptr<const Ifs> ifs;   // with `iterate`: only its views are used
    CustomIterate iterate;            // set for automata: deterministic depth only
    // Set for items with a chaos game of their own (a flame): random mode plays it, in its own
    // colours, instead of the engine's on `ifs`.
    CustomChaos chaos;
    StartSet start;                 // in the IFS space (n x D)
    Mode mode = Mode::Deterministic;
    int depth = 10;                 // deterministic: F^depth(start)
    std::uint64_t samples = 200000; // random: chaos-game samples from the first start vertex
    std::uint64_t seed = 1;
    QRectF world;                   // shown rectangle of the plane, y up (x0, y0, w, h)
    QSize size;                     // image size in pixels
    AttractorColouring colouring;
    // Lit pixels are grown by this many pixels (0..4) so that a thin curve stays visible.
    int dotRadius = 0;
    // Hits (crisp, every lit pixel opaque: the papers' look) or density (log-density tone
    // mapping: the invariant measure made visible), gamma and vibrancy.
    ToneSettings tone;
    int supersample = 1;            // 1..4 histogram cells per pixel side (anti-aliasing)
    int threads = 0;                // 0: the machine's cores
    // The coarse pass stops at the depth (or sample count) giving at most this many images.
    double coarseImages = 30000;
};

struct RenderInfo {
    int depth = 0;                  // deterministic depth drawn (0 in random mode)
    double images = 0;              // start-set images (or samples) drawn
    double seconds = 0;             // wall time of this pass
    bool final = false;             // false for the coarse preview
    QRectF world;                   // the request's world rectangle (the image's extent)
    std::uint64_t litPixels = 0;    // pixels the attractor hit (before dotRadius growth)
    // Set by gui/views/AttractorRenderer: the caller's tag of the request, and whether the
    // pass was an interactive one (chosen to fit a frame budget during a gesture).
    std::uint64_t tag = 0;
    bool interactive = false;
};

// Throws InputError when the request cannot be drawn (no maps, a non-contractive IFS, an
// empty start set or image).
void checkRenderRequest(const RenderRequest &request);

// The picture of `request` at deterministic depth `depth` or with `samples` random samples
// (the request's own for the final picture). Unlit pixels are transparent. A null image when
// control.cancel stopped it. Throws InputError.
QImage renderAttractorImage(const RenderRequest &request, int depth, std::uint64_t samples,
                            RenderInfo *info = nullptr, const IterationControl &control = {});
inline QImage renderAttractorImage(const RenderRequest &request, RenderInfo *info = nullptr,
                                   const IterationControl &control = {})
{
    return renderAttractorImage(request, request.depth, request.samples, info, control);
}

// The raw density of a picture: the histogram of the request's final picture (density
// accumulation, whatever its tone) as four floats a pixel (core densityChannels: R G B = hits
// times colour, A = hits), row 0 at the top. Empty rgba when control.cancel stopped it.
struct AttractorDensity {
    RasterFrame frame;
    std::vector<float> rgba;
    double images = 0;
};
AttractorDensity renderAttractorDensity(const RenderRequest &request,
                                        const IterationControl &control = {});

struct StyleSpec;  // model/ItemValues.h

// The colouring of an item's style (color_by, prefix_length, colors).
AttractorColouring attractorColouring(const StyleSpec &style);

// Default qualitative colours for maps and the default address gradient.
QColor attractorMapColor(int i);
QList<QColor> defaultAddressGradient();
// The colour of an image with this address (address[0] = outermost map), as the raster
// colours it: vector drawings of shallow levels use it to match the raster.
QColor attractorAddressColor(AttractorColorMode mode, int prefixLength,
                             const QList<QColor> &palette, int maps,
                             const std::uint8_t *address, int length);
inline QColor attractorAddressColor(const AttractorColouring &c, int maps,
                                    const std::uint8_t *address, int length)
{
    return attractorAddressColor(c.mode, c.prefixLength, c.palette, maps, address, length);
}

} // namespace awb
