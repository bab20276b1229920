#include "core/analysis/InvariantPolytope.h"

#include "core/Messages.h"
#include "core/analysis/LinearProgram.h"

#include <Eigen/Dense>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <optional>
#include <sstream>

namespace awb {

namespace {

using Clock = std::chrono::steady_clock;
constexpr double kEps = std::numeric_limits<double>::epsilon();
constexpr double kTie = 1e-10;          // relative: near-ties of rho(A_w)^{1/|w|}
constexpr double kDominance = 1e-8;     // relative gap to the second eigenvalue modulus
constexpr double kCoupling = 0.5;       // the complement's images use at most this of P|W
constexpr long long kProductBudget = 1 << 15;


std::string wordText(const std::vector<int> &w)
{
    std::string s;
    for (size_t k = 0; k < w.size(); ++k) {
        if (k)
            s += ' ';
        s += std::to_string(w[k]);
    }
    return s;
}

// A Lyndon word is strictly smaller than each of its proper rotations: one representative of
// every class of cyclic shifts, and never a power of a shorter word.
bool isLyndon(const std::vector<int> &w)
{
    const size_t k = w.size();
    for (size_t r = 1; r < k; ++r)
        for (size_t t = 0; t < k; ++t) {
            const int a = w[t], b = w[(t + r) % k];
            if (a < b)
                break;
            if (a > b || t + 1 == k)
                return false;
        }
    return true;
}

// The product A_w and the entrywise bound |A_{w0}| |A_{w1}| .. of its rounding.
std::pair<Mat, Mat> product(const std::vector<Mat> &A, const std::vector<int> &w)
{
    const Eigen::Index L = A.front().rows();
    Mat P = Mat::Identity(L, L), B = Mat::Identity(L, L);
    for (int i : w) {
        P = P * A[size_t(i)];
        B = B * A[size_t(i)].cwiseAbs();
    }
    return {P, B};
}

// A certified lower bound (rho(A_w) (1 - margin))^{1/k} with the rounding of the product in
// the margin (Higham §3.5: |fl(A_w) - A_w| <= gamma_{kL} B).
double certifiedLower(const std::vector<Mat> &A, const std::vector<int> &w, double *raw)
{
    const auto [P, B] = product(A, w);
    double margin = 0.0;
    const double r = spectralRadiusOf(P, &margin);
    if (raw)
        *raw = r > 0 ? std::pow(r, 1.0 / double(w.size())) : 0.0;
    if (r <= 0)
        return 0.0;
    const double gamma = 2.0 * double(w.size() * size_t(P.rows()) + 1) * kEps;
    margin += 10.0 * gamma * B.norm() / r;
    return std::pow(std::max(0.0, r * (1.0 - margin)), 1.0 / double(w.size()));
}

struct Candidate {
    std::vector<int> word;
    double value = 0.0;   // rho(A_w)^{1/|w|}
};

// Every Lyndon word up to maxLen (depth first with prefix products), best values first.
std::vector<Candidate> candidates(const std::vector<Mat> &A, int maxLen)
{
    std::vector<Candidate> out;
    const Eigen::Index L = A.front().rows();
    std::vector<int> word;
    std::vector<Mat> prefix{Mat::Identity(L, L)};
    auto visit = [&](auto &&self) -> void {
        if (int(word.size()) == maxLen)
            return;
        for (int i = 0; i < int(A.size()); ++i) {
            word.push_back(i);
            prefix.push_back(prefix.back() * A[size_t(i)]);
            if (isLyndon(word)) {
                const double r = spectralRadiusOf(prefix.back());
                out.push_back({word, r > 0 ? std::pow(r, 1.0 / double(word.size())) : 0.0});
            }
            self(self);
            prefix.pop_back();
            word.pop_back();
        }
    };
    visit(visit);
    std::stable_sort(out.begin(), out.end(),
                     [](const Candidate &a, const Candidate &b) { return a.value > b.value; });
    return out;
}

// The leading eigenvector (unit 2-norm) of A_w when its top eigenvalue is real and simple in
// modulus; otherwise a message.
std::optional<Vec> dominantEigenvector(const std::vector<Mat> &A, const std::vector<int> &w,
                                       std::string *why)
{
    const Mat P = product(A, w).first;
    Eigen::EigenSolver<Mat> es(P, true);
    const CVec ev = es.eigenvalues();
    Eigen::Index top = 0;
    for (Eigen::Index i = 1; i < ev.size(); ++i)
        if (std::abs(ev(i)) > std::abs(ev(top)))
            top = i;
    const double r = std::abs(ev(top));
    if (std::abs(ev(top).imag()) > 1e-12 * r) {
        *why = formatMessage(coreTranslate("awb::analysis", "the s.m.p. candidate's leading "
                                                            "eigenvalue is complex (%1); the "
                                                            "complex-polytope variant is not "
                                                            "implemented"),
                             streamedNumber(ev(top).real(), 6) + (ev(top).imag() < 0 ? " - " : " + ")
                                 + streamedNumber(std::abs(ev(top).imag()), 6) + "i");
        return std::nullopt;
    }
    for (Eigen::Index i = 0; i < ev.size(); ++i)
        if (i != top && std::abs(ev(i)) >= r * (1.0 - kDominance)) {
            *why = coreTranslate("awb::analysis", "the s.m.p. candidate's leading eigenvalue is "
                                                  "not simple in modulus (not a dominant "
                                                  "product)");
            return std::nullopt;
        }
    Vec v = es.eigenvectors().col(top).real();
    if (!(v.norm() > 0)) {
        *why = coreTranslate("awb::analysis", "no real leading eigenvector");
        return std::nullopt;
    }
    v /= v.norm();
    Eigen::Index big = 0;
    v.cwiseAbs().maxCoeff(&big);
    if (v(big) < 0)
        v = -v;
    return v;
}

// Every product of length L below 1e-10 s^L (s = max ||A_i||_F): the family is nilpotent to
// rounding (a semigroup of nilpotent matrices is triangularisable, Levitzki: all products of
// length L vanish). Only checked when there are at most 4096 such products.
bool numericallyNilpotent(const std::vector<Mat> &A, double s)
{
    const int L = int(A.front().rows());
    if (std::pow(double(A.size()), L) > 4096)
        return false;
    const double bound = 1e-10 * std::pow(s, L);
    std::vector<Mat> level{Mat::Identity(L, L)};
    for (int len = 1; len <= L; ++len) {
        std::vector<Mat> next;
        for (const Mat &P : level)
            for (const Mat &M : A)
                next.push_back(P * M);
        level.swap(next);
    }
    return std::all_of(level.begin(), level.end(),
                       [&](const Mat &P) { return P.norm() <= bound; });
}

class Search {
public:
    Search(const std::vector<Mat> &A, double rhoHat, const PolytopeOptions &o, Clock::time_point t0)
        : m_A(A), m_rho(rhoHat), m_opt(o), m_start(t0), m_L(int(A.front().rows()))
    {
        m_V.resize(m_L, 0);
    }

    Vec image(int i, const Vec &x) const { return Vec((m_A[size_t(i)] * x) / m_rho); }

    int addVertex(const Vec &x)
    {
        m_vertices.push_back(x);
        m_lambda.emplace_back(m_A.size());
        m_V.conservativeResize(m_L, m_V.cols() + 1);
        m_V.col(m_V.cols() - 1) = x;
        return int(m_vertices.size()) - 1;
    }

    // Seeds: x and its orbit along the cycle w (x = leading eigenvector of A_w).
    void seed(const std::vector<int> &w, const Vec &v, std::vector<int> &generation)
    {
        Vec x = v;
        const AbsoluteCombination c0 = absoluteCombination(m_V, x);
        if (c0.feasible && c0.norm <= 1.0 + m_opt.tolerance)
            return;   // already covered (a tie with the same eigenvector)
        generation.push_back(addVertex(x));
        for (size_t k = w.size() - 1; k >= 1; --k) {
            x = image(w[k], x);
            generation.push_back(addVertex(x));
        }
    }

    // Breadth first from `generation`. Returns true when a generation adds nothing.
    bool run(std::vector<int> generation, PolytopeResult &out)
    {
        while (true) {
            ++out.generations;
            std::vector<int> next;
            for (int j : generation)
                for (int i = 0; i < int(m_A.size()); ++i) {
                    const Vec y = image(i, m_vertices[size_t(j)]);
                    const AbsoluteCombination c = absoluteCombination(m_V, y);
                    if (c.feasible && c.norm <= 1.0 + m_opt.tolerance) {
                        m_lambda[size_t(j)][size_t(i)] = c.lambda;
                    } else {
                        const int m = addVertex(y);
                        m_lambda[size_t(j)][size_t(i)] = {{m, 1.0}};
                        next.push_back(m);
                    }
                    if (stop(out))
                        return false;
                }
            if (next.empty()) {
                if (rank() == m_L || out.extended)
                    return true;
                // The vertices span a proper invariant subspace W: add the complement (step 4).
                out.extended = true;
                Eigen::ColPivHouseholderQR<Mat> qr(m_V);
                qr.setThreshold(1e-9);
                const Mat Q = qr.householderQ() * Mat::Identity(m_L, m_L);
                const int r = int(qr.rank());
                const double eps = extensionScale(Q, r);
                for (int k = r; k < m_L; ++k)
                    next.push_back(addVertex(eps * Q.col(k)));
                m_extension = eps;
            }
            generation.swap(next);
        }
    }

    // eps for the complement's vertices eps u_k: as large as the coupling into W allows, since
    // the inner ball's radius (the residuals' weight in the certificate) grows with eps: the
    // W-parts of B_i u_k take at most kCoupling of the polytope's norm on W.
    double extensionScale(const Mat &Q, int r) const
    {
        const Mat QW = Q.leftCols(r);
        double coupling = 0.0;
        for (int k = r; k < m_L; ++k)
            for (int i = 0; i < int(m_A.size()); ++i) {
                const Vec w = image(i, Q.col(k));
                const AbsoluteCombination c = absoluteCombination(m_V, QW * (QW.transpose() * w));
                coupling = std::max(coupling, c.feasible ? c.norm : 1e3);
            }
        return std::clamp(kCoupling / std::max(coupling, 1e-300), 1e-3, 1.0);
    }

    // After an extension, the combinations found while the vertices spanned only W carry the
    // images' tiny components off W (rounding, or matrices reducible only to ~1e-10) as
    // residuals; those are weighed by 1/delta in the certificate. Re-solving them against the
    // full-dimensional polytope moves such components onto the complement's vertices.
    void polish()
    {
        if (m_extension == 0.0)
            return;
        const double weight = std::sqrt(double(m_L)) / m_extension;
        for (size_t j = 0; j < m_vertices.size(); ++j)
            for (int i = 0; i < int(m_A.size()); ++i) {
                auto &lam = m_lambda[j][size_t(i)];
                const Vec y = image(i, m_vertices[j]);
                Vec z = Vec::Zero(m_L);
                double s = 0.0;
                for (const auto &[m, l] : lam) {
                    z += l * m_vertices[size_t(m)];
                    s += std::abs(l);
                }
                const double before = s + (y - z).norm() * weight;
                if ((y - z).norm() <= 1e-15 * (1.0 + y.norm()))
                    continue;
                const AbsoluteCombination c = absoluteCombination(m_V, y);
                if (c.feasible && c.norm + c.residual * weight < before)
                    lam = c.lambda;
            }
    }

    int rank() const
    {
        if (m_V.cols() == 0)
            return 0;
        Eigen::ColPivHouseholderQR<Mat> qr(m_V);
        qr.setThreshold(1e-9);
        return int(qr.rank());
    }

    PolytopeCertificate certificate(const std::vector<int> &smp) const
    {
        PolytopeCertificate c;
        c.matrices = m_A;
        c.smp = smp;
        c.rhoHat = m_rho;
        c.vertices = m_vertices;
        c.lambda = m_lambda;
        return c;
    }

private:
    bool stop(PolytopeResult &out) const
    {
        const double t = std::chrono::duration<double>(Clock::now() - m_start).count();
        if (m_opt.cancel && m_opt.cancel->load()) {
            out.message = coreTranslate("awb::analysis", "invariant polytope: cancelled");
            return true;
        }
        if (t > m_opt.timeBudget) {
            out.message = formatMessage(coreTranslate("awb::analysis", "invariant polytope did "
                                                                       "not close in the budget "
                                                                       "(%1 vertices)"),
                                        int(m_vertices.size()));
            return true;
        }
        if (int(m_vertices.size()) > m_opt.maxVertices) {
            out.message = formatMessage(coreTranslate("awb::analysis", "invariant polytope did "
                                                                       "not close within %1 "
                                                                       "vertices"),
                                        m_opt.maxVertices);
            return true;
        }
        return false;
    }

    const std::vector<Mat> &m_A;
    double m_rho;
    const PolytopeOptions &m_opt;
    Clock::time_point m_start;
    int m_L;
    Mat m_V;
    double m_extension = 0.0;   // eps of the complement's vertices; 0 before an extension
    std::vector<Vec> m_vertices;
    std::vector<std::vector<std::vector<std::pair<int, double>>>> m_lambda;
};

double seconds(Clock::time_point t0)
{
    return std::chrono::duration<double>(Clock::now() - t0).count();
}

} // namespace

PolytopeVerdict verifyPolytopeCertificate(const PolytopeCertificate &c, double tolerance)
{
    PolytopeVerdict v;
    auto fail = [&](std::string message) {
        v.ok = false;
        v.upper = std::numeric_limits<double>::infinity();
        v.message = std::move(message);
        return v;
    };
    const std::vector<Mat> &A = c.matrices;
    if (A.empty())
        return fail("no matrices");
    const Eigen::Index L = A.front().rows();
    for (size_t i = 0; i < A.size(); ++i)
        if (A[i].rows() != L || A[i].cols() != L || !A[i].allFinite())
            return fail("matrix " + std::to_string(i) + " is not a finite " + std::to_string(L)
                        + " x " + std::to_string(L) + " matrix");
    const bool allZero = std::all_of(A.begin(), A.end(),
                                     [](const Mat &M) { return (M.array() == 0.0).all(); });
    if (L == 0 || (allZero && c.rhoHat == 0.0)) {
        v.ok = true;
        v.lower = v.upper = v.normBound = 0.0;
        v.message = "JSR = 0 (empty space or zero matrices)";
        return v;
    }
    if (!(c.rhoHat > 0.0) || !std::isfinite(c.rhoHat))
        return fail("rhoHat must be positive and finite, got " + streamedNumber(c.rhoHat, 10));
    if (c.smp.empty())
        return fail("the s.m.p. word is empty");
    for (int i : c.smp)
        if (i < 0 || i >= int(A.size()))
            return fail("the s.m.p. word has the index " + std::to_string(i) + ", not a map");
    double raw = 0.0;
    v.lower = certifiedLower(A, c.smp, &raw);
    if (std::abs(raw / c.rhoHat - 1.0) > tolerance)
        return fail("the s.m.p. word (" + wordText(c.smp) + ") gives rho(A_w)^(1/k) = "
                    + streamedNumber(raw, 17) + ", not rhoHat = " + streamedNumber(c.rhoHat, 17));
    const Eigen::Index n = Eigen::Index(c.vertices.size());
    if (n < L)
        return fail("fewer vertices than the dimension");
    if (Eigen::Index(c.lambda.size()) != n)
        return fail("the coefficient table does not have one row per vertex");
    Mat V(L, n);
    for (Eigen::Index j = 0; j < n; ++j) {
        if (c.vertices[size_t(j)].size() != L || !c.vertices[size_t(j)].allFinite())
            return fail("vertex " + std::to_string(j) + " is not a finite vector of length "
                        + std::to_string(L));
        V.col(j) = c.vertices[size_t(j)];
    }
    // delta: a Euclidean ball of this radius lies in absco(V) (see the header, step 5).
    Eigen::ColPivHouseholderQR<Mat> qr(V);
    Mat S(L, L);
    for (Eigen::Index k = 0; k < L; ++k)
        S.col(k) = V.col(qr.colsPermutation().indices()(k));
    Eigen::JacobiSVD<Mat> svd(S);
    const Vec sv = svd.singularValues();
    const double smin = sv(L - 1) - 8.0 * double(L) * kEps * sv(0);
    if (!(smin > 0.0))
        return fail("the vertices do not span R^" + std::to_string(L));
    v.delta = smin / std::sqrt(double(L)) * (1.0 - 4.0 * kEps);
    const double u = kEps / 2.0;
    auto gamma = [u](double k) { return k * u / (1.0 - k * u); };
    double worst = 0.0;
    for (Eigen::Index j = 0; j < n; ++j) {
        if (c.lambda[size_t(j)].size() != A.size())
            return fail("vertex " + std::to_string(j) + " lacks coefficients for some map");
        const Vec &x = c.vertices[size_t(j)];
        for (size_t i = 0; i < A.size(); ++i) {
            const Vec y = (A[i] * x) / c.rhoHat;
            Vec z = Vec::Zero(L), absz = Vec::Zero(L);
            double s = 0.0;
            int last = -1;
            for (const auto &[m, lam] : c.lambda[size_t(j)][i]) {
                if (m <= last || m >= n || !std::isfinite(lam))
                    return fail("vertex " + std::to_string(j) + ", map " + std::to_string(i)
                                + ": bad coefficient index or value");
                last = m;
                z += lam * V.col(m);
                absz += std::abs(lam) * V.col(m).cwiseAbs();
                s += std::abs(lam);
            }
            const double nnz = double(c.lambda[size_t(j)][i].size());
            const Vec r = y - z;
            const Vec err = gamma(double(L) + 2.0) * (A[i].cwiseAbs() * x.cwiseAbs()) / c.rhoHat
                            + gamma(nnz + 1.0) * absz + u * r.cwiseAbs();
            const double rnorm = (r.norm() + err.norm()) * (1.0 + gamma(double(L) + 2.0));
            const double bound = s * (1.0 + gamma(nnz + 1.0))
                                 + rnorm / v.delta * (1.0 + 4.0 * kEps);
            worst = std::max(worst, bound);
            if (!(bound <= 1.0 + tolerance)) {
                v.failingVertex = int(j);
                v.failingMap = int(i);
                return fail("vertex " + std::to_string(j) + " under map " + std::to_string(i)
                            + ": ||A_i v_j / rhoHat||_P <= " + streamedNumber(s, 12) + " + "
                            + streamedNumber(rnorm, 3) + " / " + streamedNumber(v.delta, 3) + " = " + streamedNumber(bound, 12)
                            + " > 1 + " + streamedNumber(tolerance, 3));
            }
        }
    }
    v.ok = true;
    v.normBound = worst;
    v.upper = std::max(v.lower, c.rhoHat * worst * (1.0 + 4.0 * kEps));
    v.message = "every A_i / rhoHat maps the polytope into itself (norm <= " + streamedNumber(worst, 17)
                + "): JSR in [" + streamedNumber(v.lower, 17) + ", " + streamedNumber(v.upper, 17) + "]";
    return v;
}

std::string certificateJson(const PolytopeCertificate &c)
{
    std::ostringstream os;
    auto vec = [&](const Vec &x) {
        os << '[';
        for (Eigen::Index k = 0; k < x.size(); ++k)
            os << (k ? ", " : "") << streamedNumber(x(k), 17);
        os << ']';
    };
    os << "{\n  \"format\": \"awb-invariant-polytope\",\n  \"version\": 1,\n  \"matrices\": [";
    for (size_t i = 0; i < c.matrices.size(); ++i) {
        os << (i ? ",\n    [" : "\n    [");
        for (Eigen::Index r = 0; r < c.matrices[i].rows(); ++r) {
            os << (r ? ", " : "");
            vec(c.matrices[i].row(r).transpose());
        }
        os << ']';
    }
    os << "\n  ],\n  \"smp\": [" << [&] {
        std::string s;
        for (size_t k = 0; k < c.smp.size(); ++k) {
            if (k)
                s += ", ";
            s += std::to_string(c.smp[k]);
        }
        return s;
    }() << "],\n  \"rhoHat\": " << streamedNumber(c.rhoHat, 17) << ",\n  \"vertices\": [";
    for (size_t j = 0; j < c.vertices.size(); ++j) {
        os << (j ? ",\n    " : "\n    ");
        vec(c.vertices[j]);
    }
    os << "\n  ],\n  \"lambda\": [";
    for (size_t j = 0; j < c.lambda.size(); ++j) {
        os << (j ? ",\n    [" : "\n    [");
        for (size_t i = 0; i < c.lambda[j].size(); ++i) {
            os << (i ? ", [" : "[");
            for (size_t k = 0; k < c.lambda[j][i].size(); ++k)
                os << (k ? ", [" : "[") << c.lambda[j][i][k].first << ", "
                   << streamedNumber(c.lambda[j][i][k].second, 17) << ']';
            os << ']';
        }
        os << ']';
    }
    os << "\n  ]\n}\n";
    return os.str();
}

PolytopeResult invariantPolytope(const std::vector<Mat> &A, const PolytopeOptions &options)
{
    requireMatrixFamily(A);
    const Clock::time_point t0 = Clock::now();
    PolytopeResult out;
    const int L = int(A.front().rows());
    const bool allZero = std::all_of(A.begin(), A.end(),
                                     [](const Mat &M) { return (M.array() == 0.0).all(); });
    if (L == 0 || allZero) {
        auto cert = std::make_shared<PolytopeCertificate>();
        cert->matrices = A;
        out.applies = out.closed = true;
        out.lower = out.upper = 0.0;
        out.message = coreTranslate("awb::analysis", "JSR = 0: the matrices are empty or zero");
        out.certificate = cert;
        return out;
    }
    int maxLen = options.maxLength;
    if (maxLen <= 0) {
        maxLen = 1;
        double total = double(A.size());
        while (maxLen < 12 && total + std::pow(double(A.size()), maxLen + 1) <= kProductBudget) {
            ++maxLen;
            total += std::pow(double(A.size()), maxLen);
        }
    }
    const std::vector<Candidate> cand = candidates(A, maxLen);
    const double best = cand.front().value;
    if (!(best > 0.0)) {
        out.message = formatMessage(coreTranslate("awb::analysis", "every product up to length "
                                                                   "%1 has spectral radius 0: "
                                                                   "no s.m.p. candidate"),
                                    maxLen);
        out.seconds = seconds(t0);
        return out;
    }
    // Near-ties, shortest first: the first is the candidate, the other dominant ones seed P.
    std::vector<Candidate> ties;
    for (const Candidate &c : cand)
        if (c.value >= best * (1.0 - kTie))
            ties.push_back(c);
    std::stable_sort(ties.begin(), ties.end(), [](const Candidate &a, const Candidate &b) {
        return a.word.size() < b.word.size();
    });
    out.smp = ties.front().word;
    double rhoHat = 0.0;
    out.lower = certifiedLower(A, out.smp, &rhoHat);
    double scale = 0.0;
    for (const Mat &M : A)
        scale = std::max(scale, M.norm());
    if (rhoHat < 1e-2 * scale && numericallyNilpotent(A, scale)) {
        // rho^ is rounding noise of a nilpotent family (e.g. the quotient maps of a
        // polynomial scheme), not a spectral radius to certify.
        out.message = coreTranslate("awb::analysis", "the family is numerically nilpotent "
                                                     "(every product of length L vanishes to "
                                                     "rounding): JSR = 0, no s.m.p. to certify");
        out.seconds = seconds(t0);
        return out;
    }
    std::string why;
    const std::optional<Vec> v = dominantEigenvector(A, out.smp, &why);
    if (!v) {
        out.message = why;
        out.seconds = seconds(t0);
        return out;
    }
    out.applies = true;
    Search search(A, rhoHat, options, t0);
    std::vector<int> generation;
    search.seed(out.smp, *v, generation);
    for (size_t t = 1; t < ties.size() && out.ties.size() < 8; ++t) {
        std::string ignored;
        if (const auto u = dominantEigenvector(A, ties[t].word, &ignored)) {
            out.ties.push_back(ties[t].word);
            search.seed(ties[t].word, *u, generation);
        }
    }
    const bool closed = search.run(generation, out);
    if (closed)
        search.polish();
    const PolytopeCertificate cert = search.certificate(out.smp);
    out.vertices = int(cert.vertices.size());
    out.seconds = seconds(t0);
    if (!closed)
        return out;
    const PolytopeVerdict verdict = verifyPolytopeCertificate(cert);
    if (!verdict.ok) {
        out.message = coreTranslate("awb::analysis", "the invariant polytope closed but its "
                                                     "certificate failed the check: ")
                      + verdict.message;
        return out;
    }
    out.closed = true;
    out.lower = verdict.lower;
    out.upper = verdict.upper;
    out.certificate = std::make_shared<PolytopeCertificate>(cert);
    out.message = formatMessage(coreTranslate("awb::analysis", "invariant polytope closed: JSR "
                                                               "= rho(A_w)^(1/%1) for the "
                                                               "s.m.p. w = (%2), %3 vertices"),
                                int(out.smp.size()), wordText(out.smp), out.vertices);
    out.seconds = seconds(t0);
    return out;
}

} // namespace awb
