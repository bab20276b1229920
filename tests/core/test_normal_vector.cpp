// Tests of the normal-vector p-ary scheme of 001: point counts, the presets of §3 against their
// classic constructions, the analysis of §4 (Theorems 1 and 2), the snowflake area, the
// equivalent IFS, the sign conventions of NOTES.md and the refusal of bad input.
#include "core/ifs/Attractor.h"
#include "core/schemes/ControlPointFractal.h"
#include "core/analysis/Geometry.h"
#include "core/schemes/NormalVectorScheme.h"

#include <QtTest>

#include "TestMain.h"
#include <cmath>
#include <set>

using namespace awb;
using Id = NormalVectorPresetId;

Q_DECLARE_METATYPE(awb::NormalVectorPresetId)

namespace {

const double r3 = std::sqrt(3.0);

template<class F>
QString inputError(F f)
{
    try {
        f();
    } catch (const InputError &e) {
        return QString::fromUtf8(e.what());
    }
    return QStringLiteral("<no InputError>");
}

RowVec pt(double x, double y)
{
    RowVec v(2);
    v << x, y;
    return v;
}

// Level-k Koch vertices from the classic IFS of 000 §4.1 (written with rotation matrices,
// independent of eq. (1)): vertex w = f_{w_1} o ... o f_{w_k}(0) in lexicographic order.
Mat classicKochVertices(int k)
{
    const std::vector<AffineMap> f = kochControlPointFractal().classicMaps;
    const Eigen::Index n = Eigen::Index(std::pow(4.0, k));
    Mat out(n + 1, 2);
    for (Eigen::Index w = 0; w < n; ++w) {
        Mat x = Mat::Zero(1, 2);
        Eigen::Index rest = w;
        for (int t = 0; t < k; ++t, rest /= 4) // least significant digit = innermost map
            x = applyMap(f[rest % 4], x);
        out.row(w) = x;
    }
    out.row(n) = pt(1, 0);
    return out;
}

Mat collectAllViews(const Ifs &ifs, const Mat &start, int depth)
{
    Mat all(0, 2);
    for (const Projection &view : ifs.views) {
        PointCollector sink(view);
        iterate(ifs, StartSet::points(start), depth, sink);
        const Mat p = sink.points();
        Mat grown(all.rows() + p.rows(), 2);
        grown << all, p;
        all = grown;
    }
    return all;
}

// Similarity dimension: the s with Σ r_j^s = 1 (bisection; Σ r^s decreases in s).
double similarityDimension(const Ifs &ifs)
{
    double lo = 0, hi = 4;
    for (int it = 0; it < 200; ++it) {
        const double s = 0.5 * (lo + hi);
        double sum = 0;
        for (const AffineMap &f : ifs.maps) {
            const double det = f.A(0, 0) * f.A(1, 1) - f.A(0, 1) * f.A(1, 0);
            sum += std::pow(std::sqrt(std::abs(det)), s);
        }
        (sum > 1 ? lo : hi) = s;
    }
    return 0.5 * (lo + hi);
}

} // namespace

class TestNormalVector : public QObject
{
    Q_OBJECT

private slots:
    void pointCounts();
    void conventions();
    void kochIsClassicKoch();
    void lengthRatios_data();
    void lengthRatios();
    void approximatingFirstStep();
    void theorem1();
    void contraction_data();
    void contraction();
    void snowflakeArea();
    void ifsMatchesSubdivision_data();
    void ifsMatchesSubdivision();
    void ifsFromAnyStart();
    void snowflakeIfsViews();
    void noEquivalentIfs();
    void sierpinskiIsGasket();
    void dragonNeverRetraces();
    void sevenAryIsNotMinkowski();
    void badInput();
};

void TestNormalVector::pointCounts()
{
    // 001 §2: P^k has p^k n + 1 points for an open polygon of n edges; a closed one has p^k n.
    for (const NormalVectorPreset &p : normalVectorPresets()) {
        const std::vector<ControlPolygon> levels = p.scheme.levels(p.polygon, 3);
        const double n = double(p.polygon.edgeCount()), a = p.scheme.arity();
        for (int k = 0; k <= 3; ++k) {
            const double expected = std::pow(a, k) * n + (p.polygon.closed ? 0 : 1);
            QCOMPARE(double(levels[k].points.rows()), expected);
            QCOMPARE(p.scheme.pointCount(p.polygon, k), expected);
            QCOMPARE(levels[k].closed, p.polygon.closed);
        }
        QVERIFY(levels[3].points == p.scheme.subdivide(p.polygon, 3).points);
        // Continuing from level 1 at level 1 gives the same polygons (non-stationary schemes
        // need the level passed on).
        QVERIFY(p.scheme.subdivide(levels[1], 2, 1).points == levels[3].points);
    }
    const NormalVectorPreset koch = normalVectorPreset(Id::Koch);
    QCOMPARE(koch.scheme.subdivide(equilateralTriangle(), 2).points.rows(), 48);
    QCOMPARE(subdividePreset(Id::Koch, 7).points.rows(), 16385); // 4^7 + 1
}

void TestNormalVector::conventions()
{
    // NOTES.md: positive normal = edge rotated 90° counter-clockwise.
    const NormalVectorScheme levy({0, 0.5}, {0, 0.5});
    QVERIFY(levy.step(unitSegment(), 0).points.row(1) == pt(0.5, 0.5));
    const NormalVectorScheme down({0, 0.5}, {0, 0.5}, NormalDirection::Negative);
    QVERIFY(down.step(unitSegment(), 0).points.row(1) == pt(0.5, -0.5));

    // Human-like, β = (-1)^(k+1)(...): the first step (k = 0) bumps down, the next one flips.
    const NormalVectorPreset human = normalVectorPreset(Id::HumanLike);
    const auto h = human.scheme.levels(human.polygon, 2);
    QVERIFY((h[1].points.row(2) - pt(0.5, -0.5)).norm() < 1e-15);
    const RowVec a = h[1].points.row(0), b = h[1].points.row(1), e = b - a;
    const RowVec expected = 0.5 * (a + b) + 0.5 * pt(-e(1), e(0)); // k = 1: + positive normal
    QVERIFY((h[2].points.row(2) - expected).norm() < 1e-15);

    // Sierpiński, (-1)^(k+i): up at k = 0; at k = 1 edge 0 bends back to the base line.
    const auto s = normalVectorPreset(Id::SierpinskiArrowhead).scheme.levels(unitSegment(), 2);
    QVERIFY((s[1].points.row(1) - pt(0.25, r3 / 4)).norm() < 1e-15);
    QVERIFY((s[2].points.row(1) - pt(0.25, 0)).norm() < 1e-15);
    QVERIFY(!normalVectorConventions().empty());
}

void TestNormalVector::kochIsClassicKoch()
{
    // 001 §3.3: scheme (5) "can be used to generate the classical Koch curve". Level 1 is the
    // generator exactly; level 6 matches the classic IFS vertices to round-off (1e-13: six
    // levels of products of numbers <= 1).
    const NormalVectorPreset koch = normalVectorPreset(Id::Koch);
    Mat generator(5, 2);
    generator << 0, 0, 1.0 / 3, 0, 0.5, r3 / 6, 2.0 / 3, 0, 1, 0;
    QVERIFY((koch.scheme.step(unitSegment(), 0).points - generator).cwiseAbs().maxCoeff()
            < 1e-16);
    const Mat level6 = koch.scheme.subdivide(unitSegment(), 6).points;
    const double err = (level6 - classicKochVertices(6)).cwiseAbs().maxCoeff();
    QVERIFY2(err < 1e-13, qPrintable(QString::number(err)));
}

void TestNormalVector::lengthRatios_data()
{
    QTest::addColumn<Id>("id");
    QTest::addColumn<double>("ratio");
    // Σ_j |a_{j+1} - a_j| over the new edges of a unit edge (a_j = (α_j, ±β_j)):
    QTest::newRow("levy") << Id::Levy << std::sqrt(2.0);              // 2 / √2
    QTest::newRow("dragon") << Id::Dragon << std::sqrt(2.0);          // the sign only mirrors
    QTest::newRow("sierpinski") << Id::SierpinskiArrowhead << 1.5;     // 3 edges of 1/2
    QTest::newRow("koch") << Id::Koch << 4.0 / 3;                     // Theorem 2
    QTest::newRow("snowflake") << Id::KochSnowflake << 4.0 / 3;
    // 2 * |(-1/4, 1/3)| + 2 * |(3/4, 1/6)| = 2 * 5/12 + 2 * √85/12
    QTest::newRow("tigerhead") << Id::Tigerhead << (5 + std::sqrt(85.0)) / 6;
    // 2 * |(5/9, 1/3)| + 2 * |(1/18, 1/6)| = 2√34/9 + 2√10/18
    QTest::newRow("human") << Id::HumanLike << (2 * std::sqrt(34.0) + std::sqrt(10.0)) / 9;
    // 4 edges of 2√3/9 and 2 of 1/3
    QTest::newRow("crown") << Id::Crown << 8 * r3 / 9 + 2.0 / 3;
    // 6 edges of 1/4 and the middle one of 1/2
    QTest::newRow("sevenary") << Id::SevenAry << 2.0;
}

void TestNormalVector::lengthRatios()
{
    QFETCH(Id, id);
    QFETCH(double, ratio);
    const NormalVectorPreset p = normalVectorPreset(id);
    const NormalVectorAnalysis an = analyse(p.scheme);
    QVERIFY(std::abs(an.lengthRatioMin - ratio) < 1e-14);
    QVERIFY(std::abs(an.lengthRatioMax - ratio) < 1e-14);
    // Every edge is replaced by p edges whose lengths are fixed multiples of its own, so the
    // measured ratio is exact at every level: L_k = L_0 ratio^k (Theorem 2 for Koch, (4/3)^k),
    // up to the round-off of summing p^k lengths (1e-12 relative).
    const std::vector<LevelMeasure> m = measureLevels(p.scheme, p.polygon, 6);
    for (int k = 0; k <= 6; ++k) {
        const double predicted = m[0].length * std::pow(ratio, k);
        QVERIFY2(std::abs(m[k].length - predicted) < 1e-12 * predicted,
                 qPrintable(QString("level %1: %2 vs %3").arg(k).arg(m[k].length).arg(predicted)));
    }
    QCOMPARE(an.nonRectifiable, ratio > 1);
}

void TestNormalVector::approximatingFirstStep()
{
    // The approximating curve (Fig. 8(c)) moves the old points, so the edge from the midpoint
    // of edge i to the first new point of edge i+1 is (e_i - e_{i+1}) / 2, which depends on the
    // corner. On the unit square (90° corners, |e_i - e_{i+1}| = √2) one step gives per side
    // 2|(1/4, 1/5)| + 1/2 + √2/2 = √41/10 + 1/2 + √2/2; later levels have other angles.
    const NormalVectorPreset p = normalVectorPreset(Id::Approximating);
    const NormalVectorAnalysis an = analyse(p.scheme);
    QVERIFY(std::isnan(an.lengthRatioMin) && std::isnan(an.edgeContraction));
    QCOMPARE(an.paperContractionBound, 1.0); // |1 - 1/2| + |-1/2|: the bound is not < 1
    QVERIFY(!an.convergent);
    const std::vector<LevelMeasure> m = measureLevels(p.scheme, p.polygon, 4);
    const double ratio = std::sqrt(41.0) / 10 + 0.5 + std::sqrt(2.0) / 2;
    QVERIFY(std::abs(m[1].length / m[0].length - ratio) < 1e-14);
    // What the figure shows: the edges do shrink level by level on this polygon.
    for (int k = 1; k <= 4; ++k)
        QVERIFY(m[k].maxEdge < m[k - 1].maxEdge);
}

void TestNormalVector::theorem1()
{
    // 001 Theorem 1 for scheme (5): ||F^{k+1} - F^k|| = √3/6 max|edge| and, by the triangle
    // inequality, max edge shrinks by max{1/3, 1/6 + √3/6} = (√3 + 1)/6 per step.
    const NormalVectorPreset koch = normalVectorPreset(Id::Koch);
    const NormalVectorAnalysis an = analyse(koch.scheme);
    QVERIFY(std::abs(an.paperContractionBound - (r3 + 1) / 6) < 1e-15);
    QVERIFY(std::abs(an.displacementFactor - r3 / 6) < 1e-15);
    // The exact ratio is 1/3 (|(1/6, √3/6)| = 1/3): the paper's factor is an upper bound.
    QVERIFY(std::abs(an.edgeContraction - 1.0 / 3) < 1e-15);
    QVERIFY(an.convergent);
    QVERIFY(an.verdict.find("convergent") == 0);
    QVERIFY(an.verdict.find("non-rectifiable") != std::string::npos);
    // Measured: the longest edge of level k is 3^-k; the sup distance of consecutive
    // piecewise-linear interpolants (at the new vertices) is √3/6 * 3^-k.
    const auto levels = koch.scheme.levels(unitSegment(), 5);
    const std::vector<LevelMeasure> m = measureLevels(koch.scheme, unitSegment(), 5);
    for (int k = 0; k < 5; ++k) {
        QVERIFY(std::abs(m[k].maxEdge - std::pow(3.0, -k)) < 1e-14);
        const Mat &cur = levels[k].points, &next = levels[k + 1].points;
        double sup = 0;
        for (Eigen::Index r = 0; r < next.rows(); ++r) {
            const Eigen::Index i = r / 4, j = r % 4;
            const RowVec onF = i + 1 < cur.rows()
                                   ? RowVec(cur.row(i) + (j / 4.0) * (cur.row(i + 1) - cur.row(i)))
                                   : RowVec(cur.row(i));
            sup = std::max(sup, (next.row(r) - onF).norm());
        }
        QVERIFY(std::abs(sup - an.displacementFactor * m[k].maxEdge) < 1e-14);
    }
}

void TestNormalVector::contraction_data()
{
    QTest::addColumn<Id>("id");
    QTest::addColumn<double>("exact");
    QTest::addColumn<double>("paperBound");
    // exact = max_j |Δ_j|, paperBound = max_j (|Δα_j| + |Δβ_j|), derived by hand from §3.
    QTest::newRow("levy") << Id::Levy << 1 / std::sqrt(2.0) << 1.0;
    QTest::newRow("sierpinski") << Id::SierpinskiArrowhead << 0.5 << (1 + r3) / 4;
    QTest::newRow("tigerhead") << Id::Tigerhead << std::sqrt(85.0) / 12 << 11.0 / 12;
    QTest::newRow("human") << Id::HumanLike << std::sqrt(34.0) / 9 << 8.0 / 9;
    QTest::newRow("crown") << Id::Crown << 2 * r3 / 9 << 1.0 / 3 + r3 / 9;
    QTest::newRow("sevenary") << Id::SevenAry << 0.5 << 0.5;
}

void TestNormalVector::contraction()
{
    QFETCH(Id, id);
    QFETCH(double, exact);
    QFETCH(double, paperBound);
    const NormalVectorAnalysis an = analyse(normalVectorPreset(id).scheme);
    QVERIFY(std::abs(an.edgeContraction - exact) < 1e-15);
    QVERIFY(std::abs(an.paperContractionBound - paperBound) < 1e-15);
    // Lévy: the triangle-inequality bound is exactly 1, yet the exact factor decides.
    QVERIFY(an.convergent);
}

void TestNormalVector::snowflakeArea()
{
    // Each step puts an equilateral bump of side L/3 outside every edge of length L: with 3 * 4^k
    // edges of length 3^-k, A_{k+1} = A_k + 3 * 4^k * (√3/4) * 9^-(k+1) = A_k + (A_0/3)(4/9)^k,
    // so A_k = A_0 (1 + (1/3) Σ_{j<k} (4/9)^j) = A_0 (1 + 3/5 (1 - (4/9)^k)), A_0 = √3/4.
    const NormalVectorPreset p = normalVectorPreset(Id::KochSnowflake);
    const std::vector<LevelMeasure> m = measureLevels(p.scheme, p.polygon, 7);
    const double a0 = r3 / 4;
    for (int k = 0; k <= 7; ++k) {
        const double closed = a0 * (1 + 0.6 * (1 - std::pow(4.0 / 9, k)));
        // Shoelace over 3 * 4^7 vertices: 1e-12 relative.
        QVERIFY2(std::abs(m[k].area - closed) < 1e-12 * closed,
                 qPrintable(QString("level %1: %2 vs %3").arg(k).arg(m[k].area).arg(closed)));
    }
}

void TestNormalVector::ifsMatchesSubdivision_data()
{
    QTest::addColumn<Id>("id");
    QTest::addColumn<int>("depth");
    QTest::newRow("levy") << Id::Levy << 10;
    QTest::newRow("koch") << Id::Koch << 6;
    QTest::newRow("tigerhead") << Id::Tigerhead << 5;
    QTest::newRow("crown") << Id::Crown << 4;
    QTest::newRow("sevenary") << Id::SevenAry << 4;
}

void TestNormalVector::ifsMatchesSubdivision()
{
    // Interpolatory, one sign: the new edges are images of the old edge under p similarities,
    // so F^k applied to the unit edge's end points gives exactly the vertices of level k.
    QFETCH(Id, id);
    QFETCH(int, depth);
    const NormalVectorPreset p = normalVectorPreset(id);
    QVERIFY(!whyNoEquivalentIfs(p.scheme));
    const Ifs ifs = equivalentIfs(p.scheme);
    QCOMPARE(ifs.size(), p.scheme.arity());
    const Mat fromIfs = collectAllViews(ifs, unitSegment().points, depth);
    const Mat level = p.scheme.subdivide(unitSegment(), depth).points;
    const double dH = hausdorffDistance(fromIfs, level);
    QVERIFY2(dH < 1e-12, qPrintable(QString::number(dH)));
}

void TestNormalVector::ifsFromAnyStart()
{
    // From any start set X the Hutchinson operator contracts Hausdorff distance by the largest
    // ratio γ = 1/3: d_H(F^k X, V_k) <= γ^k (d_H(X, K) + d_H(V_0, K)), V_k the level-k vertices
    // (= F^k V_0) and K the Koch curve, which lies in the triangle (0,0), (1,0), (1/2, √3/6).
    const Ifs ifs = equivalentIfs(normalVectorPreset(Id::Koch).scheme);
    const RowVec x0 = pt(0.3, 0.7);
    const int k = 7;
    const Mat image = collectAllViews(ifs, x0, k);
    const Mat level = normalVectorPreset(Id::Koch).scheme.subdivide(unitSegment(), k).points;
    double dX = 0;
    for (const RowVec &c : {pt(0, 0), pt(1, 0), pt(0.5, r3 / 6)})
        dX = std::max(dX, (x0 - c).norm());
    const double bound = std::pow(1.0 / 3, k) * (dX + 0.5); // d_H(V_0, K) <= 1/2
    const double dH = hausdorffDistance(image, level);
    QVERIFY2(dH <= bound, qPrintable(QString("%1 > %2").arg(dH).arg(bound)));
    QVERIFY(dH > 0); // the start point is not on the curve: the images only approach it
}

void TestNormalVector::snowflakeIfsViews()
{
    // One view per edge of the triangle: drawing all three views is the snowflake.
    const NormalVectorPreset p = normalVectorPreset(Id::KochSnowflake);
    const Ifs ifs = equivalentIfs(p.scheme, p.polygon);
    QCOMPARE(ifs.views.size(), size_t(3));
    const Mat fromIfs = collectAllViews(ifs, unitSegment().points, 5);
    const Mat level = p.scheme.subdivide(p.polygon, 5).points;
    QVERIFY(hausdorffDistance(fromIfs, level) < 1e-12);
}

void TestNormalVector::noEquivalentIfs()
{
    // The sign rules that change with the edge or the level still have an equivalent IFS: an
    // edge subdivided with the other sign carries a reversed or mirrored copy. The search over
    // the orientations finds it for every interpolatory preset; only the approximating curve
    // (alpha_0 != 0) has none.
    for (Id id : {Id::Dragon, Id::SierpinskiArrowhead, Id::HumanLike}) {
        const NormalVectorPreset p = normalVectorPreset(id);
        QVERIFY2(!whyNoEquivalentIfs(p.scheme), p.name.c_str());
        const Ifs ifs = equivalentIfs(p.scheme, p.polygon);
        QCOMPARE(ifs.size(), p.scheme.arity());
        // Drawn over the figure's polygon, F^6 of the edge ends is the polygon after 6 steps.
        const Mat fromIfs = collectAllViews(ifs, unitSegment().points, 6);
        const Mat level = p.scheme.subdivide(p.polygon, 6).points;
        QVERIFY2(hausdorffDistance(fromIfs, level) < 1e-12, p.name.c_str());
    }
    // The dragon: f1(z) = (1 + i) z / 2, f2(z) = 1 - (1 - i) z / 2 (issue 13; row form of
    // z |-> c z is [[Re c, Im c], [-Im c, Re c]]).
    const Ifs dragon = equivalentIfs(normalVectorPreset(Id::Dragon).scheme);
    QVERIFY((dragon.maps[0].A - matrixFromRows({{0.5, 0.5}, {-0.5, 0.5}})).norm() < 1e-15);
    QVERIFY(dragon.maps[0].b.norm() < 1e-15);
    QVERIFY((dragon.maps[1].A - matrixFromRows({{-0.5, 0.5}, {-0.5, -0.5}})).norm() < 1e-15);
    QVERIFY((dragon.maps[1].b - RowVec::Unit(2, 0)).norm() < 1e-15);
    const NormalVectorScheme approximating = normalVectorPreset(Id::Approximating).scheme;
    QVERIFY(whyNoEquivalentIfs(approximating).has_value());
    QVERIFY(inputError([&] { equivalentIfs(approximating); }).contains("no equivalent IFS"));
    QVERIFY(whyNoEquivalentIfs(approximating)->find("α_0") != std::string::npos);
    // A scheme whose new edge is as long as the old one has no attractor.
    const NormalVectorScheme flat({0, 1}, {0, 0});
    QVERIFY(inputError([&] { equivalentIfs(flat); }).contains("no map would contract"));
}

void TestNormalVector::sierpinskiIsGasket()
{
    // 001 Fig. 4(d): seven steps of scheme (3) from the unit segment give the Sierpiński gasket
    // with corners (0,0), (1,0), (1/2, √3/2). Its vertices are corners of the level-7 triangles,
    // i.e. points of F^7(corners) for the classic gasket IFS of 000 §4.2 (to round-off), and
    // every such corner is within one level-7 triangle side (2^-7) of a vertex.
    const int k = 7;
    const Mat arrow = subdividePreset(Id::SierpinskiArrowhead, k).points;
    const ControlPointFractal g = sierpinskiControlPointFractal();
    Mat corners(3, 2);
    corners << g.controlPoints.row(0), g.controlPoints.row(2), g.controlPoints.row(4);
    PointCollector sink(classicIfs(g).views.front());
    iterate(classicIfs(g), StartSet::points(corners), k, sink);
    const Mat gasket = sink.points();
    QVERIFY(directedDistance(arrow, gasket) < 1e-13);
    QVERIFY(directedDistance(gasket, arrow) <= std::ldexp(1.0, -k) + 1e-13);
}

namespace {
// Distinct undirected edges of a polyline whose vertices lie on the lattice (Z / scale)^2.
size_t distinctLatticeEdges(const Mat &d, double scale)
{
    std::set<std::pair<std::pair<long, long>, std::pair<long, long>>> edges;
    for (Eigen::Index i = 0; i + 1 < d.rows(); ++i) {
        auto a = std::make_pair(std::lround(d(i, 0) * scale), std::lround(d(i, 1) * scale));
        auto b = std::make_pair(std::lround(d(i + 1, 0) * scale),
                                std::lround(d(i + 1, 1) * scale));
        edges.insert(a < b ? std::make_pair(a, b) : std::make_pair(b, a));
    }
    return edges.size();
}
} // namespace

void TestNormalVector::dragonNeverRetraces()
{
    // Fig. 3(a): with β_1 = (-1)^i/2 the curve is Heighway's dragon: after 10 steps 2^10 edges
    // of length 2^-5 on the lattice (Z/32)^2, and no edge is traversed twice. The Lévy curve
    // (same scheme, constant sign) does retrace edges, so this checks the sign rule.
    const Mat d = subdividePreset(Id::Dragon, 10).points;
    for (Eigen::Index i = 0; i + 1 < d.rows(); ++i)
        QVERIFY(std::abs((d.row(i + 1) - d.row(i)).norm() - 1.0 / 32) < 1e-13);
    QCOMPARE(distinctLatticeEdges(d, 32), size_t(1024));
    QVERIFY(distinctLatticeEdges(subdividePreset(Id::Levy, 10).points, 32) < 1024);
}

void TestNormalVector::sevenAryIsNotMinkowski()
{
    // NOTES.md: the 7-ary curve of Fig. 9(b) equals the Minkowski sausage (8 edges of 1/4) only
    // at level 1. The sausage is itself scheme (1) with p = 8.
    const NormalVectorScheme seven = normalVectorPreset(Id::SevenAry).scheme;
    const NormalVectorScheme sausage({0, 0.25, 0.25, 0.5, 0.5, 0.5, 0.75, 0.75},
                                     {0, 0, 0.25, 0.25, 0, -0.25, -0.25, 0});
    const Mat s1 = seven.subdivide(unitSegment(), 1).points;
    const Mat m1 = sausage.subdivide(unitSegment(), 1).points;
    // Level 1: the same polyline; the sausage only has an extra vertex (1/2, 0) on the middle
    // edge (1/2, 1/4) -> (1/2, -1/4) of the 7-ary one.
    Mat m1Without(8, 2);
    m1Without << m1.topRows(4), m1.bottomRows(4);
    QVERIFY((s1 - m1Without).cwiseAbs().maxCoeff() < 1e-16);
    QVERIFY(m1.row(4) == pt(0.5, 0));
    // Level 2: the middle edge holds a half-size copy (bumps of 1/8), the sausage two quarter
    // copies (bumps of 1/16): the vertex sets are 1/16 apart somewhere.
    QVERIFY(hausdorffDistance(seven.subdivide(unitSegment(), 2).points,
                              sausage.subdivide(unitSegment(), 2).points) > 0.06);
    // Similarity dimensions: 6 (1/4)^s + (1/2)^s = 1 gives s = log_2 3; 8 (1/4)^s = 1 gives 1.5.
    QVERIFY(std::abs(similarityDimension(equivalentIfs(seven)) - std::log2(3.0)) < 1e-12);
    QVERIFY(std::abs(similarityDimension(equivalentIfs(sausage)) - 1.5) < 1e-12);
}

void TestNormalVector::badInput()
{
    using NVS = NormalVectorScheme;
    QVERIFY(inputError([] { NVS({0, 0.5}, {0}); }).contains("β has 1 values but α has 2"));
    QVERIFY(inputError([] { NVS({0}, {0}); }).contains("p = 1"));
    QVERIFY(inputError([] { NVS({0, NAN}, {0, 0}); }).contains("α_1 is not a finite number"));
    QVERIFY(inputError([] { NVS({0, 0}, {0, INFINITY}); })
                .contains("β_1 is not a finite number"));
    QVERIFY(inputError([] { NVS({0, 0.5, 1}, {0, 0, 0}, NormalDirection::Positive,
                                {BetaSign::Constant, BetaSign::EdgeAlternating}); })
                .contains("2 β signs given for p = 3"));

    const NVS koch = normalVectorPreset(Id::Koch).scheme;
    ControlPolygon one;
    one.points = Mat::Zero(1, 2);
    QVERIFY(inputError([&] { koch.subdivide(one, 1); })
                .contains("an open control polygon needs at least 2 points, got 1"));
    ControlPolygon two = unitSegment();
    two.closed = true;
    QVERIFY(inputError([&] { koch.subdivide(two, 1); })
                .contains("a closed control polygon needs at least 3 points, got 2"));
    ControlPolygon space;
    space.points = Mat::Zero(2, 3);
    QVERIFY(inputError([&] { koch.subdivide(space, 1); }).contains("need 2 coordinates"));
    ControlPolygon nan = unitSegment();
    nan.points(1, 0) = NAN;
    QVERIFY(inputError([&] { koch.subdivide(nan, 1); })
                .contains("control polygon: entry (row 2, column 1)"));
    // 4^13 + 1 ≈ 6.7e7 points is over the limit of 5e7; 4^12 + 1 ≈ 1.7e7 would be allowed.
    QVERIFY(inputError([&] { koch.subdivide(unitSegment(), 13); }).contains("would make"));
    QVERIFY(inputError([&] { koch.levels(unitSegment(), 1000); }).contains("would make"));
    QVERIFY(inputError([&] { measureLevels(koch, unitSegment(), 40); }).contains("would make"));
    QVERIFY(inputError([&] { koch.subdivide(unitSegment(), -1); }).contains("negative"));
    QVERIFY(inputError([&] { koch.step(unitSegment(), -2); }).contains("level cannot be"));
    const NVS approx = normalVectorPreset(Id::Approximating).scheme;
    QVERIFY(inputError([&] { approx.subdivide(unitSegment(), 1); })
                .contains("open control polygons need α_0 = β_0 = 0"));
}

AWB_TEST_APPLESS_MAIN(TestNormalVector)
#include "test_normal_vector.moc"
