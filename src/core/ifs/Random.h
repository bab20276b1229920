#pragma once
// The random numbers of random iteration, shared by the sink-based chaos game (Attractor.cpp)
// and the raster engine's kernels (render/Engine.cpp), so that both draw the same points for
// the same seed: xoshiro256+ (Blackman & Vigna, "Scrambled linear pseudorandom number
// generators", 2021) seeded by splitmix64, and Vose's alias table for the maps' probabilities
// (one 64-bit draw picks a map: the high half a column, the low half the coin).

#include <cstdint>
#include <vector>

namespace awb {

// Random iteration always runs this many independent streams (seeded from the seed and the
// stream index), whatever the number of threads: equal requests give equal pictures on any
// machine, and an export can replay the raster's points.
inline constexpr int kChaosStreams = 8;

inline std::uint64_t splitmix64(std::uint64_t &s)
{
    std::uint64_t z = (s += 0x9E3779B97F4A7C15ULL);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    return z ^ (z >> 31);
}

struct Xoshiro256 {
    std::uint64_t s[4] = {1, 2, 3, 4};

    Xoshiro256() = default;
    Xoshiro256(std::uint64_t seed, std::uint64_t stream)
    {
        std::uint64_t x = seed ^ (0xD1B54A32D192ED03ULL * (stream + 1));
        for (auto &w : s)
            w = splitmix64(x);
    }
    static std::uint64_t rotl(std::uint64_t x, int k) { return (x << k) | (x >> (64 - k)); }
    std::uint64_t next()
    {
        const std::uint64_t result = s[0] + s[3];
        const std::uint64_t t = s[1] << 17;
        s[2] ^= s[0];
        s[3] ^= s[1];
        s[1] ^= s[2];
        s[0] ^= s[3];
        s[2] ^= t;
        s[3] = rotl(s[3], 45);
        return result;
    }
};

// Picks map i with probability p_i from one 64-bit draw.
class AliasTable {
public:
    // Empty or all-equal weights: uniform. Weights must be finite and >= 0 with a positive sum.
    explicit AliasTable(const std::vector<double> &weights, int n);
    int size() const { return m_n; }
    int pick(std::uint64_t r) const
    {
        const auto column = int((std::uint64_t(std::uint32_t(r >> 32)) * std::uint64_t(m_n)) >> 32);
        if (m_uniform)
            return column;
        const int alias = m_alias[column];
        return std::uint32_t(r) < m_threshold[column] ? column : alias;
    }
    bool uniform() const { return m_uniform; }
    // The table itself (pick's columns), for vector kernels that pick several at once.
    const std::uint64_t *thresholds() const { return m_threshold.data(); }
    const int *aliases() const { return m_alias.data(); }

private:
    int m_n = 1;
    bool m_uniform = true;
    std::vector<std::uint64_t> m_threshold;  // keep column when the low half is below this
    std::vector<int> m_alias;
};

// The share of `samples` that stream s of kChaosStreams draws.
inline std::uint64_t streamShare(std::uint64_t samples, int s)
{
    return samples / kChaosStreams + (std::uint64_t(s) < samples % kChaosStreams ? 1 : 0);
}

} // namespace awb
