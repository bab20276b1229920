// Subdivision surfaces as attractors (000 §3): the masks derived from the schemes' own rules,
// the nets and layouts of the patches, the spectra of their S_i, and the attractor against the
// exact limit surface (closed form for bicubic; limit positions of refined vertices for Loop
// and √3) on random control nets.

#include "core/analysis/Geometry.h"
#include "core/analysis/Spectrum.h"
#include "core/ifs/Attractor.h"
#include "core/ifs/SurfaceIfs.h"
#include "core/render/SurfaceRaster.h"
#include "core/schemes/SurfacePatch.h"

#include <QtTest>

#include "TestMain.h"
#include "TestTime.h"

#include <random>

using namespace awb;

namespace {

double maskAt(const LatticeScheme &s, LatticePoint p)
{
    const auto it = s.mask().find(p);
    return it == s.mask().end() ? 0.0 : it->second;
}

// A random net: the lattice positions jittered in the plane, random heights.
Mat randomNet(const LatticeScheme &scheme, const std::vector<LatticePoint> &net, unsigned seed)
{
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    Mat P(Eigen::Index(net.size()), 3);
    for (size_t k = 0; k < net.size(); ++k) {
        const Eigen::Vector2d x =
            latticePosition(scheme.lattice(), {double(net[k].i), double(net[k].j)});
        P.row(Eigen::Index(k)) << x.x() + 0.15 * u(rng), x.y() + 0.15 * u(rng), u(rng);
    }
    return P;
}

// F^depth(X0) projected to R^3.
Mat attractorPoints(const SurfaceIfs &s, const Mat &start, int depth, bool polygon = false)
{
    PointCollector c(s.ifs.ifs.views.front());
    const Mat X0 = s.ifs.toIfsSpace(start);
    iterate(s.ifs.ifs, polygon ? StartSet::polygon(X0) : StartSet::points(X0), depth, c);
    return c.points();
}

struct Case {
    const char *name;
    LatticeScheme (*scheme)();
    const char *layout;
    int mapCount, netSize, depth;
    double sub;  // subdominant eigenvalue of the upright maps
};
const Case cases[] = {
    {"bicubic square", bicubicScheme, "square", 4, 16, 4, 0.5},
    {"loop triangle", loopScheme, "triangle", 4, 12, 4, 0.5},
    {"loop hexagon", loopScheme, "hexagon", 6, 19, 4, 0.5},
    {"sqrt3 triangle", sqrt3Scheme, "triangle", 9, 27, 3, 1.0 / 3.0},
    {"sqrt3 hexagon", sqrt3Scheme, "hexagon", 18, 37, 2, 1.0 / 3.0},
};

} // namespace

class TestSurfaces : public QObject {
    Q_OBJECT
private slots:
    void bicubicMaskIsTensorCubic();
    void loopMaskIsLoopsRules();
    void sqrt3MaskIsTwoRoundsOfKobbelt();
    void limitStencils();
    void netsAndMapCounts_data();
    void netsAndMapCounts();
    void layoutsCoverTheirDomain_data();
    void layoutsCoverTheirDomain();
    void spectra();
    void attractorIsTheLimitSurface_data();
    void attractorIsTheLimitSurface();
    void bicubicAttractorMatchesClosedForm();
    void anyStartSetConverges();
    void subsetOfMapsLiesOnTheSurface();
    void refinementConvergesToTheAttractor();
    void liftingOfSurfaceNets();
    void netsAreMatchedUpToTranslation();
    void badNetsAreNamed();
    void meshDrawsTheImagesAgain();
    void netPointMovesTheMeshByItsWeights();
    void pinholesCloseInsideNotOutside();
    void lastMapFusedWithTheViews();
};

void TestSurfaces::bicubicMaskIsTensorCubic()
{
    AWB_SKIP_WITHOUT_THREADS();
    const LatticeScheme s = bicubicScheme();
    const double c[5] = {1 / 8.0, 1 / 2.0, 3 / 4.0, 1 / 2.0, 1 / 8.0};
    QCOMPARE(int(s.mask().size()), 25);
    for (int j = -2; j <= 2; ++j)
        for (int i = -2; i <= 2; ++i)
            QCOMPARE(maskAt(s, {i, j}), c[i + 2] * c[j + 2]);
    QCOMPARE(s.dilation(), 2);
}

void TestSurfaces::loopMaskIsLoopsRules()
{
    AWB_SKIP_WITHOUT_THREADS();
    const LatticeScheme s = loopScheme();
    QCOMPARE(int(s.mask().size()), 19);
    // Vertex rule of a regular vertex: 5/8 itself, 1/16 each of its six neighbours.
    Stencil v = s.stencil({0, 0});
    QCOMPARE(int(v.size()), 7);
    for (const auto &[beta, w] : v)
        QCOMPARE(w, (beta == LatticePoint{0, 0}) ? 10.0 / 16.0 : 1.0 / 16.0);
    // Edge rule on the edge (0,0)-(1,0): 3/8 its ends, 1/8 the opposite vertices (0,1), (1,-1).
    Stencil e = s.stencil({1, 0});
    QCOMPARE(int(e.size()), 4);
    for (const auto &[beta, w] : e) {
        const bool end = beta == LatticePoint{0, 0} || beta == LatticePoint{1, 0};
        QVERIFY(end || (beta == LatticePoint{0, 1}) || (beta == LatticePoint{1, -1}));
        QCOMPARE(w, end ? 3.0 / 8.0 : 1.0 / 8.0);
    }
    QVERIFY(s.symmetricUnder(LatticeMatrix::reflection()));
    QVERIFY(s.symmetricUnder({0, -1, 1, 1}));  // turn by 60°
}

void TestSurfaces::sqrt3MaskIsTwoRoundsOfKobbelt()
{
    AWB_SKIP_WITHOUT_THREADS();
    const LatticeScheme s = sqrt3Scheme();
    QCOMPARE(s.dilation(), 3);
    double sum = 0.0;
    for (const auto &[x, w] : s.mask())
        sum += w;
    QVERIFY(std::abs(sum - 9.0) < 1e-13);
    // Two relaxations of a regular vertex, by hand: v1 = 2/3 v + 1/18 sum n; its new neighbours
    // are the centroids (v + n_k + n_k+1)/3, so v2 = 2/3 v1 + 1/18 sum c = 5/9 v + 2/27 sum n.
    Stencil v = s.stencil({0, 0});
    QCOMPARE(int(v.size()), 7);
    for (const auto &[beta, w] : v)
        QVERIFY(std::abs(w - (beta == LatticePoint{0, 0} ? 5.0 / 9.0 : 2.0 / 27.0)) < 1e-15);
    // Symmetric under the lattice's rotations and the point reflection.
    QVERIFY(s.symmetricUnder(LatticeMatrix::reflection()));
    QVERIFY(s.symmetricUnder({0, -1, 1, 1}));
}

void TestSurfaces::limitStencils()
{
    AWB_SKIP_WITHOUT_THREADS();
    // Loop: 1/2 the vertex, 1/12 each neighbour (chi = 1/(3/(8 beta) + n), beta = 1/16, n = 6).
    const LatticeScheme loop = loopScheme();
    for (const auto &[beta, w] : loop.limitStencil())
        QVERIFY(std::abs(w - (beta == LatticePoint{0, 0} ? 0.5 : 1.0 / 12.0)) < 1e-12);
    // Bicubic: (1, 4, 1)/6 in each direction.
    const double c[3] = {1 / 6.0, 4 / 6.0, 1 / 6.0};
    const Stencil b = bicubicScheme().limitStencil();
    QCOMPARE(int(b.size()), 9);
    for (const auto &[beta, w] : b)
        QVERIFY(std::abs(w - c[beta.i + 1] * c[beta.j + 1]) < 1e-12);
    // √3 (alpha = 1/3): the limit stencil has the vertex's 1-ring only, summing to 1.
    double sum = 0.0;
    const LatticeScheme sqrt3 = sqrt3Scheme();
    for (const auto &[beta, w] : sqrt3.limitStencil()) {
        QVERIFY(latticeDistance(Lattice::Triangular, beta) <= 1);
        sum += w;
    }
    QVERIFY(std::abs(sum - 1.0) < 1e-12);
}

void TestSurfaces::netsAndMapCounts_data()
{
    QTest::addColumn<int>("index");
    for (int k = 0; k < int(std::size(cases)); ++k)
        QTest::newRow(cases[k].name) << k;
}

void TestSurfaces::netsAndMapCounts()
{
    AWB_SKIP_WITHOUT_THREADS();
    QFETCH(int, index);
    const Case &c = cases[index];
    const LatticeScheme s = c.scheme();
    const PatchLayout layout = patchLayout(s, c.layout);
    const SurfaceMatrices m = surfaceMatrices(s, layout);
    QCOMPARE(int(layout.maps.size()), c.mapCount);
    QCOMPARE(int(m.net.size()), c.netSize);
    for (const Mat &S : m.S) {
        QCOMPARE(int(S.rows()), c.netSize);
        QVERIFY((S.rowwise().sum().array() - 1.0).abs().maxCoeff() < 1e-14);
    }
}

void TestSurfaces::layoutsCoverTheirDomain_data() { netsAndMapCounts_data(); }

void TestSurfaces::layoutsCoverTheirDomain()
{
    AWB_SKIP_WITHOUT_THREADS();
    QFETCH(int, index);
    const Case &c = cases[index];
    const LatticeScheme s = c.scheme();
    const PatchLayout layout = patchLayout(s, c.layout);
    const int N = s.dilation();
    // Each piece lies in the domain...
    for (const PatchMap &f : layout.maps)
        for (const Eigen::Vector2d &corner : layout.domain)
            QVERIFY(insideDomain(layout, f.apply(corner, N), 1e-12));
    // ...and the pieces cover it: every point of a fine grid over the domain is in a piece
    // (x in psi(D) iff psi^-1(x) = R^-1 (N x - t) in D; R = R^-1 for I and -I).
    int inside = 0;
    for (int b = -200; b <= 200; ++b)
        for (int a = -200; a <= 200; ++a) {
            const Eigen::Vector2d x(a / 200.0 + 1e-7, b / 200.0 + 3e-7);
            if (!insideDomain(layout, x))
                continue;
            ++inside;
            bool covered = false;
            for (const PatchMap &f : layout.maps) {
                const Eigen::Vector2d y = f.R.apply(Eigen::Vector2d(N * x - Eigen::Vector2d(f.t.i, f.t.j)));
                if (insideDomain(layout, y, 1e-9)) {
                    covered = true;
                    break;
                }
            }
            QVERIFY2(covered, qPrintable(QString("(%1, %2) is in no piece").arg(x.x()).arg(x.y())));
        }
    QVERIFY(inside > 10000);
}

void TestSurfaces::spectra()
{
    AWB_SKIP_WITHOUT_THREADS();
    const auto leading = [](const Mat &S, int n) {
        std::vector<Complex> v = spectrum(S).values;
        v.resize(size_t(n));
        return v;
    };
    const auto check = [](const std::vector<Complex> &got, const std::vector<double> &want) {
        for (size_t k = 0; k < want.size(); ++k)
            QVERIFY2(std::abs(got[k] - want[k]) < 1e-9,
                     qPrintable(QString("eigenvalue %1: %2 + %3i, expected %4")
                                    .arg(k + 1).arg(got[k].real()).arg(got[k].imag()).arg(want[k])));
    };
    // Bicubic: every S_i has the spectrum {1, 1/2, 1/4, 1/8} x {1, 1/2, 1/4, 1/8}.
    {
        std::vector<double> want;
        for (double a : {1.0, 0.5, 0.25, 0.125})
            for (double b : {1.0, 0.5, 0.25, 0.125})
                want.push_back(a * b);
        std::sort(want.begin(), want.end(), std::greater<>());
        const LatticeScheme s = bicubicScheme();
        for (const Mat &S : surfaceMatrices(s, patchLayout(s, "square")).S)
            check(leading(S, 16), want);
    }
    // Loop: 1, 1/2, 1/2, 1/4 x3, 1/8 x4 on every upright map; the turned (centre) piece of
    // the triangle layout has -1/2, -1/2 (the map reflects the domain).
    {
        const LatticeScheme s = loopScheme();
        for (const char *name : {"triangle", "hexagon"}) {
            const PatchLayout layout = patchLayout(s, name);
            const SurfaceMatrices m = surfaceMatrices(s, layout);
            for (size_t i = 0; i < m.S.size(); ++i) {
                const double sign = layout.maps[i].R == LatticeMatrix::identity() ? 1.0 : -1.0;
                std::vector<Complex> got = leading(m.S[i], 10);
                std::sort(got.begin() + 1, got.begin() + 10, [](Complex a, Complex b) {
                    return std::abs(a) > std::abs(b) + 1e-9
                           || (std::abs(std::abs(a) - std::abs(b)) < 1e-9 && a.real() > b.real());
                });
                check(got, {1, sign * 0.5, sign * 0.5, 0.25, 0.25, 0.25, sign * 0.125,
                            sign * 0.125, sign * 0.125, sign * 0.125});
            }
        }
    }
    // √3 (two rounds): 1, 1/3, 1/3, 1/9 x3 (the one-round subdominant 1/√3, squared).
    {
        const LatticeScheme s = sqrt3Scheme();
        for (const char *name : {"triangle", "hexagon"}) {
            const PatchLayout layout = patchLayout(s, name);
            const SurfaceMatrices m = surfaceMatrices(s, layout);
            for (size_t i = 0; i < m.S.size(); ++i) {
                const double sign = layout.maps[i].R == LatticeMatrix::identity() ? 1.0 : -1.0;
                check(leading(m.S[i], 6),
                      {1, sign / 3.0, sign / 3.0, 1 / 9.0, 1 / 9.0, 1 / 9.0});
            }
        }
    }
}

void TestSurfaces::attractorIsTheLimitSurface_data() { netsAndMapCounts_data(); }

// Started from the limit points of the domain's corners, F^k(X0) consists exactly of the limit
// points of the level-k vertices of the domain: the Hausdorff distance to the limit samples
// computed by global refinement of the net (mask convolution, no S_i) is rounding error.
void TestSurfaces::attractorIsTheLimitSurface()
{
    AWB_SKIP_WITHOUT_THREADS();
    QFETCH(int, index);
    const Case &c = cases[index];
    const LatticeScheme s = c.scheme();
    const PatchLayout layout = patchLayout(s, c.layout);
    const SurfaceMatrices m = surfaceMatrices(s, layout);
    for (unsigned seed : {1u, 2u, 3u}) {
        const Mat P = randomNet(s, m.net, seed);
        const SurfaceIfs ifs = buildSurfaceIfs(s, layout, m.net, P);
        QVERIFY(ifs.ifs.lifting.invertible);
        const Mat A = attractorPoints(ifs, ifs.cornerLimitStart, c.depth);
        const Mat L = limitSurfaceSamples(s, layout, m.net, P, c.depth);
        const double size = (P.colwise().maxCoeff() - P.colwise().minCoeff()).norm();
        QVERIFY2(hausdorffDistance(A, L) < 1e-12 * size,
                 qPrintable(QString("d_H = %1").arg(hausdorffDistance(A, L))));
        QVERIFY(L.rows() > 50);
    }
}

void TestSurfaces::bicubicAttractorMatchesClosedForm()
{
    AWB_SKIP_WITHOUT_THREADS();
    const LatticeScheme s = bicubicScheme();
    const PatchLayout layout = patchLayout(s, "square");
    const SurfaceMatrices m = surfaceMatrices(s, layout);
    const Mat P = randomNet(s, m.net, 11);
    const auto B = [](int a, double u) {
        switch (a) {
        case 0: return (1 - u) * (1 - u) * (1 - u) / 6;
        case 1: return (3 * u * u * u - 6 * u * u + 4) / 6;
        case 2: return (-3 * u * u * u + 3 * u * u + 3 * u + 1) / 6;
        default: return u * u * u / 6;
        }
    };
    const int k = 5, n = 1 << k;
    Mat exact((n + 1) * (n + 1), 3);
    for (int b = 0; b <= n; ++b)
        for (int a = 0; a <= n; ++a) {
            RowVec x = RowVec::Zero(3);
            for (size_t r = 0; r < m.net.size(); ++r)
                x += B(m.net[r].i + 1, double(a) / n) * B(m.net[r].j + 1, double(b) / n)
                     * P.row(Eigen::Index(r));
            exact.row(b * (n + 1) + a) = x;
        }
    const SurfaceIfs ifs = buildSurfaceIfs(s, layout, m.net, P);
    const Mat A = attractorPoints(ifs, ifs.cornerLimitStart, k);
    QVERIFY2(hausdorffDistance(A, exact) < 1e-12, qPrintable(QString::number(hausdorffDistance(A, exact))));
}

// From a triangle far from the surface, F^k(X0) approaches the surface by the subdominant
// eigenvalue per level.
void TestSurfaces::anyStartSetConverges()
{
    AWB_SKIP_WITHOUT_THREADS();
    for (const Case &c : cases) {
        if (c.mapCount > 9)
            continue;
        const LatticeScheme s = c.scheme();
        const PatchLayout layout = patchLayout(s, c.layout);
        const SurfaceMatrices m = surfaceMatrices(s, layout);
        const Mat P = randomNet(s, m.net, 5);
        const SurfaceIfs ifs = buildSurfaceIfs(s, layout, m.net, P);
        const Mat L = limitSurfaceSamples(s, layout, m.net, P, c.mapCount == 9 ? 4 : 6);
        Mat triangle(3, 3);
        triangle << 5, 5, 5, -4, 6, 2, 3, -7, -1;
        std::vector<double> d;
        const int top = c.mapCount == 9 ? 5 : 7;
        for (int k = top - 2; k <= top; ++k)
            d.push_back(directedDistance(attractorPoints(ifs, triangle, k, true), L));
        // The distance to the dense samples is bounded below by their spacing: compare the
        // first steps, where the start set still dominates.
        QVERIFY2(d[1] < 0.75 * d[0] && d[2] < 0.75 * d[1],
                 qPrintable(QString("%1: %2 %3 %4").arg(c.name).arg(d[0]).arg(d[1]).arg(d[2])));
    }
}

// 000 Fig. 9: leaving maps out draws a fractal lying on the surface.
void TestSurfaces::subsetOfMapsLiesOnTheSurface()
{
    AWB_SKIP_WITHOUT_THREADS();
    const LatticeScheme s = loopScheme();
    const PatchLayout layout = patchLayout(s, "hexagon");
    const SurfaceMatrices m = surfaceMatrices(s, layout);
    const Mat P = randomNet(s, m.net, 9);
    const SurfaceIfs all = buildSurfaceIfs(s, layout, m.net, P);
    const SurfaceIfs some = buildSurfaceIfs(s, layout, m.net, P, {0, 1, 3, 4});
    QCOMPARE(some.ifs.ifs.size(), 4);
    QCOMPARE(int(some.S.size()), 6);
    const int k = 5;
    const Mat L = limitSurfaceSamples(s, layout, m.net, P, k);
    const Mat A = attractorPoints(some, some.cornerLimitStart, k);
    QVERIFY(directedDistance(A, L) < 1e-12);  // on the surface
    QVERIFY(directedDistance(L, A) > 0.05);   // but not all of it
    QVERIFY_THROWS_EXCEPTION(InputError, buildSurfaceIfs(s, layout, m.net, P, {0, 6}));
}

void TestSurfaces::refinementConvergesToTheAttractor()
{
    AWB_SKIP_WITHOUT_THREADS();
    // The classic route (refined nets, 000 Figs. 6-8 top) and the IFS route meet: the refined
    // vertices over the domain approach the limit surface by a factor ~ 1/4 per round.
    const LatticeScheme s = loopScheme();
    const PatchLayout layout = patchLayout(s, "hexagon");
    const SurfaceMatrices m = surfaceMatrices(s, layout);
    const Mat P = randomNet(s, m.net, 4);
    const SurfaceIfs ifs = buildSurfaceIfs(s, layout, m.net, P);
    const Mat A = attractorPoints(ifs, ifs.cornerLimitStart, 5);
    std::vector<double> d;
    for (int r = 1; r <= 4; ++r) {
        const LatticeMesh mesh = refineMesh(s, netMesh(s.lattice(), m.net, P), r);
        std::vector<Eigen::Index> inside;
        for (size_t k = 0; k < mesh.at.size(); ++k)
            if (insideDomain(layout, mesh.coarseCoords(int(k)), 1e-9))
                inside.push_back(Eigen::Index(k));
        Mat V(Eigen::Index(inside.size()), 3);
        for (size_t k = 0; k < inside.size(); ++k)
            V.row(Eigen::Index(k)) = mesh.points.row(inside[k]);
        QVERIFY(!mesh.faces.empty());
        d.push_back(directedDistance(V, A));
    }
    for (size_t k = 1; k < d.size(); ++k)
        QVERIFY2(d[k] < 0.4 * d[k - 1], qPrintable(QString("%1 -> %2").arg(d[k - 1]).arg(d[k])));
}

void TestSurfaces::liftingOfSurfaceNets()
{
    AWB_SKIP_WITHOUT_THREADS();
    // The default net lies on a paraboloid; its last four points lie on a line of the lattice
    // and so in one vertical plane: 000's placement of the identity columns would be singular,
    // the chosen free rows are not.
    const LatticeScheme s = bicubicScheme();
    const PatchLayout layout = patchLayout(s, "square");
    const SurfaceMatrices m = surfaceMatrices(s, layout);
    Mat P(16, 3);
    for (int k = 0; k < 16; ++k) {
        const double x = m.net[size_t(k)].i, y = m.net[size_t(k)].j;
        P.row(k) << x, y, 0.25 * (x * x + y * y);
    }
    QVERIFY(!liftControlPoints(P).invertible);
    const SurfaceIfs ifs = buildSurfaceIfs(s, layout, m.net, P);
    QVERIFY(ifs.ifs.lifting.invertible);
    QCOMPARE(ifs.ifs.ifs.dim(), 15);
    // A flat net has no lifted IFS: the barycentric form still draws the (flat) surface.
    Mat flat = P;
    flat.col(2).setZero();
    const SurfaceIfs bary = buildSurfaceIfs(s, layout, m.net, flat);
    QVERIFY(bary.ifs.barycentric());
    QVERIFY(!bary.ifs.lifting.reason.empty());
    const Mat A = attractorPoints(bary, bary.cornerLimitStart, 3);
    QVERIFY(A.col(2).cwiseAbs().maxCoeff() < 1e-12);
}

void TestSurfaces::netsAreMatchedUpToTranslation()
{
    AWB_SKIP_WITHOUT_THREADS();
    const LatticeScheme s = loopScheme();
    const PatchLayout layout = patchLayout(s, "triangle");
    const SurfaceMatrices m = surfaceMatrices(s, layout);
    // The user lists the net shifted by (5, -2) and in reverse order.
    std::vector<LatticePoint> user;
    for (auto it = m.net.rbegin(); it != m.net.rend(); ++it)
        user.push_back(*it + LatticePoint{5, -2});
    const Mat P = randomNet(s, m.net, 3);
    const Mat Puser = P.colwise().reverse();
    const SurfaceIfs a = buildSurfaceIfs(s, layout, m.net, P);
    const SurfaceIfs b = buildSurfaceIfs(s, layout, user, Puser);
    QVERIFY(hausdorffDistance(attractorPoints(a, a.cornerLimitStart, 3),
                              attractorPoints(b, b.cornerLimitStart, 3))
            < 1e-12);
}

void TestSurfaces::badNetsAreNamed()
{
    AWB_SKIP_WITHOUT_THREADS();
    const LatticeScheme s = loopScheme();
    const SurfaceMatrices m = surfaceMatrices(s, patchLayout(s, "hexagon"));
    const auto message = [&](std::vector<LatticePoint> user) {
        try {
            matchNet(m.net, user, s.lattice());
        } catch (const InputError &e) {
            return QString(e.what());
        }
        return QString();
    };
    std::vector<LatticePoint> user = m.net;
    user.pop_back();
    QVERIFY(message(user).contains("needs 19 control points"));
    user = m.net;
    user[3] = user[4];
    QVERIFY(message(user).contains("given twice"));
    user = m.net;
    user.back() = {7, 7};
    QVERIFY(message(user).contains("(7, 7)"));
    QVERIFY(message(user).contains("missing"));
    QVERIFY_THROWS_EXCEPTION(InputError, patchLayout(bicubicScheme(), "hexagon"));
}

// The 3D view's mesh (core/render/SurfaceMesh): F^k(X0) kept as world-space primitives and
// drawn from a camera gives the very pixels of drawing the images as they are made, whatever
// the number of threads; each start set makes its kind of primitive.
void TestSurfaces::meshDrawsTheImagesAgain()
{
    const LatticeScheme s = loopScheme();
    const PatchLayout layout = patchLayout(s, "hexagon");
    const SurfaceMatrices m = surfaceMatrices(s, layout);
    const Mat P = randomNet(s, m.net, 3);
    const SurfaceIfs surface = buildSurfaceIfs(s, layout, m.net, P);
    const Ifs &f = surface.ifs.ifs;
    const StartSet start = StartSet::polygon(surface.ifs.toIfsSpace(surface.cornerLimitStart));
    const ImageLabel byMap = [](const std::uint8_t *a, int n) {
        return std::uint32_t(n > 0 ? a[0] : 0);
    };
    const int depth = 4;
    SurfaceMeshSink sink(f.views, byMap, surfaceMeshKind(start));
    iterate(f, start, depth, sink);
    const SurfaceMesh &mesh = sink.mesh;
    QCOMPARE(mesh.kind, SurfaceMesh::Kind::Triangles);
    // The hexagon of corner limits: four triangles of its fan per image.
    QCOMPARE(start.vertices.rows(), 6);
    QCOMPARE(mesh.size(), std::size_t(6 * 6 * 6 * 6 * 4));
    QCOMPARE(mesh.positions.size(), 9 * mesh.size());
    QCOMPARE(mesh.normals.size(), 3 * mesh.size());
    for (std::size_t i = 0; i < mesh.size(); ++i) {
        const double n = std::hypot(mesh.normals[3 * i], mesh.normals[3 * i + 1],
                                    mesh.normals[3 * i + 2]);
        QVERIFY(std::abs(n - 1.0) < 1e-6);
        QVERIFY(mesh.labels[i] < 6);
    }
    QVERIFY(mesh.area > 0);
    // The same surface, all cores: the same primitives (in another order, perhaps).
    const SurfaceMesh built = buildSurfaceMesh(f, start, depth, byMap);
    QCOMPARE(built.size(), mesh.size());
    QVERIFY(std::abs(built.area - mesh.area) < 1e-9 * mesh.area);

    const OrthoCamera camera = OrthoCamera::fit(P, -60, 35, 4.0 / 3.0);
    SurfaceRaster direct(320, 240, camera, f.views);
    iterate(f, start, depth, direct);
    SurfaceRaster drawn(320, 240, camera, {});
    drawn.draw(mesh, 0, mesh.size());
    QVERIFY(direct.coveredPixels() > 2000);
    QCOMPARE(drawn.coveredPixels(), direct.coveredPixels());
    for (int y = 0; y < 240; ++y)
        for (int x = 0; x < 320; ++x) {
            QCOMPARE(drawn.label(x, y), direct.label(x, y));
            QCOMPARE(drawn.depth(x, y), direct.depth(x, y));
        }
    // Drawn in ranges on several threads and merged: the picture of one thread.
    const std::vector<std::uint32_t> palette{0x1f77b4u, 0xd62728u, 0x2ca02cu};
    const auto one = drawSurfaceMesh(mesh, 320, 240, camera, 1.0, palette, 1);
    QVERIFY(one == drawSurfaceMesh(mesh, 320, 240, camera, 1.0, palette, 3));
    std::atomic<bool> cancelled{true};
    QVERIFY(drawSurfaceMesh(mesh, 320, 240, camera, 1.0, palette, 2, &cancelled).empty());

    // Points and polylines as start sets: one point per vertex, one segment per edge.
    const Mat corners = surface.ifs.toIfsSpace(surface.cornerLimitStart);
    const SurfaceMesh points = buildSurfaceMesh(f, StartSet::points(corners), 2, byMap);
    QCOMPARE(points.kind, SurfaceMesh::Kind::Points);
    QCOMPARE(points.size(), std::size_t(36 * corners.rows()));
    const SurfaceMesh segments = buildSurfaceMesh(f, StartSet::polyline(corners), 2, byMap);
    QCOMPARE(segments.kind, SurfaceMesh::Kind::Segments);
    QCOMPARE(segments.size(), std::size_t(36 * (corners.rows() - 1)));
    // The budget's depth: 6^2 images of 4 triangles fit 300, 6^3 do not.
    QCOMPARE(surfaceMeshDepth(f, start, 8, 300), 2);
    QCOMPARE(surfaceMeshDepth(f, start, 2, 1e9), 2);
    QCOMPARE(surfaceMeshDepth(f, start, 8, 0.5), 0);
}

// A mesh built with a control point's weights follows that point's move without iterating:
// exactly when the start set's coefficients on the net do not depend on the net (the corner
// limits, lambda P: the mesh is then the attractor's own triangulation), and within the
// contraction of the start set's own move otherwise (a triangle of plane points, as in 000
// Fig. 7), which the depth makes sub-pixel.
void TestSurfaces::netPointMovesTheMeshByItsWeights()
{
    AWB_SKIP_WITHOUT_THREADS();
    const LatticeScheme s = loopScheme();
    const PatchLayout layout = patchLayout(s, "hexagon");
    const SurfaceMatrices m = surfaceMatrices(s, layout);
    const Mat P = randomNet(s, m.net, 5);
    const SurfaceIfs before = buildSurfaceIfs(s, layout, m, m.net, P);
    const Projection net = before.ifs.netCoordinates();
    QCOMPARE(net.V.cols(), P.rows());
    // The coefficients reproduce every drawn point: X V0 = (X N + n) P.
    const Mat X = before.ifs.toIfsSpace(before.cornerLimitStart);
    const Mat drawn = (X * before.ifs.ifs.views[0].V).rowwise() + before.ifs.ifs.views[0].c;
    const Mat coefficients = (X * net.V).rowwise() + net.c;
    QVERIFY((coefficients * P - drawn).cwiseAbs().maxCoeff() < 1e-12);
    QVERIFY((coefficients.rowwise().sum().array() - 1.0).abs().maxCoeff() < 1e-12);

    const int j = 9; // the centre of the hexagon
    const Eigen::Vector3d delta(0.3, -0.2, 0.5);
    Mat moved = P;
    moved.row(j) += delta.transpose();
    const SurfaceIfs after = buildSurfaceIfs(s, layout, m, m.net, moved);
    const int depth = 3;
    const auto corners = [](const SurfaceIfs &f) {
        return StartSet::polygon(f.ifs.toIfsSpace(f.cornerLimitStart));
    };
    const SurfaceMesh base = buildSurfaceMesh(before.ifs.ifs, corners(before), depth, {}, {}, 1,
                                              {}, netWeight(net, j));
    QCOMPARE(base.weights.size(), base.positions.size() / 3);
    const SurfaceMesh plain = buildSurfaceMesh(before.ifs.ifs, corners(before), depth, {}, {}, 1);
    QVERIFY(plain.weights.empty());
    QVERIFY(plain.positions == base.positions);
    const SurfaceMesh followed = movedNetPoint(base, delta);
    const SurfaceMesh rebuilt = buildSurfaceMesh(after.ifs.ifs, corners(after), depth, {}, {}, 1);
    QCOMPARE(followed.positions.size(), rebuilt.positions.size());
    double worst = 0;
    for (std::size_t k = 0; k < rebuilt.positions.size(); ++k)
        worst = std::max(worst, std::abs(followed.positions[k] - rebuilt.positions[k]));
    QVERIFY2(worst < 1e-10, qPrintable(QString::number(worst)));
    QVERIFY(std::abs(followed.area - rebuilt.area) < 1e-9 * rebuilt.area);
    for (std::size_t k = 0; k < rebuilt.normals.size(); ++k)
        QVERIFY(std::abs(followed.normals[k] - rebuilt.normals[k]) < 1e-5f);

    // A triangle of plane points (000 Fig. 7's start): X = [t, 0] has coefficients only on the
    // lifting's four free rows (the barycentric coordinates of t in their tetrahedron), so the
    // move of any other point is followed exactly, and the move of a free row changes the
    // start's coefficients: the difference shrinks with the depth like the maps' contraction.
    Mat triangle(3, 3);
    triangle << P.row(0), P.row(9), P.row(18);
    const auto plane = [&](const SurfaceIfs &f) {
        return StartSet::polygon(f.ifs.toIfsSpace(triangle));
    };
    const std::vector<int> &free = before.ifs.lifting.freeRows;
    const auto gapAfterMoving = [&](int point, int k) {
        Mat movedNet = P;
        movedNet.row(point) += delta.transpose();
        const SurfaceIfs a = buildSurfaceIfs(s, layout, m, m.net, movedNet);
        const SurfaceMesh b = buildSurfaceMesh(before.ifs.ifs, plane(before), k, {}, {}, 1, {},
                                               netWeight(net, point));
        const SurfaceMesh f = movedNetPoint(b, delta);
        const SurfaceMesh r = buildSurfaceMesh(a.ifs.ifs, plane(a), k, {}, {}, 1);
        double gap = 0;
        for (std::size_t i = 0; i < r.positions.size(); ++i)
            gap = std::max(gap, std::abs(f.positions[i] - r.positions[i]));
        return gap;
    };
    int fixed = 0;
    while (std::binary_search(free.begin(), free.end(), fixed))
        ++fixed;
    QVERIFY(gapAfterMoving(fixed, 3) < 1e-10);
    const double two = gapAfterMoving(free.front(), 2), four = gapAfterMoving(free.front(), 4);
    QVERIFY2(two > 1e-6 && two < delta.norm(), qPrintable(QString::number(two)));
    QVERIFY2(four < two / 2.5, qPrintable(QString("%1 %2").arg(two).arg(four)));
}

namespace {
// The sinks as they were before the iteration fused the last map with their projections.
class UnfusedMeshSink : public SurfaceMeshSink {
public:
    using SurfaceMeshSink::SurfaceMeshSink;
    const std::vector<Projection> *projections() const override { return nullptr; }
};
class UnfusedRaster : public SurfaceRaster {
public:
    using SurfaceRaster::SurfaceRaster;
    const std::vector<Projection> *projections() const override { return nullptr; }
};
} // namespace

// The iteration applies the last map and a sink's projections as one product (D x 3 per vertex
// instead of D x D): the same mesh, weights and picture as projecting the images it made.
void TestSurfaces::lastMapFusedWithTheViews()
{
    AWB_SKIP_WITHOUT_THREADS();
    const LatticeScheme s = loopScheme();
    const PatchLayout layout = patchLayout(s, "hexagon");
    const SurfaceMatrices m = surfaceMatrices(s, layout);
    const Mat P = randomNet(s, m.net, 7);
    const SurfaceIfs f = buildSurfaceIfs(s, layout, m, m.net, P);
    Mat triangle(3, 3);
    triangle << P.row(0), P.row(9), P.row(18);
    const StartSet start = StartSet::polygon(f.ifs.toIfsSpace(triangle));
    const Projection weight = netWeight(f.ifs.netCoordinates(), 9);
    const ImageLabel label = [](const std::uint8_t *a, int n) {
        return std::uint32_t(n > 1 ? 6 * a[0] + a[1] : 0);
    };
    for (int depth : {0, 1, 3}) {
        SurfaceMeshSink fused(f.ifs.ifs.views, label, SurfaceMesh::Kind::Triangles, weight);
        UnfusedMeshSink plain(f.ifs.ifs.views, label, SurfaceMesh::Kind::Triangles, weight);
        QVERIFY(fused.projections() && fused.projections()->size() == 2);
        iterate(f.ifs.ifs, start, depth, fused);
        iterate(f.ifs.ifs, start, depth, plain);
        const SurfaceMesh &a = fused.mesh, &b = plain.mesh;
        QCOMPARE(a.size(), std::size_t(std::pow(6.0, depth)));
        QVERIFY(a.labels == b.labels);
        QCOMPARE(a.positions.size(), b.positions.size());
        QCOMPARE(a.weights.size(), a.positions.size() / 3);
        QCOMPARE(a.weights.size(), b.weights.size());
        double worst = 0, worstWeight = 0;
        for (std::size_t k = 0; k < a.positions.size(); ++k)
            worst = std::max(worst, std::abs(a.positions[k] - b.positions[k]));
        for (std::size_t k = 0; k < a.weights.size(); ++k)
            worstWeight = std::max(worstWeight, std::abs(a.weights[k] - b.weights[k]));
        QVERIFY2(worst < 1e-12 && worstWeight < 1e-12,
                 qPrintable(QString("%1 %2").arg(worst).arg(worstWeight)));
        QVERIFY(std::abs(a.area - b.area) < 1e-12 * std::max(1.0, b.area));
    }
    // The CPU raster of the same images: the same pixels but where a sample sits on an edge.
    const OrthoCamera camera = OrthoCamera::fit(f.cornerLimitStart, -60, 30, 1.25);
    SurfaceRaster fused(250, 200, camera, f.ifs.ifs.views);
    UnfusedRaster plain(250, 200, camera, f.ifs.ifs.views);
    const StartSet tiles = StartSet::polygon(f.ifs.toIfsSpace(f.cornerLimitStart));
    iterate(f.ifs.ifs, tiles, 4, fused);
    iterate(f.ifs.ifs, tiles, 4, plain);
    QVERIFY2(plain.coveredPixels() > 2000, qPrintable(QString::number(plain.coveredPixels())));
    int differ = 0;
    for (int y = 0; y < 200; ++y)
        for (int x = 0; x < 250; ++x)
            differ += fused.label(x, y) != plain.label(x, y);
    QVERIFY2(differ <= int(plain.coveredPixels() / 500), qPrintable(QString::number(differ)));
}

// Splats 3 pixels apart leave gaps of up to 2 pixels between them: fillPinholes closes those
// inside the picture and does not grow its outline.
void TestSurfaces::pinholesCloseInsideNotOutside()
{
    AWB_SKIP_WITHOUT_THREADS();
    SurfaceMesh grid;
    grid.kind = SurfaceMesh::Kind::Points;
    // Points in the plane z = 0 seen from above: world units are pixels (half height 50 at
    // 100 pixels high), a 10 x 10 grid 3 pixels apart around the centre.
    for (int j = 0; j < 10; ++j)
        for (int i = 0; i < 10; ++i) {
            grid.positions.insert(grid.positions.end(), {3.0 * i - 13.5, 3.0 * j - 13.5, 0.0});
            grid.labels.push_back(0);
        }
    OrthoCamera top;
    top.azimuth = -90;
    top.elevation = 90;
    top.halfHeight = 50;
    SurfaceRaster r(100, 100, top, {}, {}, 0.5);
    r.draw(grid, 0, grid.size());
    const std::uint64_t dots = r.coveredPixels();
    QCOMPARE(dots, std::uint64_t(100)); // one pixel a point: holes between them
    r.fillPinholes();
    // Inside the grid everything is covered; nothing beyond its outline.
    int inside = 0, outside = 0;
    for (int y = 0; y < 100; ++y)
        for (int x = 0; x < 100; ++x) {
            const bool in = x >= 36 && x <= 63 && y >= 36 && y <= 63;
            if (in)
                inside += r.covered(x, y);
            else
                outside += r.covered(x, y);
        }
    QCOMPARE(outside, 0);
    QVERIFY2(inside >= 28 * 28 * 95 / 100, qPrintable(QString::number(inside)));
}

AWB_TEST_APPLESS_MAIN(TestSurfaces)
#include "test_surfaces.moc"
