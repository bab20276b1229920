#include "core/render/Density.h"

#include "core/Messages.h"
#include "core/Types.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <mutex>
#include <type_traits>
#include <stdexcept>
#include <new>
#include <cstdlib>
#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace awb {

void RasterFrame::validate() const
{
    if (width < 1 || height < 1 || width > 32768 || height > 32768)
        throw InputError(formatMessage(
            coreTranslate("awb::render", "raster size must be between 1x1 and 32768x32768, got "
                                         "%1x%2"),
            width, height));
    if (supersample < 1 || supersample > 4)
        throw InputError(formatMessage(
            coreTranslate("awb::render", "supersampling must be 1 to 4 cells per pixel side, got "
                                         "%1"),
            supersample));
    if (double(cellsX()) * cellsY() > 1.2e9)
        throw InputError(coreTranslate("awb::render", "the supersampled raster would hold more "
                                                      "than 1.2e9 cells"));
    if (!(x1 > x0) || !(y1 > y0) || !std::isfinite(x1 - x0) || !std::isfinite(y1 - y0))
        throw InputError(coreTranslate("awb::render", "raster world rectangle is empty or not "
                                                      "finite"));
}

namespace {
constexpr std::size_t kHugePage = std::size_t(2) << 20;
}

void *allocateCells(std::size_t bytes)
{
    if (bytes < kHugePage)
        return ::operator new(bytes);
    const std::size_t rounded = (bytes + kHugePage - 1) / kHugePage * kHugePage;
    void *p = std::aligned_alloc(kHugePage, rounded);
    if (!p)
        throw std::bad_alloc();
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    madvise(p, rounded, MADV_HUGEPAGE);  // a hint: without huge pages, 4 KiB ones
#endif
    return p;
}

void freeCells(void *p, std::size_t bytes) noexcept
{
    if (bytes < kHugePage)
        ::operator delete(p);
    else
        std::free(p);
}

CellLayout CellLayout::labelPlanes(int labels, const std::vector<std::uint8_t> &coordinates)
{
    if (labels < 2 || labels > kMaxPlanes || coordinates.size() < std::size_t(labels))
        throw std::invalid_argument("CellLayout::labelPlanes: 2 to kMaxPlanes labels, each with "
                                    "its coordinate");
    CellLayout l;
    l.planes = labels;
    std::copy_n(coordinates.begin(), labels, l.coordinates.begin());
    return l;
}

DensityImage::DensityImage(int cellsX, int cellsY, Accumulation mode, CellLayout layout)
{
    reset(cellsX, cellsY, mode, layout);
}

void DensityImage::reset(int cellsX, int cellsY, Accumulation mode, CellLayout layout)
{
    if (layout.planes < 0 || layout.planes > CellLayout::kMaxPlanes)
        throw std::invalid_argument("DensityImage::reset: 0 to kMaxPlanes planes");
    if (layout.planes <= 1)
        layout.coordinates = {};  // one label's coordinate is 0; buckets keep their own
    m_w = cellsX;
    m_h = cellsY;
    m_size = std::size_t(cellsX) * std::size_t(cellsY);
    m_mode = mode;
    m_layout = layout;
    // The storage not used is released (a one-label picture after a coloured one, or back).
    auto fit = [](auto &cells, std::size_t n) {
        using Cells = std::remove_reference_t<decltype(cells)>;
        if (n == 0)
            Cells().swap(cells);
        else if (cells.size() == n)
            std::memset(static_cast<void *>(cells.data()), 0, n * sizeof(cells[0]));
        else
            cells.assign(n, typename Cells::value_type{});
    };
    fit(m_buckets, layout.planes == 0 ? m_size : 0);
    fit(m_counts, m_size * std::size_t(layout.planes));
    m_spilled.clear();
    m_room = fullRoom();
    offscreen = nonFinite = 0;
}

void DensityImage::sweep(std::size_t hits)
{
    if (hits > kSpillAt)
        throw std::length_error("DensityImage::reserve: more than kSpillAt hits in one batch");
    if (planes() > 0) {
        for (std::size_t j = 0; j < m_counts.size(); ++j)
            if (m_counts[j] >= kSpillAt) [[unlikely]]
                spill(j);
    } else {
        for (std::size_t i = 0; i < m_buckets.size(); ++i)
            if (m_buckets[i].n >= kSpillAt) [[unlikely]]
                spill(i);
    }
    m_room = fullRoom();
}

void DensityImage::spill(std::size_t i)
{
    if (planes() > 0) {
        m_spilled[i][0] += m_counts[i];
        m_counts[i] = 0;
        return;
    }
    DensityBucket &b = m_buckets[i];
    auto &s = m_spilled[i];
    s[0] += b.n;
    if (m_mode == Accumulation::Density) {
        s[1] += b.v;
        b.v = 0;
    }
    b.n = 0;
}

std::uint64_t DensityImage::stored(std::size_t j) const
{
    std::uint64_t n = planes() > 0 ? m_counts[j] : m_buckets[j].n;
    if (!m_spilled.empty()) {
        const auto it = m_spilled.find(j);
        if (it != m_spilled.end())
            n += it->second[0];
    }
    return n;
}

std::array<double, 2> DensityImage::cell(std::size_t i) const
{
    if (planes() > 0) {
        // Plane l holds label l's hits: the coordinate sum is sum_l n_l c_l (density; one
        // label: 0), the label word 1 + the first label hit (hits). Exact below 2^53.
        std::uint64_t n = 0, sum = 0;
        std::uint32_t first = 0;
        for (int l = planes() - 1; l >= 0; --l) {
            const std::uint64_t nl = stored(planeIndex(i, std::uint32_t(l)));
            n += nl;
            sum += nl * m_layout.coordinates[std::size_t(l)];
            if (nl > 0)
                first = std::uint32_t(l) + 1;
        }
        return {double(n), m_mode == Accumulation::Hits ? double(first) : double(sum)};
    }
    const DensityBucket &b = m_buckets[i];
    std::array<double, 2> out{double(b.n), double(b.v)};
    if (!m_spilled.empty()) {
        const auto it = m_spilled.find(i);
        if (it != m_spilled.end()) {
            out[0] += double(it->second[0]);
            if (m_mode == Accumulation::Density)
                out[1] += double(it->second[1]);
        }
    }
    return out;
}

std::uint64_t DensityImage::count(std::size_t i) const
{
    if (planes() == 0)
        return stored(i);
    std::uint64_t n = 0;
    for (int l = 0; l < planes(); ++l)
        n += stored(planeIndex(i, std::uint32_t(l)));
    return n;
}

std::uint64_t DensityImage::litCells() const
{
    std::uint64_t lit = 0;
    if (planes() > 0) {
        for (std::size_t i = 0; i < m_size; ++i) {
            bool hit = false;
            for (int l = 0; l < planes() && !hit; ++l) {
                const std::size_t j = planeIndex(i, std::uint32_t(l));
                hit = m_counts[j] != 0 || m_spilled.count(j);
            }
            lit += hit;
        }
        return lit;
    }
    for (std::size_t i = 0; i < m_buckets.size(); ++i)
        lit += (m_buckets[i].n != 0 || (m_buckets[i].v != 0 && m_mode == Accumulation::Hits)
                || m_spilled.count(i));
    return lit;
}

void DensityImage::merge(const DensityImage &o)
{
    mergeCells(o, 0, size());
    mergeRest(o);
}

void DensityImage::mergeCells(const DensityImage &o, std::size_t first, std::size_t last)
{
    addCells<false>(o, first, last);
}

void DensityImage::takeCells(DensityImage &o, std::size_t first, std::size_t last)
{
    addCells<true>(o, first, last);
}

template <bool Take, class Source>
void DensityImage::addCells(Source &o, std::size_t first, std::size_t last)
{
    if (o.m_w != m_w || o.m_h != m_h || o.m_mode != m_mode || !(o.m_layout == m_layout))
        throw InputError(coreTranslate("awb::render", "cannot merge density images of different "
                                                      "sizes or modes"));
    if (planes() > 0) {
        // The cells [first, last) of every plane.
        last = std::min(last, m_size);
        for (int l = 0; l < planes(); ++l)
            addCounts<Take>(o, planeIndex(first, std::uint32_t(l)),
                            planeIndex(std::max(first, last), std::uint32_t(l)));
        return;
    }
    last = std::min(last, m_buckets.size());
    auto add = [&](std::size_t i) {
        DensityBucket src = o.m_buckets[i];
        if (src.n == 0 && src.v == 0)
            return;
        if constexpr (Take)
            o.m_buckets[i] = DensityBucket{};
        DensityBucket &dst = m_buckets[i];
        // Every bucket stays below kSpillAt here too (reserve()): when the sum would reach it,
        // this bucket spills, and a source bucket of kSpillAt or more hits (up to 2^24 after
        // unchecked hits) goes to the spilled sums whole (its label, in hits mode, still
        // merges below).
        if (std::uint64_t(dst.n) + src.n >= kSpillAt) [[unlikely]] {
            const bool density = m_mode == Accumulation::Density;
            if (spillForMerge(i, src.n, density ? src.v : 0)) {
                src.n = 0;
                if (density)
                    src.v = 0;
            }
        }
        dst.n += src.n;
        if (m_mode == Accumulation::Density)
            dst.v += src.v;
        else if (src.v != 0 && (dst.v == 0 || src.v < dst.v))
            dst.v = src.v;
    };
    // Most cells of a curve's histogram are empty: skip them four at a time.
    std::size_t i = first;
    for (; i < last && i % 4 != 0; ++i)
        add(i);
    for (; i + 4 <= last; i += 4) {
        std::uint64_t w[4];
        std::memcpy(w, static_cast<const void *>(&o.m_buckets[i]), sizeof w);
        if ((w[0] | w[1] | w[2] | w[3]) == 0)
            continue;
        for (std::size_t k = i; k < i + 4; ++k)
            add(k);
    }
    for (; i < last; ++i)
        add(i);
}

bool DensityImage::spillForMerge(std::size_t i, std::uint32_t n, std::uint32_t sum)
{
    // Rare; the map of spilled sums is shared by the threads merging other ranges.
    static std::mutex spilling;
    std::lock_guard lock(spilling);
    spill(i);
    if (n < kSpillAt)
        return false;
    auto &s = m_spilled[i];
    s[0] += n;
    s[1] += sum;
    return true;
}

template <bool Take, class Source>
void DensityImage::addCounts(Source &o, std::size_t first, std::size_t last)
{
    last = std::min(last, m_counts.size());
    std::uint32_t *dst = m_counts.data();
    auto *src = o.m_counts.data();
    for (std::size_t i = first; i < last; ++i) {
        std::uint32_t n = src[i];
        if (n == 0)
            continue;
        if constexpr (Take)
            src[i] = 0;
        // As in addCells: every count stays below kSpillAt.
        if (std::uint64_t(dst[i]) + n >= kSpillAt && spillForMerge(i, n, 0)) [[unlikely]]
            n = 0;
        dst[i] += n;
    }
}

void DensityImage::mergeRest(const DensityImage &o)
{
    for (const auto &[i, s] : o.m_spilled) {
        auto &d = m_spilled[i];
        for (int k = 0; k < 2; ++k)
            d[k] += s[k];
        if (m_mode == Accumulation::Hits && planes() == 0 && m_buckets[i].v == 0)
            m_buckets[i].v = o.m_buckets[i].v;
    }
    offscreen += o.offscreen;
    nonFinite += o.nonFinite;
}

void DensityImage::takeRest(DensityImage &o)
{
    mergeRest(o);
    o.m_spilled.clear();
    o.m_room = o.fullRoom();
    o.offscreen = o.nonFinite = 0;
}

void DensityImage::clear()
{
    std::fill(m_buckets.begin(), m_buckets.end(), DensityBucket{});
    std::fill(m_counts.begin(), m_counts.end(), 0u);
    m_spilled.clear();
    m_room = fullRoom();
    offscreen = nonFinite = 0;
}

namespace {

// flam3_calc_alpha: x^g, with a linear blend below linRange so that the curve has a finite
// slope at 0 (faint pixels neither vanish nor explode).
double calcAlpha(double density, double g, double linRange)
{
    if (density <= 0)
        return 0;
    if (density >= linRange)
        return std::pow(density, g);
    const double frac = density / linRange;
    const double funcval = std::pow(linRange, g);
    return (1.0 - frac) * density * (funcval / linRange) + frac * std::pow(density, g);
}

std::uint32_t packPremultiplied(double a, double r, double g, double b)
{
    auto byte = [](double v) {
        return std::uint32_t(std::clamp(std::lround(v * 255.0), 0L, 255L));
    };
    a = std::clamp(a, 0.0, 1.0);
    // Premultiplied: no channel may exceed alpha.
    r = std::min(r, a), g = std::min(g, a), b = std::min(b, a);
    return (byte(a) << 24) | (byte(r) << 16) | (byte(g) << 8) | byte(b);
}

} // namespace

std::vector<std::uint8_t> labelCoordinates(std::size_t labels)
{
    std::vector<std::uint8_t> c(std::max<std::size_t>(1, labels), 0);
    if (labels > 1)
        for (std::size_t l = 0; l < labels; ++l)
            c[l] = std::uint8_t(std::lround(255.0 * double(l) / double(labels - 1)));
    return c;
}

std::vector<Rgb8> colourRamp(const std::vector<Rgb8> &labels)
{
    std::vector<Rgb8> ramp(256);
    if (labels.empty())
        return ramp;
    const double last = double(labels.size() - 1);
    for (int u = 0; u < 256; ++u) {
        const double x = labels.size() > 1 ? u / 255.0 * last : 0.0;
        const auto i = std::min(std::size_t(x), labels.size() - 1);
        const std::size_t j = std::min(i + 1, labels.size() - 1);
        const double t = x - double(i);
        auto mix = [t](std::uint8_t a, std::uint8_t b) {
            return std::uint8_t(std::lround(a + t * (double(b) - double(a))));
        };
        ramp[u] = {mix(labels[i].r, labels[j].r), mix(labels[i].g, labels[j].g),
                   mix(labels[i].b, labels[j].b)};
    }
    return ramp;
}

std::vector<std::uint32_t> toneMap(const DensityImage &image, const RasterFrame &frame,
                                   const ToneSettings &tone, const std::vector<Rgb8> &labels)
{
    std::vector<std::uint32_t> out(std::size_t(frame.width) * frame.height);
    toneMapInto(image, frame, tone, labels, out.data());
    return out;
}

namespace {

// One output pixel's sums over its ss x ss cells: {n, n r, n g, n b} (densitySums).
struct PixelSummer {
    const DensityImage &image;
    const std::vector<Rgb8> &labels;
    std::vector<Rgb8> ramp;
    int cw, ss;
    bool hitsImage;

    PixelSummer(const DensityImage &image, const RasterFrame &frame,
                const std::vector<Rgb8> &labels)
        : image(image), labels(labels), ramp(colourRamp(labels)), cw(image.cellsX()),
          ss(frame.supersample), hitsImage(image.mode() == Accumulation::Hits)
    {
        if (image.cellsX() != frame.width * ss || image.cellsY() != frame.height * ss)
            throw InputError(
                coreTranslate("awb::render", "density image does not match its frame"));
    }
    // The hits of the pixel alone.
    double count(int x, int y) const
    {
        double n = 0;
        for (int sy = 0; sy < ss; ++sy)
            for (int sx = 0; sx < ss; ++sx)
                n += std::max(0.0, image.cell(std::size_t(y * ss + sy) * cw + (x * ss + sx))[0]);
        return n;
    }
    std::array<double, 4> operator()(int x, int y) const
    {
        std::array<double, 4> s{0, 0, 0, 0};
        for (int sy = 0; sy < ss; ++sy)
            for (int sx = 0; sx < ss; ++sx) {
                const auto c = image.cell(std::size_t(y * ss + sy) * cw + (x * ss + sx));
                if (c[0] <= 0)
                    continue;
                Rgb8 colour;
                if (!hitsImage)
                    colour = ramp[std::size_t(std::clamp(std::lround(c[1] / c[0]), 0L, 255L))];
                else if (!labels.empty())
                    colour = labels[std::min(std::size_t(c[1]) - 1, labels.size() - 1)];
                s[0] += c[0];
                s[1] += c[0] * colour.r, s[2] += c[0] * colour.g, s[3] += c[0] * colour.b;
            }
        return s;
    }
};

} // namespace

std::vector<std::array<double, 4>> densitySums(const DensityImage &image,
                                               const RasterFrame &frame,
                                               const std::vector<Rgb8> &labels)
{
    const PixelSummer sums(image, frame, labels);
    const int W = frame.width, H = frame.height;
    std::vector<std::array<double, 4>> px(std::size_t(W) * H);
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x)
            px[std::size_t(y) * W + x] = sums(x, y);
    return px;
}

std::vector<float> densityChannels(const DensityImage &image, const RasterFrame &frame,
                                   const std::vector<Rgb8> &labels)
{
    const std::vector<std::array<double, 4>> px = densitySums(image, frame, labels);
    std::vector<float> out(4 * px.size());
    for (std::size_t i = 0; i < px.size(); ++i) {
        out[4 * i + 0] = float(px[i][1] / 255.0);
        out[4 * i + 1] = float(px[i][2] / 255.0);
        out[4 * i + 2] = float(px[i][3] / 255.0);
        out[4 * i + 3] = float(px[i][0]);
    }
    return out;
}

void toneMapInto(const DensityImage &image, const RasterFrame &frame, const ToneSettings &tone,
                 const std::vector<Rgb8> &labels, std::uint32_t *out)
{
    const int W = frame.width, H = frame.height, ss = frame.supersample;
    if (image.cellsX() != W * ss || image.cellsY() != H * ss)
        throw InputError(coreTranslate("awb::render", "density image does not match its frame"));
    std::fill(out, out + std::size_t(W) * H, 0u);
    const double cellsPerPixel = double(ss) * ss;
    const int cw = image.cellsX();
    const std::vector<Rgb8> ramp = colourRamp(labels);
    const bool hitsImage = image.mode() == Accumulation::Hits;
    // The colour of one lit cell: its label's (hits) or the ramp at its mean coordinate.
    auto colourOf = [&](const std::array<double, 2> &c) {
        if (hitsImage) {
            if (labels.empty())
                return Rgb8{};
            const auto label = std::size_t(c[1]) - 1;
            return labels[std::min(label, labels.size() - 1)];
        }
        return ramp[std::size_t(std::clamp(std::lround(c[1] / c[0]), 0L, 255L))];
    };

    if (hitsImage && ss == 1 && !image.hasSpills()) {
        // One cell per pixel, hit or not (the view's live drags): each label's opaque pixel
        // packed once, then one bucket read per pixel.
        std::vector<std::uint32_t> packed(std::max<std::size_t>(1, labels.size()),
                                          packPremultiplied(1.0, 0.0, 0.0, 0.0));
        for (std::size_t l = 0; l < labels.size(); ++l)
            packed[l] = packPremultiplied(1.0, labels[l].r / 255.0, labels[l].g / 255.0,
                                          labels[l].b / 255.0);
        const std::size_t last = packed.size() - 1;
        const std::size_t n = std::size_t(W) * H;
        if (image.planes() > 0) {
            // The first plane that counts a cell gives its label (one label: plane 0).
            const std::uint32_t *c = image.counts();
            for (int l = image.planes() - 1; l >= 0; --l) {
                const std::uint32_t *plane = c + std::size_t(l) * n;
                const std::uint32_t colour = packed[std::min(std::size_t(l), last)];
                for (std::size_t i = 0; i < n; ++i)
                    if (plane[i] != 0)
                        out[i] = colour;
            }
            return;
        }
        const DensityBucket *b = image.buckets();
        for (std::size_t i = 0; i < n; ++i)
            if (b[i].n != 0)
                out[i] = packed[std::min(std::size_t(b[i].v) - 1, last)];
        return;
    }
    if (tone.mode == Accumulation::Hits || hitsImage) {
        for (int y = 0; y < H; ++y)
            for (int x = 0; x < W; ++x) {
                double lit = 0, r = 0, g = 0, b = 0;
                for (int sy = 0; sy < ss; ++sy)
                    for (int sx = 0; sx < ss; ++sx) {
                        const auto c = image.cell(std::size_t(y * ss + sy) * cw + (x * ss + sx));
                        if (c[0] <= 0)
                            continue;
                        const Rgb8 colour = colourOf(c);
                        lit += 1;
                        r += colour.r, g += colour.g, b += colour.b;
                    }
                if (lit == 0)
                    continue;
                const double a = lit / cellsPerPixel;
                out[std::size_t(y) * W + x] =
                    packPremultiplied(a, a * r / lit / 255.0, a * g / lit / 255.0,
                                      a * b / lit / 255.0);
            }
        return;
    }

    // Density: box-filter the cells into pixels (counts and colours weighted by count), then
    // log-scale against the densest pixel -- two passes over the cells, no image of sums (a
    // megapixel's would be 32 MB to fault in, a third of a short render's time).
    const PixelSummer sums(image, frame, labels);
    double maxCount = 0;
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x)
            maxCount = std::max(maxCount, sums.count(x, y));
    if (maxCount <= 0)
        return;
    const double g = 1.0 / std::max(0.1, tone.gamma);
    const double vib = std::clamp(tone.vibrancy, 0.0, 1.0);
    const double norm = 1.0 / std::log1p(maxCount);
    for (std::size_t i = 0; i < std::size_t(W) * H; ++i) {
        const int x = int(i % std::size_t(W)), y = int(i / std::size_t(W));
        const auto s = sums(x, y);
        if (s[0] <= 0)
            continue;
        // Log density in (0, 1], the densest pixel at 1.
        const double density = std::min(1.0, tone.brightness * std::log1p(s[0]) * norm);
        const double alpha = calcAlpha(density, g, tone.linearRange);
        double rgb[3];
        for (int k = 0; k < 3; ++k) {
            const double mean = s[k + 1] / s[0] / 255.0;  // the pixel's mean colour
            rgb[k] = vib * alpha * mean
                     + (1.0 - vib) * calcAlpha(density * mean, g, tone.linearRange);
        }
        out[i] = packPremultiplied(alpha, rgb[0], rgb[1], rgb[2]);
    }
}

void dilate(std::uint32_t *argb, int width, int height, int r)
{
    if (r <= 0 || width <= 0 || height <= 0)
        return;
    // Each output pixel takes the most opaque pixel of its (2r+1)^2 window, the first in
    // row-major order on a tie (separably: the leftmost along a row, then the topmost), and
    // lit pixels keep their own colour. Most of a picture is empty: the row pass visits only
    // lit pixels and spreads each to its window (ascending order, replacing only a strictly
    // more opaque one: the leftmost wins), and the column pass skips rows with nothing lit
    // within r. The buffers stay with the thread (a drag draws many pictures).
    const auto alpha = [](std::uint32_t c) { return c >> 24; };
    const std::size_t w = std::size_t(width);
    static thread_local std::vector<std::uint32_t> tmp;
    static thread_local std::vector<std::uint8_t> rowLit;
    if (tmp.size() < w * std::size_t(height))
        tmp.resize(w * std::size_t(height));
    rowLit.assign(std::size_t(height), 0);
    for (int y = 0; y < height; ++y) {
        const std::uint32_t *row = argb + std::size_t(y) * w;
        std::uint32_t *out = tmp.data() + std::size_t(y) * w;
        bool any = false;
        for (int x = 0; x < width; ++x) {
            if (!alpha(row[x]))
                continue;
            if (!any) {
                std::fill(out, out + w, 0u);
                any = true;
            }
            for (int k = std::max(0, x - r), e = std::min(width - 1, x + r); k <= e; ++k)
                if (alpha(row[x]) > alpha(out[k]))
                    out[k] = row[x];
        }
        rowLit[std::size_t(y)] = any;
    }
    for (int y = 0; y < height; ++y) {
        const int k0 = std::max(0, y - r), k1 = std::min(height - 1, y + r);
        bool near = false;
        for (int k = k0; k <= k1 && !near; ++k)
            near = rowLit[std::size_t(k)] != 0;
        if (!near)
            continue;
        std::uint32_t *dst = argb + std::size_t(y) * w;
        for (int x = 0; x < width; ++x) {
            if (alpha(dst[x]))
                continue;  // lit pixels keep their own colour
            std::uint32_t best = 0;
            for (int k = k0; k <= k1; ++k)
                if (rowLit[std::size_t(k)]) {
                    const std::uint32_t c = tmp[std::size_t(k) * w + std::size_t(x)];
                    if (alpha(c) > alpha(best))
                        best = c;
                }
            dst[x] = best;
        }
    }
}

} // namespace awb
