#include "gui/views/SpectrumView.h"

#include <QMenu>

#include "gui/views/AttractorRenderer.h"
#include "model/NumberFormat.h"
#include "render/FigureFile.h"

#include <QBuffer>
#include <QFileInfo>
#include <QPdfWriter>
#include <QHelpEvent>
#include <QMouseEvent>
#include <QResizeEvent>
#include <QSplitter>
#include <QSvgGenerator>
#include <QTextBrowser>
#include <QToolTip>
#include <QVBoxLayout>

#include <qcustomplot.h>

#include <algorithm>
#include <cmath>

namespace awb {

namespace {

constexpr double kTooltipRadius = 9.0;  // pixels
constexpr double kSamePoint = 1e-9;     // eigenvalues closer than this share a marker

bool isOne(Complex z) { return std::abs(z - Complex(1.0, 0.0)) < 1e-9; }

// Points of map i get smaller markers of another shape than those of map i-1: coinciding
// eigenvalues of different maps (common: S_1 and S_2 share most of theirs) show as nested
// shapes, each still visible.
double markerSize(int map) { return std::max(6.0, 16.0 - 6.0 * map); }
QCPScatterStyle::ScatterShape markerShape(int map)
{
    static const QCPScatterStyle::ScatterShape shapes[] = {
        QCPScatterStyle::ssCircle, QCPScatterStyle::ssSquare, QCPScatterStyle::ssDiamond,
        QCPScatterStyle::ssTriangle, QCPScatterStyle::ssTriangleInverted,
        QCPScatterStyle::ssCircle};
    return shapes[map % 6];
}

QString richLabel(const QString &name)
{
    QString s = name.toHtmlEscaped();
    const qsizetype u = s.indexOf(QLatin1Char('_'));
    if (u >= 0)
        s = s.left(u) + QStringLiteral("<sub>") + s.mid(u + 1) + QStringLiteral("</sub>");
    return s;
}

void addUnique(std::vector<Complex> &list, Complex z)
{
    for (Complex w : list)
        if (std::abs(w - z) < kSamePoint)
            return;
    list.push_back(z);
}

} // namespace

SpectrumView::SpectrumView(QWidget *parent) : QWidget(parent)
{
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    m_splitter = new QSplitter(Qt::Horizontal, this);
    layout->addWidget(m_splitter);

    m_plot = new QCustomPlot(m_splitter);
    m_plot->setMinimumSize(150, 130);
    m_plot->setInteractions(QCP::iRangeDrag | QCP::iRangeZoom);
    m_plot->xAxis->setLabel(tr("Re λ"));
    m_plot->yAxis->setLabel(tr("Im λ"));
    m_plot->xAxis2->setVisible(true);
    m_plot->yAxis2->setVisible(true);
    m_plot->xAxis2->setTickLabels(false);
    m_plot->yAxis2->setTickLabels(false);
    connect(m_plot->xAxis, qOverload<const QCPRange &>(&QCPAxis::rangeChanged), m_plot->xAxis2,
            qOverload<const QCPRange &>(&QCPAxis::setRange));
    connect(m_plot->yAxis, qOverload<const QCPRange &>(&QCPAxis::rangeChanged), m_plot->yAxis2,
            qOverload<const QCPRange &>(&QCPAxis::setRange));
    // The legend goes below the axis rectangle so that it never hides an eigenvalue.
    m_plot->legend->setVisible(true);
    m_plot->legend->setFillOrder(QCPLayoutGrid::foColumnsFirst);
    m_plot->legend->setWrap(4);
    QFont legendFont = font();
    legendFont.setPointSizeF(legendFont.pointSizeF() * 0.9);
    m_plot->legend->setFont(legendFont);
    m_plot->axisRect()->insetLayout()->take(m_plot->legend);
    m_plot->plotLayout()->addElement(1, 0, m_plot->legend);
    m_plot->plotLayout()->setRowStretchFactor(1, 0.001);
    m_plot->legend->setBorderPen(Qt::NoPen);
    m_plot->legend->setIconSize(28, 24); // room for the subdominant ring
    // Equal scale on both axes, kept after every layout (resizes, exports at any size).
    connect(m_plot, &QCustomPlot::afterLayout, this, &SpectrumView::keepAspect);
    // A user zoom or drag ends the automatic fitting until fit() is called.
    connect(m_plot, &QCustomPlot::mouseWheel, this, [this] { m_fitPending = false; });
    connect(m_plot, &QCustomPlot::mouseMove, this, [this](QMouseEvent *e) {
        if (e->buttons() != Qt::NoButton)
            m_fitPending = false;
    });
    connect(m_plot, &QCustomPlot::mouseDoubleClick, this, [this] { fit(); });
    m_plot->installEventFilter(this);
    installEventFilter(this); // its own resizes: the splitter's orientation

    m_text = new QTextBrowser(m_splitter);
    m_text->setMinimumWidth(110);
    m_text->setOpenLinks(false);
    m_splitter->addWidget(m_plot);
    m_splitter->addWidget(m_text);
    m_splitter->setStretchFactor(0, 3);
    m_splitter->setStretchFactor(1, 2);
    m_splitter->setChildrenCollapsible(false);

    rebuildPlot();
    updateVerdicts();
}

SpectrumView::~SpectrumView() = default;

namespace {

// Whether two lists plot the same markers: labels, eigenvalues (to 1e-12 of their size) and
// the subdominant marks. A drag of a control point leaves the S_i, and so the plot, as it was.
bool samePlot(const QList<MapSpectrum> &a, const QList<MapSpectrum> &b)
{
    const auto close = [](const std::vector<Complex> &x, const std::vector<Complex> &y) {
        if (x.size() != y.size())
            return false;
        for (std::size_t i = 0; i < x.size(); ++i)
            if (std::abs(x[i] - y[i]) > 1e-12 * std::max(1.0, std::abs(x[i])))
                return false;
        return true;
    };
    if (a.size() != b.size())
        return false;
    for (int i = 0; i < a.size(); ++i) {
        const MapSpectrum &p = a[i], &q = b[i];
        if (p.label != q.label || p.spectrum.multiplicity != q.spectrum.multiplicity
            || !close(p.spectrum.values, q.spectrum.values)
            || p.subdominant.kind != q.subdominant.kind
            || !close(p.subdominant.values, q.subdominant.values))
            return false;
    }
    return true;
}

} // namespace

void SpectrumView::setMaps(const QList<MapSpectrum> &maps)
{
    if (maps.size() != m_maps.size())
        m_highlighted = -1;
    const bool replot = !m_plotted || !samePlot(maps, m_maps);
    m_maps = maps;
    if (replot)
        rebuildPlot();
    m_plotted = true;
    updateVerdicts();
}

void SpectrumView::rebuildPlot()
{
    m_plot->clearGraphs();
    m_plot->clearPlottables();
    m_mapGraphs.clear();

    auto *circle = new QCPCurve(m_plot->xAxis, m_plot->yAxis);
    circle->setName(tr("unit circle"));
    circle->setPen(QPen(QColor(150, 150, 150), 1.2));
    QVector<QCPCurveData> pts;
    for (int k = 0; k <= 360; ++k) {
        const double t = 2 * M_PI * k / 360.0;
        pts << QCPCurveData(k, std::cos(t), std::sin(t));
    }
    circle->data()->set(pts, true);
    // Self-explanatory, and the legend has little room; but an empty legend would collapse
    // the axis rectangle's column of the layout to the legend's margins.
    if (!m_maps.isEmpty())
        circle->removeFromLegend();

    std::vector<Complex> dominant, sub;
    for (int i = 0; i < m_maps.size(); ++i) {
        const MapSpectrum &m = m_maps[i];
        QCPGraph *g = m_plot->addGraph();
        g->setName(subscriptName(m.label));
        g->setLineStyle(QCPGraph::lsNone);
        const QColor c = AttractorRenderer::mapColor(i);
        // ssCircle takes the brush as fill (ssDisc would fill with the pen's colour). The
        // selected map gets a dark outline.
        const bool selected = i == m_highlighted;
        g->setScatterStyle(QCPScatterStyle(markerShape(i),
                                           selected ? QPen(QColor(20, 20, 20), 2.2)
                                                    : QPen(Qt::white, 1.0),
                                           QBrush(c), markerSize(i) + (selected ? 2 : 0)));
        g->setPen(QPen(c));
        QVector<double> x, y;
        for (Complex z : m.spectrum.values) {
            x << z.real();
            y << z.imag();
            if (isOne(z) && z == m.spectrum.values.front())
                addUnique(dominant, z);
        }
        // Keyed data is sorted by real part; that is fine for unconnected markers.
        g->setData(x, y);
        m_mapGraphs << g;
        for (Complex z : m.subdominant.values)
            addUnique(sub, z);
    }

    auto addMarkers = [&](const std::vector<Complex> &zs, const QString &name,
                          QCPScatterStyle style) {
        QCPGraph *g = m_plot->addGraph();
        g->setName(name);
        g->setLineStyle(QCPGraph::lsNone);
        g->setScatterStyle(style);
        QVector<double> x, y;
        for (Complex z : zs) {
            x << z.real();
            y << z.imag();
        }
        g->setData(x, y);
        if (zs.empty())
            g->removeFromLegend();
        return g;
    };
    m_dominantGraph = addMarkers(dominant, tr("dominant 1"),
                                 QCPScatterStyle(QCPScatterStyle::ssSquare,
                                                 QPen(QColor(30, 30, 30), 1.8), Qt::NoBrush, 19));
    m_subdominantGraph = addMarkers(sub, tr("subdominant"),
                                    QCPScatterStyle(QCPScatterStyle::ssCircle,
                                                    QPen(QColor(200, 0, 60), 2.2), Qt::NoBrush,
                                                    22));
    if (m_fitPending)
        fit();
    else
        m_plot->replot(QCustomPlot::rpQueuedReplot);
}

void SpectrumView::fit()
{
    m_fitPending = true;
    // keepAspect() sets the ranges from the axis rectangle's size after the next layout.
    m_plot->replot(QCustomPlot::rpQueuedReplot);
}

void SpectrumView::keepAspect()
{
    if (m_inKeepAspect)
        return;
    m_inKeepAspect = true;
    // The layout that just ran computed ticks and margins for the old ranges: after changing
    // the ranges, lay out again (as QCustomPlot::updateLayout does) until they settle.
    for (int pass = 0; pass < 3; ++pass) {
        const QRect r = m_plot->axisRect()->rect();
        if (r.width() < 2 || r.height() < 2)
            break;
        const QCPRange x0 = m_plot->xAxis->range(), y0 = m_plot->yAxis->range();
        if (m_fitPending) {
            double lo = -1.0, hi = 1.0, bottom = -1.0, top = 1.0;
            for (const MapSpectrum &m : m_maps)
                for (Complex z : m.spectrum.values) {
                    if (!std::isfinite(z.real()) || !std::isfinite(z.imag()))
                        continue;
                    lo = std::min(lo, z.real());
                    hi = std::max(hi, z.real());
                    bottom = std::min(bottom, z.imag());
                    top = std::max(top, z.imag());
                }
            // Room for the markers around the extreme points and the unit circle.
            const double pad = 0.12 * std::max(hi - lo, top - bottom);
            lo -= pad, hi += pad, bottom -= pad, top += pad;
            const double scale = std::min(r.width() / (hi - lo), r.height() / (top - bottom));
            const double cx = 0.5 * (lo + hi), cy = 0.5 * (bottom + top);
            m_plot->xAxis->setRange(cx - 0.5 * r.width() / scale, cx + 0.5 * r.width() / scale);
            m_plot->yAxis->setRange(cy - 0.5 * r.height() / scale,
                                    cy + 0.5 * r.height() / scale);
        } else {
            m_plot->xAxis->setScaleRatio(m_plot->yAxis, 1.0);
        }
        const QCPRange x1 = m_plot->xAxis->range(), y1 = m_plot->yAxis->range();
        const double tol = 1e-9 * std::max(x1.size(), y1.size());
        if (std::abs(x1.lower - x0.lower) < tol && std::abs(x1.upper - x0.upper) < tol
            && std::abs(y1.lower - y0.lower) < tol && std::abs(y1.upper - y0.upper) < tol)
            break;
        m_plot->plotLayout()->update(QCPLayoutElement::upPreparation);
        m_plot->plotLayout()->update(QCPLayoutElement::upMargins);
        m_plot->plotLayout()->update(QCPLayoutElement::upLayout);
    }
    m_inKeepAspect = false;
}

int SpectrumView::plottedEigenvalueCount() const
{
    int n = 0;
    for (QCPGraph *g : m_mapGraphs)
        n += g->dataCount();
    return n;
}

int SpectrumView::subdominantMarkerCount() const
{
    return m_subdominantGraph ? m_subdominantGraph->dataCount() : 0;
}

std::vector<Complex> SpectrumView::subdominantMarkers() const
{
    std::vector<Complex> out;
    if (!m_subdominantGraph)
        return out;
    for (auto it = m_subdominantGraph->data()->constBegin();
         it != m_subdominantGraph->data()->constEnd(); ++it)
        out.emplace_back(it->key, it->value);
    return out;
}

QPointF SpectrumView::pixelOf(Complex z) const
{
    return {m_plot->xAxis->coordToPixel(z.real()), m_plot->yAxis->coordToPixel(z.imag())};
}

QString SpectrumView::tooltipAt(const QPointF &pixel) const
{
    QStringList lines;
    for (const MapSpectrum &m : m_maps) {
        const auto &vals = m.spectrum.values;
        for (std::size_t k = 0; k < vals.size(); ++k) {
            const Complex z = vals[k];
            if (QLineF(pixelOf(z), pixel).length() > kTooltipRadius)
                continue;
            // A repeated eigenvalue is listed once per copy; its multiplicity says it all.
            if (std::any_of(vals.begin(), vals.begin() + k,
                            [&](Complex w) { return std::abs(w - z) < kSamePoint; }))
                continue;
            const int mult = k < m.spectrum.multiplicity.size() ? m.spectrum.multiplicity[k] : 1;
            const double degrees = std::arg(z) * 180.0 / M_PI;
            QString line = tr("<b>%1</b>: λ = %2, |λ| = %3, multiplicity %4, arg λ = %6° "
                              "(map %5)")
                               .arg(richLabel(m.label), formatComplex(z, 10),
                                    formatNumber(std::abs(z), 10))
                               .arg(mult)
                               .arg(int(&m - m_maps.data()) + 1)
                               .arg(formatNumber(std::abs(degrees) < 1e-9 ? 0.0 : degrees, 6));
            if (k == 0 && isOne(z))
                line += tr(" — dominant");
            for (Complex s : m.subdominant.values)
                if (std::abs(s - z) < kSamePoint) {
                    line += tr(" — subdominant");
                    break;
                }
            lines << line;
        }
    }
    return lines.join(QStringLiteral("<br>"));
}

void SpectrumView::placeLegend(const QSize &size)
{
    const bool legend = size.width() >= 300 && size.height() >= 260;
    QCPLayoutGrid *layout = m_plot->plotLayout();
    if (legend != layout->hasElement(1, 0)) {
        if (legend) {
            layout->addElement(1, 0, m_plot->legend);
            layout->setRowStretchFactor(1, 0.001);
        } else {
            layout->take(m_plot->legend);
            layout->simplify();
        }
        m_plot->legend->setVisible(legend);
    }
    // Legend columns that fit the width (before QCustomPlot lays out the new size).
    const int columns = std::max(1, size.width() / 120);
    if (m_plot->legend->wrap() != columns) {
        m_plot->legend->setWrap(columns);
        // setWrap alone keeps the old arrangement until elements are added.
        m_plot->legend->setFillOrder(QCPLayoutGrid::foColumnsFirst, true);
    }
}

void SpectrumView::paintPlot(QCPPainter *painter, int width, int height)
{
    // Laid out for the figure's size (legend included), then again for the screen.
    placeLegend(QSize(width, height));
    m_plot->toPainter(painter, width, height);
    placeLegend(m_plot->size());
    m_plot->replot(QCustomPlot::rpQueuedReplot);
}

QList<int> SpectrumView::mapsAt(const QPointF &pixel) const
{
    QList<int> found;
    for (int i = 0; i < m_maps.size(); ++i)
        for (Complex z : m_maps[i].spectrum.values)
            if (QLineF(pixelOf(z), pixel).length() <= std::max(kTooltipRadius, markerSize(i) / 2)) {
                found << i;
                break;
            }
    return found;
}

Complex SpectrumView::nearestEigenvalue(int map, const QPointF &pixel) const
{
    Complex best{};
    double distance = INFINITY;
    for (Complex z : m_maps[map].spectrum.values)
        if (const double d = QLineF(pixelOf(z), pixel).length(); d < distance) {
            distance = d;
            best = z;
        }
    return best;
}

int SpectrumView::mapAt(const QPointF &pixel) const
{
    // Later maps are drawn on top: the last hit is what the user sees.
    int found = -1;
    for (int i = 0; i < m_maps.size(); ++i)
        for (Complex z : m_maps[i].spectrum.values)
            if (QLineF(pixelOf(z), pixel).length() <= std::max(kTooltipRadius, markerSize(i) / 2))
                found = i;
    return found;
}

void SpectrumView::setHighlightedMap(int map)
{
    map = map >= 0 && map < m_maps.size() ? map : -1;
    if (map == m_highlighted)
        return;
    m_highlighted = map;
    rebuildPlot();
}

bool SpectrumView::eventFilter(QObject *watched, QEvent *event)
{
    if (watched == m_plot && event->type() == QEvent::MouseButtonRelease) {
        auto *e = static_cast<QMouseEvent *>(event);
        // A click, not the end of a drag of the plot.
        if (e->button() == Qt::LeftButton
            && QLineF(e->position(), m_pressPosition).length() < 4.0) {
            const int map = mapAt(e->position());
            // Eigenvalues of several maps on one spot (S_1 and S_2 of a symmetric scheme share
            // theirs): the user picks the map instead of always getting the topmost.
            const QList<int> maps = mapsAt(e->position());
            if (maps.size() > 1) {
                auto *menu = new QMenu(this);
                menu->setObjectName(QStringLiteral("coincidingEigenvalues"));
                menu->setAttribute(Qt::WA_DeleteOnClose);
                for (int i : maps) {
                    const Complex z = nearestEigenvalue(i, e->position());
                    QAction *a = menu->addAction(tr("%1: λ = %2")
                                                     .arg(subscriptName(m_maps[i].label),
                                                          formatComplex(z, 6)));
                    connect(a, &QAction::triggered, this, [this, i] {
                        setHighlightedMap(i);
                        emit mapClicked(i);
                    });
                }
                menu->popup(m_plot->mapToGlobal(e->position().toPoint()));
                return QWidget::eventFilter(watched, event);
            }
            setHighlightedMap(map);
            emit mapClicked(map);
        }
    }
    if (watched == m_plot && event->type() == QEvent::MouseButtonPress)
        m_pressPosition = static_cast<QMouseEvent *>(event)->position();
    if (watched == this && event->type() == QEvent::Resize) {
        // Narrow (a docked column on a small screen): the verdicts go below the plot.
        const int w = static_cast<QResizeEvent *>(event)->size().width();
        const Qt::Orientation o = w < 420 ? Qt::Vertical : Qt::Horizontal;
        if (m_splitter->orientation() != o) {
            m_splitter->setOrientation(o);
            // Most of the room to the plot: the verdicts scroll.
            const int length = o == Qt::Vertical ? static_cast<QResizeEvent *>(event)->size().height()
                                                 : w;
            m_splitter->setSizes({length * 3 / 5, length * 2 / 5});
        }
    }
    if (watched == m_plot && event->type() == QEvent::Resize) {
        // A small plot has no room for a legend under it (it would squash the axes to a
        // strip): the verdicts beside or below name the maps in their colours.
        placeLegend(static_cast<QResizeEvent *>(event)->size());
    }
    if (watched == m_plot && event->type() == QEvent::ToolTip) {
        auto *help = static_cast<QHelpEvent *>(event);
        const QString text = tooltipAt(help->pos());
        if (text.isEmpty()) {
            QToolTip::hideText();
            event->ignore();
        } else {
            QToolTip::showText(help->globalPos(), text, m_plot);
        }
        return true;
    }
    return QWidget::eventFilter(watched, event);
}

void SpectrumView::updateVerdicts()
{
    if (m_maps.isEmpty()) {
        setVerdictHtml(tr("<p>No maps.</p>"));
        return;
    }
    QString html;
    bool allContractive = true;
    QString firstBad;
    for (const MapSpectrum &m : m_maps)
        if (!m.contractivity.eventuallyContractive) {
            if (allContractive)
                firstBad = richLabel(m.label);
            allContractive = false;
        }
    const bool onAverage = !allContractive && m_lyapunov && *m_lyapunov < -1e-3;
    if (m_affineParts) {
        // A flame: the variations bend the maps, so only the game's own orbit tells.
        const QString parts = tr("The spectra below are those of the xforms' affine (pre) maps; "
                                 "the variations bend the maps, so the spectra alone say "
                                 "nothing of the flame's attractor.");
        if (m_lyapunov && *m_lyapunov < -1e-3)
            html += tr("<p><b>The flame contracts on average</b>: the top Lyapunov exponent of "
                       "its chaos game along its own orbit is %1 &lt; 0, so the game converges "
                       "to its attractor. %2</p>")
                        .arg(formatNumber(*m_lyapunov, 4), parts);
        else if (m_lyapunov)
            html += tr("<p style='color:#b01e1e'><b>The flame does not contract on "
                       "average</b>: the top Lyapunov exponent of its chaos game along its own "
                       "orbit is %1 &ge; 0, so its picture is not an attractor's. %2</p>")
                        .arg(formatNumber(*m_lyapunov, 4), parts);
        else
            html += QStringLiteral("<p>%1</p>").arg(parts);
    } else {
        html += allContractive
                    ? tr("<p><b>All maps are (eventually) contractive</b>: the IFS has a unique "
                         "attractor.</p>")
                : onAverage
                    ? tr("<p><b>%1 is not contractive, but the IFS contracts on average</b>: its "
                         "Lyapunov exponent is %2 &lt; 0 (Barnsley–Elton), so random iteration "
                         "converges to its attractor, as in flame renderers; deterministic "
                         "iteration does not.</p>")
                          .arg(firstBad, formatNumber(*m_lyapunov, 4))
                    : tr("<p style='color:#b01e1e'><b>%1 is not contractive</b>: the IFS has no "
                         "attractor and its iteration does not converge.</p>")
                          .arg(firstBad);
    }
    for (int i = 0; i < m_maps.size(); ++i) {
        const MapSpectrum &m = m_maps[i];
        const Contractivity &c = m.contractivity;
        const Subdominant &s = m.subdominant;
        html += QStringLiteral("<p><span style='color:%1'>&#9632;</span> <b>%2</b><br>")
                    .arg(AttractorRenderer::mapColor(i).name(), richLabel(m.label));
        const QString rho = formatNumber(c.spectralRadius, 4);
        if (!c.eventuallyContractive)
            html += tr("Not contractive: spectral radius %1 ≥ 1.").arg(rho);
        else if (c.normFactor < 1.0)
            html += tr("Contractive: ‖A‖<sub>2</sub> = %1 &lt; 1.")
                        .arg(formatNumber(c.normFactor, 4));
        else if (c.exponent > 0)
            html += tr("Eventually contractive: spectral radius %1 &lt; 1, "
                       "‖A<sup>%2</sup>‖<sub>2</sub> &lt; 1.")
                        .arg(rho)
                        .arg(c.exponent);
        else
            html += tr("Eventually contractive: spectral radius %1 &lt; 1.").arg(rho);
        html += QStringLiteral("<br>");
        QString kind;
        QString meaning;
        switch (s.kind) {
        case SubdominantKind::None:
            kind = tr("none");
            meaning = tr("No subdominant eigenvalue: the map is constant.");
            break;
        case SubdominantKind::RealPositive:
            kind = tr("real positive");
            meaning = s.multiplicity == 1
                          ? tr("The curve has a half-tangent at the fixed point, along the "
                               "eigenvector (G¹ where the two sides' eigenvectors align).")
                          : tr("Repeated: the tangent direction at the fixed point depends on "
                               "the control points.");
            break;
        case SubdominantKind::RealNegative:
            kind = tr("real negative");
            meaning = tr("The curve oscillates at the fixed point and has no tangent there.");
            break;
        case SubdominantKind::ComplexPair:
            kind = tr("complex pair");
            meaning = tr("The curve spirals around the fixed point (no tangent).");
            break;
        case SubdominantKind::Complex:
            kind = tr("complex");
            meaning = tr("Near the fixed point the map acts as the spiral similarity z ↦ λz: "
                         "the curve spirals around the fixed point (no tangent).");
            break;
        case SubdominantKind::Mixed:
            kind = tr("mixed");
            meaning = tr("Several eigenvalues of the same modulus with different signs or "
                         "phases: no single tangent behaviour.");
            break;
        }
        QStringList values;
        for (Complex z : s.values)
            values << formatComplex(z, 4);
        values.removeDuplicates();
        if (s.kind == SubdominantKind::None)
            html += tr("Subdominant: none.");
        else
            html += tr("Subdominant: %1 (%2, |λ| = %3, multiplicity %4).")
                        .arg(values.join(QStringLiteral(", ")), kind,
                             formatNumber(s.modulus, 4))
                        .arg(s.multiplicity);
        html += QStringLiteral("<br><i>%1</i></p>").arg(meaning);
    }
    setVerdictHtml(html);
}

void SpectrumView::setVerdictHtml(const QString &html)
{
    // Laying out rich text is the costly part: an unchanged verdict is left as it is.
    if (html == m_verdictHtml)
        return;
    m_verdictHtml = html;
    m_text->setHtml(html);
}

QString SpectrumView::verdictText() const { return m_text->toPlainText(); }

bool SpectrumView::exportPlot(const QString &fileName, const QSize &size, QString *error)
{
    const QString suffix = QFileInfo(fileName).suffix().toLower();
    const int w = std::max(1, size.width()), h = std::max(1, size.height());
    placeLegend(QSize(w, h));
    if (suffix != QLatin1String("pdf") && suffix != QLatin1String("png")
        && suffix != QLatin1String("svg")) {
        if (error)
            *error = tr("Unknown file type “%1”: use .pdf, .svg or .png.").arg(suffix);
        return false;
    }
    // Written whole or not at all (render/FigureFile.h).
    QString writeError;
    const bool ok = writeFigureFile(fileName, [&](QIODevice &out, QString *) {
        if (suffix == QLatin1String("png"))
            return writePng(m_plot->toPixmap(w, h).toImage(), out);
        const auto draw = [&](QPaintDevice *device, bool vector) {
            QCPPainter painter;
            if (!painter.begin(device))
                return false;
            painter.setMode(QCPPainter::pmNoCaching);
            if (vector) {
                painter.setMode(QCPPainter::pmVectorized);
                painter.setMode(QCPPainter::pmNonCosmetic);
            }
            m_plot->toPainter(&painter, w, h);
            return painter.end();
        };
        if (suffix == QLatin1String("pdf")) {
            // As QCustomPlot::savePdf: a page of the plot's size in points, vector pens.
            QPdfWriter pdf(&out);
            pdf.setResolution(72);
            pdf.setPageLayout(QPageLayout(QPageSize(QSizeF(w, h), QPageSize::Point, QString(),
                                                    QPageSize::ExactMatch),
                                          QPageLayout::Portrait, QMarginsF()));
            pdf.setTitle(tr("Eigenvalues"));
            return draw(&pdf, true);
        }
        QByteArray bytes;
        {
            QBuffer buffer(&bytes);
            QSvgGenerator svg;
            svg.setOutputDevice(&buffer);
            svg.setSize(QSize(w, h));
            svg.setViewBox(QRect(0, 0, w, h));
            svg.setTitle(tr("Eigenvalues"));
            if (!draw(&svg, false))
                return false;
        }
        return out.write(bytes) == bytes.size();
    }, &writeError);
    if (!ok && error)
        *error = writeError;
    // The export laid the plot out at its own size: lay it out again for the screen.
    placeLegend(m_plot->size());
    m_plot->replot(QCustomPlot::rpQueuedReplot);
    return ok;
}

QString qcustomplotVersion() { return QStringLiteral(QCUSTOMPLOT_VERSION_STR); }

} // namespace awb
