#pragma once
// The raster of the one attractor engine: a histogram of where the attractor's points (or the
// images of a start set) fall, with the colour each hit brings, and the tone mapping that
// turns it into pixels. Every raster picture of a curve attractor (the view, `render`, print,
// the figure sheet, the benches) goes through DensityImage and toneMap().
//
// Two ways to accumulate, chosen per picture:
// - Density: each hit adds 1 to the cell's count and its colour coordinate (0..255, the
//   position of its label's colour on the picture's colour ramp) to the cell's coordinate sum,
//   so the count is the invariant measure's mass in the cell (random iteration with the IFS's
//   probabilities, or N^-k per image of deterministic depth k) and the colour is the ramp at
//   the hit-weighted mean coordinate, as in flame renderers.
// - Hits: the cell keeps its count and the smallest colour label that hit it; the picture
//   is crisp (every lit pixel opaque, one label's exact colour), and independent of the order
//   of the hits, so a parallel render is pixel-identical to a serial one.
// Three ways to store them, chosen per picture; each gives the same picture, exactly:
// - Buckets, 8 bytes a cell: the count and the coordinate sum (density) or smallest label
//   (hits) of every hit, one 64-bit add per hit; any number of labels.
// - One plane of counts, 4 bytes a cell, when every hit carries label 0 (the engine's choice
//   for a picture whose labels all have one colour): a density cell's coordinate sum is 0, a
//   hits cell's label 0. The scattered hits touch half the memory.
// - Label planes: L <= kMaxPlanes planes of counts, plane l counting the hits of label l
//   (cell i of plane l at index l * size() + i). A cell's coordinate sum is sum_l n_l c_l
//   and its smallest label the first plane that counts it: the buckets' numbers, from 4 bytes
//   a hit. The random iteration's scattered hits then touch the cache lines of one colour's
//   counts where the labels' parts of the attractor do not overlap (the sub-copies of an IFS
//   coloured by map, the flame renderers' usual picture), instead of twice as many with
//   buckets, for 4 L bytes a cell in all.
//
// The tone mapping of density follows the log-density display of the fractal flame algorithm
// (S. Draves, E. Reckase, "The Fractal Flame Algorithm", 2003/2008, §4: log scaling, gamma,
// vibrancy) as flam3 implements it (rect.c: flam3_calc_alpha with a linear range near zero,
// then vibrancy mixing the alpha-gamma and the per-channel gamma), normalised here so that
// the densest pixel has log density 1. Qt-free: pixels are 0xAARRGGBB premultiplied.

#include <algorithm>
#include <array>
#include <bit>
#include <cstddef>
#include <cstring>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace awb {

struct Rgb8 {
    std::uint8_t r = 0, g = 0, b = 0;
};

// Picture rectangle: world [x0, x1] x [y0, y1] (y up) onto width x height output pixels, each
// made of supersample x supersample histogram cells.
struct RasterFrame {
    int width = 1, height = 1;
    double x0 = 0, y0 = 0, x1 = 1, y1 = 1;
    int supersample = 1;  // 1..4

    int cellsX() const { return width * supersample; }
    int cellsY() const { return height * supersample; }
    // Throws InputError for an empty, non-finite or oversized frame.
    void validate() const;
};

enum class Accumulation { Density, Hits };

// The allocator of a histogram's cells: blocks of 2 MiB or more are aligned to 2 MiB and
// offered to the kernel's transparent huge pages (madvise; Linux). The chaos game hits the
// cells in random order: with 4 KiB pages a coloured 1024 x 1024 histogram spans 2 048 pages,
// as many as the whole second-level TLB of this Zen 3 holds (64 in the first level), so hits
// miss the TLB; on 2 MiB pages it is 4 entries (measured: about 1.15x end to end).
void *allocateCells(std::size_t bytes);
void freeCells(void *p, std::size_t bytes) noexcept;

template <class T>
struct CellAllocator {
    using value_type = T;
    CellAllocator() = default;
    template <class U>
    CellAllocator(const CellAllocator<U> &) noexcept {}
    T *allocate(std::size_t n) { return static_cast<T *>(allocateCells(n * sizeof(T))); }
    void deallocate(T *p, std::size_t n) noexcept { freeCells(p, n * sizeof(T)); }
    template <class U>
    bool operator==(const CellAllocator<U> &) const noexcept { return true; }
};

struct DensityBucket {
    std::uint32_t n = 0;
    // Density: the sum of the hits' colour coordinates. Hits: 1 + the smallest label.
    std::uint32_t v = 0;
};

// How a histogram stores its hits' labels: 0 planes for buckets, 1 for one label, 2 to
// kMaxPlanes for label planes with the colour coordinate (0..255) of each plane's label.
struct CellLayout {
    static constexpr int kMaxPlanes = 4;
    int planes = 0;
    std::array<std::uint8_t, kMaxPlanes> coordinates{};

    static CellLayout buckets() { return {}; }
    static CellLayout oneLabel() { return {1, {}}; }
    // Planes for `labels` labels (2..kMaxPlanes), label l at coordinates[l]; throws
    // std::invalid_argument for another number of labels or too few coordinates.
    static CellLayout labelPlanes(int labels, const std::vector<std::uint8_t> &coordinates);
    bool operator==(const CellLayout &o) const = default;
};

class DensityImage {
public:
    DensityImage() = default;
    DensityImage(int cellsX, int cellsY, Accumulation mode, CellLayout layout = {});
    // Empties the image for a new picture of this size, reusing its memory when it fits (a
    // drag renders many pictures of one size: no allocation and no page faults each time).
    void reset(int cellsX, int cellsY, Accumulation mode, CellLayout layout = {});

    int cellsX() const { return m_w; }
    int cellsY() const { return m_h; }
    Accumulation mode() const { return m_mode; }
    const CellLayout &layout() const { return m_layout; }
    bool oneLabel() const { return m_layout.planes == 1; }
    // Planes of counts (one label or label planes), 0 for buckets.
    int planes() const { return m_layout.planes; }
    std::size_t size() const { return m_size; }

    // One hit of `label` at cell index i = y * cellsX + x (row 0 at the top), in any layout;
    // coordinates[label] is its colour coordinate, read by density buckets only. Labels past
    // the last plane count in it (the tone map gives them the last colour too).
    void add(std::size_t i, std::uint32_t label, const std::uint8_t *coordinates)
    {
        if (m_layout.planes > 0)
            addCount(planeIndex(i, std::min(label, std::uint32_t(m_layout.planes - 1))));
        else if (m_mode == Accumulation::Hits)
            addHit(i, label);
        else
            addDensity(i, coordinates[label]);
    }
    // Index j of cell i's count in the plane of `label` (< planes()).
    std::size_t planeIndex(std::size_t i, std::uint32_t label) const
    {
        return std::size_t(label) * m_size + i;
    }
    // The layouts' own hits: a count at index j of the planes (one label: j = i; label planes:
    // j = planeIndex(i, label)); the buckets' density or hit at cell i.
    void addCount(std::size_t j)
    {
        if (++m_counts[j] >= kSpillAt) [[unlikely]]
            spill(j);
    }
    void addDensity(std::size_t i, std::uint8_t coordinate)
    {
        if (addDensityWord(i, coordinate) >= kSpillAt) [[unlikely]]
            spill(i);
    }
    void addHit(std::size_t i, std::uint32_t label)
    {
        if (addHitWord(i, label) >= kSpillAt) [[unlikely]]
            spill(i);
    }

    // The hot loops' hits: reserve(n) announces at most n hits (n <= kSpillAt) that follow
    // without the per-hit overflow check. A check per hit is a branch on the loaded count,
    // which cannot retire before the load does, so it halves the rate of random updates
    // that miss the caches (measured: 324 vs 550 M/s of 1024^2 density updates). Instead,
    // every bucket is kept below kSpillAt by the checked adds, the merges and a sweep (which
    // spills the buckets at or above kSpillAt) before every kSpillAt unchecked hits: a bucket
    // then never exceeds 2 kSpillAt = 2^24 hits, whose coordinates (at most 255 each) sum
    // below 2^32. A plane's count carries no sum: kCountRoom unchecked hits keep it below
    // 2^32, so the planes are swept 512 times less often (a sweep reads every cell).
    void reserve(std::size_t hits)
    {
        if (hits > m_room) [[unlikely]]
            sweep(hits);
        m_room -= hits;
    }
    void addDensityUnchecked(std::size_t i, std::uint8_t coordinate)
    {
        addDensityWord(i, coordinate);
    }
    void addHitUnchecked(std::size_t i, std::uint32_t label) { addHitWord(i, label); }
    void addCountUnchecked(std::size_t j) { ++m_counts[j]; }

    // Exact totals of cell i: count and coordinate sum (hits: 1 + the smallest label).
    std::array<double, 2> cell(std::size_t i) const;
    std::uint64_t count(std::size_t i) const;
    std::uint64_t litCells() const;
    void merge(const DensityImage &other);
    // merge() in parts that threads may run side by side: mergeCells for disjoint ranges of
    // cell indices [first, last) (the buckets), then mergeRest once (spilled sums, counters).
    void mergeCells(const DensityImage &other, std::size_t first, std::size_t last);
    void mergeRest(const DensityImage &other);
    // The same, emptying `other` as it goes (takeRest clears its spilled sums and counters):
    // a histogram taken whole needs no reset before it is filled again. takeRest is for
    // after takeCells over every cell: `other` is then empty and takes a full room of
    // unchecked hits before its next sweep.
    void takeCells(DensityImage &other, std::size_t first, std::size_t last);
    void takeRest(DensityImage &other);
    void clear();
    // The buckets (the counts of the planes, plane after plane), row by row; exact totals only
    // while no bucket has spilled.
    const DensityBucket *buckets() const { return m_buckets.data(); }
    const std::uint32_t *counts() const { return m_counts.data(); }
    bool hasSpills() const { return !m_spilled.empty(); }

    std::uint64_t offscreen = 0;   // hits outside the frame
    std::uint64_t nonFinite = 0;   // images with a NaN or infinite coordinate

    static constexpr std::uint32_t kSpillAt = 1u << 23;
    // Unchecked hits between two sweeps of the planes' counts (buckets: kSpillAt).
    static constexpr std::size_t kCountRoom = 0xffffffffu - kSpillAt;

private:
    // Where n and v sit in a bucket read as one 64-bit word.
    static constexpr int kCountShift = std::endian::native == std::endian::little ? 0 : 32;
    static constexpr int kValueShift = 32 - kCountShift;
    static constexpr std::uint64_t kOneHit = std::uint64_t(1) << kCountShift;
    static_assert(sizeof(DensityBucket) == 8 && offsetof(DensityBucket, v) == 4);

    // Both halves in one 64-bit add (n + 1, v + coordinate): n < 2^24 never carries into v.
    // Returns the new count.
    std::uint32_t addDensityWord(std::size_t i, std::uint8_t coordinate)
    {
        std::uint64_t word;
        std::memcpy(&word, static_cast<const void *>(&m_buckets[i]), sizeof word);
        word += kOneHit + (std::uint64_t(coordinate) << kValueShift);
        std::memcpy(static_cast<void *>(&m_buckets[i]), &word, sizeof word);
        return std::uint32_t(word >> kCountShift);
    }
    std::uint32_t addHitWord(std::size_t i, std::uint32_t label)
    {
        DensityBucket &b = m_buckets[i];
        // v = 1 + min(label, v - 1), v = 0 (no hit yet) wrapping to the largest label: no branch
        // on the bucket's content (a mispredicted one per hit costs more than the hit).
        b.v = std::min(b.v - 1u, label) + 1u;
        return ++b.n;
    }
    void spill(std::size_t i);
    // Spills every bucket at or above kSpillAt hits; a full room of unchecked hits may follow.
    // Throws std::length_error for a batch of more than kSpillAt hits (a caller's bug).
    void sweep(std::size_t hits);
    std::size_t fullRoom() const { return planes() > 0 ? kCountRoom : kSpillAt; }
    template <bool Take, class Source>
    void addCells(Source &other, std::size_t first, std::size_t last);

    template <bool Take, class Source>
    void addCounts(Source &other, std::size_t first, std::size_t last);
    // A merge's rare path, when cell i's hits and the n to be added reach kSpillAt: cell i
    // spills, and a source of n >= kSpillAt hits (colour sum `sum`) goes to the spilled sums
    // whole (true: the caller adds nothing more of it to the bucket).
    bool spillForMerge(std::size_t i, std::uint32_t n, std::uint32_t sum);
    // The hits at index j of the storage (a bucket, or a count of a plane), spills included.
    std::uint64_t stored(std::size_t j) const;

    int m_w = 0, m_h = 0;
    std::size_t m_size = 0;  // m_w * m_h (not an int: the hot loops' uint32 stores may alias ints)
    Accumulation m_mode = Accumulation::Density;
    CellLayout m_layout;
    std::vector<DensityBucket, CellAllocator<DensityBucket>> m_buckets;  // empty with planes
    std::vector<std::uint32_t, CellAllocator<std::uint32_t>> m_counts;   // the planes' counts
    std::size_t m_room = kSpillAt;  // unchecked hits allowed before the next sweep
    // Buckets (or plane counts, by their index j) that reached kSpillAt hits, summed exactly
    // (rare: only huge sample counts).
    std::unordered_map<std::size_t, std::array<std::uint64_t, 2>> m_spilled;
};

struct ToneSettings {
    Accumulation mode = Accumulation::Hits;
    double gamma = 2.2;        // display gamma of the log density (flam3's default is 4)
    double vibrancy = 1.0;     // 1: gamma on alpha only (saturated colours); 0: per channel
    double linearRange = 0.01; // below this log density the gamma curve is linear (flam3)
    double brightness = 1.0;   // multiplies the log density before the gamma
};

// The colour coordinate (0..255) of each of `labels` labels: evenly spread over the ramp.
std::vector<std::uint8_t> labelCoordinates(std::size_t labels);
// The colour ramp of the density tone: the label colours at their coordinates, linear
// between them (256 entries).
std::vector<Rgb8> colourRamp(const std::vector<Rgb8> &labels);

// The picture of `image` (cells of frame.supersample^2 per pixel, box filtered) as
// frame.width x frame.height premultiplied 0xAARRGGBB pixels, unlit pixels transparent.
// `labels` gives the colour of each label (hits), and the ramp (density).
std::vector<std::uint32_t> toneMap(const DensityImage &image, const RasterFrame &frame,
                                   const ToneSettings &tone, const std::vector<Rgb8> &labels);
// The same into `out` (frame.width * frame.height pixels, rows contiguous), every pixel
// written: a caller's image buffer, no copy.
void toneMapInto(const DensityImage &image, const RasterFrame &frame, const ToneSettings &tone,
                 const std::vector<Rgb8> &labels, std::uint32_t *out);

// Per output pixel, the hits of its frame.supersample^2 cells summed (the box filter's sum,
// not its mean) and the same hits weighted by their colour channels (0..255: the ramp at a
// cell's mean colour coordinate for density, its label's colour for hits): {n, n r, n g, n b},
// row 0 at the top. The density tone maps these; densityChannels writes them out.
std::vector<std::array<double, 4>> densitySums(const DensityImage &image, const RasterFrame &frame,
                                               const std::vector<Rgb8> &labels);
// The raw density of a picture (render --out F.exr, --bits 16): four floats a pixel, R G B A,
// A = the pixel's hits (the invariant measure's mass in it, in hits) and R, G, B = the hits
// times their colour (0..1), so that R/A, G/A, B/A is the pixel's mean colour. Exact counts
// up to 2^24 a pixel.
std::vector<float> densityChannels(const DensityImage &image, const RasterFrame &frame,
                                   const std::vector<Rgb8> &labels);

// Grows lit pixels by r pixels (a square): an unlit pixel takes the most opaque neighbour
// within r (ties: the first in scan order), so a thin curve reads at print size.
void dilate(std::uint32_t *argb, int width, int height, int r);

} // namespace awb
