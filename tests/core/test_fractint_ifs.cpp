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
    void bareRowsAreOneEntry();
    void rowsThatDoNotFitTheirLinesAreRefused();
    void probabilitiesThatAreNoDistributionAreWarned();
    void namesOfSeveralWordsAndExactNumbersComeBack();
    void countsAreBounded();
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

void TestFractintIfs::bareRowsAreOneEntry()
{
    // Fractint 10 and 15: one IFS per file, its rows without NAME { } (e.g. Fractint 15's
    // fern.ifs). The file is one entry named after the file; 13 numbers a row is space.
    std::istringstream fern("  0     0    0     .16 0 0    .01\n"
                            "  .85  .04 -.04  .85  0 1.6  .85 ; the big leaf\n"
                            "  .2  -.26  .23  .22  0 1.6  .07\n"
                            " -.15  .28  .26  .24  0 .44  .07\n");
    const FractintFile f = readFractintIfs(fern, "fern");
    QVERIFY(f.problems.empty());
    QCOMPARE(int(f.entries.size()), 1);
    QCOMPARE(f.entries[0].name, std::string("fern"));
    QCOMPARE(f.entries[0].dimension, 2);
    QCOMPARE(f.entries[0].probabilities, (std::vector<double>{.01, .85, .07, .07}));
    QCOMPARE(fractintCoefficients(f.entries[0].maps[1]),
             (std::vector<double>{.85, .04, -.04, .85, 0, 1.6}));
    std::istringstream cube(".5 0 0 0 .5 0 0 0 .5 0 0 0 .5\n.5 0 0 0 .5 0 0 0 .5 1 1 1 .5\n");
    const FractintFile c = readFractintIfs(cube, "cube");
    QCOMPARE(int(c.entries.size()), 1);
    QCOMPARE(c.entries[0].dimension, 3);
    // A first line of neither 7 nor 13 numbers, and braces in a file of bare rows.
    std::istringstream six(".5 0 0 .5 0 0\n");
    const FractintFile g = readFractintIfs(six, "six");
    QVERIFY(g.entries.empty());
    QCOMPARE(int(g.problems.size()), 1);
    QVERIFY(g.problems[0].message.find("its first line 6") != std::string::npos);
    std::istringstream mixed(".5 0 0 .5 0 0 1\n{ .5 0 0 .5 0 0 1 }\n");
    QVERIFY(readFractintIfs(mixed, "m").problems[0].message.find("no braces")
            != std::string::npos);
}

void TestFractintIfs::rowsThatDoNotFitTheirLinesAreRefused()
{
    // Seven rows of 6 numbers are 42 numbers, six rows of 7 by count: read one per line they
    // are refused at the second line, where the second row would begin mid-line and run on.
    std::string six = "sixes {\n";
    for (int r = 0; r < 7; ++r)
        six += ".5 0 0 .5 0 0\n";
    const FractintFile f = read(six + "}\n");
    QVERIFY(f.entries.empty());
    QCOMPARE(int(f.problems.size()), 1);
    QCOMPARE(f.problems[0].line, 3);
    QVERIFY(f.problems[0].message.find("runs on to the next line") != std::string::npos);
    // Eight numbers a line: the second row starts mid-line too.
    std::string eight = "eights {\n";
    for (int r = 0; r < 7; ++r)
        eight += ".5 0 0 .5 0 0 .5 .5\n";
    QVERIFY(read(eight + "}\n").entries.empty());
    // A row written over two lines, starting at its line's start, is one row.
    const FractintFile w = read("wrapped {\n .5 0 0 .5\n 0 0 .5\n .5 0 0 .5\n .5 0 .5\n}\n");
    QVERIFY(w.problems.empty());
    QCOMPARE(int(w.entries.at(0).maps.size()), 2);
}

void TestFractintIfs::probabilitiesThatAreNoDistributionAreWarned()
{
    const FractintFile f = read("low { .5 0 0 .5 0 0 .1 .5 0 0 .5 .5 0 .2 }\n"
                                "high { .5 0 0 .5 0 0 1 .5 0 0 .5 .5 0 2 }\n"
                                "fine { .5 0 0 .5 0 0 .505 .5 0 0 .5 .5 0 .5 }\n");
    QCOMPARE(int(f.entries.size()), 3);  // kept: the probabilities are weights
    QCOMPARE(int(f.warnings.size()), 2);
    QCOMPARE(f.warnings[0].entry, std::string("low"));
    QVERIFY(f.warnings[0].message.find("sum to 0.3, not 1") != std::string::npos);
    QVERIFY(f.warnings[1].message.find("sum to 3, not 1") != std::string::npos);
}

void TestFractintIfs::namesOfSeveralWordsAndExactNumbersComeBack()
{
    // A name of several words, on the line of its '{' or alone on the line before it.
    const FractintFile f = read("Barnsley fern {\n 0 0 0 .16 0 0 .01 .85 .04 -.04 .85 0 1.6 .99 }\n"
                                "maple leaf (3D)\n{ .5 0 0 0 .5 0 0 0 .5 0 0 0 1 }\n");
    QVERIFY(f.problems.empty());
    QCOMPARE(f.entries.at(0).name, std::string("Barnsley fern"));
    QCOMPARE(f.entries.at(1).name, std::string("maple leaf"));
    QCOMPARE(f.entries.at(1).dimension, 3);
    // The writer's numbers are the shortest that read back exactly: 0.1 as "0.1", 1/3 with
    // all its digits, 1e-300, and a random double, each bit for bit.
    FractintEntry e = f.entries[0];
    e.maps[0].A << 0.1, 1.0 / 3.0, -2.0 / 7.0, 1e-300;
    e.maps[0].b << 0.123456789012345678, -3.3e17;
    e.probabilities = {0.3, 0.7};
    const std::string text = fractintEntryText(e);
    QVERIFY2(text.find(" 0.1 ") != std::string::npos, text.c_str());
    const FractintFile back = read(text);
    QCOMPARE(back.entries.at(0).name, e.name);
    QVERIFY(back.entries[0].maps[0].A == e.maps[0].A);
    QVERIFY(back.entries[0].maps[0].b == e.maps[0].b);
    QVERIFY(back.entries[0].probabilities == e.probabilities);
}

void TestFractintIfs::countsAreBounded()
{
    // More maps than the engine iterates (kMaxMaps): refused when read, the maps beyond the
    // limit only counted.
    std::string many = "many {\n";
    for (int r = 0; r < 1000; ++r)
        many += ".01 0 0 .01 0 0 1\n";
    const FractintFile f = read(many + "}\n");
    QVERIFY(f.entries.empty());
    QVERIFY2(f.problems.at(0).message.find("1000 maps: at most 255") != std::string::npos,
             f.problems[0].message.c_str());
    // A million stray braces: 100 problems and a count of the rest.
    const FractintFile g = read(std::string(1000000, '}'));
    QCOMPARE(int(g.problems.size()), 101);
    QVERIFY(g.problems.back().message.find("999900 more problems") != std::string::npos);
    // More entries than one file gives.
    std::string entries;
    for (std::size_t k = 0; k < kMaxFractintEntries + 3; ++k)
        entries += "e { .5 0 0 .5 0 0 1 }\n";
    const FractintFile h = read(entries);
    QCOMPARE(h.entries.size(), kMaxFractintEntries);
    QVERIFY(h.problems.at(0).message.find("3 more entries after the first 4096")
            != std::string::npos);
}

AWB_TEST_MAIN(TestFractintIfs)
#include "test_fractint_ifs.moc"
