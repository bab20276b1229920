#include "core/analysis/LinearProgram.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>

namespace awb {

namespace {

using Tableau = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

constexpr double kPivotTol = 1e-9;     // smallest pivot (relative to the column's scale)
constexpr double kCostTol = 1e-11;     // reduced costs above -kCostTol count as optimal
constexpr int kDegenerateRun = 40;     // degenerate pivots before switching to Bland's rule

// Rows 0..m-1: the constraints (columns 0..n-1 structural, n..n+m-1 artificial, last: rhs);
// row m: the reduced costs, with minus the objective value in the last column.
class Simplex {
public:
    Simplex(const Mat &A, const Vec &b) : m_m(int(A.rows())), m_n(int(A.cols()))
    {
        m_T = Tableau::Zero(m_m + 1, m_n + m_m + 1);
        for (int i = 0; i < m_m; ++i) {
            const double s = b(i) < 0 ? -1.0 : 1.0;   // rhs >= 0
            m_T.row(i).head(m_n) = s * A.row(i);
            m_T(i, m_n + i) = 1.0;
            m_T(i, rhs()) = s * b(i);
        }
        m_basis.resize(size_t(m_m));
        for (int i = 0; i < m_m; ++i)
            m_basis[size_t(i)] = m_n + i;
        m_bScale = 1.0 + b.cwiseAbs().sum();
        m_maxIterations = 50 * (m_m + m_n) + 1000;
    }

    // Phase 1: minimise the sum of the artificials: Optimal when feasible.
    LpResult::Status phase1(LpResult &out)
    {
        m_T.row(m_m).setZero();
        for (int i = 0; i < m_m; ++i)
            m_T.row(m_m) -= m_T.row(i);
        for (int i = 0; i < m_m; ++i)
            m_T(m_m, m_n + i) = 0.0;
        const LpResult::Status st = run(m_n + m_m, out);
        if (st != LpResult::Optimal)
            return st;   // phase 1 is bounded below: only the iteration limit is left
        if (-m_T(m_m, rhs()) > 1e-9 * m_bScale)
            return LpResult::Infeasible;
        // Pivot the artificials left in the basis (at level zero) out where possible; the
        // rows where that is impossible are redundant and never pivoted on again.
        for (int i = 0; i < m_m; ++i) {
            if (m_basis[size_t(i)] < m_n)
                continue;
            int best = -1;
            double bestAbs = kPivotTol;
            for (int j = 0; j < m_n; ++j)
                if (std::abs(m_T(i, j)) > bestAbs) {
                    bestAbs = std::abs(m_T(i, j));
                    best = j;
                }
            if (best >= 0)
                pivot(i, best);
        }
        return LpResult::Optimal;
    }

    LpResult::Status phase2(const Vec &c, LpResult &out)
    {
        m_T.row(m_m).setZero();
        m_T.row(m_m).head(m_n) = c.transpose();
        for (int i = 0; i < m_m; ++i)
            if (m_basis[size_t(i)] < m_n)
                m_T.row(m_m) -= c(m_basis[size_t(i)]) * m_T.row(i);
        return run(m_n, out);   // artificials may no longer enter
    }

    void solution(LpResult &out) const
    {
        out.x = Vec::Zero(m_n);
        out.basis.clear();
        for (int i = 0; i < m_m; ++i)
            if (m_basis[size_t(i)] < m_n) {
                out.x(m_basis[size_t(i)]) = std::max(0.0, m_T(i, rhs()));
                out.basis.push_back(m_basis[size_t(i)]);
            }
        out.value = -m_T(m_m, rhs());
    }

private:
    int rhs() const { return m_n + m_m; }

    void pivot(int r, int col)
    {
        m_T.row(r) /= m_T(r, col);
        for (int i = 0; i <= m_m; ++i)
            if (i != r && m_T(i, col) != 0.0)
                m_T.row(i) -= m_T(i, col) * m_T.row(r);
        m_T(r, col) = 1.0;
        m_basis[size_t(r)] = col;
    }

    // Simplex iterations over the columns [0, columns).
    LpResult::Status run(int columns, LpResult &out)
    {
        int degenerate = 0;
        bool bland = false;
        while (out.iterations < m_maxIterations) {
            ++out.iterations;
            int enter = -1;
            double most = -kCostTol;
            for (int j = 0; j < columns; ++j) {
                const double d = m_T(m_m, j);
                if (d < most) {
                    enter = j;
                    if (bland)
                        break;
                    most = d;
                }
            }
            if (enter < 0)
                return LpResult::Optimal;
            double colScale = 0.0;
            for (int i = 0; i < m_m; ++i)
                colScale = std::max(colScale, std::abs(m_T(i, enter)));
            int leave = -1;
            double ratio = std::numeric_limits<double>::infinity();
            for (int i = 0; i < m_m; ++i) {
                const double a = m_T(i, enter);
                if (a <= kPivotTol * std::max(1.0, colScale))
                    continue;
                const double q = std::max(0.0, m_T(i, rhs())) / a;
                const bool tie = leave >= 0 && std::abs(q - ratio) <= 1e-13 * (1.0 + ratio);
                if (leave < 0 || (!tie && q < ratio)
                    || (tie && (bland ? m_basis[size_t(i)] < m_basis[size_t(leave)]
                                      : a > m_T(leave, enter)))) {
                    leave = i;
                    ratio = q;
                }
            }
            if (leave < 0)
                return LpResult::Unbounded;
            if (ratio <= 1e-14) {
                if (++degenerate > kDegenerateRun)
                    bland = true;
            } else {
                degenerate = 0;
            }
            pivot(leave, enter);
        }
        return LpResult::IterationLimit;
    }

    int m_m, m_n;
    Tableau m_T;
    std::vector<int> m_basis;
    double m_bScale = 1.0;
    int m_maxIterations = 0;
};

} // namespace

LpResult solveStandardLp(const Mat &A, const Vec &b, const Vec &c)
{
    LpResult out;
    Simplex s(A, b);
    out.status = s.phase1(out);
    if (out.status != LpResult::Optimal)
        return out;
    out.status = s.phase2(c, out);
    if (out.status == LpResult::Optimal)
        s.solution(out);
    return out;
}

AbsoluteCombination absoluteCombination(const Mat &V, const Vec &y)
{
    AbsoluteCombination out;
    const int L = int(V.rows()), n = int(V.cols());
    if (y.cwiseAbs().maxCoeff() == 0.0 || L == 0) {
        out.feasible = true;
        out.norm = 0.0;
        return out;
    }
    if (n == 0)
        return out;
    Mat A(L, 2 * n);
    A.leftCols(n) = V;
    A.rightCols(n) = -V;
    const LpResult lp = solveStandardLp(A, y, Vec::Ones(2 * n));
    if (lp.status != LpResult::Optimal)
        return out;
    // lambda on the basic columns; polish it by least squares on those columns (the tableau
    // accumulates rounding over the pivots).
    std::vector<int> cols;
    std::vector<double> sign;
    for (int j : lp.basis) {
        cols.push_back(j % n);
        sign.push_back(j < n ? 1.0 : -1.0);
    }
    Vec lambda = Vec::Zero(n);
    for (size_t k = 0; k < cols.size(); ++k)
        lambda(cols[k]) += sign[k] * lp.x(lp.basis[k]);
    double residual = (V * lambda - y).norm();
    if (!cols.empty()) {
        Mat B(L, Eigen::Index(cols.size()));
        for (size_t k = 0; k < cols.size(); ++k)
            B.col(Eigen::Index(k)) = V.col(cols[k]);
        const Vec coef = B.colPivHouseholderQr().solve(y);
        Vec polished = Vec::Zero(n);
        for (size_t k = 0; k < cols.size(); ++k)
            polished(cols[k]) += coef(Eigen::Index(k));
        const double r2 = (V * polished - y).norm();
        if (coef.allFinite() && r2 < residual
            && polished.cwiseAbs().sum() <= lambda.cwiseAbs().sum() * (1.0 + 1e-9) + 1e-15) {
            lambda = polished;
            residual = r2;
        }
    }
    out.feasible = true;
    out.residual = residual;
    out.norm = lambda.cwiseAbs().sum();
    for (int j = 0; j < n; ++j)
        if (lambda(j) != 0.0)
            out.lambda.emplace_back(j, lambda(j));
    return out;
}

} // namespace awb
