// Fractint's .ifs files (core/exchange/FractintIfs.h, issue 34): the coefficient order of 2D
// and 3D rows (x' = a x + b y + e, y' = c x + d y + f), comments, commas and any whitespace,
// several entries, malformed ones named by line and column while the others are kept, the
// round trip through the writer, and the control cage of an imported IFS.
#include "core/exchange/FractintIfs.h"

#include <QtTest>

#include "TestMain.h"

#include <Eigen/Dense>

#include <sstream>

using namespace awb;

namespace {

// A library as Fractint ships them: Barnsley's fern (Fractint's fractint.ifs), a Sierpinski
// triangle written with commas, a 3D tetrahedron, and two malformed entries.
const char *library = R"(; comments run to the end of a line
fern {   ; Barnsley 1988
  0     0    0     .16 0 0    .01
  .85  .04 -.04  .85  0 1.6  .85
  .2  -.26  .23  .22  0 1.6  .07
 -.15  .28  .26  .24  0 .44  .07
}
triangle { .5 0 0 .5 0 0 .333, .5 0 0 .5 .5 0 .333, .5 0 0 .5 .25 .433 .334 }
broken {
  .5 0 0 .5 0 0
}
tetra (3D) {
 .5 0 0 0 .5 0 0 0 .5 0 0 0 .25
 .5 0 0 0 .5 0 0 0 .5 1 0 0 .25
 .5 0 0 0 .5 0 0 0 .5 0 1 0 .25
 .5 0 0 0 .5 0 0 0 .5 0 0 1 .25
}
bad { .5 0 0 .5 x 0 .5 }
)";

FractintFile read(const std::string &text)
{
    std::istringstream in(text);
    return readFractintIfs(in);
}

RowVec apply(const AffineMap &f, double x, double y)
{
    RowVec p(2);
    p << x, y;
    return p * f.A + f.b;
}

} // namespace

class TestFractintIfs : public QObject {
    Q_OBJECT
private slots:
    void readsEveryWellFormedEntry();
    void coefficientsMeanWhatFractintSays();
    void malformedEntriesAreNamedWithTheirPlace();
    void writerRoundTrip();
    void controlCageIsTheAttractorsBox();
};

void TestFractintIfs::readsEveryWellFormedEntry()
{
    const FractintFile f = read(library);
    QCOMPARE(int(f.entries.size()), 3);
    QCOMPARE(f.entries[0].name, std::string("fern"));
    QCOMPARE(f.entries[0].line, 2);
    QCOMPARE(int(f.entries[0].maps.size()), 4);
    QCOMPARE(f.entries[0].probabilities, (std::vector<double>{.01, .85, .07, .07}));
    QCOMPARE(f.entries[1].name, std::string("triangle"));
    QCOMPARE(int(f.entries[1].maps.size()), 3);
    QCOMPARE(f.entries[2].name, std::string("tetra"));
    QCOMPARE(f.entries[2].dimension, 3);
    QCOMPARE(int(f.entries[2].maps.size()), 4);
    QCOMPARE(int(f.problems.size()), 2);
}

void TestFractintIfs::coefficientsMeanWhatFractintSays()
{
    const FractintFile f = read(library);
    // The fern's second map: x' = .85 x + .04 y, y' = -.04 x + .85 y + 1.6.
    const AffineMap &g = f.entries[0].maps[1];
    const RowVec at = apply(g, 1.0, 2.0);
    QVERIFY(std::abs(at(0) - (.85 + .08)) < 1e-15);
    QVERIFY(std::abs(at(1) - (-.04 + 1.7 + 1.6)) < 1e-15);
    // The triangle's third map fixes (1/2, .866): the corner of the Sierpinski triangle.
    const RowVec corner = apply(f.entries[1].maps[2], 0.5, 0.866);
    QVERIFY((corner - RowVec::Map(std::vector<double>{0.5, 0.866}.data(), 2)).norm() < 1e-12);
    // 3D: x' = a x + b y + c z + j, ...: the second map halves towards its fixed point
    // (2, 0, 0).
    const AffineMap &t = f.entries[2].maps[1];
    RowVec p(3);
    p << 1, 1, 1;
    const RowVec q = p * t.A + t.b;
    QCOMPARE(q(0), 1.5);
    QCOMPARE(q(1), 0.5);
    QCOMPARE(q(2), 0.5);
    // fractintCoefficients is the inverse of the reading.
    QCOMPARE(fractintCoefficients(g), (std::vector<double>{.85, .04, -.04, .85, 0, 1.6}));
}

void TestFractintIfs::malformedEntriesAreNamedWithTheirPlace()
{
    const FractintFile f = read(library);
    QCOMPARE(f.problems[0].entry, std::string("broken"));
    QCOMPARE(f.problems[0].line, 10);
    QCOMPARE(f.problems[0].column, 3);
    QVERIFY(f.problems[0].message.find("rows of 7") != std::string::npos);
    QCOMPARE(f.problems[1].describe("lib.ifs"),
             std::string("lib.ifs, line 18, column 17: entry bad: 'x' is not a finite number"));
    // A missing '}', a stray '}', a name without '{', a negative probability, a NaN.
    const FractintFile g = read("a { .5 0 0 .5 0 0 1\n}\n}\nb\nc { .5 0 0 .5 0 0 -1 }\n"
                                "d { nan 0 0 .5 0 0 1 }\ne { .5 0 0 .5 0 0 1");
    QCOMPARE(int(g.entries.size()), 1);
    QCOMPARE(g.entries[0].name, std::string("a"));
    QCOMPARE(int(g.problems.size()), 5);
    QCOMPARE(g.problems[0].line, 3);  // the stray '}'
    QVERIFY(g.problems[0].message.find("without its '{'") != std::string::npos);
    QVERIFY(g.problems[1].message.find("'b' is not followed by '{'") != std::string::npos);
    QVERIFY(g.problems[2].message.find("negative probability -1") != std::string::npos);
    QVERIFY(g.problems[3].message.find("'nan' is not a finite number") != std::string::npos);
    QVERIFY(g.problems[4].message.find("ends before the entry's '}'") != std::string::npos);
    // An empty file is no problem: nothing in it.
    QVERIFY(read("").entries.empty() && read("; only a comment\n").problems.empty());
}

void TestFractintIfs::writerRoundTrip()
{
    const FractintFile f = read(library);
    std::string text;
    for (const FractintEntry &e : f.entries)
        text += fractintEntryText(e);
    const FractintFile back = read(text);
    QCOMPARE(int(back.entries.size()), 3);
    QVERIFY(back.problems.empty());
    for (std::size_t k = 0; k < 3; ++k) {
        QCOMPARE(back.entries[k].name, f.entries[k].name);
        QCOMPARE(back.entries[k].dimension, f.entries[k].dimension);
        QCOMPARE(back.entries[k].probabilities, f.entries[k].probabilities);
        for (std::size_t i = 0; i < f.entries[k].maps.size(); ++i) {
            QVERIFY((back.entries[k].maps[i].A - f.entries[k].maps[i].A).norm() < 1e-15);
            QVERIFY((back.entries[k].maps[i].b - f.entries[k].maps[i].b).norm() < 1e-15);
        }
    }
    AffineMap four{Mat::Identity(4, 4), RowVec::Zero(4)};
    QVERIFY_THROWS_EXCEPTION(InputError, fractintCoefficients(four));
}

void TestFractintIfs::controlCageIsTheAttractorsBox()
{
    const FractintFile f = read(library);
    // The fern lies in [-2.1820, 2.6558] x [0, 9.9983] (Barnsley): its cage, rounded outward.
    const Mat fern = fractintControlCage(f.entries[0]);
    QCOMPARE(fern.rows(), Eigen::Index(4));
    QVERIFY(fern.col(0).minCoeff() <= -2.18 && fern.col(0).minCoeff() >= -3.0);
    QVERIFY(fern.col(0).maxCoeff() >= 2.65 && fern.col(0).maxCoeff() <= 3.0);
    QCOMPARE(fern.col(1).minCoeff(), 0.0);
    QCOMPARE(fern.col(1).maxCoeff(), 10.0);
    // The tetrahedron with corners 0, 2 e_1, 2 e_2, 2 e_3 (the maps' fixed points) in the cube
    // [0, 2]^3: its eight corners, the last four spanning space.
    const Mat cube = fractintControlCage(f.entries[2]);
    QCOMPARE(cube.rows(), Eigen::Index(8));
    QCOMPARE(cube.minCoeff(), 0.0);
    QCOMPARE(cube.maxCoeff(), 2.0);
    const Mat last = cube.bottomRows(4).rowwise() - cube.row(4);
    QVERIFY(std::abs(last.bottomRows(3).determinant()) > 4.0);  // 2 x 2 x 2
    // One map that expands among contracting ones contracts on average (log 2 + 2 log 1/2 < 0):
    // the orbit stays bounded, as flame renderers rely on. Maps that all expand leave every
    // bound.
    FractintEntry grow = f.entries[1];
    grow.maps[0].A *= 4.0;
    QVERIFY(fractintControlCage(grow).allFinite());
    for (AffineMap &m : grow.maps)
        m.A *= 4.0;
    QVERIFY_THROWS_EXCEPTION(InputError, fractintControlCage(grow));
}

AWB_TEST_MAIN(TestFractintIfs)
#include "test_fractint_ifs.moc"
