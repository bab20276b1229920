// The spectrum view: one point per eigenvalue of each map, the subdominant eigenvalues and the
// dominant 1 marked, tooltips with exact values, equal aspect ratio, verdicts and export.

#include "gui/views/SpectrumView.h"

#include <QSignalSpy>
#include <QTemporaryDir>
#include <QtTest>

#include "TestMain.h"

#include <qcustomplot.h>

#include <cmath>

using namespace awb;

namespace {

Mat fig2()
{
    Mat P(5, 2);
    P << 0, 0, 1, 2, 3, 2.5, 4.5, 1, 6, 2;
    return P;
}

MapSpectrum mapSpectrum(const QString &label, const Mat &S, const Mat &A)
{
    const Spectrum s = spectrum(S);
    return {label, s, subdominant(s), contractivity(A)};
}

// S_1, S_2 of the cubic B-spline on five points (eigenvalues 1, 1/2, 1/4, 1/8, 0).
QList<MapSpectrum> cubicMaps()
{
    const SubdivisionIfs s = buildSubdivisionIfs(bsplineScheme(3), fig2());
    QList<MapSpectrum> maps;
    for (int i = 0; i < 2; ++i)
        maps << mapSpectrum(QStringLiteral("S_%1").arg(i + 1), s.matrices.S[i],
                            s.ifs.effectiveLinearPart(i));
    return maps;
}

// A row-stochastic-like map with eigenvalues 1 and 0.6 e^{±1.1 i}: a spiral.
MapSpectrum spiral()
{
    Mat R = Mat::Zero(3, 3);
    R(0, 0) = 1;
    const double c = 0.6 * std::cos(1.1), s = 0.6 * std::sin(1.1);
    R(1, 1) = c, R(1, 2) = s, R(2, 1) = -s, R(2, 2) = c;
    return mapSpectrum(QStringLiteral("S_3"), R, R.bottomRightCorner(2, 2));
}

// Eigenvalue 1/4 twice (a Jordan block): one point with multiplicity 2.
MapSpectrum repeated()
{
    Mat J = Mat::Zero(3, 3);
    J(0, 0) = 1;
    J(1, 1) = J(2, 2) = 0.25;
    J(1, 2) = 1;
    return mapSpectrum(QStringLiteral("S_4"), J, J.bottomRightCorner(2, 2));
}

bool equalAspect(QCustomPlot *plot)
{
    const QRect r = plot->axisRect()->rect();
    const double xs = plot->xAxis->range().size() / r.width();
    const double ys = plot->yAxis->range().size() / r.height();
    return std::abs(xs - ys) < 1e-9 * xs;
}

} // namespace

class TestSpectrumView : public QObject {
    Q_OBJECT
private slots:
    void pointsAndMarkers();
    void tooltips();
    void equalAspectAfterResize();
    void verdicts();
    void exportFormats();
};

void TestSpectrumView::pointsAndMarkers()
{
    SpectrumView view;
    QList<MapSpectrum> maps = cubicMaps();
    maps << spiral() << repeated();
    view.setMaps(maps);
    // One point per entry of each spectrum; with multiplicities they add up to the sizes.
    int eigenvalues = 0, withMultiplicity = 0;
    for (const MapSpectrum &m : maps) {
        eigenvalues += int(m.spectrum.values.size());
        std::vector<Complex> seen;
        for (std::size_t k = 0; k < m.spectrum.values.size(); ++k) {
            const Complex z = m.spectrum.values[k];
            if (std::none_of(seen.begin(), seen.end(), [&](Complex w) { return w == z; })) {
                seen.push_back(z);
                withMultiplicity += m.spectrum.multiplicity[k];
            }
        }
    }
    QCOMPARE(withMultiplicity, 5 + 5 + 3 + 3);
    QCOMPARE(view.plottedEigenvalueCount(), eigenvalues);
    // Subdominant: 1/2 (both B-spline maps, one marker), the spiral's complex pair and 1/4.
    QCOMPARE(view.subdominantMarkerCount(), 4);
    const std::vector<Complex> marks = view.subdominantMarkers();
    auto marked = [&](Complex z) {
        return std::any_of(marks.begin(), marks.end(),
                           [&](Complex w) { return std::abs(w - z) < 1e-9; });
    };
    QVERIFY(marked(0.5));
    QVERIFY(marked(std::polar(0.6, 1.1)));
    QVERIFY(marked(std::polar(0.6, -1.1)));
    QVERIFY(marked(0.25));
    QVERIFY(!marked(0.125));
    // Live update: fewer maps, fewer points.
    view.setMaps(cubicMaps().mid(0, 1));
    QCOMPARE(view.plottedEigenvalueCount(), 5);
    QCOMPARE(view.subdominantMarkerCount(), 1);
}

void TestSpectrumView::tooltips()
{
    SpectrumView view;
    view.resize(700, 420);
    QList<MapSpectrum> maps = cubicMaps();
    maps << spiral() << repeated();
    view.setMaps(maps);
    view.show();
    QVERIFY(QTest::qWaitForWindowExposed(&view));
    view.plot()->replot();
    const QString half = view.tooltipAt(view.pixelOf(0.5));
    QVERIFY2(half.contains(QLatin1String("S_1")) || half.contains(QLatin1String("S<sub>1")),
             qPrintable(half));
    QVERIFY(half.contains(QLatin1String("S<sub>2</sub>")));
    QVERIFY(half.contains(QStringLiteral("λ = 1/2")));
    QVERIFY(half.contains(QLatin1String("subdominant")));
    QVERIFY(half.contains(QLatin1String("multiplicity 1")));
    const QString quarter = view.tooltipAt(view.pixelOf(0.25) + QPointF(3, -2));
    QVERIFY2(quarter.contains(QStringLiteral("S<sub>4</sub></b>: λ = 1/4, |λ| = 1/4, "
                                             "multiplicity 2")),
             qPrintable(quarter));
    QVERIFY(quarter.contains(QStringLiteral("S<sub>1</sub></b>: λ = 1/4, |λ| = 1/4, "
                                            "multiplicity 1")));
    const QString one = view.tooltipAt(view.pixelOf(1.0));
    QVERIFY(one.contains(QLatin1String("dominant")));
    const QString pair = view.tooltipAt(view.pixelOf(std::polar(0.6, 1.1)));
    QVERIFY2(pair.contains(QLatin1String("0.2721")) && pair.contains(QLatin1String("i")),
             qPrintable(pair));
    QVERIFY(pair.contains(QStringLiteral("|λ| = 3/5")));
    QVERIFY(view.tooltipAt(view.pixelOf(Complex(-0.7, -0.7))).isEmpty());
}

void TestSpectrumView::equalAspectAfterResize()
{
    SpectrumView view;
    view.setMaps(cubicMaps());
    view.show();
    QVERIFY(QTest::qWaitForWindowExposed(&view));
    for (QSize size : {QSize(800, 400), QSize(420, 700), QSize(600, 600)}) {
        view.resize(size);
        QTest::qWait(30); // the window system delivers the resize
        view.plot()->replot();
        QVERIFY(equalAspect(view.plot()));
        // The unit circle and every eigenvalue are inside the ranges.
        QVERIFY(view.plot()->xAxis->range().contains(-1.0));
        QVERIFY(view.plot()->xAxis->range().contains(1.05));
        QVERIFY(view.plot()->yAxis->range().contains(-1.05));
        QVERIFY(view.plot()->yAxis->range().contains(1.05));
        // Ticks follow the final ranges (no stale ticks from before the aspect fix).
        const QVector<double> ticks = view.plot()->yAxis->tickVector();
        QVERIFY(!ticks.isEmpty());
        QVERIFY(ticks.front() < -0.9 && ticks.back() > 0.9);
    }
    // After a user zoom (mouse wheel) the ranges stay the user's, still with equal scale.
    QCustomPlot *plot = view.plot();
    const QPointF centre = plot->axisRect()->rect().center();
    for (int i = 0; i < 5; ++i) {
        QWheelEvent wheel(centre, plot->mapToGlobal(centre), QPoint(), QPoint(0, 120),
                          Qt::NoButton, Qt::NoModifier, Qt::NoScrollPhase, false);
        QApplication::sendEvent(plot, &wheel);
    }
    plot->replot();
    QVERIFY(!plot->yAxis->range().contains(-1.0));
    view.resize(700, 450);
    QTest::qWait(30);
    plot->replot();
    QVERIFY(equalAspect(plot));
    QVERIFY(!plot->yAxis->range().contains(-1.0));
    // fit() shows everything again.
    view.fit();
    plot->replot();
    QVERIFY(equalAspect(plot));
    QVERIFY(plot->yAxis->range().contains(-1.05));
}

void TestSpectrumView::verdicts()
{
    SpectrumView view;
    QList<MapSpectrum> maps = cubicMaps();
    maps << spiral();
    view.setMaps(maps);
    const QString text = view.verdictText();
    QVERIFY2(text.contains(QLatin1String("All maps are (eventually) contractive")),
             qPrintable(text));
    QVERIFY(text.contains(QLatin1String("half-tangent")));
    QVERIFY(text.contains(QLatin1String("spirals")));
    QVERIFY(text.contains(QLatin1String("complex pair")));
    QVERIFY(text.contains(QLatin1String("Subdominant: 1/2 (real positive")));
    // A map with spectral radius above 1.
    Mat bad = Mat::Identity(2, 2) * 1.25;
    view.setMaps({mapSpectrum(QStringLiteral("A_1"), bad, bad)});
    QVERIFY(view.verdictText().contains(QLatin1String("not contractive")));
    QVERIFY(view.verdictText().contains(QStringLiteral("5/4 ≥ 1")));
}

void TestSpectrumView::exportFormats()
{
    SpectrumView view;
    view.resize(600, 400);
    view.setMaps(cubicMaps());
    view.show();
    QVERIFY(QTest::qWaitForWindowExposed(&view));
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    for (const char *name : {"s.pdf", "s.svg", "s.png"}) {
        const QString file = dir.filePath(QLatin1String(name));
        QString error;
        QVERIFY2(view.exportPlot(file, QSize(500, 400), &error), qPrintable(error));
        QVERIFY(QFileInfo(file).size() > 1000);
    }
    QFile svg(dir.filePath(QStringLiteral("s.svg")));
    QVERIFY(svg.open(QIODevice::ReadOnly));
    const QByteArray content = svg.readAll();
    // Vector content: the unit circle and axes as polylines, markers as circles, text as text.
    QVERIFY(content.contains("<svg"));
    QVERIFY(content.count("<polyline") > 20);
    // (one marker shape per map: S_1 circles, S_2 squares, ...)
    QVERIFY(content.count("<circle") + content.count("<rect") + content.count("<polygon") >= 10);
    QVERIFY(content.contains("<text"));
    QVERIFY(!content.contains("<image"));
    QCOMPARE(QImage(dir.filePath(QStringLiteral("s.png"))).size(), QSize(500, 400));
    QFile pdf(dir.filePath(QStringLiteral("s.pdf")));
    QVERIFY(pdf.open(QIODevice::ReadOnly));
    QVERIFY(pdf.read(5) == "%PDF-");
    QString error;
    QVERIFY(!view.exportPlot(dir.filePath(QStringLiteral("s.bmpx")), QSize(10, 10), &error));
    QVERIFY(error.contains(QLatin1String("bmpx")));
    // The on-screen plot keeps its equal aspect after exporting at another shape.
    view.plot()->replot();
    QVERIFY(equalAspect(view.plot()));
}

AWB_TEST_MAIN(TestSpectrumView)
#include "test_spectrum_view.moc"
