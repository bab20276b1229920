// AttractorView: the vector images of F^k(X0) (the Hutchinson step drawn over the raster)
// and the vector dots an export draws instead of the raster when there are few points.

#include "gui/views/AttractorView.h"

#include "gui/views/AttractorViewDetail.h"

#include <algorithm>
#include <memory>

namespace awb {

using namespace attractor_view;

void AttractorView::updateHutchinson()
{
    m_hutch.clear();
    m_hutchTooMany = false;
    if (m_hutchStep < 0 || !m_ifs || m_chaos)
        return;  // a flame's images are not those of its affine parts
    m_hutchTooMany = !vectorImages(m_hutchStep, kMaxHutchinsonVertices, &m_hutch);
}

bool AttractorView::vectorImages(int depth, std::size_t maxVertices,
                                 std::vector<VectorImage> *out) const
{
    out->clear();
    if (!m_ifs || m_ifs->size() == 0 || m_start.vertices.rows() == 0)
        return true;
    const double vertices = imageCount(*m_ifs, depth) * double(m_start.vertices.rows())
                            * double(m_ifs->views.size());
    if (vertices > double(maxVertices))
        return false;
    const RenderSettings &s = m_settings;
    const int maps = m_ifs->size();
    const auto &views = m_ifs->views;
    CallbackSink sink([&](const Mat &v, StartSet::Kind, const std::uint8_t *a, int n) {
        const QColor c = AttractorRenderer::addressColor(s.colouring, maps, a, n);
        for (const Projection &view : views)
            out->push_back({toPolygon(project(view, v)), c});
    });
    try {
        iterate(*m_ifs, m_start, depth, sink);
    } catch (const std::exception &) {
        // Bad input shows up through the renderer's failed() message; draw nothing here.
        out->clear();
    }
    return true;
}

bool AttractorView::randomVectorImages(std::size_t maxVertices,
                                       std::vector<VectorImage> *out) const
{
    out->clear();
    if (!m_ifs || m_start.vertices.rows() == 0)
        return true;
    // A flame's points are its own chaos game's, not the engine's on its affine parts: the
    // raster only.
    if (m_chaos || double(m_settings.samples) * double(m_ifs->views.size()) > double(maxVertices))
        return false;
    const RenderSettings &s = m_settings;
    const int maps = m_ifs->size();
    // One collector per stream, as in the renderer, so the dots are the raster's points.
    std::vector<std::vector<VectorImage>> parts(kRandomStreams);
    std::vector<std::unique_ptr<CallbackSink>> sinks;
    std::vector<AttractorSink *> raw;
    for (int t = 0; t < kRandomStreams; ++t) {
        sinks.push_back(std::make_unique<CallbackSink>(
            [&, t](const Mat &v, StartSet::Kind, const std::uint8_t *a, int n) {
                const QColor c = AttractorRenderer::addressColor(s.colouring, maps, a, n);
                for (const Projection &view : m_ifs->views)
                    parts[t].push_back({toPolygon(project(view, v)), c});
            }));
        raw.push_back(sinks.back().get());
    }
    ChaosOptions opt;
    opt.samples = s.samples;
    opt.seed = s.seed;
    opt.addressLength = std::clamp(s.colouring.prefixLength, 1, 3);
    try {
        chaosGameParallel(*m_ifs, m_start.vertices.row(0), opt, raw);
    } catch (const std::exception &) {
        return true;
    }
    for (auto &p : parts)
        out->insert(out->end(), p.begin(), p.end());
    return true;
}

} // namespace awb
