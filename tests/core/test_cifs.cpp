// Tests of the controlled IFS (003 §2.2): the fern automaton of Fig. 4 (left) against the
// classic fern IFS, the fern with one arc redirected into a Sierpinski state (Fig. 4 right,
// Fig. 5 bottom), cycle contractivity, random iteration and the messages for bad input.

#include "core/ifs/Cifs.h"
#include "core/analysis/Geometry.h"
#include "core/analysis/Spectrum.h"

#include <QtTest>

#include "TestMain.h"

#include <functional>
#include <map>

using namespace awb;

namespace {

// The images of one CIFS state at `depth`, drawn with the state's control points; `keep`
// filters by address.
Mat drawState(const Cifs &c, int state, int depth,
              const std::function<bool(const std::uint8_t *)> &keep = {})
{
    std::vector<double> xy;
    const Projection view = c.view(state);
    CallbackSink sink([&](const Mat &v, StartSet::Kind, const std::uint8_t *a, int) {
        if (keep && !keep(a))
            return;
        const Mat p = project(view, v);
        for (Eigen::Index r = 0; r < p.rows(); ++r)
            xy.insert(xy.end(), {p(r, 0), p(r, 1)});
    });
    iterate(c, state, attractorSeeds(c), depth, sink);
    return Eigen::Map<Mat>(xy.data(), 2, Eigen::Index(xy.size() / 2)).transpose();
}

// The classic gasket on triangle V (3 x 2): the vertices under all words of length `depth`
// of x |-> (x + v_k) / 2, computed directly in the plane (independent of the core).
void gasket(const Mat &V, const RowVec &a, const RowVec &b, const RowVec &c, int depth,
            std::vector<RowVec> &out)
{
    if (depth == 0) {
        out.insert(out.end(), {a, b, c});
        return;
    }
    const RowVec ab = (a + b) / 2, bc = (b + c) / 2, ca = (c + a) / 2;
    gasket(V, a, ab, ca, depth - 1, out);
    gasket(V, ab, b, bc, depth - 1, out);
    gasket(V, ca, bc, c, depth - 1, out);
}
Mat classicGasket(const Mat &V, int depth)
{
    std::vector<RowVec> pts;
    gasket(V, V.row(0), V.row(1), V.row(2), depth, pts);
    Mat out(pts.size(), 2);
    for (size_t i = 0; i < pts.size(); ++i)
        out.row(i) = pts[i];
    return out;
}

// Radius of a disc around 0 mapped into itself by every fern map: max |b| / (1 - ||A||_2).
double fernRadius()
{
    double R = 0;
    for (const AffineMap &f : barnsleyFernMaps())
        R = std::max(R, f.b.norm() / (1.0 - contractivity(f.A).normFactor));
    return R;
}

Mat square3(std::initializer_list<double> v)
{
    Mat M(3, 3);
    auto it = v.begin();
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c)
            M(r, c) = *it++;
    return M;
}

} // namespace

class TestCifs : public QObject {
    Q_OBJECT

private slots:
    void fernStateIsTheClassicFern();
    void everyStateIsNonEmptyAndBounded();
    void sierpinskiStateIsTheClassicGasket();
    void fernContainsAnAffineCopyOfTheGasket();
    void addressesFollowTheArcs();
    void pathCountMatchesTheImages();
    void cyclesAreCheckedForContraction();
    void randomIterationLandsOnTheAttractors();
    void badInputIsNamed();
};

void TestCifs::fernStateIsTheClassicFern()
{
    // 003 Fig. 4 (left) is the ordinary IFS: the one-state automaton in barycentric form must
    // draw exactly the classic fern. Both start from the maps' fixed points; at equal depth the
    // point sets agree up to rounding of the 3 x 3 barycentric products (tolerance 1e-10 on a
    // figure 10 units tall).
    const int depth = 7;
    const Cifs c = barnsleyFernCifs();
    const Mat cifsPts = drawState(c, 0, depth);

    Ifs ifs;
    for (const AffineMap &f : barnsleyFernMaps())
        ifs.maps.push_back(f);
    ifs.views.push_back({Mat::Identity(2, 2), RowVec::Zero(2)});
    Mat fixedPts(4, 2);
    for (int i = 0; i < 4; ++i)
        fixedPts.row(i) = *fixedPoint(ifs.maps[i]);
    PointCollector classic(ifs.views[0]);
    iterate(ifs, StartSet::points(fixedPts), depth, classic);

    QCOMPARE(cifsPts.rows(), classic.points().rows());
    QVERIFY(hausdorffDistance(cifsPts, classic.points()) < 1e-10);
}

void TestCifs::everyStateIsNonEmptyAndBounded()
{
    // Both states of Fig. 4 (right) have non-empty attractors inside the disc every fern map
    // sends into itself (the gasket lies in its frame triangle, within that disc too).
    const Cifs c = fernSierpinskiCifs();
    const double R = fernRadius();
    QVERIFY(R > 10.0 && R < 11.0);  // 1.6 / (1 - 0.851): the main frond's translation
    for (int s = 0; s < 2; ++s) {
        BoundsSink bounds({c.view(s)});
        const IterationStats st = iterate(c, s, attractorSeeds(c), 8, bounds);
        QVERIFY(st.images > 0);
        QVERIFY(!bounds.empty());
        QVERIFY(bounds.finite());
        const Mat pts = drawState(c, s, 6);
        QVERIFY(pts.rowwise().norm().maxCoeff() <= R);
    }
}

void TestCifs::sierpinskiStateIsTheClassicGasket()
{
    // The Sierpinski state (arcs lambda |-> (lambda + e_k)/2 on the frame) equals the gasket
    // drawn directly in the plane: same points at equal depth, Hausdorff ~1e-12.
    const Cifs c = fernSierpinskiCifs();
    const int s = c.stateIndex("Sierpinski");
    for (int depth : {0, 3, 8}) {
        const Mat cifsPts = drawState(c, s, depth);
        const Mat classic = classicGasket(fernFrame(), depth);
        QVERIFY2(hausdorffDistance(cifsPts, classic) < 1e-12, qPrintable(QString::number(depth)));
    }
}

void TestCifs::fernContainsAnAffineCopyOfTheGasket()
{
    // 003 §2.2: after the redirected arc the iteration follows the Sierpinski rules, so the
    // fern state's images behind that arc are f(gasket) for the redirected fern map f.
    for (int redirected : {1, 2, 3}) {
        const Cifs c = fernSierpinskiCifs(redirected);
        const int depth = 7;
        const Mat copy = drawState(c, c.stateIndex("Fern"), depth,
                                   [&](const std::uint8_t *a) { return a[0] == redirected; });
        const AffineMap f = barnsleyFernMaps()[redirected];
        const Mat expected = applyMap(f, classicGasket(fernFrame(), depth - 1));
        QVERIFY(hausdorffDistance(copy, expected) < 1e-12);
        // And the rest of the fern is made of further copies: deeper paths through the arc.
        const Mat deeper = drawState(c, 0, depth, [&](const std::uint8_t *a) {
            return a[0] != redirected && a[1] == redirected;
        });
        QVERIFY(deeper.rows() > 0);
    }
}

void TestCifs::addressesFollowTheArcs()
{
    // address[0] leaves the drawn state; every next symbol leaves the previous arc's target.
    const Cifs c = fernSierpinskiCifs(2);
    int checked = 0;
    CallbackSink sink([&](const Mat &, StartSet::Kind, const std::uint8_t *a, int n) {
        QCOMPARE(n, 4);
        int state = 0;
        for (int k = 0; k < n; ++k) {
            QCOMPARE(c.transitions[a[k]].from, state);
            state = c.transitions[a[k]].to;
        }
        ++checked;
    });
    iterate(c, 0, controlPolygonStarts(c), 4, sink);
    QCOMPARE(double(checked), pathCount(c, 0, 4));
}

void TestCifs::pathCountMatchesTheImages()
{
    // Paths of length k from the fern state: c_k(S) = 3^k and c_k(F) = 3 c_{k-1}(F) +
    // c_{k-1}(S), so c_k(F) = 3^k + k 3^(k-1): 648 for k = 5.
    const Cifs c = fernSierpinskiCifs();
    QCOMPARE(pathCount(c, 0, 5), 648.0);
    QCOMPARE(pathCount(c, 1, 5), 243.0);
    CallbackSink sink([](const Mat &, StartSet::Kind, const std::uint8_t *, int) {});
    QCOMPARE(iterate(c, 0, attractorSeeds(c), 5, sink).images, std::uint64_t(648));
}

void TestCifs::cyclesAreCheckedForContraction()
{
    // Fig. 4 right has six simple cycles (the self-loops); the slowest is the main frond,
    // whose linear part has eigenvalues 0.85 +- 0.04i, modulus sqrt(0.7241) = 0.85094.
    const Cifs c = fernSierpinskiCifs();
    const CifsCheck check = checkCifs(c);
    QVERIFY(check.contractive);
    QVERIFY(check.complete);
    QCOMPARE(int(check.cycles.size()), 6);
    double slowest = 0;
    for (const auto &cy : check.cycles)
        slowest = std::max(slowest, cy.spectralRadius);
    QVERIFY(std::abs(slowest - std::sqrt(0.7241)) < 1e-12);

    // A two-state cycle whose arcs expand by 1.5 and contract by 0.9 expands (1.35) although
    // one arc contracts; 1.2 and 0.5 contract (0.6). Scaling by s about the centroid in
    // barycentric form: S = s I + (1 - s)/3 ones.
    auto scaling = [](double s) { return Mat(s * Mat::Identity(3, 3)
                                             + Mat::Constant(3, 3, (1 - s) / 3)); };
    for (auto [sa, sb, ok] : {std::tuple{1.2, 0.5, true}, std::tuple{1.5, 0.9, false}}) {
        Cifs two;
        two.addState("A", fernFrame());
        two.addState("B", fernFrame());
        two.addTransition("x", 0, 1, scaling(sa));
        two.addTransition("y", 1, 0, scaling(sb));
        const CifsCheck ch = checkCifs(two);
        QCOMPARE(ch.contractive, ok);
        QCOMPARE(int(ch.cycles.size()), 1);
        QVERIFY(std::abs(ch.cycles[0].spectralRadius - sa * sb) < 1e-12);
        if (!ok) {
            QVERIFY(ch.message.find("A -x-> B -y-> A") != std::string::npos);
            QVERIFY(ch.message.find("1.35") != std::string::npos);
            QVERIFY_THROWS_EXCEPTION(InputError, attractorSeeds(two));
        }
    }
}

void TestCifs::randomIterationLandsOnTheAttractors()
{
    // Each chaos point is within rho^skip of its attractor (2^-64 for the gasket). The depth-10
    // gasket's vertices are within one level-10 triangle (diameter 10.44 / 2^10) of every
    // gasket point. A fern point whose latest arc is the redirected one is f(x) for the
    // Sierpinski chain's current point x, so the same bound holds scaled by ||A_f||_2.
    const Cifs c = fernSierpinskiCifs(2);
    const int S = c.stateIndex("Sierpinski");
    const double diam = std::sqrt(109.0), cell = diam / 1024.0;
    const Mat gasket10 = classicGasket(fernFrame(), 10);

    ChaosOptions opt;
    opt.samples = 20000;
    opt.skip = 64;
    PointCollector onGasket(c.view(S));
    QCOMPARE(chaosGame(c, S, opt, onGasket).images, std::uint64_t(20000));
    QVERIFY(directedDistance(onGasket.points(), gasket10) <= cell + 1e-9);

    PointCollector onFern(c.view(0));
    chaosGame(c, 0, opt, onFern);
    const Mat pts = onFern.points();
    std::map<int, int> seen;
    std::vector<int> copyRows;
    for (Eigen::Index r = 0; r < pts.rows(); ++r) {
        ++seen[onFern.firstSymbols()[r]];
        if (onFern.firstSymbols()[r] == 2)
            copyRows.push_back(int(r));
    }
    QCOMPARE(int(seen.size()), 4);  // every fern arc is taken
    Mat copy(copyRows.size(), 2);
    for (size_t i = 0; i < copyRows.size(); ++i)
        copy.row(i) = pts.row(copyRows[i]);
    const AffineMap f = barnsleyFernMaps()[2];
    const double bound = contractivity(f.A).normFactor * cell + 1e-9;
    QVERIFY(copy.rows() > 100);  // the leaflet's weight 0.07 of 20000
    QVERIFY(directedDistance(copy, applyMap(f, gasket10)) <= bound);
    QVERIFY(pts.rowwise().norm().maxCoeff() <= fernRadius());
}

void TestCifs::badInputIsNamed()
{
    auto message = [](const std::function<void()> &fn) -> std::string {
        try {
            fn();
        } catch (const InputError &e) {
            return e.what();
        }
        return "no error";
    };
    auto contains = [](const std::string &s, const char *part) {
        return s.find(part) != std::string::npos;
    };
    const Mat frame = fernFrame();
    const Mat good = square3({1, 0, 0, 0.5, 0.5, 0, 0.5, 0, 0.5});

    Cifs wrongSize;
    wrongSize.addState("A", frame);
    wrongSize.addTransition("t", 0, 0, Mat::Identity(2, 3) * 0.5);
    std::string m = message([&] { wrongSize.validate(); });
    QVERIFY2(contains(m, "arc 't' (A -> A) has a 2 x 3 matrix; it must be 3 x 3"), m.c_str());

    Cifs rows;
    rows.addState("A", frame);
    rows.addTransition("t", 0, 0, square3({1, 0, 0, 0.5, 0.4, 0, 0.5, 0, 0.5}));
    m = message([&] { rows.validate(); });
    QVERIFY2(contains(m, "row 2 of arc 't' (A -> A) sums to 0.9, not 1"), m.c_str());

    Cifs nan;
    nan.addState("A", frame);
    Mat bad = good;
    bad(1, 1) = std::numeric_limits<double>::quiet_NaN();
    nan.addTransition("t", 0, 0, bad);
    m = message([&] { nan.validate(); });
    QVERIFY2(contains(m, "arc 't' (A -> A): entry (row 2, column 2) is not a finite number"),
             m.c_str());

    Cifs dead;
    dead.addState("A", frame);
    dead.addState("B", frame);
    dead.addTransition("t", 0, 1, good);
    m = message([&] { dead.validate(); });
    QVERIFY2(contains(m, "state 'B' has no outgoing arc"), m.c_str());

    Cifs column;  // 003's column convention: T = S^T, columns summing to 1
    column.addState("A", frame);
    column.addColumnTransition("t", 0, 0, good.transpose());
    column.validate();
    QVERIFY(column.transitions[0].S.isApprox(good));

    const Cifs fern = fernSierpinskiCifs();
    CallbackSink sink([](const Mat &, StartSet::Kind, const std::uint8_t *, int) {});
    m = message([&] { iterate(fern, 0, attractorSeeds(fern), 65, sink); });
    QVERIFY2(contains(m, "iteration depth must be between 0 and 64"), m.c_str());
    auto starts = attractorSeeds(fern);
    starts[1] = StartSet::points(Mat::Ones(1, 2));
    m = message([&] { iterate(fern, 0, starts, 3, sink); });
    QVERIFY2(contains(m, "start set of state 'Sierpinski' has 2 coordinates"), m.c_str());
    m = message([&] { fern.stateIndex("Koch"); });
    QVERIFY2(contains(m, "no state 'Koch'"), m.c_str());
    m = message([&] { fernSierpinskiCifs(4); });
    QVERIFY2(contains(m, "T0..T3"), m.c_str());
    Mat collinear(3, 2);
    collinear << 0, 0, 1, 1, 2, 2;
    m = message([&] { barycentricMatrix(barnsleyFernMaps()[1], frame, collinear); });
    QVERIFY2(contains(m, "affinely dependent"), m.c_str());
}

AWB_TEST_APPLESS_MAIN(TestCifs)
#include "test_cifs.moc"
