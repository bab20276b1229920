#include "core/analysis/RegularityFamily.h"

#include "core/Messages.h"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace awb {

namespace {

// +1: certified C^k (r > k); -1: certified not C^k (r < k, or no such member); 0: the bounds
// straddle k (r = k exactly, or too close to tell within the budget).
class FamilyEvaluator {
public:
    FamilyEvaluator(const std::function<Regularity(double, const RegularityOptions &)> &f, int k,
                    const FamilyOptions &o, FamilyResult &out)
        : m_f(f), m_k(k), m_options(o), m_out(out)
    {
    }

    int operator()(double t)
    {
        RegularityOptions ro;
        ro.timeBudget = m_options.budgetPerValue;
        ro.cancel = m_options.cancel;
        const Regularity r = m_f(t, ro);
        FamilySample s;
        s.parameter = t;
        s.applies = r.applies;
        s.lower = r.infinite ? std::numeric_limits<double>::infinity() : r.lower;
        s.upper = r.infinite ? std::numeric_limits<double>::infinity() : r.upper;
        m_out.samples.push_back(s);
        ++m_done;
        if (m_options.progress)
            m_options.progress(m_out.samples, std::min(1.0, m_done / m_expected));
        return smoothnessVerdict(r.applies, s.lower, s.upper, m_k);
    }

    bool cancelled() const { return m_options.cancel && m_options.cancel->load(); }
    void expect(double evaluations) { m_expected = std::max(m_expected, evaluations); }

private:
    const std::function<Regularity(double, const RegularityOptions &)> &m_f;
    int m_k;
    const FamilyOptions &m_options;
    FamilyResult &m_out;
    double m_done = 0;
    double m_expected = 1;
};

// Narrows [inner, outer] (inner certified C^k, outer not or undecided) towards the boundary.
FamilyBoundary bisect(FamilyEvaluator &eval, double inner, double outer, bool outerUndecided,
                      const FamilyOptions &o)
{
    FamilyBoundary b{inner, outer, false, outerUndecided};
    for (int step = 0; step < o.maxBisections && b.width() > o.tolerance; ++step) {
        if (eval.cancelled())
            break;
        const double mid = 0.5 * (b.inner + b.outer);
        const int v = eval(mid);
        if (v > 0) {
            b.inner = mid;
        } else if (v < 0) {
            b.outer = mid;
            b.undecided = false;
        } else {
            // Too close to r = k to tell: the boundary is near mid, on a side the bounds cannot
            // name. The quarter points may still move an end (the one nearer the boundary
            // first); when neither moves, the bracket is as tight as the bounds allow.
            const double q1 = 0.5 * (b.inner + mid), q3 = 0.5 * (mid + b.outer);
            const int a = eval(q1), c = eval(q3);
            const double wasInner = b.inner, wasOuter = b.outer;
            if (c > 0)
                b.inner = q3;
            else if (a > 0)
                b.inner = q1;
            if (a < 0) {
                b.outer = q1;
                b.undecided = false;
            } else if (c < 0) {
                b.outer = q3;
                b.undecided = false;
            }
            if (b.inner == wasInner && b.outer == wasOuter)
                break;
        }
    }
    return b;
}

} // namespace

FamilyResult regularityInterval(
    const std::function<Regularity(double t, const RegularityOptions &)> &regularity,
    double from, double to, int k, const FamilyOptions &options)
{
    const auto start = std::chrono::steady_clock::now();
    if (!std::isfinite(from) || !std::isfinite(to) || !(from < to))
        throw InputError(formatMessage(
            coreTranslate("awb::analysis", "the parameter range [%1, %2] must be finite with "
                                           "from < to"),
            streamedNumber(from), streamedNumber(to)));
    if (k < 0 || k > 30)
        throw InputError(formatMessage(
            coreTranslate("awb::analysis", "the smoothness k must be between 0 and 30, got %1"),
            k));
    if (options.grid < 2 || options.grid > 10000)
        throw InputError(formatMessage(
            coreTranslate("awb::analysis", "the grid must have 2 to 10000 values, got %1"),
            options.grid));
    FamilyResult out;
    out.smoothness = k;
    FamilyEvaluator eval(regularity, k, options, out);
    eval.expect(options.grid + 2.0 * options.maxBisections);

    std::vector<double> t(size_t(options.grid));
    std::vector<int> v(t.size());
    for (size_t i = 0; i < t.size(); ++i) {
        t[i] = i + 1 == t.size() ? to : from + (to - from) * double(i) / double(t.size() - 1);
        if (eval.cancelled())
            break;
        v[i] = eval(t[i]);
    }
    for (size_t i = 0; i < t.size() && !eval.cancelled();) {
        if (v[i] <= 0) {
            ++i;
            continue;
        }
        size_t j = i;
        while (j + 1 < t.size() && v[j + 1] > 0)
            ++j;
        FamilyRun run;
        eval.expect(double(out.samples.size()) + 2.0 * options.maxBisections);
        run.from = i == 0 ? FamilyBoundary{from, from, true, false}
                          : bisect(eval, t[i], t[i - 1], v[i - 1] == 0, options);
        run.to = j + 1 == t.size() ? FamilyBoundary{to, to, true, false}
                                   : bisect(eval, t[j], t[j + 1], v[j + 1] == 0, options);
        out.runs.push_back(run);
        i = j + 1;
    }
    out.cancelled = eval.cancelled();
    std::sort(out.samples.begin(), out.samples.end(),
              [](const FamilySample &a, const FamilySample &b) {
                  return a.parameter < b.parameter;
              });
    out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return out;
}

} // namespace awb
