// The matrices as MATLAB cell arrays (model/NamedMatrix.h, issue 34): for the JSR toolbox the
// S_i, M_i and their linear parts A_i of 000 Fig. 2's cubic B-spline come out as exact
// fractions, and read back -- by a small reader of MATLAB's matrix syntax, as MATLAB would --
// they give the same eigenvalues: 1, 1/2, 1/4, 1/8, 0 for each S_i (000 §2, Fig. 2).
#include "core/analysis/Spectrum.h"
#include "model/AttractorItem.h"
#include "model/NamedMatrix.h"
#include "model/NumberFormat.h"
#include "model/Project.h"
#include "model/ProjectIO.h"

#include <QRegularExpression>
#include <QtTest>

#include "Fig2Example.h"
#include "TestMain.h"

using namespace awb;

namespace {

// The matrices of cell array `name` in `text` ("S = {[1/2 1/2 0; ...], [...]};").
std::vector<Mat> readCell(const QString &text, const QString &name)
{
    const QRegularExpression line(QStringLiteral("^%1 = \\{(.*)\\};$").arg(name),
                                  QRegularExpression::MultilineOption);
    const QRegularExpressionMatch m = line.match(text);
    if (!m.hasMatch())
        return {};
    std::vector<Mat> out;
    const QRegularExpression bracket(QStringLiteral("\\[([^\\]]*)\\]"));
    for (auto it = bracket.globalMatch(m.captured(1)); it.hasNext();) {
        const QStringList rows = it.next().captured(1).split(QLatin1Char(';'));
        Mat M(rows.size(), rows.front().split(QLatin1Char(' '), Qt::SkipEmptyParts).size());
        for (int r = 0; r < rows.size(); ++r) {
            const QStringList cells = rows[r].split(QLatin1Char(' '), Qt::SkipEmptyParts);
            if (cells.size() != M.cols())
                return {};
            for (int c = 0; c < cells.size(); ++c) {
                const auto v = parseNumber(cells[c]);
                if (!v)
                    return {};
                M(r, c) = *v;
            }
        }
        out.push_back(M);
    }
    return out;
}

} // namespace

class TestMatlabExport : public QObject {
    Q_OBJECT
private slots:
    void cubicBSplineRoundTrip();
    void complexAndAffineMatrices();
};

void TestMatlabExport::cubicBSplineRoundTrip()
{
    Project p;
    QString error;
    QVERIFY2(p.open(test::fig2File, &error), qPrintable(error));
    auto *curve = dynamic_cast<AttractorItem *>(p.findItem(test::fig2Curve));
    QVERIFY(curve);
    const auto d = curve->derivedIfs();
    QVERIFY(d);
    const QString text = matlabMatrices(namedMatrices(*d), curve->name());
    QVERIFY2(text.startsWith(QStringLiteral("% ") + curve->name()), qPrintable(text));
    // Exact fractions: the cubic B-spline's 1/8, 3/4, 1/2.
    QVERIFY2(text.contains(QStringLiteral("[1/2 1/2 0 0 0; 1/8 3/4 1/8 0 0;")),
             qPrintable(text));
    const std::vector<Mat> S = readCell(text, QStringLiteral("S"));
    QCOMPARE(int(S.size()), 2);
    for (std::size_t i = 0; i < S.size(); ++i) {
        QVERIFY((S[i] - d->S.real[i]).cwiseAbs().maxCoeff() == 0.0);  // the very numbers
        std::vector<double> ev;
        for (const Complex &z : spectrum(S[i]).values)
            ev.push_back(z.real());
        std::sort(ev.rbegin(), ev.rend());
        const std::vector<double> paper{1.0, 0.5, 0.25, 0.125, 0.0};
        for (std::size_t k = 0; k < paper.size(); ++k)
            QVERIFY2(std::abs(ev[k] - paper[k]) < 1e-12, qPrintable(QString::number(ev[k])));
    }
    // The lifted maps and their linear parts (4 x 4 blocks of the 5 x 5 M_i).
    const std::vector<Mat> M = readCell(text, QStringLiteral("M"));
    const std::vector<Mat> A = readCell(text, QStringLiteral("A"));
    QCOMPARE(int(M.size()), 2);
    QCOMPARE(int(A.size()), 2);
    QCOMPARE(A[0].rows(), M[0].rows() - 1);
    QVERIFY((A[1] - M[1].topLeftCorner(A[1].rows(), A[1].cols())).cwiseAbs().maxCoeff() == 0.0);
}

void TestMatlabExport::complexAndAffineMatrices()
{
    CMat c(1, 2);
    c << Complex(0.5, 0.25), Complex(-1.0 / 3.0, -2.0);
    Mat f(3, 3);
    f << 0.5, 0, 0, 0, std::sqrt(0.5), 0, 0.25, 0.1, 1;
    const QString text = matlabMatrices({NamedMatrix(QStringLiteral("L_1"), c),
                                         NamedMatrix(QStringLiteral("f_1"), f, 2)});
    QVERIFY2(text.contains(QStringLiteral("L = {[1/2+(1/4)i -1/3-2i]};")), qPrintable(text));
    // sqrt(1/2) has no small fraction: 17 significant digits, which read back to the same
    // double (MATLAB's parser rounds as parseNumber does).
    const std::vector<Mat> F = readCell(text, QStringLiteral("f"));
    QCOMPARE(int(F.size()), 1);
    QVERIFY((F[0] - f).cwiseAbs().maxCoeff() == 0.0);
    QVERIFY2(text.contains(QStringLiteral("; 1/4 1/10 1]};")), qPrintable(text));
    const std::vector<Mat> A = readCell(text, QStringLiteral("A"));
    QCOMPARE(int(A.size()), 1);
    QVERIFY((A[0] - f.topLeftCorner(2, 2)).cwiseAbs().maxCoeff() == 0.0);
}

AWB_TEST_MAIN(TestMatlabExport)
#include "test_matlab_export.moc"
