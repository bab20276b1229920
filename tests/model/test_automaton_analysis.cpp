// What `analyse --json` says of the papers' automata and unions (issue 46, model/
// AutomatonAnalysisJson.h, ItemAnalysisJson.h), against the papers' numbers: 003 §4.1's junction
// T^i with its subdominant 0.696 and eigenvectors, the vertex blocks of T^l and T^r with
// eigenvalues {1, 1/2, 1/4} and {1, 1/2}; the refined junction's T^il, T^ir with j and r; the
// constrained JSR and cycles of the fern of gaskets; the joint spectral radius of 002's unions
// of quadratic Bézier curves, exact where an invariant polytope closes.

#include "TestPaths.h"
#include "core/analysis/Spectrum.h"
#include "model/AttractorItem.h"
#include "model/ItemAnalysisJson.h"
#include "model/Project.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QtTest>

#include "TestMain.h"

#include <algorithm>
#include <cmath>

using namespace awb;

namespace {

QJsonObject analysed(const QString &example)
{
    Project p;
    QString error;
    if (!p.open(awb::test::sourceDir() + "/examples/" + example, &error))
        return {{"open error", error}};
    const auto *item = qobject_cast<const AttractorItem *>(p.child(0));
    return item ? analyseItemJson(item) : QJsonObject();
}

Mat matrixOf(const QJsonValue &v)
{
    const QJsonArray rows = v.toArray();
    Mat M(rows.size(), rows.isEmpty() ? 0 : rows[0].toArray().size());
    for (qsizetype r = 0; r < rows.size(); ++r)
        for (qsizetype c = 0; c < rows[r].toArray().size(); ++c)
            M(r, c) = rows[r].toArray()[c].toDouble();
    return M;
}

Complex complexOf(const QJsonValue &v)
{
    return v.isArray() ? Complex(v.toArray()[0].toDouble(), v.toArray()[1].toDouble())
                       : Complex(v.toDouble(), 0.0);
}

CVec vectorOf(const QJsonValue &v)
{
    const QJsonArray a = v.toArray();
    CVec out(a.size());
    for (qsizetype i = 0; i < a.size(); ++i)
        out(i) = complexOf(a[i]);
    return out;
}

// The eigenvalues, sorted by real part, and every pair checked: T v = lambda v.
std::vector<double> checkedEigenvalues(const QJsonObject &o, const Mat &T)
{
    std::vector<double> values;
    const QJsonArray l = o["eigenvalues"].toArray(), V = o["eigenvectors"].toArray();
    if (l.size() != T.rows() || V.size() != T.rows())
        return {};
    for (qsizetype k = 0; k < l.size(); ++k) {
        const Complex lambda = complexOf(l[k]);
        const CVec v = vectorOf(V[k]);
        if ((T.cast<Complex>() * v - lambda * v).norm() > 1e-9 || v.norm() < 1e-9)
            return {};
        values.push_back(lambda.real());
    }
    std::sort(values.begin(), values.end());
    return values;
}

} // namespace

class TestAutomatonAnalysis : public QObject {
    Q_OBJECT
private slots:
    void junctionOf003Section41();
    void refinedJunctionOf003Section5();
    void fernOfGaskets();
    void unionsOfBezierCurves();
};

void TestAutomatonAnalysis::junctionOf003Section41()
{
    const QJsonObject o = analysed("003-fig16-junction-g1.awb");
    const QJsonObject j = o["junction"].toObject();
    QVERIFY2(!j.isEmpty(), qPrintable(QJsonDocument(o).toJson()));
    const Mat Ti = matrixOf(j["T_i"].toObject()["matrix"]);
    QCOMPARE(Ti.rows(), 5);
    const QJsonObject ti = j["T_i"].toObject();
    QCOMPARE(int(checkedEigenvalues(ti, Ti).size()), 5);  // every pair: T v = lambda v
    // 003 §4.1, Fig. 16 top: the subdominant eigenvalue 0.696 (NOTES.md: it reproduces).
    QVERIFY(std::abs(complexOf(ti["eigenvalues"].toArray()[1]) - Complex(0.696)) < 5e-4);
    // The eigenvector of 1 is T^i's fixed point: it sums to 1, and T v = v.
    const CVec v1 = vectorOf(ti["eigenvectors"].toArray()[0]);
    QVERIFY(std::abs(v1.sum() - Complex(1.0)) < 1e-12);
    QVERIFY((Ti.cast<Complex>() * v1 - v1).norm() < 1e-12);
    // The vertex blocks: the cubic's V^l has {1, 1/2, 1/4}, the quadratic's V^r {1, 1/2}.
    const QJsonObject bl = j["T_l"].toObject()["block"].toObject();
    const QJsonObject br = j["T_r"].toObject()["block"].toObject();
    const auto l = checkedEigenvalues(bl, matrixOf(bl["matrix"]));
    const auto r = checkedEigenvalues(br, matrixOf(br["matrix"]));
    QCOMPARE(int(l.size()), 3);
    QCOMPARE(int(r.size()), 2);
    QVERIFY(std::abs(l[0] - 0.25) < 1e-12 && std::abs(l[1] - 0.5) < 1e-12
            && std::abs(l[2] - 1) < 1e-12);
    QVERIFY(std::abs(r[0] - 0.5) < 1e-12 && std::abs(r[1] - 1) < 1e-12);
    QCOMPARE(matrixOf(j["T_l"].toObject()["matrix"]).cols(), 4);
    QCOMPARE(matrixOf(j["T_r"].toObject()["matrix"]).cols(), 3);
}

void TestAutomatonAnalysis::refinedJunctionOf003Section5()
{
    const QJsonObject j = analysed("003-fig18-refined-junction-g1.awb")["junction"].toObject();
    const QJsonObject il = j["T_il"].toObject(), ir = j["T_ir"].toObject();
    const auto left = checkedEigenvalues(il, matrixOf(il["matrix"]));
    const auto right = checkedEigenvalues(ir, matrixOf(ir["matrix"]));
    QCOMPARE(int(left.size()), 5);
    QCOMPARE(int(right.size()), 4);
    // j = 3/4 and r = 1/2 (003 §5, the example's values) are the tangent eigenvalues.
    QVERIFY(std::any_of(left.begin(), left.end(), [](double x) { return std::abs(x - 0.75) < 1e-12; }));
    QVERIFY(std::any_of(right.begin(), right.end(), [](double x) { return std::abs(x - 0.5) < 1e-12; }));
}

void TestAutomatonAnalysis::fernOfGaskets()
{
    const QJsonObject a =
        analysed("003-fig05-fern-of-sierpinski-gaskets.awb")["automaton"].toObject();
    const QJsonObject jsr = a["constrained_jsr"].toObject();
    // The main frond's spectral radius: the fern maps' JSR is reached by one of them.
    QVERIFY(jsr["lower"].toDouble() <= jsr["upper"].toDouble());
    QVERIFY(std::abs(jsr["lower"].toDouble() - 0.8509406559801891) < 1e-9);
    QVERIFY(jsr["upper"].toDouble() < 0.851);
    QCOMPARE(jsr["word"].toArray(), QJsonArray{"T1"});
    QCOMPARE(a["cycles"].toArray().size(), 6);
    QVERIFY(a["contractive"].toBool());
    // A Sierpinski loop: (lambda + e_k)/2, its product in column form has eigenvalues 1, 1/2,
    // 1/2 and its fixed point e_k.
    const QJsonObject loop = a["cycles"].toArray()[3].toObject();
    QCOMPARE(loop["path"].toString(), QString("Sierpinski -S0-> Sierpinski"));
    const QJsonObject product = loop["product"].toObject();
    const auto values = checkedEigenvalues(product, matrixOf(product["matrix"]));
    QCOMPARE(int(values.size()), 3);
    QVERIFY(std::abs(values[0] - 0.5) < 1e-12 && std::abs(values[2] - 1) < 1e-12);
    const CVec fixed = vectorOf(product["eigenvectors"].toArray()[0]);
    QVERIFY(std::abs(fixed(0) - Complex(1.0)) < 1e-12);
}

void TestAutomatonAnalysis::unionsOfBezierCurves()
{
    // 002 Fig. 3: two QBCs split at u = 1/2, all four maps together. Every product of the
    // lifted linear parts scales by 1/2 per map at best: the JSR is 1/2, certified.
    for (const char *file : {"002-fig03-union-p1.awb", "002-fig03-union-p3.awb"}) {
        const QJsonObject j = analysed(file)["joint_spectral_radius"].toObject();
        QVERIFY2(j["exact"].toBool(), file);
        QVERIFY(std::abs(j["lower"].toDouble() - 0.5) < 1e-9);
        QVERIFY(std::abs(j["upper"].toDouble() - 0.5) < 1e-9);
        QVERIFY(j["contractive"].toBool());
    }
    // 002 Fig. 4, u = 0.3: the right halves contract by 1 - u = 0.7, which bounds the JSR below.
    const QJsonObject j = analysed("002-fig04-union-u-0.3.awb")["joint_spectral_radius"].toObject();
    QVERIFY(std::abs(j["lower"].toDouble() - 0.7) < 1e-9);
    QVERIFY(j["upper"].toDouble() < 0.71);
}

AWB_TEST_GUILESS_MAIN(TestAutomatonAnalysis)
#include "test_automaton_analysis.moc"
