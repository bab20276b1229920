#include "core/ifs/Random.h"

#include "core/Messages.h"
#include "core/Types.h"

#include <cmath>

namespace awb {

AliasTable::AliasTable(const std::vector<double> &weights, int n)
    : m_n(std::max(1, n)), m_threshold(std::size_t(m_n), std::uint64_t(1) << 32),
      m_alias(std::size_t(m_n))
{
    for (int i = 0; i < m_n; ++i)
        m_alias[i] = i;
    if (weights.empty())
        return;
    m_uniform = false;
    if (int(weights.size()) != m_n)
        throw InputError("expected " + std::to_string(m_n) + " probabilities, got "
                         + std::to_string(weights.size()));
    double sum = 0;
    for (double w : weights) {
        if (!std::isfinite(w) || w < 0)
            throw InputError(coreTranslate("awb::ifs", "probabilities must be finite and "
                                                       "non-negative"));
        sum += w;
    }
    if (!(sum > 0))
        throw InputError(coreTranslate("awb::ifs", "the probabilities sum to zero"));
    // Vose's method: scaled weights n p_i, small ones topped up by a large one's alias.
    std::vector<double> q(static_cast<std::size_t>(m_n));
    std::vector<int> small, large;
    for (int i = 0; i < m_n; ++i) {
        q[i] = weights[i] * m_n / sum;
        (q[i] < 1.0 ? small : large).push_back(i);
    }
    while (!small.empty() && !large.empty()) {
        const int s = small.back(), l = large.back();
        small.pop_back();
        m_threshold[s] = std::uint64_t(std::llround(q[s] * 4294967296.0));
        m_alias[s] = l;
        q[l] -= 1.0 - q[s];
        if (q[l] < 1.0) {
            large.pop_back();
            small.push_back(l);
        }
    }
    // Left-overs are 1 up to rounding: always keep their own column.
    for (int i : small)
        m_threshold[i] = std::uint64_t(1) << 32;
    for (int i : large)
        m_threshold[i] = std::uint64_t(1) << 32;
    m_uniform = true;
    for (int i = 0; i < m_n; ++i)
        m_uniform = m_uniform && m_alias[i] == i && m_threshold[i] == (std::uint64_t(1) << 32);
}

} // namespace awb
