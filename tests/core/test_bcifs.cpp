// Tests of the BCIFS junction curves (003 §2.3-§5): the §4.1 matrices and the subdominant
// eigenvalue 0.696 of Fig. 16 (top), the incidence and adjacency equations, the junction's
// ends against the exact B-splines, the refined automaton of §5 (spectrum {1, j, 1/2, 1/8, 0},
// eigenvector e4 - e5, ranges of j and r, G1 through aligned handles), the unreproducible
// second example of Fig. 16, and the messages for bad input.

#include "core/ifs/Bcifs.h"
#include "core/schemes/Curves.h"
#include "core/analysis/Geometry.h"

#include <Eigen/Dense>
#include <QtTest>

#include "TestMain.h"

#include <functional>
#include <map>

using namespace awb;

namespace {

Mat rows(int r, int c, std::initializer_list<double> v)
{
    Mat M(r, c);
    auto it = v.begin();
    for (int i = 0; i < r; ++i)
        for (int j = 0; j < c; ++j)
            M(i, j) = *it++;
    return M;
}

// The test geometry: a cubic on the left, a quadratic on the right, a gap between them.
const Mat Pl = rows(4, 2, {0, 0, 1, 2, 3, 2.5, 4, 1});
const Mat Pr = rows(3, 2, {7, 0.5, 8, 2, 10, 1.5});

std::string message(const std::function<void()> &fn)
{
    try {
        fn();
    } catch (const InputError &e) {
        return e.what();
    }
    return "no error";
}
bool contains(const std::string &s, const std::string &part)
{
    return s.find(part) != std::string::npos;
}

// The images of a state at `depth` from points on its attractor, in the plane, split by the
// first arc's name (empty key: all).
std::map<std::string, Mat> drawByFirstArc(const Cifs &c, const std::string &state, int depth)
{
    std::map<std::string, std::vector<double>> xy;
    const int s = c.stateIndex(state);
    const Projection view = c.view(s);
    CallbackSink sink([&](const Mat &v, StartSet::Kind, const std::uint8_t *a, int) {
        const Mat p = project(view, v);
        for (Eigen::Index r = 0; r < p.rows(); ++r)
            for (const std::string &key : {std::string(), c.transitions[a[0]].name})
                xy[key].insert(xy[key].end(), {p(r, 0), p(r, 1)});
    });
    iterate(c, s, attractorSeeds(c), depth, sink);
    std::map<std::string, Mat> out;
    for (auto &[k, v] : xy)
        out[k] = Eigen::Map<Mat>(v.data(), 2, Eigen::Index(v.size() / 2)).transpose();
    return out;
}

double minDistance(const Mat &pts, const RowVec &q)
{
    return (pts.rowwise() - q).rowwise().norm().minCoeff();
}

} // namespace

class TestBcifs : public QObject {
    Q_OBJECT

private slots:
    void junctionMatricesAreThePapers();
    void subdominantOfFig16TopIs0696();
    void spectrumFollowsTheFreeParameters();
    void zeroComponentHandsOverToTheNextEigenvalue();
    void constraintsHoldForThePapersConstruction();
    void brokenMatrixIsReportedByName();
    void junctionEndsAreTheBSplines();
    void refinedSpectrumIsOneJHalfEighthZero();
    void refinedRangesAreThePapers();
    void refinedCurvePassesThroughTheVertexWithG1();
    void secondExampleOfFig16DoesNotReproduce();
    void badInputIsNamed();
};

void TestBcifs::junctionMatricesAreThePapers()
{
    // 003 §4.1 prints T^l, T^r, T^i; ours come from the core's B-spline schemes and eqs. (2),
    // (5), (7), (8). Entries are dyadic or the parameters themselves: exact to 1e-15.
    const JunctionParameters p;
    const double a = p.a, b = p.b, c = p.c, d = p.d, e = p.e();
    const double k = p.k, l = p.l, m = p.m, n = p.n, q = p.p();
    QVERIFY(std::abs(e - 0.0) < 1e-15);   // 1 - 0.131 - 0.2 - 0.38 - 0.289
    QVERIFY(std::abs(q - 0.55) < 1e-15);  // 1 - 0.11 - 0.12 - 0.1 - 0.12
    const JunctionMatrices jm = cubicQuadraticMatrices(p);
    const Mat Tl = rows(5, 4, {0.5, 0.125, 0, a, 0.5, 0.75, 0.5, b, 0, 0.125, 0.5, c,
                               0, 0, 0, d, 0, 0, 0, e});
    const Mat Tr = rows(5, 3, {k, 0, 0, l, 0, 0, m, 0, 0, n, 0.75, 0.25, q, 0.25, 0.75});
    const Mat Ti = rows(5, 5, {0.125, 0, a, k, 0, 0.75, 0.5, b, l, 0, 0.125, 0.5, c, m, 0,
                               0, 0, d, n, 0.75, 0, 0, e, q, 0.25});
    QVERIFY((jm.Tl - Tl).cwiseAbs().maxCoeff() < 1e-15);
    QVERIFY((jm.Tr - Tr).cwiseAbs().maxCoeff() < 1e-15);
    QVERIFY((jm.Ti - Ti).cwiseAbs().maxCoeff() < 1e-15);
}

void TestBcifs::subdominantOfFig16TopIs0696()
{
    // 003 Fig. 16 (top): a = 0.131, b = 0.2, c = 0.38, d = 0.289, k = 0.11, l = 0.12,
    // m = 0.1, n = 0.12 give lambda_2 = 0.696, printed to 3 decimals: |error| < 5e-4.
    // "Positive sub-dominant eigenvalue yields G1-continuity": both copies are governed by
    // lambda_2 and approach the junction point from opposite sides.
    const JunctionAnalysis an = analyseCubicQuadratic(JunctionParameters(), Pl, Pr);
    QVERIFY(an.subdominant.kind == SubdominantKind::RealPositive);
    QCOMPARE(an.subdominant.multiplicity, 1);
    QVERIFY(std::abs(an.subdominant.values[0].real() - 0.696) < 5e-4);
    QVERIFY(std::abs(an.subdominant.vectors[0].sum()) < 1e-12);  // parallel to BI^i
    QVERIFY(an.left.kind == SubdominantKind::RealPositive);
    QVERIFY(an.right.kind == SubdominantKind::RealPositive);
    QVERIFY(!an.left.skippedSubdominant && !an.right.skippedSubdominant);
    QVERIFY(an.g1);
    QVERIFY(contains(an.verdict, "G1"));
    // The half-tangent is the eigenvector seen through the junction's control points.
    Mat Pi(5, 2);
    Pi << Pl.bottomRows(3), Pr.topRows(2);
    RowVec dir = an.subdominant.vectors[0].real().transpose() * Pi;
    dir.normalize();
    QVERIFY(std::abs(std::abs(an.left.direction.dot(dir)) - 1.0) < 1e-12);
}

void TestBcifs::spectrumFollowsTheFreeParameters()
{
    // A caller (the GUI) sets a..d, k..n and reads the verdict of 003 §4 / §6.2-6.3 back.
    // These parameters (found by a search) give a real negative lambda_2 = -0.587: no tangent.
    JunctionParameters neg;
    neg.a = 0.06, neg.b = 0.06, neg.c = 0.15, neg.d = 0.16;
    neg.k = 0.04, neg.l = 0.13, neg.m = 0.13, neg.n = 0.0;
    const JunctionAnalysis an = analyseCubicQuadratic(neg);
    QVERIFY(an.subdominant.kind == SubdominantKind::RealNegative);
    QVERIFY(std::abs(an.subdominant.values[0].real() + 0.587) < 5e-4);
    QVERIFY(!an.g1);
    QVERIFY(contains(an.verdict, "no tangent"));
    QVERIFY(an.left.direction.size() == 0);
    // And a complex pair spirals (the reading R3 of the second example below).
    JunctionParameters spiral;
    spiral.b = 0.097, spiral.c = 0.115, spiral.d = -0.53;
    const JunctionAnalysis sp = analyseCubicQuadratic(spiral);
    QVERIFY(sp.subdominant.kind == SubdominantKind::ComplexPair);
    QVERIFY(contains(sp.verdict, "spiral"));
}

void TestBcifs::zeroComponentHandsOverToTheNextEigenvalue()
{
    // 003 §4: when the copy has no component along v2 the next eigenvalue gives the
    // half-tangent. T = V diag(1, 0.5, 0.3) V^-1 with v1 = (1,1,1)/3, v2 = (1,-1,0),
    // v3 = (1,1,-2): columns sum to 1. Copies built from v1 + t v3 only see 0.3.
    Mat V(3, 3);
    V << 1.0 / 3, 1, 1, 1.0 / 3, -1, 1, 1.0 / 3, 0, -2;
    const Mat T = V * Vec(Eigen::Vector3d(1, 0.5, 0.3)).asDiagonal() * V.inverse();
    const Vec v1 = V.col(0), v3 = V.col(2);
    Mat C(3, 2);
    C << v1 + 0.1 * v3, v1 + 0.3 * v3;
    HalfTangent h = halfTangent(T, C);
    QVERIFY(h.skippedSubdominant);
    QVERIFY(h.kind == SubdominantKind::RealPositive);
    QVERIFY(std::abs(h.values[0].real() - 0.3) < 1e-12);
    QVERIFY((h.direction.transpose() - v3.normalized()).norm() < 1e-12);  // towards the copy
    C.col(1) = v1 - 0.3 * v3;  // summed component -0.2: the copy lies on the other side
    QVERIFY((halfTangent(T, C).direction.transpose() + v3.normalized()).norm() < 1e-12);
    C.col(1) += 0.01 * V.col(1);  // a component along v2: 0.5 governs again
    h = halfTangent(T, C);
    QVERIFY(!h.skippedSubdominant);
    QVERIFY(std::abs(h.values[0].real() - 0.5) < 1e-12);
}

void TestBcifs::constraintsHoldForThePapersConstruction()
{
    // 003 eqs. (1)-(8) and each curve's §2.4 equations hold exactly (dyadic entries and
    // copied columns: residual 0; tolerance 1e-12) for Fig. 16's parameters, for other
    // parameters, and for the refined automaton of §5 at several j, r.
    for (const JunctionParameters &p : {JunctionParameters(), JunctionParameters{
                                            0.3, -0.2, 0.5, 0.1, 0.25, 0.25, 0.25, 0.2}}) {
        const ConstraintReport rep = checkConstraints(cubicQuadraticJunction(p, Pl, Pr));
        QVERIFY2(rep.satisfied, rep.message.c_str());
        QCOMPARE(int(rep.residuals.size()), 12);  // 6 for the curves, (1), (2), (4), (5), (7), (8)
    }
    const Mat H = rows(3, 2, {5, 1, 5.5, 1.5, 6, 2});
    for (double j : {0.55, 0.75, 0.95})
        for (double r : {0.3, 0.6, 0.9}) {
            const ConstraintReport rep = checkConstraints(refinedJunction({j, r}, Pl, Pr, H));
            QVERIFY2(rep.satisfied, rep.message.c_str());
            QCOMPARE(int(rep.residuals.size()), 15);
        }
}

void TestBcifs::brokenMatrixIsReportedByName()
{
    // Moving 0.01 between two entries of T^i's first column keeps the column sum (so the
    // matrix is still barycentric) but breaks adjacency (8): T^l ∂^l_1 = T^i ∂^i_0, by 0.01.
    Bcifs b = cubicQuadraticJunction(JunctionParameters(), Pl, Pr);
    Mat Ti = b.matrix("T^i");
    Ti(0, 0) += 0.01;
    Ti(1, 0) -= 0.01;
    b.setMatrix("T^i", Ti);
    ConstraintReport rep = checkConstraints(b);
    QVERIFY(!rep.satisfied);
    QVERIFY2(contains(rep.message, "adjacency constraint (8) T^l ∂^l_1 = T^i ∂^i_0 is violated"
                                   " by 0.01 (entry row 1, column 1)"), rep.message.c_str());
    for (const auto &r : rep.residuals)
        QVERIFY2((r.name == "(8)") == (r.residual > 1e-12), r.name.c_str());

    // Breaking the vertex block of T^l violates incidence (2) only (its column 0 is not
    // shared with T^i).
    b = cubicQuadraticJunction(JunctionParameters(), Pl, Pr);
    Mat Tl = b.matrix("T^l");
    Tl(0, 0) += 0.02;
    Tl(1, 0) -= 0.02;
    b.setMatrix("T^l", Tl);
    rep = checkConstraints(b);
    QVERIFY2(contains(rep.message, "incidence constraint (2) T^l ∂^l_0 = ∂^i_0 V^l is violated"
                                   " by 0.02"), rep.message.c_str());
    for (const auto &r : rep.residuals)
        QVERIFY2((r.name == "(2)") == (r.residual > 1e-12), r.name.c_str());
}

void TestBcifs::junctionEndsAreTheBSplines()
{
    // The junction's first piece (behind T^l) is a cubic B-spline segment with control points
    // (T^l)^T P^i, its last (behind T^r) a quadratic one with (T^r)^T P^i; the initial curves
    // are the exact B-splines of P^l, P^r. The seeds are curve points, so every image lies on
    // its curve (distance to the 4000-sample polyline < 1e-5, its chord error); the curve is
    // covered up to half the largest gap between images: at depth 12 a piece spans 2^-11 of
    // its segment (length < 6), so the Hausdorff distance is < 6 / 2^12 < 2e-3.
    const Bcifs b = cubicQuadraticJunction(JunctionParameters(), Pl, Pr);
    const Cifs c = toCifs(b);
    QCOMPARE(int(c.states.size()), 3);  // l, r, i
    const auto junction = drawByFirstArc(c, "i", 12);
    const Mat Pi = b.matrix("P^i").transpose();
    const BSplineBasis cubic = BSplineBasis::uniform(3, 4), quad = BSplineBasis::uniform(2, 3);
    struct Piece { std::string state, arc; const BSplineBasis *basis; Mat P; };
    const Piece pieces[] = {
        {"l", "", &cubic, Pl},
        {"r", "", &quad, Pr},
        {"i", "T^l", &cubic, b.matrix("T^l").transpose() * Pi},
        {"i", "T^r", &quad, b.matrix("T^r").transpose() * Pi},
    };
    for (const Piece &pc : pieces) {
        const Mat pts = pc.state == "i" ? junction.at(pc.arc)
                                        : drawByFirstArc(c, pc.state, 11).at("");
        const Mat exact = pc.basis->curve(pc.P, 4000);
        QVERIFY2(distanceToPolyline(pts, exact) < 1e-5, pc.arc.c_str());
        QVERIFY2(hausdorffToCurve(pts, exact) < 2e-3, pc.arc.c_str());
    }
    // The two ends meet the initial curves: the cubic's end and the quadratic's start are
    // points of the junction (to rounding).
    const RowVec cubicEnd = cubic.pointWeights(cubic.domainEnd()) * Pl;
    const RowVec quadStart = quad.pointWeights(quad.domainStart()) * Pr;
    QVERIFY(minDistance(junction.at(""), cubicEnd) < 1e-12);
    QVERIFY(minDistance(junction.at(""), quadStart) < 1e-12);
    // Adjacency (8) in the plane: the T^l piece's right end is the T^i piece's left end.
    const Vec f0 = barycentricFixedPoint(cubicCurve(Pl).T0.transpose()).transpose();
    const Vec f1 = barycentricFixedPoint(cubicCurve(Pl).T1.transpose()).transpose();
    const Mat &Tl = b.matrix("T^l"), &Ti = b.matrix("T^i");
    QVERIFY((Pi.transpose() * (Tl * f1 - Ti * Tl * f0)).norm() < 1e-12);
}

void TestBcifs::refinedSpectrumIsOneJHalfEighthZero()
{
    // 003 §5: T^il has eigenvalues {1, j, 1/2, 1/8, 0} and the eigenvector of j is along
    // e4 - e5; T^ir has {1, r, 1/4, 0} with r's eigenvector along e1 - e2. Triangular matrices
    // with dyadic entries: 1e-12. Both copies are governed by j and r.
    for (double j : {0.51, 0.6, 0.75, 0.9, 0.99})
        for (double r : {0.26, 0.5, 0.99}) {
            const RefinedAnalysis an = analyseRefined({j, r});
            const std::vector<double> expL = {1, j, 0.5, 0.125, 0}, expR = {1, r, 0.25, 0};
            QCOMPARE(an.left.values.size(), expL.size());
            for (size_t i = 0; i < expL.size(); ++i)
                QVERIFY(std::abs(an.left.values[i] - expL[i]) < 1e-12);
            for (size_t i = 0; i < expR.size(); ++i)
                QVERIFY(std::abs(an.right.values[i] - expR[i]) < 1e-12);
            const Vec vj = an.left.vectors[1].real();
            QVERIFY(std::abs(std::abs(vj.dot(Vec(Eigen::Vector<double, 5>(0, 0, 0, 1, -1))))
                             / std::sqrt(2.0) - 1.0) < 1e-12);
            const Vec vr = an.right.vectors[1].real();
            QVERIFY(std::abs(std::abs(vr.dot(Vec(Eigen::Vector4d(1, -1, 0, 0)))) / std::sqrt(2.0)
                             - 1.0) < 1e-12);
            QVERIFY(an.leftTangent.kind == SubdominantKind::RealPositive);
            QVERIFY(std::abs(an.leftTangent.values[0] - j) < 1e-12);
            QVERIFY(std::abs(an.rightTangent.values[0] - r) < 1e-12);
        }
}

void TestBcifs::refinedRangesAreThePapers()
{
    // 003 §5: "j in (0.5, 1)" and r "(0.25, 1)", computed from the fixed blocks: 1e-12.
    QVERIFY(std::abs(refinedRangeJ().lo - 0.5) < 1e-12 && refinedRangeJ().hi == 1.0);
    QVERIFY(std::abs(refinedRangeR().lo - 0.25) < 1e-12 && refinedRangeR().hi == 1.0);
    // Just below the bound, 1/2 (or 1/4) takes over as the subdominant eigenvalue.
    const Mat Til = refinedMatrices({0.51, 0.5}).Til;
    Mat below = Til;
    below(3, 3) = 0.45, below(4, 3) = 0.55;  // j = 0.45 written into the matrix directly
    QVERIFY(std::abs(subdominant(spectrum(below)).values[0] - 0.5) < 1e-12);
}

void TestBcifs::refinedCurvePassesThroughTheVertexWithG1()
{
    // 003 §5/§6.4: the curve passes through the vertex handle; the half-tangents point to the
    // first and third handles; aligned handles give G1, others do not.
    const Mat aligned = rows(3, 2, {5, 1, 5.5, 1.5, 6.5, 2.5});
    const Mat bent = rows(3, 2, {5, 1, 5.5, 1.5, 6.5, 1.0});
    for (const bool isAligned : {true, false}) {
        const Mat &H = isAligned ? aligned : bent;
        const RefinedAnalysis an = analyseRefined({0.7, 0.6}, Pl, Pr, H);
        const RowVec towardsLeft = (H.row(0) - H.row(1)).normalized();
        const RowVec towardsRight = (H.row(2) - H.row(1)).normalized();
        QVERIFY((an.leftTangent.direction - towardsLeft).norm() < 1e-12);
        QVERIFY((an.rightTangent.direction - towardsRight).norm() < 1e-12);
        QCOMPARE(an.g1, isAligned);
        const Cifs c = toCifs(refinedJunction({0.7, 0.6}, Pl, Pr, H));
        for (const char *side : {"il", "ir"})
            QVERIFY(minDistance(drawByFirstArc(c, side, 8).at(""), H.row(1)) < 1e-12);
    }
}

void TestBcifs::secondExampleOfFig16DoesNotReproduce()
{
    // 003 Fig. 16 (bottom) prints "a = 0.131, b = 0.745, c = -0.061, d = 0.289, k = 0.11,
    // b = 0.097, c = 0.115, d = -0.53, lambda_2,3 = 0.112 +- 0.449i": the second b, c, d are
    // garbled letters. No reading reproduces the pair (NOTES.md). What they give:
    //   R1 l, m, n = 0.097, 0.115, -0.53:     lambda = -1.193 (|.| > 1: T^i does not contract)
    //   R2 as R1 with n = +0.53:               lambda_2 = 0.711 (real)
    //   R3 b, c, d = 0.097, 0.115, -0.53 with Fig. 16 top's l, m, n:  0.333 +- 0.239i
    //   R4 first b, c, d with Fig. 16 top's l, m, n:  lambda_2 = 0.785 (real)
    //   R5 as R1 with n = -0.053:              lambda_2 = 0.808 (real)
    //   R6 as R1 with c = +0.061:              lambda = -1.194 (does not contract)
    //   R7 the two triples swapped:            0.404 +- 0.755i
    // and none of the 256 sign patterns of R1's eight values comes closer than 0.04.
    using P = JunctionParameters;
    const P readings[] = {
        {0.131, 0.745, -0.061, 0.289, 0.11, 0.097, 0.115, -0.53},
        {0.131, 0.745, -0.061, 0.289, 0.11, 0.097, 0.115, 0.53},
        {0.131, 0.097, 0.115, -0.53, 0.11, 0.12, 0.1, 0.12},
        {0.131, 0.745, -0.061, 0.289, 0.11, 0.12, 0.1, 0.12},
        {0.131, 0.745, -0.061, 0.289, 0.11, 0.097, 0.115, -0.053},
        {0.131, 0.745, 0.061, 0.289, 0.11, 0.097, 0.115, -0.53},
        {0.131, 0.097, 0.115, -0.53, 0.11, 0.745, -0.061, 0.289},
    };
    const Complex target(0.112, 0.449);
    const Complex expected[] = {-1.193, 0.711, {0.333, 0.239}, 0.785, 0.808, -1.194,
                                {0.404, 0.755}};
    for (size_t i = 0; i < std::size(readings); ++i) {
        const Spectrum s = analyseCubicQuadratic(readings[i]).spectrum;
        // Largest eigenvalue other than 1 (R1, R6 have one of modulus > 1).
        Complex top = 0;
        for (const Complex &z : s.values)
            if (std::abs(z - 1.0) > 1e-9 && std::abs(z) > std::abs(top) + 1e-12)
                top = z;
        top = Complex(top.real(), std::abs(top.imag()));
        QVERIFY2(std::abs(top - expected[i]) < 5e-4, qPrintable(QString::number(i + 1)));
        QVERIFY(std::abs(top - target) > 0.3);
    }
    double closest = 1e9;
    for (int mask = 0; mask < 256; ++mask) {
        double v[8] = {0.131, 0.745, -0.061, 0.289, 0.11, 0.097, 0.115, -0.53};
        for (int bit = 0; bit < 8; ++bit)
            if (mask >> bit & 1)
                v[bit] = -v[bit];
        const P p{v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7]};
        for (const Complex &z : analyseCubicQuadratic(p).spectrum.values)
            closest = std::min(closest, std::abs(z - target));
    }
    QVERIFY(closest > 0.04);
}

void TestBcifs::badInputIsNamed()
{
    Bcifs b = cubicQuadraticJunction(JunctionParameters(), Pl, Pr);
    b.setMatrix("T^i", Mat::Constant(4, 5, 0.25));
    std::string m = message([&] { b.validate(); });
    QVERIFY2(contains(m, "operator 'T^i' (i -> i) is 4 x 5; it must be 5 x 5"), m.c_str());

    b = cubicQuadraticJunction(JunctionParameters(), Pl, Pr);
    Mat Ti = b.matrix("T^i");
    Ti(2, 2) += 0.1;
    b.setMatrix("T^i", Ti);
    m = message([&] { checkConstraints(b); });
    QVERIFY2(contains(m, "column 3 of operator 'T^i' (i -> i) sums to 1.1, not 1"), m.c_str());

    Ti(2, 2) = std::numeric_limits<double>::infinity();
    b.setMatrix("T^i", Ti);
    m = message([&] { toCifs(b); });
    QVERIFY2(contains(m, "(row 3, column 3) is not a finite number"), m.c_str());

    JunctionParameters nan;
    nan.c = std::numeric_limits<double>::quiet_NaN();
    m = message([&] { analyseCubicQuadratic(nan); });
    QVERIFY2(contains(m, "junction parameter c is not a finite number"), m.c_str());

    const std::pair<RefinedParameters, const char *> outside[] = {
        {{0.5, 0.5}, "parameter j = 0.5 is outside its admissible range (0.5, 1)"},
        {{1.0, 0.5}, "parameter j = 1 is outside its admissible range (0.5, 1)"},
        {{0.3, 0.5}, "parameter j = 0.3 is outside"},
        {{0.7, 0.25}, "parameter r = 0.25 is outside its admissible range (0.25, 1)"},
        {{0.7, 1.2}, "parameter r = 1.2 is outside"},
        {{0.7, std::nan("")}, "parameter r is not a finite number"},
    };
    for (const auto &[p, expected] : outside) {
        const RefinedParameters params = p; // clang 14 cannot capture a structured binding
        m = message([&] { refinedMatrices(params); });
        QVERIFY2(contains(m, expected), m.c_str());
    }

    m = message([&] { junctionMatrices(Mat::Identity(3, 3), Mat::Identity(2, 2),
                                       Mat::Constant(4, 1, 0.25), Mat::Constant(5, 1, 0.2)); });
    QVERIFY2(contains(m, "the free columns must have 5 rows"), m.c_str());
    m = message([&] { junctionMatrices(Mat::Identity(3, 3), Mat::Identity(2, 2),
                                       Mat::Constant(5, 1, 0.25), Mat::Constant(5, 1, 0.2)); });
    QVERIFY2(contains(m, "column 1 of the free columns X of T^l sums to 1.25, not 1"),
             m.c_str());
    m = message([&] { cubicQuadraticJunction(JunctionParameters(), Pr, Pr); });
    QVERIFY2(contains(m, "the left curve needs 4 control points, got 3"), m.c_str());

    Bcifs kinds = cubicQuadraticJunction(JunctionParameters(), Pl, Pr);
    kinds.addOperator("bad", OperatorKind::Boundary, "vl", "l", Mat::Constant(3, 4, 1.0 / 3));
    m = message([&] { kinds.validate(); });
    QVERIFY2(contains(m, "operator 'bad' (vl -> l) joins cells of the wrong kinds"), m.c_str());

    Bcifs chain = cubicQuadraticJunction(JunctionParameters(), Pl, Pr);
    chain.addConstraint("(x)", ConstraintKind::Adjacency, {"T^l", "∂^r_0"}, {"T^i", "∂^i_1"});
    m = message([&] { chain.validate(); });
    QVERIFY2(contains(m, "constraint (x): T^l ends at 'l' but ∂^r_0 starts at 'r'"), m.c_str());
}

AWB_TEST_APPLESS_MAIN(TestBcifs)
#include "test_bcifs.moc"
