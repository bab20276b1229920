#include "gui/views/VertexPanel.h"

#include <QChart>
#include <QChartView>
#include <QHBoxLayout>
#include <QLegendMarker>
#include <QLineSeries>
#include <QPainter>
#include <QPainterPath>
#include <QPushButton>
#include <QScatterSeries>
#include <QSplitter>
#include <QTextBrowser>
#include <QTextDocument>
#include <QValueAxis>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace awb {

namespace {

QString number(double x, int digits = 6) { return QString::number(x, 'g', digits); }

QString schemeName(MeshScheme scheme)
{
    return scheme == MeshScheme::Loop ? VertexPanel::tr("Loop")
                                      : VertexPanel::tr("Catmull–Clark");
}

// The core's messages name eigenvalues in ASCII ("lambda2 = lambda3"): here, in the panel's
// own letters.
QString greek(const std::string &message)
{
    QString text = QString::fromStdString(message);
    for (const auto &[ascii, letter] : {std::pair{"lambda1", "λ₁"}, std::pair{"lambda2", "λ₂"},
                                        std::pair{"lambda3", "λ₃"}})
        text.replace(QLatin1String(ascii), QString::fromUtf8(letter));
    return text;
}

QString mark(bool ok)
{
    return ok ? QStringLiteral("<span style='color:#1a7f1a'>✓</span>")
              : QStringLiteral("<span style='color:#b01e1e'>✗</span>");
}

} // namespace

// ---- the characteristic map -------------------------------------------------------------------

CharacteristicMapView::CharacteristicMapView(QWidget *parent) : QWidget(parent)
{
    setAttribute(Qt::WA_OpaquePaintEvent);
    setToolTip(tr("The characteristic map: the n faces around the vertex under the two "
                  "eigenvectors of the subdominant eigenvalue. Cells where the Jacobian changes "
                  "sign are red."));
}

void CharacteristicMapView::setMap(const CharacteristicMap &map, int valence)
{
    m_map = map;
    m_valence = valence;
    update();
}

int CharacteristicMapView::foldedCells() const
{
    int positive = 0, negative = 0;
    for (double a : m_map.cellAreas)
        (a > 0 ? positive : a < 0 ? negative : positive) += a != 0 ? 1 : 0;
    return std::min(positive, negative);
}

void CharacteristicMapView::paintMap(QPainter &p, const QRectF &target) const
{
    p.save();
    p.setRenderHint(QPainter::Antialiasing);
    p.fillRect(target, Qt::white);
    if (m_map.cells.empty()) {
        p.setPen(QColor(110, 110, 110));
        p.drawText(target, Qt::AlignCenter | Qt::TextWordWrap,
                   tr("Click an extraordinary vertex in the 3D view to see its characteristic "
                      "map."));
        p.restore();
        return;
    }
    // The majority orientation is drawn counter-clockwise (the eigenvectors' basis is free:
    // a mirror image is the same map).
    int positive = 0, negative = 0;
    for (double a : m_map.cellAreas)
        if (a > 0)
            ++positive;
        else if (a < 0)
            ++negative;
    const double flip = negative > positive ? -1.0 : 1.0;
    double lo[2] = {qInf(), qInf()}, hi[2] = {-qInf(), -qInf()};
    for (const auto &cell : m_map.cells)
        for (const Eigen::Vector2d &v : cell)
            for (int k = 0; k < 2; ++k) {
                const double x = k == 0 ? flip * v.x() : v.y();
                lo[k] = std::min(lo[k], x);
                hi[k] = std::max(hi[k], x);
            }
    const QRectF box = target.adjusted(14, 26, -14, -14);
    const double span = std::max({hi[0] - lo[0], hi[1] - lo[1], 1e-300});
    const double scale = std::min(box.width(), box.height()) / span;
    const QPointF mid((lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2);
    const auto at = [&](const Eigen::Vector2d &v) {
        return box.center() + QPointF((flip * v.x() - mid.x()) * scale,
                                      -(v.y() - mid.y()) * scale);
    };
    // Sectors in two alternating blues; with an odd n the last one gets a third tone, so that
    // no two neighbours look alike.
    const QColor sectors[3] = {QColor(196, 218, 244), QColor(150, 190, 232),
                               QColor(176, 206, 214)};
    const QColor folded(235, 70, 60);
    const double majority = flip;  // the sign of the majority's areas
    p.setPen(QPen(QColor(90, 110, 140, 120), 0.6));
    for (std::size_t c = 0; c < m_map.cells.size(); ++c) {
        QPolygonF poly;
        for (const Eigen::Vector2d &v : m_map.cells[c])
            poly << at(v);
        const double a = c < m_map.cellAreas.size() ? m_map.cellAreas[c] : 0.0;
        const int sector = c < m_map.cellSectors.size() ? m_map.cellSectors[c] : 0;
        const int tone = m_valence % 2 == 1 && sector == m_valence - 1 ? 2 : sector % 2;
        p.setBrush(a * majority < 0 ? folded : sectors[tone]);
        p.drawPolygon(poly);
    }
    if (!m_map.outline.empty()) {
        QPolygonF outline;
        for (const Eigen::Vector2d &v : m_map.outline)
            outline << at(v);
        p.setBrush(Qt::NoBrush);
        p.setPen(QPen(QColor(20, 30, 60), 1.8));
        p.drawPolygon(outline);
    }
    p.setPen(Qt::NoPen);
    p.setBrush(QColor(20, 20, 20));
    p.drawEllipse(at(Eigen::Vector2d::Zero()), 3.0, 3.0);
    p.setPen(QColor(30, 30, 30));
    const int folds = foldedCells();
    const QString caption =
        folds == 0 ? tr("n = %1: regular, %2").arg(m_valence).arg(
                         m_map.injective() ? tr("injective") : tr("not injective"))
                   : tr("n = %1: the Jacobian changes sign in %2 cells").arg(m_valence).arg(folds);
    p.drawText(target.adjusted(8, 4, -8, 0), Qt::AlignLeft | Qt::AlignTop, caption);
    p.restore();
}

void CharacteristicMapView::paintEvent(QPaintEvent *)
{
    QPainter p(this);
    paintMap(p, rect());
}

// ---- the verdict ------------------------------------------------------------------------------

QString VertexPanel::verdictHtml(const ExtraordinaryVertex &e, MeshScheme scheme,
                                 const std::optional<VertexSpectrum> &interior,
                                 const QString &where)
{
    const QString rule = e.rule == "dart"     ? tr("a dart (one sharp edge ends here)")
                         : e.rule == "crease" ? tr("on a crease")
                         : e.rule == "corner" ? tr("a corner")
                                              : tr("smooth");
    const QString kind = tr("valence %1, %2, %3, %4")
                             .arg(e.valence)
                             .arg(e.boundary ? tr("on the boundary") : tr("interior"), rule,
                                  schemeName(scheme));
    QString html = QStringLiteral("<p><b>%1</b> — %2</p>").arg(where.toHtmlEscaped(), kind);
    if (!e.note.empty()) {
        // Not analysed (an interior valence of 2, or above 64): say so, and the limit only.
        html += QStringLiteral("<p>%1</p>").arg(
            tr("No spectrum: %1.").arg(QString::fromStdString(e.note)).toHtmlEscaped());
        if (e.limit.size() == 3)
            html += QStringLiteral("<p>%1</p>").arg(tr("Limit position (%1, %2, %3).")
                                                        .arg(number(e.limit(0)),
                                                             number(e.limit(1)),
                                                             number(e.limit(2))));
        return html;
    }
    const QString ring =
        !e.smoothInterior()
            ? tr("Local subdivision matrix S: %1 × %1 (the net of the vertex's piece).")
                   : tr("Local subdivision matrix S: %1 × %1 (the vertex and every point "
                        "within two faces of it).");
    html += QStringLiteral("<p>%1</p>").arg(ring.arg(e.ringSize));
    const double l = e.subdominant, m = e.subsubdominant;
    QString numbers =
        tr("λ₁ = 1, λ = %1, μ = %2, λ² = %3").arg(number(l), number(m), number(l * l));
    if (e.smoothInterior()) {
        // The formula itself, with n put in, and what it gives (Stam 1998 for Catmull-Clark).
        const QString n = QString::number(e.valence);
        const QString form = scheme == MeshScheme::Loop
            ? QStringLiteral("3/8 + cos(2π/%1)/4").arg(n)
            : QStringLiteral("(5 + cos(2π/%1) + cos(π/%1)·√(2(9 + cos(2π/%1))))/16").arg(n);
        // One line: a formula broken across lines reads as two.
        numbers += tr("; in closed form λ = %1 = %2")
                       .arg(QStringLiteral("<span style=\"white-space: nowrap\">%1</span>")
                                .arg(form.toHtmlEscaped()),
                            number(closedFormSubdominant(scheme, e.valence)));
    }
    html += QStringLiteral("<p>%1</p>").arg(numbers);
    if (e.sharp) {
        // Sector by sector, on the canonical star of this neighbourhood (VertexSpectrum.h).
        html += QStringLiteral("<p>%1</p>").arg(
            tr("Reif's criterion sector by sector (Zorin 2000): each run of faces between sharp "
               "edges, with the eigenvalues whose eigenvectors do not vanish on it, on the "
               "canonical star of this neighbourhood:"));
        html += QStringLiteral("<ul>");
        for (const SectorVerdict &v : e.sharp->sectors) {
            const QString faces = v.faces == 1
                                      ? tr("face %1").arg(v.firstFace)
                                      : tr("faces %1–%2").arg(v.firstFace).arg(v.firstFace + v.faces - 1);
            QString line = tr("%1: λ₁ = %2, λ₂ = %3, μ = %4")
                               .arg(faces, number(v.lambda1), number(v.lambda2), number(v.mu));
            const QString curvature = v.curvature == "zero"      ? tr("zero (μ < λ₂²)")
                                      : v.curvature == "bounded" ? tr("bounded (μ = λ₂²)")
                                                                 : tr("unbounded (μ > λ₂²)");
            line += v.c1()       ? tr("; C¹, curvature %1").arg(curvature)
                    : v.decided ? tr("; not C¹: %1").arg(greek(v.reason))
                                : tr("; %1").arg(greek(v.reason));
            if (!v.chain.empty())
                line += QStringLiteral(" (%1)").arg(greek(v.chain));
            html += QStringLiteral("<li>%1 %2</li>").arg(mark(v.c1()), line.toHtmlEscaped());
        }
        html += QStringLiteral("</ul><p><b>%1</b></p>")
                    .arg(e.sharp->c1.value_or(false)
                             ? tr("Verdict: the limit surface is C¹ on every sector up to the "
                                  "creases (for generic data).")
                             : tr("Verdict: C¹ is not established on every sector."));
    } else if (!e.smoothInterior() || !interior) {
        html += QStringLiteral("<p>%1</p>").arg(
            tr("Reif's criterion is decided for valences 3 to 64: this vertex is outside "
               "them."));
    } else {
        const VertexSpectrum &s = *interior;
        const CharacteristicMap &c = s.characteristic;
        const QString item = QStringLiteral("<li>%1 %2</li>");
        html += QStringLiteral("<ul>");
        html += item.arg(mark(s.spectralC1), tr("spectral condition 1 > λ₂ = λ₃ > |λ₄|, λ real"));
        if (s.spectralC1) {
            const QString lo = number(c.minArea, 3), hi = number(c.maxArea, 3);
            html += item.arg(mark(s.characteristicRegular),
                             s.characteristicRegular
                                 ? tr("characteristic map regular: the Jacobian keeps one "
                                      "sign on all %1 cells (signed areas %2 … %3)")
                                       .arg(int(c.cells.size()))
                                       .arg(lo, hi)
                                 : tr("characteristic map not regular: signed areas from "
                                      "%1 to %2")
                                       .arg(lo, hi));
            html += item.arg(mark(s.characteristicInjective),
                             tr("characteristic map injective: its boundary winds %1 "
                                "time(s) around the vertex")
                                 .arg(std::abs(c.winding)));
        }
        html += QStringLiteral("</ul>");
        html += QStringLiteral("<p><b>%1</b></p>")
                    .arg(s.c1 ? tr("Verdict (Reif 1995): the limit surface is C¹ at the "
                                   "vertex (for generic data).")
                              : tr("Verdict (Reif 1995): C¹ is not established at the "
                                   "vertex."));
        const QString curvature =
            s.curvature == "zero"
                ? tr("μ < λ²: the curvature is zero at the vertex (the surface is flat "
                     "there to second order, for generic data: no convex or saddle shape "
                     "can be modelled at it)")
            : s.curvature == "bounded"
                ? tr("μ = λ²: the curvature is bounded at the vertex")
                : tr("μ > λ²: the curvature is unbounded at the vertex (for generic data)");
        html += QStringLiteral("<p>%1</p>").arg(curvature);
    }
    if (e.limit.size() == 3)
        html += QStringLiteral("<p>%1</p>")
                    .arg(tr("Limit position (%1, %2, %3), normal (%4, %5, %6).")
                             .arg(number(e.limit(0)), number(e.limit(1)), number(e.limit(2)))
                             .arg(number(e.normal(0), 4), number(e.normal(1), 4),
                                  number(e.normal(2), 4)));
    return html;
}

VertexPanel::VertexPanel(QWidget *parent) : QWidget(parent)
{
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(2, 2, 2, 2);
    auto *split = m_split = new QSplitter(Qt::Vertical, this);
    m_text = new QTextBrowser;
    m_text->setObjectName(QStringLiteral("vertexVerdict"));
    m_text->setOpenLinks(false);
    m_map = new CharacteristicMapView;
    m_map->setObjectName(QStringLiteral("characteristicMap"));
    split->addWidget(m_text);
    split->addWidget(m_map);
    split->setStretchFactor(0, 1);
    split->setStretchFactor(1, 1);
    split->setChildrenCollapsible(false);
    layout->addWidget(split, 1);
    m_plot = new QPushButton(tr("New Eigenvalue Plot"));
    m_plot->setObjectName(QStringLiteral("vertexPlotButton"));
    m_plot->setToolTip(tr("Adds an eigenvalue plot item whose source is this extraordinary "
                          "vertex: its local subdivision matrix's eigenvalues, kept in the "
                          "project and printed with it"));
    connect(m_plot, &QPushButton::clicked, this, &VertexPanel::plotRequested);
    layout->addWidget(m_plot);
    clear();
}

void VertexPanel::setVertex(const ExtraordinaryVertex &vertex, MeshScheme scheme,
                            const std::optional<VertexSpectrum> &interior, const QString &where)
{
    m_has = true;
    m_text->setHtml(verdictHtml(vertex, scheme, interior, where));
    const SectorVerdict *sector = nullptr;  // the first sector whose map is drawn, a failed one first
    if (vertex.sharp)
        for (const SectorVerdict &v : vertex.sharp->sectors)
            if (v.spectral && v.creaseInPlane && (!sector || (sector->c1() && !v.c1())))
                sector = &v;
    if (interior && interior->spectralC1)
        m_map->setMap(interior->characteristic, vertex.valence);
    else if (sector)
        m_map->setMap(sector->map, vertex.valence);
    else
        m_map->setMap({}, 0);
    m_plot->setEnabled(true);
}

void VertexPanel::clear(const QString &why)
{
    m_has = false;
    m_text->setHtml(QStringLiteral("<p>%1</p>").arg(
        (why.isEmpty() ? tr("Click an extraordinary vertex (a purple diamond labelled with its "
                            "valence) in the 3D view of a mesh surface: its spectrum, Reif's "
                            "verdict and its characteristic map appear here.")
                       : why)
            .toHtmlEscaped()));
    m_map->setMap({}, 0);
    m_plot->setEnabled(false);
}

QString VertexPanel::verdictText() const { return m_text->toPlainText(); }

void VertexPanel::resizeEvent(QResizeEvent *event)
{
    QWidget::resizeEvent(event);
    // The map is square: beside the text it takes its height (at most 45% of the width), the
    // text the rest; above the text, its width (at most 45% of the height). A narrow dock
    // thus keeps the verdict readable instead of a wrapped column (issue 47).
    const Qt::Orientation wanted = width() > 1.3 * height() ? Qt::Horizontal : Qt::Vertical;
    m_split->setOrientation(wanted);
    const int total = wanted == Qt::Horizontal ? m_split->width() : m_split->height();
    const int across = wanted == Qt::Horizontal ? m_split->height() : m_split->width();
    const int map = std::min(across, int(0.45 * total));
    m_split->setSizes({total - map, map});
}

// ---- the valence chart ------------------------------------------------------------------------

ValenceChart::ValenceChart(QWidget *parent) : QWidget(parent)
{
    auto *layout = new QHBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    auto *split = m_split = new QSplitter(Qt::Horizontal, this);
    const auto makeView = [](const QString &name) {
        auto *chart = new QChart;
        chart->legend()->setAlignment(Qt::AlignBottom);
        chart->setMargins(QMargins(4, 4, 4, 4));
        auto *view = new QChartView(chart);
        view->setObjectName(name);
        view->setRenderHint(QPainter::Antialiasing);
        view->setMinimumSize(100, 100);
        return view;
    };
    m_byValence = makeView(QStringLiteral("valenceChart"));
    m_curvature = makeView(QStringLiteral("curvatureChart"));
    split->addWidget(m_byValence);
    split->addWidget(m_curvature);
    layout->addWidget(split);
}

ValenceChart::~ValenceChart() = default;

void ValenceChart::setScheme(MeshScheme scheme, std::vector<int> itemValences)
{
    std::sort(itemValences.begin(), itemValences.end());
    itemValences.erase(std::unique(itemValences.begin(), itemValences.end()), itemValences.end());
    m_scheme = scheme;
    m_marked = std::move(itemValences);
    if (isVisible())
        rebuild();
}

const std::vector<VertexSpectrum> &ValenceChart::table() const { return m_table; }

void ValenceChart::resizeEvent(QResizeEvent *event)
{
    QWidget::resizeEvent(event);
    // Side by side when each chart gets a width of about its height, else one above the other.
    m_split->setOrientation(width() > 1.8 * height() ? Qt::Horizontal : Qt::Vertical);
    fitToSize();
}

void ValenceChart::fitToSize()
{
    if (!m_drawn)
        return;
    const bool sideBySide = m_split->orientation() == Qt::Horizontal;
    const int cw = sideBySide ? width() / 2 : width();
    const int ch = sideBySide ? height() : height() / 2;
    const bool roomy = cw >= 330 && ch >= 200;
    const QString scheme = schemeName(*m_drawn);
    m_byValence->chart()->setTitle(roomy ? tr("λ, μ, λ² against n (%1)").arg(scheme)
                                         : tr("λ, μ, λ² (%1)").arg(scheme));
    m_curvature->chart()->setTitle(tr("μ against λ²"));
    for (QChartView *view : {m_byValence, m_curvature}) {
        QChart *chart = view->chart();
        // Without room the legend's names are cut to "μ…": the tooltip names the lines then.
        chart->legend()->setVisible(roomy);
        for (QAbstractAxis *a : chart->axes()) {
            auto *axis = qobject_cast<QValueAxis *>(a);
            if (!axis)
                continue;
            const bool horizontal = a->orientation() == Qt::Horizontal;
            const int room = horizontal ? cw : ch;
            if (axis->tickType() == QValueAxis::TicksDynamic)
                axis->setTickInterval(room > 520 ? 1 : room > 300 ? 2 : 4);
            else
                axis->setTickCount(std::clamp(room / 55, 3, 6));
            axis->setLabelFormat(room > 300 ? QStringLiteral("%.2f") : QStringLiteral("%.1f"));
            if (horizontal && axis->tickType() == QValueAxis::TicksDynamic)
                axis->setLabelFormat(QStringLiteral("%.0f"));
        }
    }
}

void ValenceChart::showEvent(QShowEvent *event)
{
    QWidget::showEvent(event);
    rebuild();
}

void ValenceChart::rebuild()
{
    if (m_drawn == m_scheme && m_drawnMarked == m_marked)
        return;
    m_drawn = m_scheme;
    m_drawnMarked = m_marked;
    // The core computes each valence once per process (sharedVertexSpectrum).
    m_table = m_scheme ? valenceSpectra(*m_scheme, kFrom, kTo) : std::vector<VertexSpectrum>{};
    for (QChartView *view : {m_byValence, m_curvature}) {
        QChart *chart = view->chart();
        chart->removeAllSeries();
        for (QAbstractAxis *a : chart->axes()) {
            chart->removeAxis(a);
            delete a;
        }
    }
    if (!m_scheme) {
        m_byValence->chart()->setTitle(tr("Valences: choose a mesh surface"));
        m_curvature->chart()->setTitle({});
        return;
    }
    const std::vector<VertexSpectrum> &rows = table();
    const auto series = [](QXYSeries *s, const QString &name, QColor colour,
                           Qt::PenStyle style = Qt::SolidLine) {
        s->setName(name);
        QPen pen(colour, 2.0, style);
        s->setPen(pen);
        if (auto *scatter = qobject_cast<QScatterSeries *>(s)) {
            scatter->setColor(colour);
            scatter->setBorderColor(colour.darker(140));
        }
        return s;
    };
    // λ(n), μ(n), λ²(n).
    auto *lambda = new QLineSeries, *mu = new QLineSeries, *lambda2 = new QLineSeries;
    series(lambda, tr("λ (subdominant)"), QColor(30, 90, 180));
    series(mu, tr("μ = |λ₄|"), QColor(200, 90, 20), Qt::DashLine);
    series(lambda2, tr("λ²"), QColor(90, 150, 60), Qt::DotLine);
    auto *own = new QScatterSeries;
    series(own, tr("this mesh"), QColor(150, 90, 210));
    own->setMarkerSize(11);
    double top = 0;
    for (const VertexSpectrum &s : rows) {
        lambda->append(s.valence, s.subdominant);
        mu->append(s.valence, s.subsubdominant);
        lambda2->append(s.valence, s.subdominant * s.subdominant);
        top = std::max({top, s.subdominant, s.subsubdominant});
        if (std::binary_search(m_marked.begin(), m_marked.end(), s.valence))
            own->append(s.valence, s.subdominant);
    }
    QChart *chart = m_byValence->chart();  // titled by fitToSize() for its size
    m_byValence->setToolTip(tr("The subdominant eigenvalue λ, the next modulus μ and λ² of "
                               "the local subdivision matrix at an interior vertex of valence "
                               "n; the purple dots are this mesh's valences"));
    auto *x = new QValueAxis;
    x->setTitleText(tr("valence n"));
    x->setRange(kFrom - 0.5, kTo + 0.5);
    x->setTickType(QValueAxis::TicksDynamic);
    x->setTickAnchor(0);
    x->setTickInterval(2);  // fitToSize() sets it for the chart's width
    x->setLabelFormat(QStringLiteral("%.0f"));
    auto *y = new QValueAxis;
    y->setRange(0, std::ceil(top * 10 + 0.5) / 10);
    y->setLabelFormat(QStringLiteral("%.2f"));
    chart->addAxis(x, Qt::AlignBottom);
    chart->addAxis(y, Qt::AlignLeft);
    for (QXYSeries *s : std::initializer_list<QXYSeries *>{lambda, mu, lambda2, own}) {
        chart->addSeries(s);
        s->attachAxis(x);
        s->attachAxis(y);
    }
    // μ against λ²: the diagonal μ = λ² separates zero curvature (below) from unbounded
    // curvature (above).
    auto *diagonal = new QLineSeries;
    auto *points = new QScatterSeries, *mine = new QScatterSeries;
    series(diagonal, tr("μ = λ² (bounded curvature)"), QColor(120, 120, 120), Qt::DashLine);
    series(points, tr("n = %1 … %2").arg(kFrom).arg(kTo), QColor(30, 90, 180));
    series(mine, tr("this mesh"), QColor(150, 90, 210));
    points->setMarkerSize(7);
    mine->setMarkerSize(12);
    double hi = 0;
    for (const VertexSpectrum &s : rows) {
        const double l2 = s.subdominant * s.subdominant;
        points->append(l2, s.subsubdominant);
        if (std::binary_search(m_marked.begin(), m_marked.end(), s.valence))
            mine->append(l2, s.subsubdominant);
        hi = std::max({hi, l2, s.subsubdominant});
    }
    hi = std::ceil(hi * 20 + 0.5) / 20;
    diagonal->append(0, 0);
    diagonal->append(hi, hi);
    QChart *c = m_curvature->chart();
    m_curvature->setToolTip(tr("Below the diagonal (μ < λ²) the curvature at the vertex is "
                               "zero, on it bounded, above it unbounded (for generic data)"));
    auto *cx = new QValueAxis, *cy = new QValueAxis;
    cx->setTitleText(tr("λ²"));
    cy->setTitleText(tr("μ"));
    cx->setRange(0, hi);
    cy->setRange(0, hi);
    cx->setLabelFormat(QStringLiteral("%.2f"));
    cy->setLabelFormat(QStringLiteral("%.2f"));
    c->addAxis(cx, Qt::AlignBottom);
    c->addAxis(cy, Qt::AlignLeft);
    for (QXYSeries *s : std::initializer_list<QXYSeries *>{diagonal, points, mine}) {
        c->addSeries(s);
        s->attachAxis(cx);
        s->attachAxis(cy);
    }
    fitToSize();
}

} // namespace awb
