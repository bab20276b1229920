// Addresses of an item (issue 16, part 3): the parameter pieces of each curve scheme, the
// control points S_w P of a sub-copy, and the point export limited to a sub-copy (`attractor-cli
// points --address`), which must be f_w applied to the points written without it.

#include "PointCsv.h"
#include "TestProjects.h"

#include "model/ItemAddress.h"
#include "model/PointExport.h"

#include <QBuffer>
#include <QtTest>

#include "TestMain.h"

using namespace awb;
using namespace awb::test;

namespace {

QByteArray writeCsv(const DerivedIfs &d, const StartSet &start, int depth, const Address &w)
{
    QBuffer buffer;
    buffer.open(QIODevice::WriteOnly);
    writePointsCsv(buffer, d, start, depth, {}, w);
    return buffer.data();
}

} // namespace

class TestItemAddress : public QObject {
    Q_OBJECT
private slots:
    void parameterPiecesFollowTheScheme();
    void controlPointsOfASubCopy();
    void exportOfASubCopyIsTheWordApplied();
    void refusesBadAddresses();
};

void TestItemAddress::parameterPiecesFollowTheScheme()
{
    using K = SchemeSpec::Kind;
    auto bspline = curve("b", scheme(K::BSpline), fivePoints());
    QCOMPARE(parameterPieces(*bspline), uniformPieces(2));
    QVERIFY(parameterMeaning(*bspline).contains("knot parameter"));
    SchemeSpec bez = scheme(K::Bezier);
    bez.degree = 3;
    bez.t = {0.3, 0.0};
    auto bezier = curve("z", bez, {{0, 0}, {1, 2}, {3, 2}, {4, 0}});
    QCOMPARE(parameterPieces(*bezier),
             (std::vector<ParameterInterval>{{0.0, 0.3}, {0.3, 1.0}}));
    QVERIFY(parameterMeaning(*bezier).contains("Bernstein"));
    bez.t = {0.5, 0.3};
    QVERIFY(bezier->setScheme(bez));
    QVERIFY(parameterPieces(*bezier).empty());   // a complex split has no real parameter
    auto four = curve("f", scheme(K::FourPoint), fivePoints());
    QCOMPARE(parameterPieces(*four), uniformPieces(2));
}

void TestItemAddress::controlPointsOfASubCopy()
{
    auto item = curve("b", scheme(SchemeSpec::Kind::BSpline), fivePoints());
    const auto d = item->derivedIfs();
    QVERIFY(d);
    const Mat P = toMatrix(fivePoints());
    const auto one = addressControlPoints(*d, {1});
    QVERIFY(one);
    QVERIFY((*one - d->S.real[1] * P).cwiseAbs().maxCoeff() < 1e-15);
    // w = 0,1,1: S_2 S_2 S_1 P, the coarse piece first.
    const auto three = addressControlPoints(*d, {0, 1, 1});
    QVERIFY(three);
    const Mat expected = d->S.real[1] * d->S.real[1] * d->S.real[0] * P;
    QVERIFY((*three - expected).cwiseAbs().maxCoeff() < 1e-14);
}

void TestItemAddress::exportOfASubCopyIsTheWordApplied()
{
    auto item = curve("b", scheme(SchemeSpec::Kind::BSpline), fivePoints());
    const auto d = item->derivedIfs();
    const StartSet start = item->coreStartSet(*d);
    const Address w{0, 1, 1};
    const int depth = 7;
    std::vector<int> maps;
    const Mat sub = csvPoints(writeCsv(*d, start, depth, w), &maps);
    const Mat all = csvPoints(writeCsv(*d, start, depth, {}));
    QCOMPARE(sub.rows(), all.rows());
    QCOMPARE(sub.rows(), Eigen::Index(128));
    QVERIFY(std::all_of(maps.begin(), maps.end(), [](int m) { return m == 1; }));
    // The same points in the IFS space, f_w applied, projected: equal to 17 digits.
    std::vector<RowVec> space;
    CallbackSink sink([&](const Mat &v, StartSet::Kind, const std::uint8_t *, int) {
        space.push_back(v.row(0));
    });
    iterate(d->ifs, start, depth, sink);
    const AffineMap f = composeAddress(d->ifs, w);
    QCOMPARE(Eigen::Index(space.size()), sub.rows());
    for (std::size_t i = 0; i < space.size(); ++i) {
        const RowVec x = project(d->ifs.views[0], Mat(space[i] * f.A + f.b));
        QVERIFY2((x - sub.row(Eigen::Index(i))).norm() < 1e-13, qPrintable(QString::number(i)));
        const RowVec y = project(d->ifs.views[0], Mat(space[i]));
        QVERIFY((y - all.row(Eigen::Index(i))).norm() < 1e-13);
    }
}

void TestItemAddress::refusesBadAddresses()
{
    auto item = curve("b", scheme(SchemeSpec::Kind::BSpline), fivePoints());
    const auto d = item->derivedIfs();
    QCOMPARE(parseItemAddress("1,0", *d), (Address{1, 0}));
    QVERIFY_THROWS_EXCEPTION(InputError, parseItemAddress("0,3", *d));
    QVERIFY_THROWS_EXCEPTION(InputError, parseItemAddress("", *d));
    QVERIFY(!parseParameterInterval("0,1"));
    QCOMPARE(*parseParameterInterval("[0.25, 0.5]"), (ParameterInterval{0.25, 0.5}));
    QVERIFY_THROWS_EXCEPTION(InputError, parseParameterInterval("[0.5, 0.25]"));
    QVERIFY_THROWS_EXCEPTION(InputError, parseParameterInterval("[a, 0.25]"));
    QBuffer buffer;
    buffer.open(QIODevice::WriteOnly);
    QVERIFY_THROWS_EXCEPTION(InputError, writePointsCsv(buffer, *d, item->coreStartSet(*d), 3,
                                                        {}, Address{2}));
}

AWB_TEST_GUILESS_MAIN(TestItemAddress)
#include "test_item_address.moc"
