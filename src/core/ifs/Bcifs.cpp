#include "core/ifs/Bcifs.h"

#include "core/Decompositions.h"
#include "core/Messages.h"
#include "core/schemes/Scheme.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace awb {

namespace {


// "0.696" or "0.112 ± 0.449i" (complex eigenvalues of real matrices come in pairs).
// (Real numbers too: as streamedNumber.)
std::string fmt(Complex z)
{
    return z.imag() == 0.0 ? streamedNumber(z.real())
                           : streamedNumber(z.real()) + " ± " + streamedNumber(std::abs(z.imag()))
                                 + "i";
}

Vec column(std::initializer_list<double> v)
{
    return Eigen::Map<const Vec>(v.begin(), Eigen::Index(v.size()));
}

std::string size(const Mat &M)
{
    return std::to_string(M.rows()) + " x " + std::to_string(M.cols());
}

// Columns of a barycentric operator must sum to 1; names the first that does not.
void requireColumnSums(const Mat &T, const std::string &label)
{
    for (Eigen::Index c = 0; c < T.cols(); ++c) {
        const double sum = T.col(c).sum();
        if (std::abs(sum - 1.0) > 1e-9 * std::max(1.0, T.col(c).cwiseAbs().sum()))
            throw InputError(formatMessage(
                coreTranslate("awb::ifs", "column %1 of %2 sums to %3, not 1: it does not map "
                                          "barycentric points to barycentric points"),
                c + 1, label, fmt(sum)));
    }
}

} // namespace

std::string toString(ConstraintKind kind)
{
    switch (kind) {
    case ConstraintKind::Incidence: return "incidence";
    case ConstraintKind::Adjacency: return "adjacency";
    case ConstraintKind::Junction: return "junction";
    }
    return "incidence";
}

int Bcifs::addCell(std::string name, CellKind kind, int dim)
{
    cells.push_back({std::move(name), kind, dim});
    return int(cells.size()) - 1;
}

int Bcifs::addOperator(std::string name, OperatorKind kind, const std::string &from,
                       const std::string &to, const Mat &T)
{
    operators.push_back({std::move(name), kind, cellIndex(from), cellIndex(to), T});
    return int(operators.size()) - 1;
}

void Bcifs::addConstraint(std::string name, ConstraintKind kind,
                          const std::vector<std::string> &lhs,
                          const std::vector<std::string> &rhs)
{
    BcifsConstraint c{std::move(name), kind, {}, {}};
    for (const auto &op : lhs)
        c.lhs.push_back(operatorIndex(op));
    for (const auto &op : rhs)
        c.rhs.push_back(operatorIndex(op));
    constraints.push_back(std::move(c));
}

int Bcifs::cellIndex(const std::string &name) const
{
    for (size_t i = 0; i < cells.size(); ++i)
        if (cells[i].name == name)
            return int(i);
    throw InputError(formatMessage(coreTranslate("awb::ifs", "the BCIFS has no cell '%1'"), name));
}

int Bcifs::operatorIndex(const std::string &name) const
{
    for (size_t i = 0; i < operators.size(); ++i)
        if (operators[i].name == name)
            return int(i);
    throw InputError(
        formatMessage(coreTranslate("awb::ifs", "the BCIFS has no operator '%1'"), name));
}

const Mat &Bcifs::matrix(const std::string &op) const { return operators[operatorIndex(op)].T; }

void Bcifs::setMatrix(const std::string &op, const Mat &T) { operators[operatorIndex(op)].T = T; }

std::string Bcifs::equation(const BcifsConstraint &c) const
{
    auto path = [this](const std::vector<int> &ops) {
        std::string s;
        for (int o : ops)
            s += (s.empty() ? "" : " ") + operators.at(o).name;
        return s;
    };
    return path(c.lhs) + " = " + path(c.rhs);
}

void Bcifs::validate() const
{
    if (cells.empty())
        throw InputError(coreTranslate("awb::ifs", "the BCIFS has no cells"));
    const int N = int(cells.size());
    for (const BcifsCell &c : cells)
        if (c.dim < 1)
            throw InputError(formatMessage(
                coreTranslate("awb::ifs", "cell '%1' has dimension %2; it needs at least one "
                                          "control point"),
                c.name, c.dim));
    for (const BcifsOperator &o : operators) {
        if (o.from < 0 || o.from >= N || o.to < 0 || o.to >= N)
            throw InputError(formatMessage(
                coreTranslate("awb::ifs", "operator '%1' joins a cell that does not exist"),
                o.name));
        const BcifsCell &a = cells[o.from], &b = cells[o.to];
        const std::string label = formatMessage(
            coreTranslate("awb::ifs", "operator '%1' (%2 -> %3)"), o.name, a.name, b.name);
        const bool kindsOk =
            (o.kind == OperatorKind::Subdivision && a.kind == b.kind && a.kind != CellKind::Model)
            || (o.kind == OperatorKind::Boundary && a.kind == CellKind::Edge
                && b.kind == CellKind::Vertex)
            || (o.kind == OperatorKind::Placement && a.kind == CellKind::Model
                && b.kind != CellKind::Model);
        if (!kindsOk)
            throw InputError(formatMessage(
                coreTranslate("awb::ifs", "%1 joins cells of the wrong kinds: subdivisions join "
                                          "edges or vertices, boundary operators go from an edge "
                                          "to a vertex, placements from the model"),
                label));
        if (o.T.rows() != a.dim || o.T.cols() != b.dim)
            throw InputError(formatMessage(
                coreTranslate("awb::ifs", "%1 is %2; it must be %3 x %4 (column convention: rows "
                                          "= dimension of '%5', columns = dimension of '%6')"),
                label, size(o.T), a.dim, b.dim, a.name, b.name));
        requireFinite(o.T, label);
        if (o.kind != OperatorKind::Placement)
            requireColumnSums(o.T, label);
    }
    for (int c = 0; c < N; ++c) {
        if (cells[c].kind != CellKind::Edge)
            continue;
        const bool subdivided = std::any_of(operators.begin(), operators.end(), [c](auto &o) {
            return o.kind == OperatorKind::Subdivision && o.from == c;
        });
        if (!subdivided)
            throw InputError(formatMessage(
                coreTranslate("awb::ifs", "edge cell '%1' has no subdivision operator: its "
                                          "attractor would be empty"),
                cells[c].name));
    }
    for (const BcifsConstraint &c : constraints) {
        const std::string label =
            formatMessage(coreTranslate("awb::ifs", "constraint %1"), c.name);
        for (const std::vector<int> *p : {&c.lhs, &c.rhs}) {
            if (p->empty() || std::any_of(p->begin(), p->end(), [this](int o) {
                    return o < 0 || o >= int(operators.size());
                }))
                throw InputError(formatMessage(
                    coreTranslate("awb::ifs", "%1 has an empty side or an unknown operator"),
                    label));
            for (size_t k = 1; k < p->size(); ++k) {
                const BcifsOperator &x = operators[(*p)[k - 1]], &y = operators[(*p)[k]];
                if (x.to != y.from)
                    throw InputError(formatMessage(
                        coreTranslate("awb::ifs", "%1: %2 ends at '%3' but %4 starts at '%5'"),
                        label, x.name, cells[x.to].name, y.name, cells[y.from].name));
            }
        }
        if (operators[c.lhs.front()].from != operators[c.rhs.front()].from
            || operators[c.lhs.back()].to != operators[c.rhs.back()].to)
            throw InputError(formatMessage(
                coreTranslate("awb::ifs", "%1 (%2) compares paths between different cells"),
                label, equation(c)));
    }
}

namespace {

Mat pathMatrix(const Bcifs &b, const std::vector<int> &path)
{
    Mat M = b.operators[path.front()].T;
    for (size_t k = 1; k < path.size(); ++k)
        M = (M * b.operators[path[k]].T).eval();
    return M;
}

} // namespace

ConstraintReport checkConstraints(const Bcifs &bcifs, double tol)
{
    bcifs.validate();
    ConstraintReport report;
    std::vector<const ConstraintResidual *> violated;
    for (const BcifsConstraint &c : bcifs.constraints) {
        const Mat D = (pathMatrix(bcifs, c.lhs) - pathMatrix(bcifs, c.rhs)).cwiseAbs();
        Eigen::Index r = 0, k = 0;
        const double res = D.size() ? D.maxCoeff(&r, &k) : 0.0;
        report.residuals.push_back({c.name, c.kind, bcifs.equation(c), res, int(r), int(k)});
    }
    for (const auto &r : report.residuals)
        if (r.residual > tol)
            violated.push_back(&r);
    if (violated.empty())
        return report;
    std::sort(violated.begin(), violated.end(),
              [](auto *a, auto *b) { return a->residual > b->residual; });
    report.satisfied = false;
    const ConstraintResidual &w = *violated.front();
    report.message = formatMessage(
        coreTranslate("awb::ifs", "%1 constraint %2 %3 is violated by %4 (entry row %5, column "
                                  "%6)"),
        toString(w.kind), w.name, w.equation, fmt(w.residual), w.row + 1, w.column + 1);
    if (violated.size() > 1) {
        report.message += coreTranslate("awb::ifs", "; also violated:");
        for (size_t i = 1; i < violated.size(); ++i)
            report.message += " " + violated[i]->name + " (" + fmt(violated[i]->residual) + ")";
    }
    return report;
}

Cifs toCifs(const Bcifs &bcifs)
{
    bcifs.validate();
    Cifs cifs;
    std::vector<int> state(bcifs.cells.size(), -1);
    for (size_t c = 0; c < bcifs.cells.size(); ++c) {
        if (bcifs.cells[c].kind != CellKind::Edge)
            continue;
        const auto it = std::find_if(bcifs.operators.begin(), bcifs.operators.end(),
                                     [c](auto &o) {
                                         return o.kind == OperatorKind::Placement
                                                && o.to == int(c);
                                     });
        if (it == bcifs.operators.end())
            throw InputError(formatMessage(
                coreTranslate("awb::ifs", "edge cell '%1' has no placement (control points): it "
                                          "cannot be drawn"),
                bcifs.cells[c].name));
        state[c] = cifs.addState(bcifs.cells[c].name, it->T.transpose());
    }
    for (const BcifsOperator &o : bcifs.operators)
        if (o.kind == OperatorKind::Subdivision && state[o.from] >= 0)
            cifs.addColumnTransition(o.name, state[o.from], state[o.to], o.T);
    return cifs;
}

// ---- spectral analysis -------------------------------------------------------------------

HalfTangent halfTangent(const Mat &T, const Mat &C, const Mat &P)
{
    const Eigen::Index n = T.rows();
    if (T.cols() != n || n < 2)
        throw InputError(formatMessage(
            coreTranslate("awb::ifs", "the junction matrix must be square and at least 2 x 2, "
                                      "got %1"),
            size(T)));
    if (C.rows() != n || C.cols() == 0)
        throw InputError(formatMessage(
            coreTranslate("awb::ifs", "the copy's placement must have %1 rows (one per control "
                                      "point of the junction), got %2"),
            n, size(C)));
    if (P.size() && P.rows() != n)
        throw InputError(formatMessage(
            coreTranslate("awb::ifs", "the junction has %1 control points, got %2"), n,
            P.rows()));
    requireFinite(T, coreTranslate("awb::ifs", "junction matrix"));
    requireFinite(C, coreTranslate("awb::ifs", "copy placement"));
    requireColumnSums(T, coreTranslate("awb::ifs", "the junction matrix"));
    requireColumnSums(C, coreTranslate("awb::ifs", "the copy placement"));

    const Spectrum s = spectrum(T);
    size_t one = 0;
    for (size_t i = 1; i < s.values.size(); ++i)
        if (std::abs(s.values[i] - 1.0) < std::abs(s.values[one] - 1.0))
            one = i;
    HalfTangent h;
    CMat V(n, n);
    for (Eigen::Index i = 0; i < n; ++i)
        V.col(i) = s.vectors[i];
    Eigen::JacobiSVD<CMat> svd(V);
    const auto &sv = svd.singularValues();
    h.eigenbasisComplete = sv(n - 1) > 1e-8 * sv(0) && s.multiplicity[one] == 1;
    const Subdominant global = subdominant(s);
    Subdominant governing = global;
    CVec coefSum;  // component of the copy's control points along each eigenvector, summed
    std::vector<size_t> kept;
    if (h.eigenbasisComplete) {
        Vec v1 = s.vectors[one].real();
        v1 /= v1.sum();
        const CMat rel = (C - v1 * RowVec::Ones(C.cols())).cast<Complex>();
        const CMat coef = V.fullPivLu().solve(rel);  // n x m
        const double scale = std::max(rel.cwiseAbs().maxCoeff(), 1e-300);
        Spectrum f;
        for (size_t i = 0; i < s.values.size(); ++i)
            if (i != one && coef.row(i).cwiseAbs().maxCoeff() > 1e-8 * scale) {
                f.values.push_back(s.values[i]);
                f.vectors.push_back(s.vectors[i]);
                f.multiplicity.push_back(s.multiplicity[i]);
                kept.push_back(i);
            }
        governing = subdominant(f, false);
        coefSum = coef.rowwise().sum();
        h.skippedSubdominant = governing.modulus < global.modulus - 1e-9;
    }
    h.kind = governing.kind;
    h.values = governing.values;
    h.vectors = governing.vectors;

    std::ostringstream os;
    os.precision(4);
    if (governing.values.empty()) {
        os << coreTranslate("awb::ifs", "the copies collapse onto the fixed point: no tangent "
                                        "information");
    } else {
        os << formatMessage(coreTranslate("awb::ifs", "lambda = %1: %2"),
                            fmt(governing.values.front()), governing.meaning());
        if (governing.modulus >= 1.0 - 1e-12)
            os << coreTranslate("awb::ifs", "; |lambda| >= 1, so the junction matrix does not "
                                            "contract");
    }
    if (h.skippedSubdominant)
        os << formatMessage(coreTranslate("awb::ifs", " (the copy has no component along the "
                                                      "subdominant eigenvector, lambda = %1, so "
                                                      "the next eigenvalue governs)"),
                            fmt(global.values.front()));
    if (!h.eigenbasisComplete)
        os << coreTranslate("awb::ifs", " (the eigenvectors are not complete; the copy's "
                                        "components were not examined)");
    if (h.kind == SubdominantKind::RealPositive && governing.multiplicity == 1) {
        const Vec v = h.vectors.front().real();
        // The side of the fixed point the copy lies on: the sign of its summed component.
        double sign = 1.0;
        for (size_t i : kept)
            if (std::abs(s.values[i] - h.values.front()) < 1e-12)
                sign = coefSum(i).real() < 0 ? -1.0 : 1.0;
        const RowVec dir = P.size() ? RowVec(sign * v.transpose() * P)
                                    : RowVec(sign * v.transpose());
        if (dir.norm() > 1e-12 * std::max(1.0, P.size() ? P.cwiseAbs().maxCoeff() : 1.0))
            h.direction = dir / dir.norm();
        else
            os << "; the control points have no extent along the eigenvector, so the "
                  "half-tangent direction is undefined";
    }
    h.verdict = os.str();
    return h;
}

bool isG1(const HalfTangent &left, const HalfTangent &right, double angleTol)
{
    if (left.kind != SubdominantKind::RealPositive || right.kind != SubdominantKind::RealPositive
        || left.direction.size() == 0 || left.direction.size() != right.direction.size())
        return false;
    // Angle between left and -right, robust near 0: 2 atan2(|a - b|, |a + b|) for unit a, b.
    const double angle =
        2.0 * std::atan2((left.direction + right.direction).norm(),
                         (left.direction - right.direction).norm());
    return angle <= angleTol;
}

// ---- the junction of 003 §3-§4.1 ---------------------------------------------------------

JunctionMatrices junctionMatrices(const Mat &Vl, const Mat &Vr, const Mat &X, const Mat &Y)
{
    if (Vl.rows() != Vl.cols() || Vr.rows() != Vr.cols() || Vl.rows() == 0 || Vr.rows() == 0)
        throw InputError(formatMessage(
            coreTranslate("awb::ifs", "vertex subdivisions must be square and non-empty, got %1 "
                                      "and %2"),
            size(Vl), size(Vr)));
    const Eigen::Index nl = Vl.rows(), nr = Vr.rows(), n = nl + nr;
    if (X.rows() != n || Y.rows() != n)
        throw InputError(formatMessage(
            coreTranslate("awb::ifs", "the free columns must have %1 rows (n_l + n_r), got X %2 "
                                      "and Y %3"),
            n, size(X), size(Y)));
    requireFinite(X, coreTranslate("awb::ifs", "free columns X of T^l"));
    requireFinite(Y, coreTranslate("awb::ifs", "free columns Y of T^r"));
    requireColumnSums(X, coreTranslate("awb::ifs", "the free columns X of T^l"));
    requireColumnSums(Y, coreTranslate("awb::ifs", "the free columns Y of T^r"));
    JunctionMatrices m;
    m.Tl = Mat::Zero(n, nl + X.cols());
    m.Tl.topLeftCorner(nl, nl) = Vl;
    m.Tl.rightCols(X.cols()) = X;
    m.Tr = Mat::Zero(n, Y.cols() + nr);
    m.Tr.leftCols(Y.cols()) = Y;
    m.Tr.bottomRightCorner(nr, nr) = Vr;
    m.Ti.resize(n, n);
    m.Ti << m.Tl.rightCols(nl), m.Tr.leftCols(nr);
    return m;
}

namespace {

Mat selection(Eigen::Index rows, Eigen::Index first, Eigen::Index count)
{
    Mat D = Mat::Zero(rows, count);
    D.middleRows(first, count).setIdentity();
    return D;
}

// A curve's own cells and equations (003 §2.3-§2.4): cell c, vertex cell v, ∂^c_0, ∂^c_1,
// V^c, placement P^c, and ∂_0 V = T_0 ∂_0, ∂_1 V = T_1 ∂_1, T_0 ∂_1 = T_1 ∂_0.
void addCurve(Bcifs &b, const std::string &n, const JunctionCurve &c, const Mat &V,
              const std::string &eqLeft, const std::string &eqRight)
{
    const Eigen::Index m = c.T0.rows(), p = c.vertexDim;
    const std::string d0 = "∂^" + n + "_0", d1 = "∂^" + n + "_1";
    const std::string T0 = (n == "l" ? "L" : n == "r" ? "R" : n) + "0";
    const std::string T1 = (n == "l" ? "L" : n == "r" ? "R" : n) + "1";
    b.addCell(n, CellKind::Edge, int(m));
    b.addCell("v" + n, CellKind::Vertex, int(p));
    b.addOperator(T0, OperatorKind::Subdivision, n, n, c.T0);
    b.addOperator(T1, OperatorKind::Subdivision, n, n, c.T1);
    b.addOperator("V^" + n, OperatorKind::Subdivision, "v" + n, "v" + n, V);
    b.addOperator(d0, OperatorKind::Boundary, n, "v" + n, selection(m, 0, p));
    b.addOperator(d1, OperatorKind::Boundary, n, "v" + n, selection(m, m - p, p));
    b.addOperator("P^" + n, OperatorKind::Placement, "model", n, c.P.transpose());
    b.addConstraint(eqLeft, ConstraintKind::Incidence, {d0, "V^" + n}, {T0, d0});
    b.addConstraint(eqRight, ConstraintKind::Incidence, {d1, "V^" + n}, {T1, d1});
    b.addConstraint("(" + n + ", halves)", ConstraintKind::Adjacency, {T0, d1}, {T1, d0});
}

void requireCurve(const JunctionCurve &c, const std::string &which)
{
    const Eigen::Index m = c.T0.rows();
    if (c.T0.cols() != m || c.T1.rows() != m || c.T1.cols() != m || m == 0)
        throw InputError(formatMessage(
            coreTranslate("awb::ifs", "the %1 curve's subdivision operators must both be m x m, "
                                      "got %2 and %3"),
            which, size(c.T0), size(c.T1)));
    if (c.vertexDim < 1 || c.vertexDim > m)
        throw InputError(formatMessage(
            coreTranslate("awb::ifs", "the %1 curve's vertex dimension must be in 1..%2, got %3"),
            which, m, c.vertexDim));
    if (c.P.rows() != m)
        throw InputError(formatMessage(
            coreTranslate("awb::ifs", "the %1 curve needs %2 control points, got %3"), which, m,
            c.P.rows()));
    requireFinite(c.P, formatMessage(coreTranslate("awb::ifs", "control points of the %1 curve"),
                                     which));
}

// The core's row-stochastic S_i (Scheme.h) in 003's column convention: T_i = S_i^T. The end
// point of a uniform B-spline of degree n depends on n control points: the vertex dimension.
JunctionCurve bsplineCurve(int degree, int m, const Mat &P)
{
    const SubdivisionMatrices s = bsplineScheme(degree).matrices(m);
    return {s.S[0].transpose(), s.S[1].transpose(), degree, P};
}

} // namespace

Bcifs junctionBcifs(const JunctionCurve &left, const JunctionCurve &right, const Mat &X,
                    const Mat &Y)
{
    requireCurve(left, "left");
    requireCurve(right, "right");
    if (left.P.cols() != right.P.cols())
        throw InputError(coreTranslate("awb::ifs", "both curves' control points must have the same "
                                                   "dimension"));
    const int nl = left.vertexDim, nr = right.vertexDim;
    const Mat Vl = left.T1.bottomRightCorner(nl, nl), Vr = right.T0.topLeftCorner(nr, nr);
    const JunctionMatrices jm = junctionMatrices(Vl, Vr, X, Y);
    if (jm.Tl.cols() != left.T0.rows() || jm.Tr.cols() != right.T0.rows())
        throw InputError(coreTranslate("awb::ifs", "X must have m_l - n_l columns and Y m_r - "
                                                   "n_r"));
    Bcifs b;
    b.addCell("model", CellKind::Model, int(left.P.cols()));
    addCurve(b, "l", left, Vl, "(l, left end)", "(3)");
    addCurve(b, "r", right, Vr, "(6)", "(r, right end)");
    const int n = nl + nr;
    b.addCell("i", CellKind::Edge, n);
    b.addOperator("∂^i_0", OperatorKind::Boundary, "i", "vl", selection(n, 0, nl));
    b.addOperator("∂^i_1", OperatorKind::Boundary, "i", "vr", selection(n, nl, nr));
    b.addOperator("T^l", OperatorKind::Subdivision, "i", "l", jm.Tl);
    b.addOperator("T^r", OperatorKind::Subdivision, "i", "r", jm.Tr);
    b.addOperator("T^i", OperatorKind::Subdivision, "i", "i", jm.Ti);
    // Eqs. (1), (4): the junction's end control points are the curves' end control points.
    Mat Pi(left.P.cols(), n);
    Pi << left.P.bottomRows(nl).transpose(), right.P.topRows(nr).transpose();
    b.addOperator("P^i", OperatorKind::Placement, "model", "i", Pi);
    using K = ConstraintKind;
    b.addConstraint("(1)", K::Junction, {"P^i", "∂^i_0"}, {"P^l", "∂^l_1"});
    b.addConstraint("(2)", K::Incidence, {"T^l", "∂^l_0"}, {"∂^i_0", "V^l"});
    b.addConstraint("(4)", K::Junction, {"P^i", "∂^i_1"}, {"P^r", "∂^r_0"});
    b.addConstraint("(5)", K::Incidence, {"T^r", "∂^r_1"}, {"∂^i_1", "V^r"});
    b.addConstraint("(7)", K::Adjacency, {"T^r", "∂^r_0"}, {"T^i", "∂^i_1"});
    b.addConstraint("(8)", K::Adjacency, {"T^l", "∂^l_1"}, {"T^i", "∂^i_0"});
    return b;
}

JunctionCurve cubicCurve(const Mat &P) { return bsplineCurve(3, 4, P); }
JunctionCurve quadraticCurve(const Mat &P) { return bsplineCurve(2, 3, P); }

namespace {
// X = (a, b, c, d, e)^T and Y = (k, l, m, n, p)^T of 003 §4.1.
std::pair<Vec, Vec> freeColumns(const JunctionParameters &p)
{
    const double v[] = {p.a, p.b, p.c, p.d, p.k, p.l, p.m, p.n};
    for (int i = 0; i < 8; ++i)
        if (!std::isfinite(v[i]))
            throw InputError(formatMessage(
                coreTranslate("awb::ifs", "junction parameter %1 is not a finite number"),
                std::string(1, "abcdklmn"[i])));
    return {column({p.a, p.b, p.c, p.d, p.e()}), column({p.k, p.l, p.m, p.n, p.p()})};
}
} // namespace

JunctionMatrices cubicQuadraticMatrices(const JunctionParameters &p)
{
    const auto [X, Y] = freeColumns(p);
    const JunctionCurve l = cubicCurve(Mat::Zero(4, 2)), r = quadraticCurve(Mat::Zero(3, 2));
    return junctionMatrices(l.T1.bottomRightCorner(3, 3), r.T0.topLeftCorner(2, 2), X, Y);
}

Bcifs cubicQuadraticJunction(const JunctionParameters &p, const Mat &Pl, const Mat &Pr)
{
    const auto [X, Y] = freeColumns(p);
    return junctionBcifs(cubicCurve(Pl), quadraticCurve(Pr), X, Y);
}

JunctionAnalysis analyseJunction(const JunctionMatrices &m, const Mat &Pi)
{
    JunctionAnalysis a;
    a.left = halfTangent(m.Ti, m.Tl, Pi);
    a.right = halfTangent(m.Ti, m.Tr, Pi);
    a.spectrum = spectrum(m.Ti);
    a.subdominant = subdominant(a.spectrum);
    a.g1 = isG1(a.left, a.right);
    std::ostringstream os;
    os.precision(4);
    if (a.subdominant.values.empty())
        os << coreTranslate("awb::ifs", "T^i has no subdominant eigenvalue");
    else
        os << formatMessage(coreTranslate("awb::ifs", "lambda_2 = %1 (%2)"),
                            fmt(a.subdominant.values.front()), toString(a.subdominant.kind));
    if (a.subdominant.modulus >= 1.0 - 1e-12)
        os << coreTranslate("awb::ifs", ": |lambda_2| >= 1, T^i does not contract and the "
                                        "junction does not converge");
    else if (a.g1)
        os << coreTranslate("awb::ifs", ": both sides have half-tangents along the same "
                                        "eigenvector, from opposite sides: G1 at the junction "
                                        "point");
    else if (a.left.kind == SubdominantKind::RealPositive
             && a.right.kind == SubdominantKind::RealPositive)
        os << coreTranslate("awb::ifs", ": both sides have half-tangents, but they are not "
                                        "opposite (a corner or cusp)");
    else
        os << ": " << a.subdominant.meaning();
    a.verdict = os.str();
    return a;
}

JunctionAnalysis analyseCubicQuadratic(const JunctionParameters &p, const Mat &Pl,
                                       const Mat &Pr)
{
    const JunctionMatrices m = cubicQuadraticMatrices(p);
    if (Pl.size() == 0 && Pr.size() == 0)
        return analyseJunction(m);
    if (Pl.rows() != 4 || Pr.rows() != 3 || Pl.cols() != Pr.cols())
        throw InputError(formatMessage(
            coreTranslate("awb::ifs", "the cubic needs 4 and the quadratic 3 control points of "
                                      "one dimension, got %1 and %2"),
            size(Pl), size(Pr)));
    Mat Pi(5, Pl.cols());
    Pi << Pl.bottomRows(3), Pr.topRows(2);
    return analyseJunction(m, Pi);
}

// ---- the refined junction of 003 §5 ------------------------------------------------------

namespace {

// No range check: refinedRangeJ/R build it to read the fixed blocks.
RefinedMatrices buildRefined(double j, double r)
{
    const JunctionCurve cl = cubicCurve(Mat::Zero(4, 2)), cr = quadraticCurve(Mat::Zero(3, 2));
    // As in §3 but il = (cubic vertex 3, handle, vertex) and ir = (vertex, handle, quadratic
    // vertex 2): T^l's free column is e_4 (the handle, d = 1), T^r's is e_2.
    RefinedMatrices m;
    m.Tl = Mat::Zero(5, 4);
    m.Tl.topLeftCorner(3, 3) = cl.T1.bottomRightCorner(3, 3);
    m.Tl(3, 3) = 1.0;
    m.Tr = Mat::Zero(4, 3);
    m.Tr(1, 0) = 1.0;
    m.Tr.bottomRightCorner(2, 2) = cr.T0.topLeftCorner(2, 2);
    m.Til.resize(5, 5);
    m.Til << m.Tl.rightCols(3), column({0, 0, 0, j, 1 - j}), column({0, 0, 0, 0, 1});
    m.Tir.resize(4, 4);
    m.Tir << column({1, 0, 0, 0}), column({1 - r, r, 0, 0}), m.Tr.leftCols(2);
    return m;
}

// The other eigenvalues of T^il (T^ir) are those of its fixed block; the parameter must exceed
// them to be subdominant and stay below 1 for the map to contract.
ParameterRange rangeAbove(const Mat &fixedBlock, const std::string &name, const char *matrix)
{
    const double lo = spectrum(fixedBlock).spectralRadius;
    return {lo, 1.0,
            formatMessage(coreTranslate("awb::ifs", "%1 must exceed the other eigenvalues of %2 "
                                                    "(largest modulus %3) to be subdominant, and "
                                                    "be below 1 for %2 to contract"),
                          name, matrix, fmt(lo))};
}
} // namespace

// T^il is block lower triangular: its fixed top-left 3 x 3 block holds 1/8, 1/2, 0 and
// [[j, 0], [1-j, 1]] adds j and 1. T^ir is block upper triangular: [[1, 1-r], [0, r]] and the
// fixed [[0, 3/4], [0, 1/4]].
ParameterRange refinedRangeJ()
{
    return rangeAbove(buildRefined(0.75, 0.5).Til.topLeftCorner(3, 3), "j", "T^il");
}
ParameterRange refinedRangeR()
{
    return rangeAbove(buildRefined(0.75, 0.5).Tir.bottomRightCorner(2, 2), "r", "T^ir");
}

void checkRefinedParameters(const RefinedParameters &p)
{
    const std::pair<const char *, double> params[] = {{"j", p.j}, {"r", p.r}};
    for (const auto &[name, v] : params) {
        const ParameterRange range = name[0] == 'j' ? refinedRangeJ() : refinedRangeR();
        if (!std::isfinite(v))
            throw InputError(formatMessage(
                coreTranslate("awb::ifs", "refined junction parameter %1 is not a finite number"),
                name));
        if (!(v > range.lo && v < range.hi))
            throw InputError(formatMessage(
                coreTranslate("awb::ifs", "refined junction parameter %1 = %2 is outside its "
                                          "admissible range (%3, %4): %5"),
                name, fmt(v), fmt(range.lo), fmt(range.hi), range.why));
    }
}

RefinedMatrices refinedMatrices(const RefinedParameters &p)
{
    checkRefinedParameters(p);
    return buildRefined(p.j, p.r);
}

namespace {
// il: the cubic's last three, the left handle, the vertex; ir: vertex, right handle, the
// quadratic's first two (rows).
std::pair<Mat, Mat> refinedControlPoints(const Mat &Pl, const Mat &Pr, const Mat &H)
{
    if (Pl.rows() != 4 || Pr.rows() != 3 || H.rows() != 3 || Pl.cols() != Pr.cols()
        || Pl.cols() != H.cols())
        throw InputError(formatMessage(
            coreTranslate("awb::ifs", "the refined junction needs 4 cubic, 3 quadratic and 3 "
                                      "handle control points of one dimension, got %1, %2 and "
                                      "%3"),
            size(Pl), size(Pr), size(H)));
    requireFinite(H, coreTranslate("awb::ifs", "handles of the refined junction"));
    Mat il(5, Pl.cols()), ir(4, Pl.cols());
    il << Pl.bottomRows(3), H.topRows(2);
    ir << H.bottomRows(2), Pr.topRows(2);
    return {il, ir};
}
} // namespace

Bcifs refinedJunction(const RefinedParameters &p, const Mat &Pl, const Mat &Pr,
                      const Mat &handles)
{
    const RefinedMatrices m = refinedMatrices(p);
    const auto [Pil, Pir] = refinedControlPoints(Pl, Pr, handles);
    const JunctionCurve cl = cubicCurve(Pl), cr = quadraticCurve(Pr);
    Bcifs b;
    b.addCell("model", CellKind::Model, int(Pl.cols()));
    addCurve(b, "l", cl, cl.T1.bottomRightCorner(3, 3), "(l, left end)", "(3)");
    addCurve(b, "r", cr, cr.T0.topLeftCorner(2, 2), "(6)", "(r, right end)");
    b.addCell("vi", CellKind::Vertex, 1);
    b.addCell("il", CellKind::Edge, 5);
    b.addCell("ir", CellKind::Edge, 4);
    // The interpolated vertex: a 1 x 1 space whose only IFS is the identity (003 §5).
    b.addOperator("V^i", OperatorKind::Subdivision, "vi", "vi", Mat::Identity(1, 1));
    b.addOperator("∂^il_0", OperatorKind::Boundary, "il", "vl", selection(5, 0, 3));
    b.addOperator("∂^il_1", OperatorKind::Boundary, "il", "vi", selection(5, 4, 1));
    b.addOperator("∂^ir_0", OperatorKind::Boundary, "ir", "vi", selection(4, 0, 1));
    b.addOperator("∂^ir_1", OperatorKind::Boundary, "ir", "vr", selection(4, 2, 2));
    b.addOperator("T^l", OperatorKind::Subdivision, "il", "l", m.Tl);
    b.addOperator("T^il", OperatorKind::Subdivision, "il", "il", m.Til);
    b.addOperator("T^r", OperatorKind::Subdivision, "ir", "r", m.Tr);
    b.addOperator("T^ir", OperatorKind::Subdivision, "ir", "ir", m.Tir);
    b.addOperator("P^il", OperatorKind::Placement, "model", "il", Pil.transpose());
    b.addOperator("P^ir", OperatorKind::Placement, "model", "ir", Pir.transpose());
    using K = ConstraintKind;
    b.addConstraint("(1)", K::Junction, {"P^il", "∂^il_0"}, {"P^l", "∂^l_1"});
    b.addConstraint("(4)", K::Junction, {"P^ir", "∂^ir_1"}, {"P^r", "∂^r_0"});
    b.addConstraint("(vi)", K::Junction, {"P^il", "∂^il_1"}, {"P^ir", "∂^ir_0"});
    b.addConstraint("(2)", K::Incidence, {"T^l", "∂^l_0"}, {"∂^il_0", "V^l"});
    b.addConstraint("(il, right end)", K::Incidence, {"T^il", "∂^il_1"}, {"∂^il_1", "V^i"});
    b.addConstraint("(8)", K::Adjacency, {"T^l", "∂^l_1"}, {"T^il", "∂^il_0"});
    b.addConstraint("(ir, left end)", K::Incidence, {"T^ir", "∂^ir_0"}, {"∂^ir_0", "V^i"});
    b.addConstraint("(5)", K::Incidence, {"T^r", "∂^r_1"}, {"∂^ir_1", "V^r"});
    b.addConstraint("(7)", K::Adjacency, {"T^r", "∂^r_0"}, {"T^ir", "∂^ir_1"});
    return b;
}

RefinedAnalysis analyseRefined(const RefinedParameters &p, const Mat &Pl, const Mat &Pr,
                               const Mat &handles)
{
    const RefinedMatrices m = refinedMatrices(p);
    Mat Pil, Pir;
    const bool placed = Pl.size() || Pr.size() || handles.size();
    if (placed)
        std::tie(Pil, Pir) = refinedControlPoints(Pl, Pr, handles);
    RefinedAnalysis a;
    a.left = spectrum(m.Til);
    a.right = spectrum(m.Tir);
    a.leftTangent = halfTangent(m.Til, m.Tl, Pil);
    a.rightTangent = halfTangent(m.Tir, m.Tr, Pir);
    // Without control points the two directions live in different spaces (il, ir).
    a.g1 = placed && isG1(a.leftTangent, a.rightTangent);
    a.verdict = "left: " + a.leftTangent.verdict + "; right: " + a.rightTangent.verdict + "; "
                + (!placed ? "give the handles to judge G1 at the vertex"
                   : a.g1  ? "G1 at the interpolated vertex (the three handles are aligned)"
                           : "not G1 at the interpolated vertex (the handles are not aligned)");
    return a;
}

} // namespace awb
