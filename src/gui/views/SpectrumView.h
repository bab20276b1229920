#pragma once
// The spectrum view: eigenvalues of each map of the current item in the complex plane (one
// colour per map) with the unit circle, the dominant eigenvalue 1 and the subdominant ones
// marked, and beside it the verdicts (contractive or not; subdominant kind and what it means
// for tangents at the fixed points). Cheap to update: it follows a live parameter drag.
// Each map has its own marker shape and size (coinciding eigenvalues of several maps show as
// nested shapes); a tooltip gives λ, |λ|, arg λ, the map and the multiplicity, and a click on a
// marker selects its map (mapClicked) and outlines that map's markers.
// QCustomPlot stays out of this header.

#include "core/analysis/Spectrum.h"

#include <QList>
#include <QPointF>
#include <QSize>
#include <QString>
#include <QWidget>

#include <optional>

#include <vector>

class QCustomPlot;
class QCPGraph;
class QCPPainter;
class QSplitter;
class QTextBrowser;

namespace awb {

struct MapSpectrum {
    QString label;            // "S_1", "A_2", ...
    Spectrum spectrum;
    Subdominant subdominant;
    Contractivity contractivity;
};

class SpectrumView : public QWidget {
    Q_OBJECT
public:
    explicit SpectrumView(QWidget *parent = nullptr);
    ~SpectrumView() override;

    void setMaps(const QList<MapSpectrum> &maps);
    // When a map is not contractive: the IFS's top Lyapunov exponent (core IfsCheck), so that
    // the verdict says whether it contracts on average (random iteration draws its attractor,
    // as flame renderers do). nullopt: not known (every map contractive, an automaton, a
    // vertex's matrix). Takes effect at the next setMaps().
    void setLyapunovExponent(std::optional<double> exponent) { m_lyapunov = exponent; }
    // Whether the maps shown are the affine parts of maps that are not affine (a flame's
    // xforms, bent by their variations): the verdict then rests on the Lyapunov exponent and
    // says what the spectra cannot tell. Takes effect at the next setMaps().
    void setAffineParts(bool affineParts) { m_affineParts = affineParts; }
    const QList<MapSpectrum> &maps() const { return m_maps; }

    // Eigenvalue points plotted (one per distinct eigenvalue of each map; multiplicity is
    // in the tooltip), and subdominant markers drawn.
    int plottedEigenvalueCount() const;
    int subdominantMarkerCount() const;
    // Plot positions of the subdominant markers (for tests and for the owner's status text).
    std::vector<Complex> subdominantMarkers() const;
    // The tooltip text for a point of the plot widget (empty when no eigenvalue is near).
    QString tooltipAt(const QPointF &plotPixel) const;
    // The map whose marker is under `plotPixel` (the last drawn, i.e. topmost), or -1.
    int mapAt(const QPointF &plotPixel) const;
    // Every map with an eigenvalue under `plotPixel` (a click there offers them in a menu).
    QList<int> mapsAt(const QPointF &plotPixel) const;
    Complex nearestEigenvalue(int map, const QPointF &plotPixel) const;
    // Outlines map `map`'s markers (-1: none).
    void setHighlightedMap(int map);
    int highlightedMap() const { return m_highlighted; }
    // Where eigenvalue z is drawn, in plot widget pixels.
    QPointF pixelOf(Complex z) const;
    QString verdictText() const;   // the panel's text as plain text

    QCustomPlot *plot() const { return m_plot; }
    // Paints the plot at width x height (a figure's size: with its legend, which a small dock
    // leaves out) into `painter`.
    void paintPlot(QCPPainter *painter, int width, int height);
    // Writes the plot to .pdf, .svg or .png (by suffix) at `size` (in points/pixels).
    // Returns false with a message in *error on failure.
    bool exportPlot(const QString &fileName, const QSize &size, QString *error = nullptr);

signals:
    // A click on a marker of map `map` (0-based), or on no marker (-1).
    void mapClicked(int map);

public slots:
    // Ranges to show the unit circle and every eigenvalue, with equal scale on both axes.
    void fit();

protected:
    bool eventFilter(QObject *watched, QEvent *event) override;

private:
    void rebuildPlot();
    void setVerdictHtml(const QString &html);
    void updateVerdicts();
    void keepAspect();
    // The legend under the axes when a plot of `size` has room for it.
    void placeLegend(const QSize &size);

    QSplitter *m_splitter = nullptr;
    QCustomPlot *m_plot = nullptr;
    QTextBrowser *m_text = nullptr;
    QList<MapSpectrum> m_maps;
    bool m_plotted = false;     // rebuildPlot ran for m_maps
    QString m_verdictHtml;
    QList<QCPGraph *> m_mapGraphs;
    QCPGraph *m_dominantGraph = nullptr;
    QCPGraph *m_subdominantGraph = nullptr;
    bool m_fitPending = true;
    int m_highlighted = -1;
    std::optional<double> m_lyapunov;
    bool m_affineParts = false;
    QPointF m_pressPosition;
    bool m_inKeepAspect = false;
};

// The version of QCustomPlot the spectrum view was built with ("2.1.0"), for the About box
// (keeps qcustomplot.h out of the other sources).
QString qcustomplotVersion();

} // namespace awb
