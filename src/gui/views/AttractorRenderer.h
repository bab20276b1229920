#pragma once
// Off-GUI-thread rendering of an attractor into a QImage (the heavy half of AttractorView).
// A request is drawn progressively: a coarse level first for quick feedback, then the full one.
// A newer request cancels the running one through the core's cancel flag (latest wins), so
// dragging a control point never queues up stale renders and the GUI thread never waits.
// Every pass is render/AttractorImage's renderAttractorImage(): the one raster engine.

#include "render/AttractorImage.h"

#include <QObject>

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <mutex>
#include <optional>
#include <thread>

namespace awb {

class AttractorRenderer : public QObject {
    Q_OBJECT
public:
    // Sinks a vector export of random mode feeds (any count gives the raster's points: the
    // core always runs kChaosStreams streams, core/ifs/Random.h).
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
                            const IterationControl &control = {})
    {
        return renderAttractorImage(request, info, control);
    }

    // Default qualitative colours for maps and the default address gradient.
    static QColor mapColor(int i) { return attractorMapColor(i); }
    static QList<QColor> defaultGradient() { return defaultAddressGradient(); }
    // The colour of an image with this address (address[0] = outermost map), as the raster
    // colours it: vector drawings of shallow levels use it to match the raster.
    static QColor addressColor(const AttractorColouring &colouring, int maps,
                               const std::uint8_t *address, int length)
    {
        return attractorAddressColor(colouring, maps, address, length);
    }

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
