// The eigenvalue plot item: the example of 000 Fig. 2 (cubic B-spline on 5 points) shows the
// five eigenvalues 1, 1/2, 1/4, 1/8, 0 of each S_i (the 4 x 4 cubic B-spline block and a zero
// column: S_1 does not use p_5, S_2 not p_1); the A_i and the lifted M_i are offered too; choosing the source and the matrices is one undo step each and is saved.
#include "model/EigenvaluePlotItem.h"
#include "model/Project.h"

#include "ItemKindTests.h"

#include <QtTest>

#include "TestMain.h"

#include "Fig2Example.h"

#include <algorithm>

using namespace awb;

namespace {

const QString &fig2 = test::fig2File;
const QString &plotName = test::fig2Plot;
const QString &curveName = test::fig2Curve;

// The eigenvalues of one spectrum, real parts sorted downwards (they are all real here).
std::vector<double> sortedReal(const Spectrum &s)
{
    std::vector<double> v;
    for (Complex z : s.values) {
        if (std::abs(z.imag()) > 1e-12)
            return {};
        v.push_back(z.real());
    }
    std::sort(v.rbegin(), v.rend());
    return v;
}

bool near(const std::vector<double> &a, const std::vector<double> &b, double tol = 1e-10)
{
    if (a.size() != b.size())
        return false;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (std::abs(a[i] - b[i]) > tol)
            return false;
    return true;
}

QString describe(const std::vector<double> &v)
{
    QStringList s;
    for (double x : v)
        s << QString::number(x, 'g', 17);
    return s.join(", ");
}

} // namespace

class TestEigenvaluePlotItem : public QObject {
    Q_OBJECT
private slots:
    void fig2ShowsTheEigenvaluesOfS();
    void linearPartsAndLiftedMaps();
    void sourceAndMatricesAreUndoableAndSaved();
    void explainsWhatIsMissing();
};

void TestEigenvaluePlotItem::fig2ShowsTheEigenvaluesOfS()
{
    Project p;
    QString error;
    QVERIFY2(p.open(fig2, &error), qPrintable(error));
    auto *plot = qobject_cast<EigenvaluePlotItem *>(p.findItem(plotName));
    QVERIFY(plot);
    QCOMPARE(plot->source(), curveName);
    QCOMPARE(plot->matrixKind(), EigenvaluePlotItem::MatrixKind::S);
    const auto data = plot->eigenvalues();
    QVERIFY2(data, qPrintable(plot->derivedError()));
    QCOMPARE(data->symbol, QStringLiteral("S"));
    QCOMPARE(int(data->spectra.size()), 2);
    QCOMPARE(data->matrices.count(), 2);
    // Cubic B-spline subdivision on 5 points: 1, 1/2, 1/4, 1/8 (the 4 x 4 block of the
    // uniform cubic B-spline, 000 §3) and 0 (the point S_i does not use) for S_1 and S_2.
    const std::vector<double> expected{1.0, 0.5, 0.25, 0.125, 0.0};
    for (const Spectrum &s : data->spectra) {
        QCOMPARE(int(s.values.size()), 5);
        QVERIFY2(near(sortedReal(s), expected), qPrintable(describe(sortedReal(s))));
    }
    // The subdominant eigenvalue after the 1 of affine invariance is 1/2.
    for (const Subdominant &s : data->subdominants)
        QVERIFY(std::abs(s.modulus - 0.5) < 1e-12);
}

void TestEigenvaluePlotItem::linearPartsAndLiftedMaps()
{
    Project p;
    QVERIFY(p.open(fig2));
    auto *plot = qobject_cast<EigenvaluePlotItem *>(p.findItem(plotName));
    QVERIFY(plot->setMatrixKind(EigenvaluePlotItem::MatrixKind::A));
    auto data = plot->eigenvalues();
    QVERIFY2(data, qPrintable(plot->derivedError()));
    QCOMPARE(data->symbol, QStringLiteral("A"));
    for (const Spectrum &s : data->spectra)
        QVERIFY2(near(sortedReal(s), {0.5, 0.25, 0.125, 0.0}), qPrintable(describe(sortedReal(s))));
    // M_i = P^-1 S_i P is similar to S_i: the same five eigenvalues, 5 x 5.
    QVERIFY(plot->setMatrixKind(EigenvaluePlotItem::MatrixKind::M));
    data = plot->eigenvalues();
    QVERIFY2(data, qPrintable(plot->derivedError()));
    QCOMPARE(data->symbol, QStringLiteral("M"));
    QCOMPARE(data->matrices.real.front().rows(), Eigen::Index(5));
    for (const Spectrum &s : data->spectra)
        QVERIFY2(near(sortedReal(s), {1.0, 0.5, 0.25, 0.125, 0.0}, 1e-9),
                 qPrintable(describe(sortedReal(s))));
}

void TestEigenvaluePlotItem::sourceAndMatricesAreUndoableAndSaved()
{
    Project p;
    QVERIFY(test::load(p, R"({"type": "subdivision-curve", "name": "Chaikin",
        "scheme": {"kind": "chaikin"}, "control_points": [[0, 0], [1, 2], [3, 2], [4, 0]]},
        {"type": "eigenvalue-plot", "name": "Plot", "source": ""})"));
    auto *plot = qobject_cast<EigenvaluePlotItem *>(p.findItem("Plot"));
    QVERIFY(plot && !plot->eigenvalues());
    test::roundTrip(
        p, [&] { QVERIFY(plot->setSource("Chaikin")); },
        [&] {
            QCOMPARE(plot->source(), QStringLiteral("Chaikin"));
            QVERIFY(plot->eigenvalues());
        },
        [&] { QVERIFY(plot->source().isEmpty()); });
    test::roundTrip(
        p, [&] { QVERIFY(plot->setMatrixKind(EigenvaluePlotItem::MatrixKind::M)); },
        [&] { QCOMPARE(plot->eigenvalues()->symbol, QStringLiteral("M")); },
        [&] { QCOMPARE(plot->matrixKind(), EigenvaluePlotItem::MatrixKind::S); });
    const QByteArray text = p.serialize();
    QVERIFY(text.contains(R"("matrices": "M")"));
    QVERIFY(test::reloadsIdentically(p));
    // An unknown choice is a load error naming the choices.
    const QString error = test::loadError(
        R"({"type": "eigenvalue-plot", "name": "P", "source": "", "matrices": "B"})");
    QVERIFY2(error.contains("matrices"), qPrintable(error));
}

void TestEigenvaluePlotItem::explainsWhatIsMissing()
{
    Project p;
    QVERIFY(test::load(p, R"({"type": "eigenvalue-plot", "name": "Plot", "source": "Nothing"})"));
    auto *plot = qobject_cast<EigenvaluePlotItem *>(p.findItem("Plot"));
    QVERIFY(!plot->eigenvalues());
    QVERIFY2(plot->derivedError().contains("Nothing"), qPrintable(plot->derivedError()));
}

AWB_TEST_GUILESS_MAIN(TestEigenvaluePlotItem)
#include "test_eigenvalue_plot_item.moc"
