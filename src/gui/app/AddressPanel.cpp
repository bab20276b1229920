#include "gui/app/AddressPanel.h"

#include "gui/app/ItemController.h"
#include "gui/views/AttractorView.h"
#include "model/AttractorItem.h"
#include "model/ItemAddress.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QVBoxLayout>

#include <algorithm>

namespace awb {

namespace {

// The highlight draws at most this many points of a sub-copy.
constexpr Eigen::Index kHighlightPoints = 12000;
// The control polygons of at most this many pieces of a parameter interval are drawn.
constexpr std::size_t kMaxIntervalPolygons = 16;

QString number(double v) { return QString::number(v, 'g', 10); }

// Rows `rows` of `shown` views stacked (n x 2 per view).
Mat stackViews(const std::vector<Mat> &views)
{
    Eigen::Index n = 0;
    for (const Mat &v : views)
        n += v.cols() >= 2 ? v.rows() : 0;
    Mat out(n, 2);
    Eigen::Index r = 0;
    for (const Mat &v : views) {
        if (v.cols() < 2)
            continue;
        out.middleRows(r, v.rows()) = v.leftCols(2);
        r += v.rows();
    }
    return out;
}

// The samples f_u(x*) of a shorter length, at most maxPoints of them, spread over the whole
// attractor: those whose last symbols are 0 (f_0(x*) = x*). Every k-th row would not do: the
// iteration emits the words in an order where the first symbol alternates fastest.
std::vector<Eigen::Index> coarserSamples(const AddressedPoints &a, Eigen::Index maxPoints)
{
    int zeros = 0;
    Eigen::Index count = a.size();
    while (count > maxPoints && zeros < a.length) {
        count /= a.maps;
        ++zeros;
    }
    std::vector<Eigen::Index> rows;
    rows.reserve(std::size_t(count));
    for (Eigen::Index i = 0; i < a.size(); ++i) {
        const std::uint8_t *end = a.symbols.data() + std::size_t(i + 1) * std::size_t(a.length);
        if (std::all_of(end - zeros, end, [](std::uint8_t s) { return s == 0; }))
            rows.push_back(i);
    }
    return rows;
}

// "S_2 S_2 S_1 P" for w = 0,1,1: the matrices as the Matrices dock names them (1-based).
QString productName(const Address &w)
{
    QStringList factors;
    for (auto it = w.rbegin(); it != w.rend(); ++it)
        factors << QStringLiteral("S_%1").arg(*it + 1);
    return factors.join(QLatin1Char(' ')) + QStringLiteral(" P");
}

QString pointRows(const Mat &P)
{
    QStringList rows;
    for (Eigen::Index i = 0; i < P.rows(); ++i)
        rows << QStringLiteral("(%1, %2)").arg(number(P(i, 0)), number(P(i, 1)));
    return rows.join(QStringLiteral("<br>"));
}

} // namespace

AddressPanel::AddressPanel(ItemController *controller, AttractorView *view, QWidget *parent)
    : QWidget(parent), m_controller(controller), m_view(view)
{
    m_edit = new QLineEdit;
    m_edit->setObjectName(QStringLiteral("addressEdit"));
    m_edit->setPlaceholderText(tr("Address 0,1,1 or interval [0.25, 0.5]"));
    m_edit->setToolTip(tr("An address selects the sub-copy f_w(A) = f_w1(f_w2(…(A))): map "
                          "numbers from 0, the outermost map first. A subdivision curve also "
                          "takes a parameter interval [t0, t1]. Enter selects, an empty field "
                          "clears."));
    m_edit->setClearButtonEnabled(true);
    auto *clear = new QPushButton(tr("Clear"));
    clear->setObjectName(QStringLiteral("addressClear"));
    m_prefixes = new QLabel;
    m_prefixes->setObjectName(QStringLiteral("addressPrefixes"));
    m_prefixes->setWordWrap(true);
    m_prefixes->setTextFormat(Qt::RichText);
    m_prefixes->setText(tr("Click the attractor to pick an address; click a symbol of it to "
                           "select that prefix."));
    m_details = new QLabel;
    m_details->setObjectName(QStringLiteral("addressDetails"));
    m_details->setWordWrap(true);
    m_details->setTextFormat(Qt::RichText);
    m_details->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_details->setAlignment(Qt::AlignTop | Qt::AlignLeft);

    auto *row = new QHBoxLayout;
    row->addWidget(m_edit, 1);
    row->addWidget(clear);
    auto *layout = new QVBoxLayout(this);
    layout->addLayout(row);
    layout->addWidget(m_prefixes);
    layout->addWidget(m_details, 1);

    connect(m_edit, &QLineEdit::returnPressed, this, [this] { select(m_edit->text()); });
    connect(clear, &QPushButton::clicked, this, &AddressPanel::clearSelection);
    connect(m_prefixes, &QLabel::linkActivated, this, [this](const QString &link) {
        const int k = std::clamp(link.toInt(), 1, int(m_pinned.size()));
        select(QString::fromStdString(
            formatAddress(Address(m_pinned.begin(), m_pinned.begin() + k))));
    });
    connect(m_view, &AttractorView::attractorClicked, this, &AddressPanel::clickedAt);
    connect(m_controller, &ItemController::refreshed, this, &AddressPanel::refresh);
}

AddressPanel::~AddressPanel() = default;

bool AddressPanel::ensureSamples()
{
    AttractorItem *item = m_controller->drawnItem();
    if (item != m_item) {
        // Another item: its own selection starts empty (refresh() clears the old one).
        m_item = item;
        m_pinned.clear();
        showPinned();
    }
    std::shared_ptr<const DerivedIfs> d = item ? item->derivedIfs() : nullptr;
    if (!d || item->pointDimension() != 2 || d->iterate || d->ifs.size() < 1
        || d->ifs.views.empty() || d->ifs.views.front().outDim() != 2) {
        m_samples.reset();
        m_derived.reset();
        return false;
    }
    if (d == m_derived && m_samples)
        return true;
    m_derived = d;
    m_samples.reset();
    m_pieces = parameterPieces(*item);
    m_meaning = parameterMeaning(*item);
    try {
        const StartSet start = item->coreStartSet(*d);
        const RowVec seed = start.vertices.rows() > 0 ? RowVec(start.vertices.row(0))
                                                      : RowVec(RowVec::Zero(d->ifs.dim()));
        m_samples = std::make_unique<AddressedPoints>(sampleAddresses(d->ifs, seed));
    } catch (const std::exception &) {
        m_samples.reset();
    }
    return bool(m_samples);
}

std::optional<AddressPanel::Hit> AddressPanel::addressAt(const QPointF &world, double maxPixels)
{
    if (!ensureSamples() || m_samples->size() == 0)
        return std::nullopt;
    const NearestAddress near = nearestAddress(*m_samples, world.x(), world.y());
    if (near.index < 0 || near.distance * m_view->pixelsPerUnit() > maxPixels)
        return std::nullopt;
    Hit hit;
    hit.address = m_samples->address(near.index);
    const Mat &shown = m_samples->shown[std::size_t(near.view)];
    hit.point = QPointF(shown(near.index, 0), shown(near.index, 1));
    // The sample is f_w(x*), x* the start of the curve (t = 0): the curve at the left end of
    // w's parameter interval.
    if (!m_pieces.empty())
        hit.t = addressInterval(m_pieces, hit.address).t0;
    return hit;
}

QString AddressPanel::hoverText(const QPointF &world)
{
    const auto hit = addressAt(world);
    if (!hit)
        return {};
    QString text = tr("address %1").arg(QString::fromStdString(formatAddress(hit->address)));
    if (hit->t)
        text += tr(", t ≈ %1").arg(QString::number(*hit->t, 'g', 6));
    return text;
}

void AddressPanel::clickedAt(const QPointF &world)
{
    const auto hit = addressAt(world);
    if (!hit)
        return;
    pinAddress(hit->address);
    const int k = std::clamp(m_selectedLength, 1, int(hit->address.size()));
    select(QString::fromStdString(
        formatAddress(Address(hit->address.begin(), hit->address.begin() + k))));
    if (QWidget *dock = parentWidget())
        dock->raise();
}

void AddressPanel::pinAddress(const Address &w)
{
    m_pinned = w;
    showPinned();
}

void AddressPanel::showPinned()
{
    if (m_pinned.empty()) {
        m_prefixes->setText(tr("Click the attractor to pick an address; click a symbol of it "
                               "to select that prefix."));
        return;
    }
    QStringList links;
    for (std::size_t k = 0; k < m_pinned.size(); ++k)
        links << QStringLiteral("<a href=\"%1\">%2</a>").arg(k + 1).arg(m_pinned[k]);
    m_prefixes->setText(tr("Clicked: %1<br><small>click a symbol to select the prefix up to "
                           "it</small>").arg(links.join(QStringLiteral(" "))));
}

bool AddressPanel::select(const QString &text, QString *error)
{
    if (text.trimmed().isEmpty()) {
        clearSelection();
        return true;
    }
    QString why;
    if (!apply(text, &why)) {
        m_details->setText(QStringLiteral("<span style=\"color:#b00020\">%1</span>")
                               .arg(why.toHtmlEscaped()));
        if (error)
            *error = why;
        return false;
    }
    if (m_edit->text() != m_selection)
        m_edit->setText(m_selection);
    emit selectionChanged(m_selection);
    return true;
}

void AddressPanel::clearSelection()
{
    m_selection.clear();
    m_edit->clear();
    m_details->clear();
    m_view->setHighlight({});
    emit selectionChanged({});
}

QString AddressPanel::details() const { return m_details->text(); }

bool AddressPanel::apply(const QString &text, QString *error)
{
    if (!ensureSamples()) {
        *error = tr("The item drawn has no addresses to select (only items drawn by one IFS "
                    "in the plane have).");
        return false;
    }
    const DerivedIfs &d = *m_derived;
    const AddressedPoints &samples = *m_samples;
    const std::vector<Eigen::Index> coarse = coarserSamples(samples, kHighlightPoints);
    AttractorView::Highlight h;
    QString html;
    try {
        if (const auto interval = parseParameterInterval(text)) {
            if (m_pieces.empty())
                throw InputError(tr("a parameter interval selects on a subdivision curve with "
                                    "a real parameter; this item has none").toStdString());
            // The sampled points whose t lies in [t0, t1], and the largest pieces inside it.
            std::vector<Eigen::Index> rows;
            for (Eigen::Index i : coarse) {
                const double t = addressInterval(m_pieces, samples.address(i)).t0;
                if (t >= interval->t0 && t <= interval->t1)
                    rows.push_back(i);
            }
            std::vector<Mat> views;
            for (const Mat &shown : samples.shown) {
                Mat v(Eigen::Index(rows.size()), shown.cols());
                for (std::size_t k = 0; k < rows.size(); ++k)
                    v.row(Eigen::Index(k)) = shown.row(rows[k]);
                views.push_back(v);
            }
            h.points = stackViews(views);
            const auto cover = coverInterval(m_pieces, interval->t0, interval->t1, 8);
            QStringList pieces;
            for (const Address &w : cover) {
                pieces << QString::fromStdString(formatAddress(w));
                if (h.controlPolygons.size() < kMaxIntervalPolygons)
                    if (const auto cp = addressControlPoints(d, w); cp && cp->cols() >= 2)
                        h.controlPolygons.push_back(*cp);
            }
            m_selection = QStringLiteral("[%1, %2]").arg(number(interval->t0),
                                                         number(interval->t1));
            h.caption = tr("t in %1").arg(m_selection);
            html = tr("<b>t in %1</b> (%2)<br>Pieces inside it (addresses up to 8 symbols): "
                      "%3")
                       .arg(m_selection, m_meaning.toHtmlEscaped(),
                            pieces.isEmpty() ? tr("none") : pieces.join(QStringLiteral("; ")));
            if (cover.size() > kMaxIntervalPolygons)
                html += tr("<br>The control polygons of the first %1 pieces are drawn.")
                            .arg(kMaxIntervalPolygons);
        } else {
            const Address w = parseItemAddress(text, d);
            const AffineMap f = composeAddress(d.ifs, w);
            Mat space(Eigen::Index(coarse.size()), samples.space.cols());
            for (std::size_t r = 0; r < coarse.size(); ++r)
                space.row(Eigen::Index(r)) = samples.space.row(coarse[r]);
            const Mat image = applyMap(f, space);
            std::vector<Mat> views;
            for (const Projection &v : d.ifs.views)
                views.push_back(project(v, image));
            h.points = stackViews(views);
            m_selection = QString::fromStdString(formatAddress(w));
            m_selectedLength = int(w.size());
            h.caption = tr("w = %1").arg(m_selection);
            html = tr("<b>w = %1</b>: the sub-copy f_w(A) = %2(A)")
                       .arg(m_selection, [&] {
                           QStringList maps;
                           for (int s : w)
                               maps << QStringLiteral("f_%1").arg(s);
                           return maps.join(QStringLiteral(" ∘ "));
                       }());
            if (!m_pieces.empty()) {
                const ParameterInterval t = addressInterval(m_pieces, w);
                h.caption += tr("   t in [%1, %2]").arg(number(t.t0), number(t.t1));
                html += tr("<br>t in [%1, %2] (%3)")
                            .arg(number(t.t0), number(t.t1), m_meaning.toHtmlEscaped());
            }
            if (const auto cp = addressControlPoints(d, w); cp && cp->cols() >= 2) {
                h.controlPolygons.push_back(*cp);
                html += tr("<br>Control points S_w P = %1 (symbol i is S_(i+1)):<br>%2")
                            .arg(productName(w), pointRows(*cp));
            }
        }
    } catch (const InputError &e) {
        *error = QString::fromStdString(e.what());
        return false;
    }
    m_details->setText(html);
    m_view->setHighlight(h);
    return true;
}

void AddressPanel::refresh()
{
    AttractorItem *item = m_controller->drawnItem();
    if (item != m_item || !item) {
        m_item = item;
        m_pinned.clear();
        showPinned();
        if (!m_selection.isEmpty())
            clearSelection();
        return;
    }
    if (m_selection.isEmpty())
        return;
    QString why;
    if (!apply(m_selection, &why)) {
        // The edit took the selection away (fewer maps, no real parameter any more).
        clearSelection();
        m_details->setText(why.toHtmlEscaped());
    }
}

} // namespace awb
