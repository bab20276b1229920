#include "core/analysis/JointSpectralRadius.h"

#include "core/Decompositions.h"
#include "core/Messages.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>

namespace awb {

namespace {

using Clock = std::chrono::steady_clock;
constexpr double kEps = std::numeric_limits<double>::epsilon();
constexpr double kNormMargin = 1e-12;

// One operator norm on L x L matrices, with a rigorous bound for the rounding of a computed
// product: given the computed P and B >= |A_{w0}| |A_{w1}| ... (entrywise), the exact product
// lies within gamma * B of P (Higham, "Accuracy and Stability of Numerical Algorithms", §3.5).
class OperatorNorm {
public:
    enum Kind { One, Two, Infinity, Ellipsoid };
    OperatorNorm(Kind kind, Mat R = {}) : m_kind(kind), m_R(std::move(R))
    {
        if (m_kind == Ellipsoid) {
            m_Rinv = m_R.inverse();
            m_cond = spectral(m_R) * spectral(m_Rinv);
        }
    }
    std::string name() const
    {
        switch (m_kind) {
        case One: return "induced 1-norm";
        case Two: return "spectral norm";
        case Infinity: return "induced infinity-norm";
        case Ellipsoid: return "ellipsoid norm";
        }
        return {};
    }
    double raw(const Mat &M) const
    {
        switch (m_kind) {
        case One: return M.cwiseAbs().colwise().sum().maxCoeff();
        case Infinity: return M.cwiseAbs().rowwise().sum().maxCoeff();
        case Two: return spectral(M);
        case Ellipsoid: return spectral(m_R * M * m_Rinv);
        }
        return 0.0;
    }
    // An upper bound on the norm of the exact product of `length` factors.
    double upper(const Mat &P, const Mat &B, int length) const
    {
        const double n = double(P.rows());
        const double gamma = 2.0 * (length + 1) * n * kEps;
        double err = 0.0;
        switch (m_kind) {
        case One: err = gamma * B.colwise().sum().maxCoeff(); break;
        case Infinity: err = gamma * B.rowwise().sum().maxCoeff(); break;
        case Two: err = gamma * B.norm(); break;
        case Ellipsoid: err = m_cond * (gamma * B.norm() + 4 * n * kEps * P.norm()); break;
        }
        return raw(P) * (1.0 + kNormMargin) + err;
    }

private:
    static double spectral(const Mat &M)
    {
        if (M.size() == 0)
            return 0.0;
        Eigen::SelfAdjointEigenSolver<Mat> es(Mat(M.transpose() * M), Eigen::EigenvaluesOnly);
        return std::sqrt(std::max(0.0, es.eigenvalues().maxCoeff()));
    }
    Kind m_kind;
    Mat m_R, m_Rinv;
    double m_cond = 1.0;
};

struct Node {
    Mat P;          // the product A_w (computed)
    Mat B;          // |A_{w0}| |A_{w1}| ... : bounds the rounding of P
    double p;       // min over prefixes v of w of ||A_v||^{1/|v|} (upper bounds)
    std::vector<int> word;
};

class Search {
public:
    Search(const std::vector<Mat> &A, const JsrOptions &o) : m_A(A), m_opt(o), m_start(Clock::now())
    {
        for (const Mat &M : m_A)
            m_absA.push_back(M.cwiseAbs());
    }

    bool stopRequested()
    {
        if (m_opt.cancel && m_opt.cancel->load()) {
            m_out.cancelled = true;
            return true;
        }
        if (m_opt.maxNodes > 0 && m_out.nodes >= m_opt.maxNodes) {
            m_out.workSpent = true;
            return true;
        }
        if (elapsed() > m_opt.timeBudget) {
            m_out.timedOut = true;
            return true;
        }
        return false;
    }
    double elapsed() const
    {
        return std::chrono::duration<double>(Clock::now() - m_start).count();
    }
    void report()
    {
        m_out.seconds = elapsed();
        if (m_opt.progress)
            m_opt.progress(m_out, std::min(1.0, m_out.seconds / std::max(1e-9, m_opt.timeBudget)));
    }

    void offerLower(const Mat &P, const std::vector<int> &word)
    {
        double margin = 0.0;
        const double r = spectralRadiusOf(P, &margin);
        const double v = std::pow(std::max(0.0, r * (1.0 - margin)), 1.0 / double(word.size()));
        if (v > m_out.lower) {
            m_out.lower = v;
            m_out.product = word;
        }
    }

    // Every product of length <= maxLen while there are at most `budget` of them: lower bounds.
    void enumerateShort(int maxLen)
    {
        std::vector<std::pair<Mat, std::vector<int>>> level{{Mat::Identity(dim(), dim()), {}}};
        for (int len = 1; len <= maxLen; ++len) {
            std::vector<std::pair<Mat, std::vector<int>>> next;
            for (const auto &[P, w] : level)
                for (size_t i = 0; i < m_A.size(); ++i) {
                    auto word = w;
                    word.push_back(int(i));
                    next.push_back({P * m_A[i], word});
                    offerLower(next.back().first, word);
                    ++m_out.nodes;
                }
            level.swap(next);
            m_out.enumerated = len;
            if (stopRequested())
                return;
        }
    }

    // The norm with the smallest bound max_{|w| = d} ||A_w||^{1/d} (d <= maxLen), which also
    // is a certified upper bound.
    OperatorNorm chooseNorm(int maxLen)
    {
        std::vector<OperatorNorm> norms{OperatorNorm(OperatorNorm::One),
                                        OperatorNorm(OperatorNorm::Infinity),
                                        OperatorNorm(OperatorNorm::Two)};
        if (auto R = ellipsoid())
            norms.emplace_back(OperatorNorm::Ellipsoid, *R);
        int best = 0;
        double bestBound = std::numeric_limits<double>::infinity();
        for (size_t k = 0; k < norms.size(); ++k) {
            const double b = shortBound(norms[k], maxLen);
            if (b < bestBound) {
                bestBound = b;
                best = int(k);
            }
        }
        if (bestBound < m_out.upper) {
            m_out.upper = bestBound;
            m_out.norm = norms[size_t(best)].name();
        }
        return norms[size_t(best)];
    }

    // Gripenberg's branch and bound in `norm` with pruning threshold theta. Returns true when
    // every branch was pruned (then JSR <= theta).
    bool branchAndBound(const OperatorNorm &norm, double theta)
    {
        std::vector<Node> frontier{{Mat::Identity(dim(), dim()), Mat::Identity(dim(), dim()),
                                    std::numeric_limits<double>::infinity(), {}}};
        for (int len = 1; len <= m_opt.maxLength; ++len) {
            std::vector<Node> next;
            double worst = theta;
            for (const Node &n : frontier) {
                for (size_t i = 0; i < m_A.size(); ++i) {
                    Node c{n.P * m_A[i], n.B * m_absA[i], 0.0, n.word};
                    c.word.push_back(int(i));
                    ++m_out.nodes;
                    offerLower(c.P, c.word);
                    const double q = std::pow(norm.upper(c.P, c.B, len), 1.0 / len);
                    c.p = std::min(n.p, q);
                    if (c.p <= theta)
                        continue;   // every extension has a prefix within theta
                    worst = std::max(worst, c.p);
                    next.push_back(std::move(c));
                    if ((m_out.nodes & 255) == 0 && stopRequested())
                        return false;
                }
            }
            m_out.depth = std::max(m_out.depth, len);
            // Every product of length len has a prefix bounded by theta or is in `next`.
            if (worst < m_out.upper) {
                m_out.upper = worst;
                m_out.norm = norm.name();
            }
            report();
            if (next.empty())
                return true;
            if (static_cast<long long>(next.size()) > m_opt.maxFrontier || stopRequested())
                return false;
            frontier.swap(next);
        }
        return false;
    }

    JsrBounds &out() { return m_out; }

private:
    int dim() const { return int(m_A.front().rows()); }

    double shortBound(const OperatorNorm &norm, int maxLen)
    {
        double best = std::numeric_limits<double>::infinity();
        std::vector<std::pair<Mat, Mat>> level{{Mat::Identity(dim(), dim()),
                                                Mat::Identity(dim(), dim())}};
        for (int len = 1; len <= maxLen; ++len) {
            std::vector<std::pair<Mat, Mat>> next;
            double worst = 0.0;
            for (const auto &[P, B] : level)
                for (size_t i = 0; i < m_A.size(); ++i) {
                    next.push_back({P * m_A[i], B * m_absA[i]});
                    worst = std::max(worst, norm.upper(next.back().first, next.back().second, len));
                }
            best = std::min(best, std::pow(worst, 1.0 / len));
            level.swap(next);
        }
        return best;
    }

    // R with Q = R^T R = sum_{|w| <= d} (A_w / l)^T (A_w / l): the unit ball {x^T Q x <= 1}
    // is nearly invariant under A_i / JSR when l is close to the JSR.
    std::optional<Mat> ellipsoid() const
    {
        const int L = dim();
        const double l = m_out.lower > 0 ? m_out.lower : 1.0;
        Mat Q = Mat::Identity(L, L);
        std::vector<Mat> level{Mat::Identity(L, L)};
        for (int len = 1; len <= 10 && level.size() * m_A.size() <= 1024; ++len) {
            std::vector<Mat> next;
            for (const Mat &P : level)
                for (const Mat &M : m_A) {
                    next.push_back(P * M / l);
                    Q += next.back().transpose() * next.back();
                }
            level.swap(next);
        }
        Q /= Q.norm();
        Eigen::LLT<Mat> llt(Q);
        if (llt.info() != Eigen::Success || !Q.allFinite())
            return std::nullopt;
        const Mat R = llt.matrixU();
        Eigen::JacobiSVD<Mat> svd(R);
        const Vec s = svd.singularValues();
        if (s(s.size() - 1) <= 1e-10 * s(0))
            return std::nullopt;
        return R;
    }

    const std::vector<Mat> &m_A;
    std::vector<Mat> m_absA;
    const JsrOptions &m_opt;
    Clock::time_point m_start;
    JsrBounds m_out;
};

} // namespace

double spectralRadiusOf(const Mat &M, double *margin)
{
    if (margin)
        *margin = 0.0;
    if (M.size() == 0)
        return 0.0;
    if (M.rows() == 1) {
        if (margin)
            *margin = kEps;
        return std::abs(M(0, 0));
    }
    Eigen::EigenSolver<Mat> es(M, false);
    const CVec ev = es.eigenvalues();
    Eigen::Index top = 0;
    for (Eigen::Index i = 1; i < ev.size(); ++i)
        if (std::abs(ev(i)) > std::abs(ev(top)))
            top = i;
    const double r = std::abs(ev(top));
    if (margin) {
        // The top eigenvalue's cluster: a nearly defective eigenvalue of multiplicity s is
        // computed to about eps^{1/s} (relative to ||M||).
        int s = 0;
        for (Eigen::Index i = 0; i < ev.size(); ++i)
            if (std::abs(ev(i) - ev(top)) <= 1e-5 * std::max(r, 1e-300))
                ++s;
        const double scale = std::max(1.0, M.norm() / std::max(r, 1e-300));
        *margin = std::min(1.0, 1e-12 + 10.0 * std::pow(kEps * scale, 1.0 / s) * (s > 1 ? 1 : 0)
                                    + 100.0 * kEps * scale);
    }
    return r;
}

void requireMatrixFamily(const std::vector<Mat> &A)
{
    if (A.empty())
        throw InputError(coreTranslate("awb::analysis", "the joint spectral radius needs at least "
                                                        "one matrix"));
    const Eigen::Index L = A.front().rows();
    for (size_t i = 0; i < A.size(); ++i) {
        if (A[i].rows() != L || A[i].cols() != L)
            throw InputError(formatMessage(
                coreTranslate("awb::analysis", "the joint spectral radius needs square matrices "
                                               "of one size; matrix %1 differs"),
                i + 1));
        requireFinite(A[i], formatMessage(coreTranslate("awb::analysis", "matrix %1"), i + 1));
    }
}

JsrBounds jointSpectralRadius(const std::vector<Mat> &A, const JsrOptions &options)
{
    requireMatrixFamily(A);
    const Eigen::Index L = A.front().rows();
    if (L == 0) {
        JsrBounds b;
        b.upper = 0.0;
        b.converged = true;
        b.norm = "empty space";
        return b;
    }
    Search s(A, options);
    JsrBounds &out = s.out();
    // Products up to a few hundred per length for the lower bound and the norm choice.
    int shortLen = 1;
    while (shortLen < 12 && std::pow(double(A.size()), shortLen + 1) <= 512)
        ++shortLen;
    s.enumerateShort(shortLen);
    const OperatorNorm norm = s.chooseNorm(std::min(shortLen, 6));
    s.report();
    // Tighten the pruning threshold while the branch and bound keeps closing.
    double delta = 1e-2;
    while (!out.cancelled && !out.timedOut) {
        if (out.upper <= out.lower * (1.0 + options.tolerance)) {
            out.converged = true;
            break;
        }
        const double base = out.lower > 0 ? out.lower : out.upper * 1e-3;
        const double theta = base * (1.0 + delta);
        if (theta >= out.upper) {
            delta /= 10.0;
            if (delta < options.tolerance * 0.1)
                break;
            continue;
        }
        if (!s.branchAndBound(norm, theta))
            break;
        out.upper = std::min(out.upper, theta);
        delta /= 10.0;
    }
    if (out.upper <= out.lower * (1.0 + options.tolerance))
        out.converged = true;
    out.upper = std::max(out.upper, out.lower);
    s.report();
    return out;
}

std::vector<int> primitiveRoot(const std::vector<int> &w)
{
    const std::size_t n = w.size();
    for (std::size_t p = 1; p < n; ++p)
        if (n % p == 0 && std::equal(w.begin() + std::ptrdiff_t(p), w.end(), w.begin()))
            return {w.begin(), w.begin() + std::ptrdiff_t(p)};
    return w;
}

} // namespace awb
