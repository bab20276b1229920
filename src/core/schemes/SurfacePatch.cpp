#include "core/schemes/SurfacePatch.h"

#include "core/Messages.h"

#include <algorithm>
#include <cmath>
#include <set>

namespace awb {

namespace {

std::string str(LatticePoint p)
{
    // Appended piece by piece: GCC 12 warns (-Wrestrict, a false positive) on "(" + string.
    std::string s(1, '(');
    s += std::to_string(p.i);
    s += ", ";
    s += std::to_string(p.j);
    s += ')';
    return s;
}

bool byRow(LatticePoint a, LatticePoint b) { return std::tie(a.j, a.i) < std::tie(b.j, b.i); }

double cross2(const Eigen::Vector2d &a, const Eigen::Vector2d &b)
{
    return a.x() * b.y() - a.y() * b.x();
}

// Lattice from the layout: square layouts live on the square lattice.
Lattice layoutLattice(const PatchLayout &layout)
{
    return layout.name == "square" ? Lattice::Square : Lattice::Triangular;
}

} // namespace

std::vector<std::string> layoutNames(Lattice lattice)
{
    if (lattice == Lattice::Square)
        return {"square"};
    return {"triangle", "hexagon"};
}

PatchLayout patchLayout(const LatticeScheme &scheme, const std::string &name)
{
    const int N = scheme.dilation();
    const Lattice lattice = scheme.lattice();
    PatchLayout out;
    out.name = name;
    const auto names = layoutNames(lattice);
    if (std::find(names.begin(), names.end(), name) == names.end()) {
        std::string list;
        for (const auto &n : names)
            list += (list.empty() ? "" : ", ") + n;
        throw InputError(formatMessage(
            lattice == Lattice::Square
                ? coreTranslate("awb::schemes", "the square lattice of %1 has no layout '%2' (it "
                                                "has: %3)")
                : coreTranslate("awb::schemes", "the triangular lattice of %1 has no layout '%2' "
                                                "(it has: %3)"),
            scheme.name(), name, list));
    }
    if (name == "square") {
        out.domain = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
        for (int b = 0; b < N; ++b)
            for (int a = 0; a < N; ++a)
                out.maps.push_back({LatticeMatrix::identity(), {a, b}});
    } else if (name == "triangle") {
        out.domain = {{0, 0}, {1, 0}, {0, 1}};
        for (int b = 0; b < N; ++b)
            for (int a = 0; a + b <= N - 1; ++a)
                out.maps.push_back({LatticeMatrix::identity(), {a, b}});
        for (int b = 1; b < N; ++b)
            for (int a = 1; a + b <= N; ++a)
                out.maps.push_back({LatticeMatrix::reflection(), {a, b}});
    } else {  // hexagon
        for (const LatticePoint &n : latticeNeighbours(lattice))
            out.domain.push_back({double(n.i), double(n.j)});
        // Ring by ring, counter-clockwise from the direction (1, 0).
        for (int ring = 1; ring <= N - 1; ++ring) {
            std::vector<LatticePoint> pts;
            for (int j = -ring; j <= ring; ++j)
                for (int i = -ring; i <= ring; ++i)
                    if (latticeDistance(lattice, {i, j}) == ring)
                        pts.push_back({i, j});
            const auto angle = [&](LatticePoint p) {
                const Eigen::Vector2d x = latticePosition(lattice, {double(p.i), double(p.j)});
                const double a = std::atan2(x.y(), x.x());
                return a < -1e-12 ? a + 2 * M_PI : a;
            };
            std::sort(pts.begin(), pts.end(),
                      [&](LatticePoint a, LatticePoint b) { return angle(a) < angle(b); });
            for (const LatticePoint &t : pts)
                out.maps.push_back({LatticeMatrix::identity(), t});
        }
    }
    return out;
}

bool insideDomain(const PatchLayout &layout, const Eigen::Vector2d &x, double tol)
{
    const Lattice lattice = layoutLattice(layout);
    const Eigen::Vector2d q = latticePosition(lattice, x);
    const size_t n = layout.domain.size();
    for (size_t k = 0; k < n; ++k) {
        const Eigen::Vector2d a = latticePosition(lattice, layout.domain[k]);
        const Eigen::Vector2d b = latticePosition(lattice, layout.domain[(k + 1) % n]);
        if (cross2(b - a, q - a) < -tol * (b - a).norm())
            return false;
    }
    return true;
}

SurfaceMatrices surfaceMatrices(const LatticeScheme &scheme, const PatchLayout &layout)
{
    for (size_t i = 0; i < layout.maps.size(); ++i)
        if (!scheme.symmetricUnder(layout.maps[i].R))
            throw InputError(formatMessage(
                coreTranslate("awb::schemes", "%1: the mask is not symmetric under the turn of "
                                              "map %2 of the %3 layout"),
                scheme.name(), i + 1, layout.name));
    // Start from the lattice points of the closed domain; close under the sub-nets' stencils.
    std::set<LatticePoint> net;
    for (int j = -2; j <= 2; ++j)
        for (int i = -2; i <= 2; ++i)
            if (insideDomain(layout, {double(i), double(j)}))
                net.insert({i, j});
    for (bool grew = true; grew;) {
        grew = false;
        const std::vector<LatticePoint> current(net.begin(), net.end());
        for (const PatchMap &f : layout.maps)
            for (const LatticePoint &g : current)
                for (const auto &[beta, w] : scheme.stencil(f.R.apply(g) + f.t))
                    grew |= net.insert(beta).second;
        if (net.size() > 4096)
            throw InputError(formatMessage(
                coreTranslate("awb::schemes", "%1: the pieces of the %2 layout are not determined "
                                              "by a finite net"),
                scheme.name(), layout.name));
    }
    SurfaceMatrices out;
    out.net.assign(net.begin(), net.end());
    std::sort(out.net.begin(), out.net.end(), byRow);
    std::map<LatticePoint, int> index;
    for (size_t k = 0; k < out.net.size(); ++k)
        index[out.net[k]] = int(k);
    const int m = int(out.net.size());
    for (const PatchMap &f : layout.maps) {
        Mat S = Mat::Zero(m, m);
        for (int k = 0; k < m; ++k)
            for (const auto &[beta, w] : scheme.stencil(f.R.apply(out.net[size_t(k)]) + f.t))
                S(k, index.at(beta)) = w;
        out.S.push_back(std::move(S));
    }
    return out;
}

std::vector<int> matchNet(const std::vector<LatticePoint> &net,
                          const std::vector<LatticePoint> &user, Lattice lattice)
{
    if (user.size() != net.size())
        throw InputError(formatMessage(
            coreTranslate("awb::schemes", "the patch needs %1 control points on its net, got %2"),
            net.size(), user.size()));
    std::map<LatticePoint, int> seen;
    for (size_t k = 0; k < user.size(); ++k) {
        const auto [it, fresh] = seen.emplace(user[k], int(k));
        if (!fresh)
            throw InputError(formatMessage(
                coreTranslate("awb::schemes", "lattice point %1 is given twice (points %2 and "
                                              "%3)"),
                str(user[k]), it->second + 1, k + 1));
    }
    const LatticePoint offset = *std::min_element(user.begin(), user.end(), byRow)
                                - *std::min_element(net.begin(), net.end(), byRow);
    std::map<LatticePoint, int> index;
    for (size_t k = 0; k < net.size(); ++k)
        index[net[k]] = int(k);
    std::vector<int> order(user.size());
    std::set<LatticePoint> used;
    for (size_t k = 0; k < user.size(); ++k) {
        const auto it = index.find(user[k] - offset);
        if (it == index.end()) {
            std::string missing;
            for (const LatticePoint &p : net)
                if (!seen.count(p + offset))
                    missing += (missing.empty() ? "" : ", ") + str(p + offset);
            throw InputError(formatMessage(
                lattice == Lattice::Square
                    ? coreTranslate("awb::schemes", "lattice point %1 (point %2) is not on the "
                                                    "square net of the patch; missing: %3")
                    : coreTranslate("awb::schemes", "lattice point %1 (point %2) is not on the "
                                                    "triangular net of the patch; missing: %3"),
                str(user[k]), k + 1, missing));
        }
        order[k] = it->second;
    }
    return order;
}

Mat reorder(const Mat &S, const std::vector<int> &order)
{
    const int m = int(order.size());
    Mat out(m, m);
    for (int k = 0; k < m; ++k)
        for (int l = 0; l < m; ++l)
            out(k, l) = S(order[size_t(k)], order[size_t(l)]);
    return out;
}

// ---- meshes -----------------------------------------------------------------------------------

Eigen::Vector2d LatticeMesh::coarseCoords(int k) const
{
    const double s = std::pow(double(scale), double(level));
    return Eigen::Vector2d(at[size_t(k)].i, at[size_t(k)].j) / s;
}

namespace {

void buildFaces(LatticeMesh &mesh)
{
    std::map<LatticePoint, int> index;
    for (size_t k = 0; k < mesh.at.size(); ++k)
        index[mesh.at[k]] = int(k);
    const auto find = [&](LatticePoint p) {
        const auto it = index.find(p);
        return it == index.end() ? -1 : it->second;
    };
    mesh.faces.clear();
    for (size_t k = 0; k < mesh.at.size(); ++k) {
        const LatticePoint p = mesh.at[k];
        std::vector<std::vector<LatticePoint>> cells;
        if (mesh.lattice == Lattice::Square)
            cells = {{p, p + LatticePoint{1, 0}, p + LatticePoint{1, 1}, p + LatticePoint{0, 1}}};
        else
            cells = {{p, p + LatticePoint{1, 0}, p + LatticePoint{0, 1}},
                     {p + LatticePoint{1, 0}, p + LatticePoint{1, 1}, p + LatticePoint{0, 1}}};
        for (const auto &cell : cells) {
            std::vector<int> face;
            for (const LatticePoint &c : cell)
                face.push_back(find(c));
            if (std::find(face.begin(), face.end(), -1) == face.end())
                mesh.faces.push_back(std::move(face));
        }
    }
}

} // namespace

LatticeMesh netMesh(Lattice lattice, const std::vector<LatticePoint> &at, const Mat &P)
{
    if (Eigen::Index(at.size()) != P.rows())
        throw InputError(formatMessage(
            coreTranslate("awb::schemes", "the net has %1 lattice points but %2 control points"),
            at.size(), P.rows()));
    LatticeMesh mesh;
    mesh.lattice = lattice;
    mesh.at = at;
    mesh.points = P;
    buildFaces(mesh);
    return mesh;
}

LatticeMesh refineMesh(const LatticeScheme &scheme, const LatticeMesh &mesh, int rounds)
{
    if (rounds < 0 || rounds > 12)
        throw InputError(formatMessage(
            coreTranslate("awb::schemes", "refinement rounds must be from 0 to 12, got %1"),
            rounds));
    if (mesh.level > 0 && mesh.scale != scheme.dilation())
        throw InputError(coreTranslate("awb::schemes", "the mesh was refined by another scheme"));
    LatticeMesh cur = mesh;
    const int N = scheme.dilation();
    for (int r = 0; r < rounds; ++r) {
        std::map<LatticePoint, int> index;
        for (size_t k = 0; k < cur.at.size(); ++k)
            index[cur.at[k]] = int(k);
        std::set<LatticePoint> candidates;
        for (const LatticePoint &b : cur.at)
            for (const auto &[x, w] : scheme.mask())
                candidates.insert(b * N + x);
        LatticeMesh next;
        next.lattice = cur.lattice;
        next.level = cur.level + 1;
        next.scale = N;
        std::vector<RowVec> rows;
        for (const LatticePoint &rho : candidates) {
            RowVec q = RowVec::Zero(cur.points.cols());
            bool complete = true;
            for (const auto &[beta, w] : scheme.stencil(rho)) {
                const auto it = index.find(beta);
                if (it == index.end()) {
                    complete = false;
                    break;
                }
                q += w * cur.points.row(it->second);
            }
            if (complete) {
                next.at.push_back(rho);
                rows.push_back(q);
            }
        }
        next.points.resize(Eigen::Index(rows.size()), cur.points.cols());
        for (size_t k = 0; k < rows.size(); ++k)
            next.points.row(Eigen::Index(k)) = rows[k];
        buildFaces(next);
        cur = std::move(next);
    }
    return cur;
}

Mat limitPoints(const LatticeScheme &scheme, const LatticeMesh &mesh, std::vector<int> *at)
{
    std::map<LatticePoint, int> index;
    for (size_t k = 0; k < mesh.at.size(); ++k)
        index[mesh.at[k]] = int(k);
    std::vector<RowVec> rows;
    if (at)
        at->clear();
    for (size_t k = 0; k < mesh.at.size(); ++k) {
        RowVec q = RowVec::Zero(mesh.points.cols());
        bool complete = true;
        for (const auto &[delta, w] : scheme.limitStencil()) {
            const auto it = index.find(mesh.at[k] + delta);
            if (it == index.end()) {
                complete = false;
                break;
            }
            q += w * mesh.points.row(it->second);
        }
        if (complete) {
            rows.push_back(q);
            if (at)
                at->push_back(int(k));
        }
    }
    Mat out(Eigen::Index(rows.size()), mesh.points.cols());
    for (size_t k = 0; k < rows.size(); ++k)
        out.row(Eigen::Index(k)) = rows[k];
    return out;
}

Mat limitSurfaceSamples(const LatticeScheme &scheme, const PatchLayout &layout,
                        const std::vector<LatticePoint> &net, const Mat &P, int rounds)
{
    const LatticeMesh fine = refineMesh(scheme, netMesh(scheme.lattice(), net, P), rounds);
    std::vector<int> at;
    const Mat all = limitPoints(scheme, fine, &at);
    std::vector<Eigen::Index> keep;
    for (size_t k = 0; k < at.size(); ++k)
        if (insideDomain(layout, fine.coarseCoords(at[k]), 1e-9))
            keep.push_back(Eigen::Index(k));
    Mat out(Eigen::Index(keep.size()), all.cols());
    for (size_t k = 0; k < keep.size(); ++k)
        out.row(Eigen::Index(k)) = all.row(keep[k]);
    return out;
}

} // namespace awb
