#pragma once
// Off-GUI-thread rendering of an attractor into a QImage (the heavy half of AttractorView).
// Two kinds of request:
//  - Full: drawn progressively, a coarse level first for quick feedback, then the full one.
//    A newer request cancels it through the core's cancel flag (latest wins).
//  - Refine: as Full without the coarse level, for a picture whose interactive pass is shown.
//  - Interactive (during a gesture: a drag, a slider, an animation): one pass, the best level
//    (depth or sample count) whose predicted time fits the frame budget. It is short, so a
//    newer request does not cancel it: the newer one waits as the only pending request, and
//    every interactive pass ends in a picture. A drag thus shows a new picture per frame the
//    engine can draw, instead of cancelling each render before it ends.
// Results are delivered in request order and never older than one already delivered; a
// cancelled request delivers nothing more. Only Full requests make the renderer "busy"
// (progress bars, the "Rendering…" note): an interactive pass is a frame, not a job.
// Every pass is render/AttractorImage's renderAttractorImage(): the one raster engine.

#include "gui/views/ThreadInbox.h"
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

// The time of a pass as a function of its work (images or samples) at one picture size:
// ms = fixed + perUnit * work, fitted by least squares to the latest passes (the fixed part is
// clearing, tone mapping and converting the picture). Thread-safe.
class PassCostModel {
public:
    void add(double work, double ms, QSize size);
    // The predicted milliseconds, or a negative number when nothing was measured at `size`.
    double predict(double work, QSize size) const;
    // The largest work whose predicted time fits `budgetMs` (-1 when nothing was measured).
    double workWithin(double budgetMs, QSize size) const;

private:
    struct Sample {
        double work, ms;
    };
    bool fit(double *fixed, double *perUnit) const; // under m_mutex
    mutable std::mutex m_mutex;
    QSize m_size;
    std::vector<Sample> m_samples; // the latest kept first-in first-out
};

class AttractorRenderer : public QObject {
    Q_OBJECT
public:
    // Sinks a vector export of random mode feeds (any count gives the raster's points: the
    // core always runs kChaosStreams streams, core/ifs/Random.h).
    static constexpr int kRandomStreams = 4;
    // The default time an interactive pass may take: a 60 Hz frame less the GUI thread's part.
    static constexpr double kDefaultFrameBudgetMs = 12.0;

    enum class Quality { Full, Refine, Interactive };

    explicit AttractorRenderer(QObject *parent = nullptr);
    ~AttractorRenderer() override;

    // Starts rendering `request`. A request cancels whatever runs, unless that is an
    // interactive pass, which ends first; `tag` comes back in RenderInfo::tag.
    void request(const RenderRequest &request, Quality quality = Quality::Full,
                 std::uint64_t tag = 0);
    // Stops the running render (nothing further is emitted for any request made so far).
    void cancel();
    // True while a Full or Refine request is pending or running.
    bool isBusy() const { return m_busy; }
    // Whether an interactive pass is being drawn now (for tests).
    bool drawingInteractive() const;
    void setFrameBudget(double ms) { m_budgetMs = ms; }
    double frameBudget() const { return m_budgetMs; }
    // The level an interactive pass of `request` draws: its depth (deterministic) or sample
    // count (random), chosen by the cost model of the passes drawn so far.
    int interactiveDepth(const RenderRequest &request) const;
    std::uint64_t interactiveSamples(const RenderRequest &request) const;

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
        Quality quality = Quality::Full;
        std::uint64_t tag = 0;
    };
    void workerLoop();
    void runJob(const Job &job);
    // Queues `fn` to the GUI thread, run unless a newer result was delivered or a cancel came
    // after the request.
    void post(std::uint64_t serial, std::function<void()> fn);
    void setBusy(bool busy);

    ThreadInbox m_inbox{this};  // before m_thread: outlives the worker
    std::thread m_thread;
    mutable std::mutex m_mutex;
    std::condition_variable m_wake;
    std::optional<Job> m_pending;   // guarded by m_mutex
    bool m_runningCancellable = false; // guarded by m_mutex
    bool m_runningInteractive = false; // guarded by m_mutex
    bool m_stop = false;            // guarded by m_mutex
    std::atomic<bool> m_cancel{false};
    std::atomic<double> m_budgetMs{kDefaultFrameBudgetMs};
    PassCostModel m_deterministicCost, m_randomCost;
    // GUI thread:
    std::uint64_t m_serial = 0;       // the latest request
    std::uint64_t m_floor = 1;        // results of requests below this are dropped (cancel)
    std::uint64_t m_delivered = 0;    // the newest request whose result was shown
    std::uint64_t m_busySerial = 0;   // the Full request that makes the renderer busy
    bool m_busy = false;
};

} // namespace awb

Q_DECLARE_METATYPE(awb::RenderInfo)
