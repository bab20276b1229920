// Addresses of attractors (issue 16, part 3): parsing with clear errors, the address <-> t
// round trip (exact for the dyadic parameters of B-splines), f_w and the control points
// S_w P = S_{w_k} .. S_{w_1} P of a sub-copy (de Casteljau halves of a cubic Bézier, the
// midpoint rule of the cubic B-spline), and the sampled points a hover looks up.

#include "core/ifs/Address.h"
#include "core/ifs/Ifs.h"
#include "core/schemes/Scheme.h"

#include <QtTest>

#include "TestMain.h"

#include <cstdint>

using namespace awb;

namespace {

Mat pts(std::initializer_list<std::initializer_list<double>> r) { return matrixFromRows(r); }

// The uniform cubic B-spline segment on four points at u in [0, 1].
RowVec cubicSegment(const Mat &P, double u)
{
    const double v = 1 - u;
    return (v * v * v * P.row(0) + (3 * u * u * u - 6 * u * u + 4) * P.row(1)
            + (-3 * u * u * u + 3 * u * u + 3 * u + 1) * P.row(2) + u * u * u * P.row(3))
           / 6.0;
}

// One de Casteljau split of a cubic at s: the control points of [0, s] or [s, 1].
Mat deCasteljau(const Mat &P, double s, bool left)
{
    std::vector<Mat> levels{P};
    while (levels.back().rows() > 1) {
        const Mat &q = levels.back();
        Mat next(q.rows() - 1, q.cols());
        for (Eigen::Index i = 0; i + 1 < q.rows(); ++i)
            next.row(i) = (1 - s) * q.row(i) + s * q.row(i + 1);
        levels.push_back(next);
    }
    Mat out(P.rows(), P.cols());
    for (Eigen::Index k = 0; k < P.rows(); ++k)
        out.row(k) = left ? levels[std::size_t(k)].row(0)
                          : levels[std::size_t(P.rows() - 1 - k)].row(
                                levels[std::size_t(P.rows() - 1 - k)].rows() - 1);
    return out;
}

// A reproducible word of `length` symbols below `maps`.
Address word(std::uint64_t seed, int length, int maps)
{
    Address w;
    std::uint64_t x = seed * 6364136223846793005ULL + 1442695040888963407ULL;
    for (int k = 0; k < length; ++k) {
        x = x * 6364136223846793005ULL + 1442695040888963407ULL;
        w.push_back(int((x >> 33) % std::uint64_t(maps)));
    }
    return w;
}

void expectError(const std::string &text, int maps, const char *needle)
{
    try {
        parseAddress(text, maps);
        QFAIL(qPrintable(QString("'%1' was accepted").arg(QString::fromStdString(text))));
    } catch (const InputError &e) {
        QVERIFY2(QString(e.what()).contains(QLatin1String(needle)), e.what());
    }
}

const Mat kBezier = pts({{0, 0}, {1, 2}, {3, 2}, {4, 0}});

} // namespace

class TestAddresses : public QObject {
    Q_OBJECT
private slots:
    void parsesAddresses();
    void refusesBadAddresses();
    void dyadicRoundTripIsExact();
    void ternaryRoundTrip();
    void bezierPiecesAtAnySplit();
    void coversAnInterval();
    void composedMapIsTheWordApplied();
    void bezierHalvesAreDeCasteljau();
    void bsplineSubCopyIsItsPieceOfTheCurve();
    void sampledPointsLieAtTheirParameter();
    void parameterIsTheKnotParameter_data();
    void parameterIsTheKnotParameter();
};

void TestAddresses::parsesAddresses()
{
    QCOMPARE(parseAddress("0,1,1", 2), (Address{0, 1, 1}));
    QCOMPARE(parseAddress(" 0 , 1 ,1 ", 2), (Address{0, 1, 1}));
    QCOMPARE(parseAddress("0 1 1", 2), (Address{0, 1, 1}));
    QCOMPARE(parseAddress("011", 2), (Address{0, 1, 1}));   // one digit a symbol (N <= 10)
    QCOMPARE(parseAddress("12", 13), (Address{12}));         // not with more maps
    QCOMPARE(parseAddress("2,0", 3), (Address{2, 0}));
    QCOMPARE(formatAddress({0, 1, 1}), std::string("0,1,1"));
    QCOMPARE(formatAddress({}), std::string());
}

void TestAddresses::refusesBadAddresses()
{
    expectError("", 2, "empty");
    expectError("  ", 2, "empty");
    expectError("0,2", 2, "map 2, but the IFS has 2 maps (0..1)");
    expectError("0,x,1", 2, "'x', is not a map number");
    expectError("0,-1", 2, "is not a map number");
    expectError("0.5", 2, "is not a map number");
    expectError("0,,1", 2, "empty symbol");
    expectError(",0", 2, "empty symbol");
    expectError("0,1,", 2, "ends with a comma");
    expectError(std::string(65, '0'), 2, "65 symbols, more than 64");
    QCOMPARE(parseAddress(std::string(64, '1'), 2).size(), std::size_t(64));
    QVERIFY_THROWS_EXCEPTION(InputError, composeAddress(Ifs{}, Address{0}));
}

// t(w) = 0.w_1 w_2 .. w_k in base 2, compared exactly with the integer numerator / 2^k.
void TestAddresses::dyadicRoundTripIsExact()
{
    const auto pieces = uniformPieces(2);
    int checked = 0;
    for (int length = 1; length <= 20; ++length) {
        for (std::uint64_t seed = 0; seed < 60; ++seed) {
            const Address w = word(seed * 31 + std::uint64_t(length), length, 2);
            std::uint64_t numerator = 0;
            for (int s : w)
                numerator = 2 * numerator + std::uint64_t(s);
            const double scale = std::ldexp(1.0, -length);
            const ParameterInterval t = addressInterval(pieces, w);
            QCOMPARE(t.t0, double(numerator) * scale);           // exact, no tolerance
            QCOMPARE(t.t1, double(numerator + 1) * scale);
            QCOMPARE(addressOfParameter(pieces, t.t0, length), w);
            // Any dyadic t inside the piece, e.g. its midpoint, has w as its first symbols.
            const Address longer = addressOfParameter(pieces, t.t0 + scale / 2, length + 1);
            QCOMPARE(Address(longer.begin(), longer.begin() + length), w);
            QCOMPARE(longer.back(), 1);
            ++checked;
        }
    }
    // Every word of length 12 maps to a distinct grid point, in order.
    for (std::uint64_t n = 0; n < 4096; ++n) {
        const Address w = addressOfParameter(pieces, double(n) / 4096.0, 12);
        QCOMPARE(addressInterval(pieces, w).t0, double(n) / 4096.0);
    }
    QCOMPARE(addressOfParameter(pieces, 1.0, 5), (Address{1, 1, 1, 1, 1}));
    QCOMPARE(checked, 20 * 60);
}

void TestAddresses::ternaryRoundTrip()
{
    const auto pieces = uniformPieces(3);
    for (int length = 1; length <= 12; ++length) {
        const Address w = word(std::uint64_t(length), length, 3);
        const ParameterInterval t = addressInterval(pieces, w);
        QCOMPARE(addressOfParameter(pieces, 0.5 * (t.t0 + t.t1), length), w);
        QVERIFY(std::abs(t.t1 - t.t0 - std::pow(3.0, -length)) < 1e-15);
    }
}

// A Bézier curve split at s: piece 0 is [0, s], piece 1 [s, 1] of the Bernstein parameter.
void TestAddresses::bezierPiecesAtAnySplit()
{
    const std::vector<ParameterInterval> pieces{{0.0, 0.25}, {0.25, 1.0}};
    const ParameterInterval t = addressInterval(pieces, {1, 0});
    QCOMPARE(t.t0, 0.25);
    QCOMPARE(t.t1, 0.25 + 0.75 * 0.25);
    QCOMPARE(addressOfParameter(pieces, 0.3, 2), (Address{1, 0}));
}

void TestAddresses::coversAnInterval()
{
    const auto pieces = uniformPieces(2);
    QCOMPARE(coverInterval(pieces, 0.25, 0.625, 8),
             (std::vector<Address>{{0, 1}, {1, 0, 0}}));
    QCOMPARE(coverInterval(pieces, 0.0, 1.0, 8), (std::vector<Address>{{}}));
    QVERIFY_THROWS_EXCEPTION(InputError, coverInterval(pieces, 0.5, 0.25, 8));
}

void TestAddresses::composedMapIsTheWordApplied()
{
    const SubdivisionIfs s = buildSubdivisionIfs(bsplineScheme(3), kBezier);
    const Address w{0, 1, 1, 0};
    const AffineMap f = composeAddress(s.ifs, w);
    RowVec x = RowVec::LinSpaced(s.ifs.dim(), 0.3, 1.7);
    RowVec y = x;
    for (auto it = w.rbegin(); it != w.rend(); ++it)   // f_{w_4} first, f_{w_1} last
        y = y * s.ifs.maps[std::size_t(*it)].A + s.ifs.maps[std::size_t(*it)].b;
    QVERIFY((x * f.A + f.b - y).norm() < 1e-13);
    const AffineMap id = composeAddress(s.ifs, {});
    QVERIFY(id.A.isIdentity() && id.b.isZero());
}

// The classical halves of the cubic Bézier (0,0), (1,2), (3,2), (4,0) at t = 1/2.
void TestAddresses::bezierHalvesAreDeCasteljau()
{
    const SubdivisionMatrices m = BezierScheme(3, 0.5).matrices(4);
    const Mat left = addressMatrix(m.S, {0}) * kBezier;
    const Mat classic = pts({{0, 0}, {0.5, 1}, {1.25, 1.5}, {2, 1.5}});
    QVERIFY2((left - classic).cwiseAbs().maxCoeff() < 1e-15, "left half");
    const Mat right = addressMatrix(m.S, {1}) * kBezier;
    QVERIFY((right - pts({{2, 1.5}, {2.75, 1.5}, {3.5, 1}, {4, 0}})).cwiseAbs().maxCoeff()
            < 1e-15);
    // w = 0,1: the right half of the left half, i.e. the curve on [1/4, 1/2].
    const Mat quarter = addressMatrix(m.S, {0, 1}) * kBezier;
    QVERIFY((quarter - deCasteljau(deCasteljau(kBezier, 0.5, true), 0.5, false))
                .cwiseAbs()
                .maxCoeff()
            < 1e-15);
    // At a split s = 0.3 the words follow the Bernstein parameter the same way.
    const SubdivisionMatrices m3 = BezierScheme(3, 0.3).matrices(4);
    const Mat w10 = addressMatrix(m3.S, {1, 0}) * kBezier;
    QVERIFY((w10 - deCasteljau(deCasteljau(kBezier, 0.3, false), 0.3, true))
                .cwiseAbs()
                .maxCoeff()
            < 1e-14);
}

// S_w P of a cubic B-spline (one segment, four points) is the control polygon of the curve
// on w's parameter interval: midpoint rule for one step, the curve itself for longer words.
void TestAddresses::bsplineSubCopyIsItsPieceOfTheCurve()
{
    const SubdivisionMatrices m = bsplineScheme(3).matrices(4);
    const Mat &P = kBezier;
    const Mat left = addressMatrix(m.S, {0}) * P;
    Mat midpoint(4, 2);
    midpoint.row(0) = (P.row(0) + P.row(1)) / 2;
    midpoint.row(1) = (P.row(0) + 6 * P.row(1) + P.row(2)) / 8;
    midpoint.row(2) = (P.row(1) + P.row(2)) / 2;
    midpoint.row(3) = (P.row(1) + 6 * P.row(2) + P.row(3)) / 8;
    QVERIFY((left - midpoint).cwiseAbs().maxCoeff() < 1e-15);
    const auto pieces = uniformPieces(2);
    for (int length = 1; length <= 10; ++length) {
        const Address w = word(std::uint64_t(100 + length), length, 2);
        const Mat Q = addressMatrix(m.S, w) * P;
        const ParameterInterval t = addressInterval(pieces, w);
        for (double u : {0.0, 0.25, 0.5, 1.0}) {
            const RowVec onPiece = cubicSegment(Q, u);
            const RowVec onCurve = cubicSegment(P, t.t0 + u * (t.t1 - t.t0));
            QVERIFY2((onPiece - onCurve).norm() < 1e-12,
                     qPrintable(QString::fromStdString(formatAddress(w))));
        }
    }
}

void TestAddresses::sampledPointsLieAtTheirParameter()
{
    const SubdivisionIfs s = buildSubdivisionIfs(bsplineScheme(3), kBezier);
    const AddressedPoints a = sampleAddresses(s.ifs, s.toIfsSpace(pts({{5, 5}})), 1 << 12);
    QCOMPARE(a.length, 12);
    QCOMPARE(a.size(), Eigen::Index(4096));
    QCOMPARE(a.shown.size(), std::size_t(1));
    const auto pieces = uniformPieces(2);
    for (Eigen::Index i = 0; i < a.size(); i += 97) {
        const double t = addressInterval(pieces, a.address(i)).t0;
        QVERIFY((a.shown[0].row(i) - cubicSegment(kBezier, t)).norm() < 1e-12);
    }
    const RowVec target = cubicSegment(kBezier, 0.375);
    const NearestAddress n = nearestAddress(a, target(0), target(1));
    QVERIFY(n.distance < 1e-12);
    QCOMPARE(a.address(n.index), (Address{0, 1, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0}));
}

void TestAddresses::parameterIsTheKnotParameter_data()
{
    QTest::addColumn<int>("kind");   // 0: uniform B-spline, 1: end-interpolating, 2: Bézier
    QTest::addColumn<int>("degree");
    QTest::newRow("uniform cubic, 5 points") << 0 << 3;
    QTest::newRow("uniform quadratic (Chaikin), 5 points") << 0 << 2;
    QTest::newRow("end-interpolating cubic, 5 points") << 1 << 3;
    QTest::newRow("Bezier quartic") << 2 << 4;
}

// The point of the attractor at address w (the start of its piece) is the exact curve at
// t_0(w) scaled to the knot domain: what the status bar's t means.
void TestAddresses::parameterIsTheKnotParameter()
{
    QFETCH(int, kind);
    QFETCH(int, degree);
    const Mat P = pts({{0, 0}, {1, 2}, {2.5, 2.25}, {4, 1}, {5.125, -0.5}});
    std::unique_ptr<CurveScheme> scheme;
    if (kind == 0)
        scheme = std::make_unique<UniformScheme>(bsplineScheme(degree));
    else if (kind == 1)
        scheme = std::make_unique<EndInterpolatingBSplineScheme>(degree);
    else
        scheme = std::make_unique<BezierScheme>(degree, 0.5);
    const SubdivisionIfs s = buildSubdivisionIfs(*scheme, P);
    QVERIFY(!s.barycentric());
    const AddressedPoints a = sampleAddresses(s.ifs, s.toIfsSpace(pts({{1, 1}})), 1 << 6);
    QCOMPARE(a.length, 6);
    const Mat exact = *scheme->exactCurve(P, 65);   // t = j / 64
    const auto pieces = uniformPieces(2);
    for (Eigen::Index i = 0; i < a.size(); ++i) {
        const double t = addressInterval(pieces, a.address(i)).t0;
        const auto j = Eigen::Index(std::lround(t * 64));
        QVERIFY2((a.shown[0].row(i) - exact.row(j)).norm() < 1e-10,
                 qPrintable(QString::fromStdString(formatAddress(a.address(i)))));
    }
}

AWB_TEST_APPLESS_MAIN(TestAddresses)
#include "test_addresses.moc"
