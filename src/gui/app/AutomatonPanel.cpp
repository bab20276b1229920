#include "gui/app/AutomatonPanel.h"

#include "gui/views/AutomatonGraph.h"
#include "gui/views/LatestJobWorker.h"
#include "core/analysis/CifsAnalysis.h"
#include "core/ifs/Cifs.h"
#include "model/AutomatonAnalysisJson.h"
#include "model/CifsItem.h"
#include "model/NumberFormat.h"
#include "model/ProjectIO.h"
#include "model/SchemeSpec.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QJsonArray>
#include <QJsonObject>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QScrollArea>
#include <QSpinBox>
#include <QStackedWidget>
#include <QTableWidget>
#include <QTextBrowser>
#include <QVBoxLayout>

#include <cmath>

namespace awb {

namespace {

enum MapForm { FormMatrix, FormAffine, FormScheme };

// The curve schemes whose pieces an arc may take (their file names, as in a curve's "scheme").
const QStringList &schemeKinds()
{
    static const QStringList kinds{"bezier", "bspline", "bspline-end-interpolating", "chaikin",
                                   "four-point"};
    return kinds;
}

// Points of a new state: a regular polygon of `n` points around `centre`.
PointList polygon(int n, const Point &centre, double radius)
{
    PointList out;
    for (int k = 0; k < n; ++k) {
        const double a = M_PI / 2 + 2 * M_PI * k / n;
        out.push_back({centre.x + radius * std::cos(a), centre.y + radius * std::sin(a)});
    }
    return out;
}

} // namespace

AutomatonPanel::AutomatonPanel(QWidget *parent)
    : QWidget(parent), m_worker(std::make_unique<LatestJobWorker>())
{
    auto *layout = new QVBoxLayout(this);
    m_intro = new QLabel(tr("Select a controlled IFS item to see and edit its automaton "
                            "(Item > Add > Controlled IFS, or the example 003 Fig. 5)."));
    m_intro->setWordWrap(true);
    layout->addWidget(m_intro);
    m_body = new QWidget;
    // The editor grows with the arc's matrix: the panel scrolls rather than squeezes it.
    m_scroll = new QScrollArea;
    m_scroll->setWidgetResizable(true);
    m_scroll->setFrameShape(QFrame::NoFrame);
    m_scroll->setWidget(m_body);
    layout->addWidget(m_scroll, 1);
    auto *body = new QVBoxLayout(m_body);
    body->setContentsMargins(0, 0, 0, 0);

    auto *top = new QHBoxLayout;
    top->addWidget(new QLabel(tr("Drawn:")));
    m_drawn = new QComboBox;
    m_drawn->setObjectName(QStringLiteral("automatonDrawn"));
    m_drawn->setToolTip(tr("The state whose attractor is drawn, or the union of all"));
    top->addWidget(m_drawn, 1);
    body->addLayout(top);
    connect(m_drawn, &QComboBox::activated, this, [this](int i) {
        if (m_item)
            setDrawn(i < int(m_item->spec().states.size())
                         ? m_item->spec().states[size_t(i)].name
                         : CifsSpec::allStates);
    });

    m_graph = new AutomatonGraph;
    m_graph->setObjectName(QStringLiteral("automatonGraph"));
    m_graph->setMinimumHeight(280);
    body->addWidget(m_graph, 3);
    connect(m_graph, &AutomatonGraph::stateClicked, this, [this] { showSelection(); });
    connect(m_graph, &AutomatonGraph::arcClicked, this, [this] { showSelection(); });

    auto *buttons = new QGridLayout;
    auto *addStateButton = new QPushButton(tr("Add State"));
    addStateButton->setObjectName(QStringLiteral("automatonAddState"));
    m_newPoints = new QSpinBox;
    m_newPoints->setRange(1, CifsSpec::maxStatePoints);
    m_newPoints->setValue(3);
    m_newPoints->setSuffix(tr(" points"));
    m_newPoints->setToolTip(tr("The new state's number of control points: the dimension of its "
                               "barycentric space (3: a frame triangle)"));
    m_removeState = new QPushButton(tr("Remove State"));
    m_addArc = new QPushButton(tr("Add Arc"));
    m_addArc->setObjectName(QStringLiteral("automatonAddArc"));
    m_addArc->setToolTip(tr("A new arc leaving the selected state (into itself; pick its "
                            "target below)"));
    m_removeArc = new QPushButton(tr("Remove Arc"));
    buttons->addWidget(addStateButton, 0, 0);
    buttons->addWidget(m_newPoints, 0, 1);
    buttons->addWidget(m_removeState, 0, 2);
    buttons->addWidget(m_addArc, 1, 0);
    buttons->addWidget(m_removeArc, 1, 2);
    body->addLayout(buttons);
    connect(addStateButton, &QPushButton::clicked, this,
            [this] { addState(m_newPoints->value()); });
    connect(m_removeState, &QPushButton::clicked, this,
            [this] { removeState(m_graph->selectedState()); });
    connect(m_addArc, &QPushButton::clicked, this, [this] {
        int from = m_graph->selectedState();
        if (from < 0 && m_graph->selectedArc() >= 0 && m_item)
            from = m_item->spec().arcs[size_t(m_graph->selectedArc())].from;
        addArc(std::max(0, from), std::max(0, from));
    });
    connect(m_removeArc, &QPushButton::clicked, this,
            [this] { removeArc(m_graph->selectedArc()); });

    m_editor = new QStackedWidget;
    // Page 0: nothing selected.
    auto *none = new QLabel(tr("Click a state or an arc to edit it."));
    none->setWordWrap(true);
    m_editor->addWidget(none);
    // Page 1: a state.
    auto *statePage = new QWidget;
    auto *stateForm = new QFormLayout(statePage);
    m_stateName = new QLineEdit;
    m_stateName->setObjectName(QStringLiteral("automatonStateName"));
    stateForm->addRow(tr("State name"), m_stateName);
    m_stateInfo = new QLabel;
    m_stateInfo->setWordWrap(true);
    stateForm->addRow(m_stateInfo);
    m_editor->addWidget(statePage);
    connect(m_stateName, &QLineEdit::editingFinished, this, [this] {
        if (!m_rebuilding && m_graph->selectedState() >= 0)
            renameState(m_graph->selectedState(), m_stateName->text());
    });
    // Page 2: an arc.
    auto *arcPage = new QWidget;
    auto *arcForm = new QFormLayout(arcPage);
    m_arcName = new QLineEdit;
    m_arcName->setObjectName(QStringLiteral("automatonArcName"));
    arcForm->addRow(tr("Arc name"), m_arcName);
    auto *ends = new QHBoxLayout;
    m_from = new QComboBox;
    m_to = new QComboBox;
    m_from->setObjectName(QStringLiteral("automatonArcFrom"));
    m_to->setObjectName(QStringLiteral("automatonArcTo"));
    ends->addWidget(m_from, 1);
    ends->addWidget(new QLabel(QStringLiteral("→")));
    ends->addWidget(m_to, 1);
    arcForm->addRow(tr("From → to"), ends);
    m_weight = new QDoubleSpinBox;
    m_weight->setDecimals(6);
    m_weight->setRange(1e-6, 1e6);
    m_weight->setToolTip(tr("The arc's relative probability among the arcs leaving its state "
                            "(random iteration)"));
    arcForm->addRow(tr("Weight"), m_weight);
    m_mapForm = new QComboBox;
    m_mapForm->setObjectName(QStringLiteral("automatonMapForm"));
    m_mapForm->addItems({tr("Matrix S (rows sum to 1)"), tr("Plane affine map"),
                         tr("Piece of a curve scheme")});
    arcForm->addRow(tr("Map"), m_mapForm);
    m_mapPages = new QStackedWidget;
    // Matrix.
    auto *matrixPage = new QWidget;
    auto *matrixLayout = new QVBoxLayout(matrixPage);
    matrixLayout->setContentsMargins(0, 0, 0, 0);
    m_matrix = new QTableWidget;
    m_matrix->setObjectName(QStringLiteral("automatonMatrix"));
    m_matrix->horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
    m_matrix->setMinimumHeight(90);
    m_matrix->setToolTip(tr("S: a row per control point of the target state, a column per "
                            "control point of the source; numbers like 1/3 are read exactly"));
    auto *applyMatrix = new QPushButton(tr("Apply Matrix"));
    applyMatrix->setObjectName(QStringLiteral("automatonApplyMatrix"));
    matrixLayout->addWidget(m_matrix);
    matrixLayout->addWidget(applyMatrix);
    m_mapPages->addWidget(matrixPage);
    connect(applyMatrix, &QPushButton::clicked, this, [this] { applyMatrixTable(); });
    // Affine.
    auto *affinePage = new QWidget;
    auto *affine = new QGridLayout(affinePage);
    affine->setContentsMargins(0, 0, 0, 0);
    const char *labels[6] = {"a₁₁", "a₁₂", "a₂₁", "a₂₂", "b₁", "b₂"};
    for (int k = 0; k < 6; ++k) {
        m_affine[k] = new QLineEdit(k == 0 || k == 3 ? QStringLiteral("0.5") : QStringLiteral("0"));
        affine->addWidget(new QLabel(QString::fromUtf8(labels[k])), k / 2, 2 * (k % 2));
        affine->addWidget(m_affine[k], k / 2, 2 * (k % 2) + 1);
    }
    auto *applyAffineButton = new QPushButton(tr("Apply Affine Map"));
    affine->addWidget(applyAffineButton, 3, 0, 1, 4);
    auto *affineNote = new QLabel(tr("x ↦ x A + b, taking the target state's frame triangle "
                                     "into the plane of the source's; kept as its matrix"));
    affineNote->setWordWrap(true);
    affine->addWidget(affineNote, 4, 0, 1, 4);
    m_mapPages->addWidget(affinePage);
    connect(applyAffineButton, &QPushButton::clicked, this, [this] { applyAffine(); });
    // Scheme.
    auto *schemePage = new QWidget;
    auto *scheme = new QFormLayout(schemePage);
    scheme->setContentsMargins(0, 0, 0, 0);
    m_schemeKind = new QComboBox;
    m_schemeKind->addItems({tr("Bézier (de Casteljau at 1/2)"), tr("Uniform B-spline"),
                            tr("End-interpolating B-spline"), tr("Chaikin"),
                            tr("Four-point")});
    m_schemeDegree = new QSpinBox;
    m_schemeDegree->setRange(1, 20);
    m_schemePiece = new QSpinBox;
    m_schemePiece->setRange(1, 16);
    scheme->addRow(tr("Scheme"), m_schemeKind);
    scheme->addRow(tr("Degree"), m_schemeDegree);
    scheme->addRow(tr("Piece S_i, i ="), m_schemePiece);
    auto *applySchemeButton = new QPushButton(tr("Apply Scheme Piece"));
    scheme->addRow(applySchemeButton);
    m_mapPages->addWidget(schemePage);
    connect(applySchemeButton, &QPushButton::clicked, this, [this] { applyScheme(); });
    connect(m_mapForm, &QComboBox::currentIndexChanged, m_mapPages,
            &QStackedWidget::setCurrentIndex);
    arcForm->addRow(m_mapPages);
    m_mapNote = new QLabel;
    m_mapNote->setWordWrap(true);
    arcForm->addRow(m_mapNote);
    m_editor->addWidget(arcPage);
    m_editor->setSizePolicy(QSizePolicy::Preferred, QSizePolicy::Maximum);
    body->addWidget(m_editor);
    connect(m_arcName, &QLineEdit::editingFinished, this, [this] {
        if (!m_rebuilding && m_graph->selectedArc() >= 0)
            renameArc(m_graph->selectedArc(), m_arcName->text());
    });
    const auto ends_ = [this] {
        if (!m_rebuilding && m_graph->selectedArc() >= 0)
            setArcStates(m_graph->selectedArc(), m_from->currentIndex(), m_to->currentIndex());
    };
    connect(m_from, &QComboBox::activated, this, ends_);
    connect(m_to, &QComboBox::activated, this, ends_);
    connect(m_weight, &QDoubleSpinBox::editingFinished, this, [this] {
        if (!m_rebuilding && m_graph->selectedArc() >= 0)
            setArcWeight(m_graph->selectedArc(), m_weight->value());
    });

    m_analysis = new QTextBrowser;
    m_analysis->setObjectName(QStringLiteral("automatonAnalysis"));
    m_analysis->setPlaceholderText(tr("The analysis of a controlled IFS item: its constrained "
                                      "joint spectral radius, its cycles' spectra and the "
                                      "Lyapunov exponent of random iteration."));
    m_summary = new QLabel;
    m_summary->setObjectName(QStringLiteral("automatonSummary"));
    m_summary->setWordWrap(true);
    m_summary->setTextInteractionFlags(Qt::TextSelectableByMouse);
    body->addWidget(m_summary);
    setItem(nullptr);
}

AutomatonPanel::~AutomatonPanel()
{
    m_worker.reset(); // its job may still post here
    if (m_analysis && !m_analysis->parent())
        delete m_analysis;
}

QWidget *AutomatonPanel::analysisView() const { return m_analysis; }

void AutomatonPanel::setItem(Item *item)
{
    auto *cifs = qobject_cast<CifsItem *>(item);
    if (cifs == m_item && (cifs || m_scroll->isHidden()))
        return;
    if (m_item)
        disconnect(m_item, nullptr, this, nullptr);
    m_item = cifs;
    m_intro->setVisible(!cifs);
    m_scroll->setVisible(cifs);
    if (!cifs)
        m_analysis->clear();
    if (cifs) {
        connect(cifs, &CifsItem::specChanged, this, [this] { rebuild(); });
        m_graph->selectState(-1);
        m_graph->selectArc(-1);
    }
    rebuild();
}

void AutomatonPanel::rebuild()
{
    if (!m_item)
        return;
    m_rebuilding = true;
    const CifsSpec &s = m_item->spec();
    std::vector<AutomatonGraph::State> states;
    for (const CifsStateSpec &q : s.states)
        states.push_back({q.name, int(q.points.size()),
                          s.drawn == CifsSpec::allStates || s.drawn == q.name});
    std::vector<AutomatonGraph::Arc> arcs;
    for (const CifsArcSpec &a : s.arcs)
        arcs.push_back({a.name, a.from, a.to});
    m_graph->setAutomaton(std::move(states), std::move(arcs));
    m_drawn->clear();
    m_drawn->addItems(s.stateNames() << tr("All states"));
    m_drawn->setCurrentIndex(s.drawn == CifsSpec::allStates ? int(s.states.size())
                                                            : s.stateIndex(s.drawn));
    m_rebuilding = false;
    showSelection();
    analyse();
}

void AutomatonPanel::analyse()
{
    // The bounds take up to a second or two: on the worker, the latest automaton only.
    const CifsSpec spec = m_item->spec();
    const QString name = m_item->name();
    const int generation = ++m_generation;
    m_summary->setText(tr("Analysing the automaton…"));
    m_worker->post([this, spec, name, generation](const std::atomic<bool> &cancel) {
        QStringList lines, all;
        try {
            CifsAnalysisOptions o;
            o.cancel = &cancel;
            const CifsAnalysis a = analyseCifs(spec.toCore(), o);
            if (a.cancelled)
                return;
            lines = automatonSummary(spec, a, 0);
            all = automatonSummary(spec, a, 200);
        } catch (const std::exception &e) {
            lines = all = QStringList{QString::fromStdString(e.what())};
        }
        QMetaObject::invokeMethod(
            this,
            [this, lines, all, name, generation] {
                if (generation != m_generation)
                    return;
                m_summary->setText(lines.join(QLatin1Char('\n')));
                QString html = QStringLiteral("<h3>%1</h3><ul>")
                                   .arg(tr("Automaton of %1").arg(name).toHtmlEscaped());
                for (const QString &line : all)
                    html += QStringLiteral("<li>%1</li>").arg(line.toHtmlEscaped());
                m_analysis->setHtml(html + QStringLiteral("</ul>"));
                emit analysed();
            },
            Qt::QueuedConnection);
    });
}

void AutomatonPanel::showSelection()
{
    if (!m_item)
        return;
    m_rebuilding = true;
    const CifsSpec &s = m_item->spec();
    const int state = m_graph->selectedState(), arc = m_graph->selectedArc();
    m_removeState->setEnabled(state >= 0 && s.states.size() > 1);
    m_removeArc->setEnabled(arc >= 0);
    if (state >= 0) {
        const CifsStateSpec &q = s.states[size_t(state)];
        m_stateName->setText(q.name);
        int in = 0, out = 0;
        for (const CifsArcSpec &a : s.arcs) {
            in += a.to == state;
            out += a.from == state;
        }
        m_stateInfo->setText(tr("%1 control points (its barycentric space), %2 arcs leave it, "
                                "%3 arrive. Drag its control points in the attractor view.")
                                 .arg(q.points.size()).arg(out).arg(in));
        m_editor->setCurrentIndex(1);
    } else if (arc >= 0) {
        const CifsArcSpec &a = s.arcs[size_t(arc)];
        m_arcName->setText(a.name);
        m_from->clear();
        m_to->clear();
        m_from->addItems(s.stateNames());
        m_to->addItems(s.stateNames());
        m_from->setCurrentIndex(a.from);
        m_to->setCurrentIndex(a.to);
        m_weight->setValue(a.weight);
        m_matrix->clear();
        m_matrix->setRowCount(int(a.S.rows()));
        m_matrix->setColumnCount(int(a.S.cols()));
        for (int r = 0; r < a.S.rows(); ++r)
            for (int c = 0; c < a.S.cols(); ++c)
                m_matrix->setItem(r, c, new QTableWidgetItem(exactText(a.S(r, c))));
        m_matrix->setFixedHeight(std::min(420, 32 + 30 * int(a.S.rows())));
        const int n = int(a.S.cols());
        m_schemeDegree->setValue(std::max(1, n - 1));
        m_mapNote->setText(tr("S is %1 × %2: a row per point of %3, a column per point of %4. "
                              "It maps the space of %3 into that of %4.")
                               .arg(a.S.rows()).arg(a.S.cols())
                               .arg(s.states[size_t(a.to)].name, s.states[size_t(a.from)].name));
        m_editor->setCurrentIndex(2);
    } else {
        m_editor->setCurrentIndex(0);
    }
    m_rebuilding = false;
}

void AutomatonPanel::selectState(int state)
{
    m_graph->selectState(state);
    showSelection();
}

void AutomatonPanel::selectArc(int arc)
{
    m_graph->selectArc(arc);
    showSelection();
}

bool AutomatonPanel::apply(const CifsSpec &spec, QString *error)
{
    QString why;
    if (!m_item)
        why = tr("no controlled IFS item is selected");
    else if (m_item->setSpec(spec, 0, &why))
        return true;
    if (error)
        *error = why;
    emit problem(why);
    return false;
}

bool AutomatonPanel::addState(int points, QString *error)
{
    if (!m_item)
        return apply({}, error);
    CifsSpec s = m_item->spec();
    // Around the selected state's points (or the first state's), a little aside.
    const int near = std::max(0, m_graph->selectedState());
    const PointList &ref = s.states[size_t(near)].points;
    Point c{0, 0};
    double extent = 1.0;
    for (const Point &p : ref) {
        c.x += p.x / double(ref.size());
        c.y += p.y / double(ref.size());
    }
    for (const Point &p : ref)
        extent = std::max(extent, std::hypot(p.x - c.x, p.y - c.y));
    s.states.push_back({s.freshStateName(),
                        points == int(ref.size()) ? ref : polygon(points, c, extent)});
    if (!apply(s, error))
        return false;
    selectState(int(s.states.size()) - 1);
    return true;
}

bool AutomatonPanel::removeState(int state, QString *error)
{
    if (!m_item || state < 0 || state >= int(m_item->spec().states.size()))
        return apply({}, error);
    CifsSpec s = m_item->spec();
    const QString name = s.states[size_t(state)].name;
    s.states.erase(s.states.begin() + state);
    std::vector<CifsArcSpec> arcs;
    for (CifsArcSpec a : s.arcs) {
        if (a.from == state || a.to == state)
            continue;
        a.from -= a.from > state;
        a.to -= a.to > state;
        arcs.push_back(std::move(a));
    }
    s.arcs = std::move(arcs);
    if (s.drawn == name)
        s.drawn = s.states.empty() ? CifsSpec::allStates : s.states.front().name;
    if (!apply(s, error))
        return false;
    selectState(-1);
    return true;
}

bool AutomatonPanel::renameState(int state, const QString &name, QString *error)
{
    if (!m_item)
        return apply({}, error);
    CifsSpec s = m_item->spec();
    const QString old = s.states.at(size_t(state)).name;
    if (old == name.trimmed())
        return true;
    s.states[size_t(state)].name = name.trimmed();
    if (s.drawn == old)
        s.drawn = name.trimmed();
    if (apply(s, error))
        return true;
    showSelection(); // back to the name it has
    return false;
}

bool AutomatonPanel::addArc(int from, int to, QString *error)
{
    if (!m_item)
        return apply({}, error);
    CifsSpec s = m_item->spec();
    int leaving = 0;
    for (const CifsArcSpec &a : s.arcs)
        leaving += a.from == from;
    const int nTo = int(s.states.at(size_t(to)).points.size());
    const int nFrom = int(s.states.at(size_t(from)).points.size());
    s.arcs.push_back({s.freshArcName(), from, to, CifsSpec::defaultArcMatrix(nTo, nFrom, leaving),
                      1.0});
    if (!apply(s, error))
        return false;
    selectArc(int(s.arcs.size()) - 1);
    return true;
}

bool AutomatonPanel::removeArc(int arc, QString *error)
{
    if (!m_item || arc < 0 || arc >= int(m_item->spec().arcs.size()))
        return apply({}, error);
    CifsSpec s = m_item->spec();
    s.arcs.erase(s.arcs.begin() + arc);
    if (!apply(s, error))
        return false;
    selectArc(-1);
    return true;
}

bool AutomatonPanel::renameArc(int arc, const QString &name, QString *error)
{
    if (!m_item)
        return apply({}, error);
    CifsSpec s = m_item->spec();
    if (s.arcs.at(size_t(arc)).name == name.trimmed())
        return true;
    s.arcs[size_t(arc)].name = name.trimmed();
    if (apply(s, error))
        return true;
    showSelection();
    return false;
}

bool AutomatonPanel::setArcStates(int arc, int from, int to, QString *error)
{
    if (!m_item)
        return apply({}, error);
    CifsSpec s = m_item->spec();
    CifsArcSpec &a = s.arcs.at(size_t(arc));
    if (a.from == from && a.to == to)
        return true;
    a.from = from;
    a.to = to;
    const int nTo = int(s.states.at(size_t(to)).points.size());
    const int nFrom = int(s.states.at(size_t(from)).points.size());
    if (a.S.rows() != nTo || a.S.cols() != nFrom)
        a.S = CifsSpec::defaultArcMatrix(nTo, nFrom, 0);
    if (apply(s, error))
        return true;
    showSelection();
    return false;
}

bool AutomatonPanel::setArcWeight(int arc, double weight, QString *error)
{
    if (!m_item)
        return apply({}, error);
    CifsSpec s = m_item->spec();
    if (s.arcs.at(size_t(arc)).weight == weight)
        return true;
    s.arcs[size_t(arc)].weight = weight;
    return apply(s, error);
}

bool AutomatonPanel::setArcMatrix(int arc, const Mat &S, QString *error)
{
    if (!m_item)
        return apply({}, error);
    CifsSpec s = m_item->spec();
    s.arcs.at(size_t(arc)).S = S;
    return apply(s, error);
}

bool AutomatonPanel::setArcMap(int arc, const QJsonObject &map, QString *error)
{
    if (!m_item)
        return apply({}, error);
    const CifsSpec &s = m_item->spec();
    const CifsArcSpec &a = s.arcs.at(size_t(arc));
    try {
        return setArcMatrix(arc,
                            cifsArcMatrixFromJson(map, s.states[size_t(a.from)],
                                                  s.states[size_t(a.to)], QString()),
                            error);
    } catch (const LoadError &e) {
        const QString why = e.field.isEmpty() ? e.message : e.field + QStringLiteral(": ") + e.message;
        if (error)
            *error = why;
        emit problem(why);
        return false;
    }
}

bool AutomatonPanel::setDrawn(const QString &state, QString *error)
{
    if (!m_item)
        return apply({}, error);
    CifsSpec s = m_item->spec();
    s.drawn = state;
    return s == m_item->spec() || apply(s, error);
}

void AutomatonPanel::applyMatrixTable()
{
    const int arc = m_graph->selectedArc();
    if (!m_item || arc < 0)
        return;
    Mat S(m_matrix->rowCount(), m_matrix->columnCount());
    for (int r = 0; r < S.rows(); ++r)
        for (int c = 0; c < S.cols(); ++c) {
            const QTableWidgetItem *cell = m_matrix->item(r, c);
            const auto x = parseNumber(cell ? cell->text() : QString());
            if (!x) {
                emit problem(tr("row %1, column %2 of the matrix is not a number: %3")
                                 .arg(r + 1).arg(c + 1)
                                 .arg(cell ? cell->text() : QString()));
                return;
            }
            S(r, c) = *x;
        }
    setArcMatrix(arc, S);
}

void AutomatonPanel::applyAffine()
{
    const int arc = m_graph->selectedArc();
    if (!m_item || arc < 0)
        return;
    double v[6];
    for (int k = 0; k < 6; ++k) {
        const auto x = parseNumber(m_affine[k]->text());
        if (!x) {
            emit problem(tr("%1 is not a number").arg(m_affine[k]->text()));
            return;
        }
        v[k] = *x;
    }
    setArcMap(arc, QJsonObject{{"affine", QJsonObject{{"A", QJsonArray{QJsonArray{v[0], v[1]},
                                                                         QJsonArray{v[2], v[3]}}},
                                                      {"b", QJsonArray{v[4], v[5]}}}}});
}

void AutomatonPanel::applyScheme()
{
    const int arc = m_graph->selectedArc();
    if (!m_item || arc < 0)
        return;
    QJsonObject scheme{{"kind", schemeKinds().at(m_schemeKind->currentIndex())}};
    if (m_schemeKind->currentIndex() <= 2)
        scheme["degree"] = m_schemeDegree->value();
    setArcMap(arc, QJsonObject{{"scheme", scheme}, {"piece", m_schemePiece->value()}});
}

} // namespace awb
