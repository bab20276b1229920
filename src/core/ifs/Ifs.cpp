#include "core/ifs/Ifs.h"

#include "core/Decompositions.h"
#include "core/Messages.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace awb {

void Ifs::validate() const
{
    if (maps.empty())
        throw InputError(coreTranslate("awb::ifs", "the IFS has no maps"));
    const int D = dim();
    for (size_t i = 0; i < maps.size(); ++i) {
        const auto &f = maps[i];
        if (f.A.rows() != D || f.A.cols() != D || f.b.size() != D)
            throw InputError(formatMessage(
                coreTranslate("awb::ifs", "map %1 does not act on the same space as map 1"),
                i + 1));
        requireFinite(f.A, formatMessage(coreTranslate("awb::ifs", "map %1 (linear part)"), i + 1));
        requireFinite(Mat(f.b),
                      formatMessage(coreTranslate("awb::ifs", "map %1 (translation)"), i + 1));
    }
    for (size_t v = 0; v < views.size(); ++v)
        if (views[v].V.rows() != D || views[v].c.size() != views[v].V.cols())
            throw InputError(formatMessage(
                coreTranslate("awb::ifs", "view %1 does not fit the IFS space"), v + 1));
    if (!probabilities.empty()) {
        if (probabilities.size() != maps.size())
            throw InputError(formatMessage(
                coreTranslate("awb::ifs", "the IFS has %1 maps but %2 probabilities"),
                maps.size(), probabilities.size()));
        double sum = 0;
        for (size_t i = 0; i < probabilities.size(); ++i) {
            if (!std::isfinite(probabilities[i]) || probabilities[i] < 0)
                throw InputError(formatMessage(
                    coreTranslate("awb::ifs", "probability of map %1 must be a finite number >= 0"),
                    i + 1));
            sum += probabilities[i];
        }
        if (!(sum > 0))
            throw InputError(coreTranslate("awb::ifs", "the map probabilities sum to 0"));
    }
}

Mat Ifs::effectiveLinearPart(int i) const
{
    const Mat &A = maps.at(i).A;
    if (barycentricBlocks.empty())
        return A;
    const int D = dim();
    std::vector<bool> constrained(D, false);
    std::vector<RowVec> basis;
    for (auto [off, size] : barycentricBlocks) {
        for (int k = 0; k < size; ++k)
            constrained[off + k] = true;
        for (int k = 0; k + 1 < size; ++k) {
            RowVec v = RowVec::Zero(D);
            v(off + k) = 1.0;
            v(off + size - 1) = -1.0;
            basis.push_back(v);
        }
    }
    for (int k = 0; k < D; ++k)
        if (!constrained[k]) {
            RowVec v = RowVec::Zero(D);
            v(k) = 1.0;
            basis.push_back(v);
        }
    Mat T(basis.size(), D);
    for (size_t r = 0; r < basis.size(); ++r)
        T.row(r) = basis[r];
    // v = c T  |->  v A = c T A = c' T  with  c' = c T A T^+.
    const Mat Tpinv = T.completeOrthogonalDecomposition().pseudoInverse();
    return T * A * Tpinv;
}

Lifting liftControlPoints(const Mat &P, const std::vector<int> &freeRowsIn)
{
    const int m = int(P.rows()), d = int(P.cols());
    Lifting L;
    if (m < d + 1) {
        L.reason = "the lifted matrix P needs at least " + std::to_string(d + 1)
                   + " control points in " + std::to_string(d) + "D, the curve has "
                   + std::to_string(m);
        for (int i = 0; i < m; ++i)
            L.culprits.push_back(i);
        return L;
    }
    std::vector<int> freeRows = freeRowsIn;
    if (freeRows.empty())
        for (int i = m - d - 1; i < m; ++i)
            freeRows.push_back(i);
    std::sort(freeRows.begin(), freeRows.end());
    if (int(freeRows.size()) != d + 1 || freeRows.front() < 0 || freeRows.back() >= m
        || std::adjacent_find(freeRows.begin(), freeRows.end()) != freeRows.end())
        throw InputError(formatMessage(
            coreTranslate("awb::ifs", "the lifting needs %1 distinct free rows of the control "
                                      "points"),
            d + 1));
    L.freeRows = freeRows;
    L.lifted = Mat::Zero(m, m);
    L.lifted.leftCols(d) = P;
    for (int i = 0, col = d; i < m; ++i)
        if (!std::binary_search(freeRows.begin(), freeRows.end(), i))
            L.lifted(i, col++) = 1.0;
    L.lifted.col(m - 1).setOnes();

    Eigen::JacobiSVD<Mat> svd(L.lifted);
    const auto &sv = svd.singularValues();
    L.reciprocalCondition = sv(0) > 0 ? sv(sv.size() - 1) / sv(0) : 0.0;
    // Only the free rows carry no identity column: they must be affinely independent.
    std::ostringstream names;
    for (size_t k = 0; k < freeRows.size(); ++k)
        names << freeRows[k] + 1
              << (k + 2 < freeRows.size()
                      ? ", "
                      : (k + 2 == freeRows.size() ? coreTranslate("awb::ifs", " and ") : ""));
    if (L.reciprocalCondition > 1e-12) {
        L.invertible = true;
        L.inverse = L.lifted.partialPivLu().inverse();
        if (L.reciprocalCondition < 1e-8) {
            std::ostringstream condition;
            condition.precision(2);
            condition << L.reciprocalCondition;
            L.warning = formatMessage(
                d == 2 ? coreTranslate("awb::ifs", "the lifted matrix P is nearly singular "
                                                   "(reciprocal condition number %1): M_i = P^-1 "
                                                   "S_i P lose about %2 of 16 significant digits; "
                                                   "control points %3 are almost collinear")
                       : coreTranslate("awb::ifs", "the lifted matrix P is nearly singular "
                                                   "(reciprocal condition number %1): M_i = P^-1 "
                                                   "S_i P lose about %2 of 16 significant digits; "
                                                   "control points %3 are almost coplanar"),
                condition.str(), int(std::lround(-std::log10(L.reciprocalCondition))),
                names.str());
        }
        return L;
    }
    for (int row : freeRows)
        L.culprits.push_back(row);
    L.reason = formatMessage(
        d == 2   ? coreTranslate("awb::ifs", "control points %1 are collinear, so the lifted "
                                             "matrix P of 000 §2 is singular and M_i = P^-1 S_i P "
                                             "is not defined; the attractor is computed in "
                                             "barycentric form")
        : d == 3 ? coreTranslate("awb::ifs", "control points %1 are coplanar, so the lifted "
                                             "matrix P of 000 §2 is singular and M_i = P^-1 S_i P "
                                             "is not defined; the attractor is computed in "
                                             "barycentric form")
                 : coreTranslate("awb::ifs", "control points %1 are affinely dependent, so the "
                                             "lifted matrix P of 000 §2 is singular and M_i = "
                                             "P^-1 S_i P is not defined; the attractor is "
                                             "computed in barycentric form"),
        names.str());
    return L;
}

std::vector<int> affineBasisRows(const Mat &P)
{
    const int m = int(P.rows()), d = int(P.cols());
    std::vector<int> rows;
    if (m == 0)
        return rows;
    const RowVec centroid = P.colwise().mean();
    const double scale = std::max(1.0, (P.rowwise() - centroid).rowwise().norm().maxCoeff());
    // Orthonormal basis of the directions spanned so far (from the first chosen point).
    std::vector<RowVec> basis;
    const auto distance = [&](int i) {
        RowVec v = rows.empty() ? RowVec(P.row(i) - centroid) : RowVec(P.row(i) - P.row(rows[0]));
        if (!rows.empty())
            for (const RowVec &e : basis)
                v -= v.dot(e) * e;
        return v;
    };
    while (int(rows.size()) < d + 1) {
        int best = -1;
        double far = -1.0;
        for (int i = 0; i < m; ++i) {
            if (std::find(rows.begin(), rows.end(), i) != rows.end())
                continue;
            const double n = distance(i).norm();
            if (n > far * (1 + 1e-12) + 1e-300)
                far = n, best = i;
        }
        if (best < 0 || (!rows.empty() && far <= 1e-9 * scale))
            break;
        if (!rows.empty())
            basis.push_back(distance(best) / far);
        rows.push_back(best);
    }
    return rows;
}

LiftedMap liftMatrix(const Lifting &lifting, const Mat &S)
{
    if (!lifting.invertible)
        throw InputError(lifting.reason);
    LiftedMap out;
    out.M = lifting.inverse * S * lifting.lifted;
    const Eigen::Index n = out.M.rows() - 1;
    out.A = out.M.topLeftCorner(n, n);
    out.b = out.M.bottomLeftCorner(1, n);
    return out;
}

Ifs barycentricIfs(const std::vector<Mat> &S, const Mat &P)
{
    Ifs ifs;
    ifs.space = "barycentric";
    for (const Mat &Si : S)
        ifs.maps.push_back({Si, RowVec::Zero(Si.rows())});
    ifs.views.push_back({P, RowVec::Zero(P.cols())});
    if (!S.empty())
        ifs.barycentricBlocks.push_back({0, int(S.front().rows())});
    return ifs;
}

SubdivisionIfs buildSubdivisionIfs(const std::vector<Mat> &S, int overlap, const Mat &P,
                                   IfsForm form, const std::vector<int> &freeRows)
{
    requireFinite(P, coreTranslate("awb::ifs", "control points"));
    for (size_t i = 0; i < S.size(); ++i) {
        if (S[i].rows() != P.rows() || S[i].cols() != P.rows())
            throw InputError(formatMessage(
                coreTranslate("awb::ifs", "matrix S_%1 does not match %2 control points"), i + 1,
                P.rows()));
        requireFinite(S[i], formatMessage(coreTranslate("awb::ifs", "matrix S_%1"), i + 1));
    }
    SubdivisionIfs out;
    out.controlPoints = P;
    out.matrices.S = S;
    out.matrices.overlap = overlap;
    out.lifting = liftControlPoints(P, freeRows);
    if (out.lifting.invertible && form != IfsForm::Barycentric) {
        const int d = int(P.cols());
        const int D = int(P.rows()) - 1;
        out.ifs.space = "lifted";
        for (const Mat &Si : S) {
            out.lifted.push_back(liftMatrix(out.lifting, Si));
            out.ifs.maps.push_back({out.lifted.back().A, out.lifted.back().b});
        }
        Mat V = Mat::Zero(D, d);
        V.topRows(d).setIdentity();
        out.ifs.views.push_back({V, RowVec::Zero(d)});
    } else {
        if (form == IfsForm::Lifted)
            throw InputError(out.lifting.reason);
        if (out.lifting.invertible)
            for (const Mat &Si : S)
                out.lifted.push_back(liftMatrix(out.lifting, Si));
        out.ifs = barycentricIfs(S, P);
    }
    return out;
}

SubdivisionIfs buildSubdivisionIfs(const CurveScheme &scheme, const Mat &P, IfsForm form)
{
    requireFinite(P, coreTranslate("awb::ifs", "control points"));
    const SubdivisionMatrices sm = scheme.matrices(int(P.rows()));
    return buildSubdivisionIfs(sm.S, sm.overlap, P, form);
}

Mat SubdivisionIfs::toIfsSpace(const Mat &points) const
{
    requireFinite(points, coreTranslate("awb::ifs", "start set"));
    const int d = int(controlPoints.cols());
    const int D = ifs.dim();
    if (points.cols() == D)
        return points;
    if (barycentric()) {
        if (points.cols() != d)
            throw InputError(formatMessage(
                coreTranslate("awb::ifs", "start points must have %1 (plane) or %2 (barycentric) "
                                          "coordinates"),
                d, D));
        // Least-norm lambda with lambda P = y and sum(lambda) = 1.
        const int m = int(controlPoints.rows());
        Mat E(d + 1, m);
        E.topRows(d) = controlPoints.transpose();
        E.row(d).setOnes();
        Eigen::CompleteOrthogonalDecomposition<Mat> cod(E);
        Mat out(points.rows(), m);
        for (Eigen::Index r = 0; r < points.rows(); ++r) {
            Vec rhs(d + 1);
            rhs.head(d) = points.row(r).transpose();
            rhs(d) = 1.0;
            Vec lambda = cod.solve(rhs);
            lambda /= lambda.sum(); // exact affine normalisation if y is off the affine hull
            out.row(r) = lambda.transpose();
        }
        return out;
    }
    if (points.cols() == D + 1) // homogeneous lifted point: drop the trailing 1
        return points.leftCols(D);
    if (points.cols() != d)
        throw InputError(formatMessage(
            coreTranslate("awb::ifs", "start points must have %1 (plane) or %2 (lifted) "
                                      "coordinates"),
            d, D));
    Mat out = Mat::Zero(points.rows(), D);
    out.leftCols(d) = points;
    return out;
}

Projection SubdivisionIfs::netCoordinates() const
{
    const Eigen::Index m = controlPoints.rows();
    if (barycentric() && ifs.dim() == m)
        return {Mat::Identity(m, m), RowVec::Zero(m)};
    if (barycentric() || !lifting.invertible || lifting.inverse.rows() != m || ifs.dim() != m - 1)
        return {};
    return {lifting.inverse.topRows(m - 1), lifting.inverse.row(m - 1)};
}

Ifs blockUnion(const std::vector<Ifs> &components)
{
    if (components.empty())
        throw InputError(coreTranslate("awb::ifs", "a union needs at least one component"));
    const int N = components.front().size();
    int D = 0;
    for (size_t k = 0; k < components.size(); ++k) {
        components[k].validate();
        if (components[k].size() != N)
            throw InputError(formatMessage(
                coreTranslate("awb::ifs", "component %1 has %2 maps, component 1 has %3: a block "
                                          "union needs equally many"),
                k + 1, components[k].size(), N));
        D += components[k].dim();
    }
    Ifs out;
    out.space = "block union";
    for (int i = 0; i < N; ++i) {
        AffineMap f{Mat::Zero(D, D), RowVec::Zero(D)};
        int off = 0;
        for (const Ifs &c : components) {
            const int Dk = c.dim();
            f.A.block(off, off, Dk, Dk) = c.maps[i].A;
            f.b.segment(off, Dk) = c.maps[i].b;
            off += Dk;
        }
        out.maps.push_back(f);
    }
    int off = 0;
    for (const Ifs &c : components) {
        for (auto [o, size] : c.barycentricBlocks)
            out.barycentricBlocks.push_back({off + o, size});
        off += c.dim();
    }
    off = 0;
    for (const Ifs &c : components) {
        for (const Projection &v : c.views) {
            Projection w{Mat::Zero(D, v.V.cols()), v.c};
            w.V.middleRows(off, c.dim()) = v.V;
            out.views.push_back(w);
        }
        off += c.dim();
    }
    return out;
}

AffineMap realify(const CMat &A, const Eigen::RowVectorXcd &b)
{
    const Eigen::Index D = A.rows();
    AffineMap f{Mat::Zero(2 * D, 2 * D), RowVec::Zero(2 * D)};
    for (Eigen::Index i = 0; i < D; ++i) {
        for (Eigen::Index j = 0; j < D; ++j) {
            const Complex a = A(i, j);
            // [Re z_i, Im z_i] * [[Re a, Im a], [-Im a, Re a]] = [Re(z_i a), Im(z_i a)]
            f.A(2 * i, 2 * j) = a.real();
            f.A(2 * i, 2 * j + 1) = a.imag();
            f.A(2 * i + 1, 2 * j) = -a.imag();
            f.A(2 * i + 1, 2 * j + 1) = a.real();
        }
        f.b(2 * i) = b(i).real();
        f.b(2 * i + 1) = b(i).imag();
    }
    return f;
}

Mat applyMap(const AffineMap &f, const Mat &X)
{
    Mat Y = X * f.A;
    Y.rowwise() += f.b;
    return Y;
}

Mat project(const Projection &v, const Mat &X)
{
    Mat Y = X * v.V;
    Y.rowwise() += v.c;
    return Y;
}

} // namespace awb
