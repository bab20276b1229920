#pragma once
// Off-GUI-thread rendering of an attractor into a QImage (the heavy half of AttractorView).
// A request is drawn progressively: a coarse level first for quick feedback, then the full one.
// A newer request cancels the running one through the core's cancel flag, so dragging a
// control point never queues up stale renders. The core streams images into per-thread
// RasterSinks (merged at the end): memory is bounded by the raster size, not by the depth.

#include "core/ifs/Attractor.h"

#include <QColor>
#include <QImage>
#include <QList>
#include <QObject>
#include <QRectF>
#include <QSize>

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>

namespace awb {

enum class AttractorColorMode {
    ByMap,      // colour of the outermost map (which of the N pieces a pixel lies in)
    ByAddress,  // gradient over the address prefix of length prefixLength (curve order)
    Single      // one colour
};

// Streams F^depth of an attractor that is not that of one IFS (an automaton's state) to the
// sinks, like awb::iterateParallel (model/AttractorItem.h, DerivedIfs::iterate).
using CustomIterate = std::function<IterationStats(const StartSet &, int,
                                                   const std::vector<AttractorSink *> &,
                                                   const IterationControl &)>;

struct RenderRequest {
    enum class Mode { Deterministic, Random };

    std::shared_ptr<const Ifs> ifs;   // with `iterate`: only its views are used
    CustomIterate iterate;            // set for automata: deterministic depth only
    StartSet start;                 // in the IFS space (n x D)
    Mode mode = Mode::Deterministic;
    int depth = 10;                 // deterministic: F^depth(start)
    std::uint64_t samples = 200000; // random: chaos-game samples from the first start vertex
    std::uint64_t seed = 1;
    QRectF world;                   // shown rectangle of the plane, y up (x0, y0, w, h)
    QSize size;                     // image size in pixels
    AttractorColorMode colorMode = AttractorColorMode::ByMap;
    int prefixLength = 2;           // 1..3, for ByAddress
    QList<QColor> palette;          // ByMap: one per map; ByAddress: gradient stops; Single: [0]
    // Lit pixels are grown by this many pixels (0..4) so that a thin curve stays visible;
    // where grown pixels meet, the smaller label wins, as in the raster itself.
    int dotRadius = 0;
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
};

class AttractorRenderer : public QObject {
    Q_OBJECT
public:
    // Random mode always uses this many independent chaos-game streams, whatever the machine:
    // samples and seeds are split per stream, so a fixed count keeps equal requests
    // pixel-identical (and lets a vector export reproduce the raster's points).
    static constexpr int kRandomStreams = 4;

    explicit AttractorRenderer(QObject *parent = nullptr);
    ~AttractorRenderer() override;

    // Starts rendering `request`, cancelling any running render. Results of cancelled
    // requests are never emitted.
    void request(const RenderRequest &request);
    // Stops the running render (nothing further is emitted for it).
    void cancel();
    bool isBusy() const { return m_busy; }

    // The full-depth image of `request`, computed synchronously on the calling thread with
    // the same code (and so the same pixels) as the asynchronous path. `control` may cancel it
    // (then the image is null) and reports progress. Throws InputError.
    static QImage renderNow(const RenderRequest &request, RenderInfo *info = nullptr,
                            const IterationControl &control = {});

    // Default qualitative colours for maps and the default address gradient.
    static QColor mapColor(int i);
    static QList<QColor> defaultGradient();
    // The colour of an image with this address (address[0] = outermost map), as the raster
    // colours it: vector drawings of shallow levels use it to match the raster.
    static QColor addressColor(AttractorColorMode mode, int prefixLength,
                               const QList<QColor> &palette, int maps,
                               const std::uint8_t *address, int length);

signals:
    void imageReady(const QImage &image, const awb::RenderInfo &info);
    void progress(double fraction);
    void failed(const QString &message);
    void busyChanged(bool busy);

private:
    struct Job {
        RenderRequest request;
        std::uint64_t serial = 0;
    };
    void workerLoop();
    void runJob(const Job &job);
    void post(std::uint64_t serial, std::function<void()> fn);

    std::thread m_thread;
    std::mutex m_mutex;
    std::condition_variable m_wake;
    std::optional<Job> m_pending;   // guarded by m_mutex
    bool m_stop = false;            // guarded by m_mutex
    std::atomic<bool> m_cancel{false};
    std::uint64_t m_serial = 0;     // GUI thread: the request whose results are wanted
    bool m_busy = false;            // GUI thread
};

} // namespace awb

Q_DECLARE_METATYPE(awb::RenderInfo)
