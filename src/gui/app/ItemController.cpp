#include "gui/app/ItemController.h"

#include "gui/views/BackgroundPriority.h"

#include "core/ifs/Attractor.h"
#include "core/ifs/SurfaceIfs.h"
#include "core/analysis/Geometry.h"
#include "core/schemes/Scheme.h"
#include "core/analysis/Spectrum.h"
#include "gui/app/FrameBudget.h"
#include "gui/views/AnalysisCharts.h"
#include "gui/views/AttractorView.h"
#include "gui/views/MatrixView.h"
#include "gui/views/RegularityPanel.h"
#include "model/NumberFormat.h"
#include "gui/views/SpectrumView.h"
#include "gui/views/SurfaceView.h"
#include "model/AttractorItem.h"
#include "model/EigenvaluePlotItem.h"
#include "model/ExactCurve.h"
#include "model/Project.h"
#include "model/SubdivisionCurveItem.h"
#include "model/SubdivisionSurfaceItem.h"
#include "model/SubdivisionMeshItem.h"

#include <QColor>
#include <QJsonDocument>
#include <QJsonObject>
#include <QMenu>
#include <algorithm>
#include <cmath>

namespace awb {


namespace {

QList<MapSpectrum> mapSpectra(const DerivedIfs &d)
{
    QList<MapSpectrum> maps;
    const auto contractivityOf = [&](int i) {
        if (int(d.A.real.size()) > i)
            return contractivity(d.A.real[std::size_t(i)]);
        if (int(d.A.complex.size()) > i)
            return contractivity(d.A.complex[std::size_t(i)]);
        if (i < d.ifs.size())
            return contractivity(d.ifs.effectiveLinearPart(i));
        // Automata list their row-stochastic arc matrices in S but have no plain maps.
        return ItemController::stochasticContractivity(d.S.real.at(std::size_t(i)));
    };
    if (!d.S.real.empty() || !d.S.complex.empty()) {
        for (int i = 0; i < d.S.count(); ++i) {
            MapSpectrum m;
            m.label = QStringLiteral("S_%1").arg(i + 1);
            m.spectrum = d.S.isComplex() ? spectrum(d.S.complex[std::size_t(i)])
                                         : spectrum(d.S.real[std::size_t(i)]);
            m.subdominant = subdominant(m.spectrum, true);
            m.contractivity = contractivityOf(i);
            maps.append(m);
        }
    } else {
        for (int i = 0; i < d.ifs.size(); ++i) {
            MapSpectrum m;
            m.label = QStringLiteral("A_%1").arg(i + 1);
            m.spectrum = spectrum(d.ifs.effectiveLinearPart(i));
            m.subdominant = subdominant(m.spectrum, false);
            m.contractivity = contractivityOf(i);
            maps.append(m);
        }
    }
    return maps;
}

} // namespace

namespace {

// The matrices an eigenvalue plot analyses, named by its symbol (S_i, A_i or M_i).
QList<NamedMatrix> plotMatrices(const EigenvalueData &data)
{
    QList<NamedMatrix> list;
    const AnalysisMatrices &m = data.matrices;
    const bool lifted = data.symbol == QLatin1String("M");
    for (int i = 0; i < m.count(); ++i) {
        const QString name = QStringLiteral("%1_%2").arg(data.symbol).arg(i + 1);
        if (m.isComplex()) {
            const CMat &M = m.complex[std::size_t(i)];
            list.append({name, M, lifted ? int(M.rows()) - 1 : -1});
        } else {
            const Mat &M = m.real[std::size_t(i)];
            list.append({name, M, lifted ? int(M.rows()) - 1 : -1, false});
        }
    }
    return list;
}

} // namespace

std::shared_ptr<const CurveScheme> ItemController::realScheme(const Item *item)
{
    const auto *curve = qobject_cast<const SubdivisionCurveItem *>(item);
    if (!curve || curve->scheme().isComplex())
        return nullptr;
    try {
        return std::shared_ptr<const CurveScheme>(curve->scheme().makeScheme());
    } catch (const std::exception &) {
        return nullptr;
    }
}

ItemController::ItemController(AttractorView *attractor, MatrixView *matrices,
                               SpectrumView *spectrum, AnalysisCharts *charts,
                               FrameBudget *budget, QObject *parent)
    : QObject(parent), m_attractor(attractor), m_matrices(matrices), m_spectrum(spectrum),
      m_charts(charts), m_budget(budget ? budget : new FrameBudget(this))
{
    m_refreshTimer.setSingleShot(true);
    m_refreshTimer.setInterval(0);
    connect(&m_refreshTimer, &QTimer::timeout, this, &ItemController::refreshViews);
    // The docks beside the view: coalesced during gestures (FrameBudget).
    m_matricesPanel = m_budget->addPanel(m_matrices, [this] { showMatrices(); });
    m_spectrumPanel = m_budget->addPanel(m_spectrum, [this] { showSpectrum(); });
    m_chartsPanel = m_budget->addPanel(m_charts, [this] { showCharts(); });
    connect(m_budget, &FrameBudget::gestureChanged, this, [this](bool active) {
        m_attractor->setGestureActive(active);
        if (m_surface)
            m_surface->setGestureActive(active);
    });
    // The analysis waits until a drag pauses: it is the slow part.
    m_analysisTimer.setSingleShot(true);
    m_analysisTimer.setInterval(250);
    connect(&m_analysisTimer, &QTimer::timeout, this, &ItemController::startAnalysis);

    connect(m_attractor, &AttractorView::controlPointPressed, this,
            &ItemController::onControlPressed);
    connect(m_attractor, &AttractorView::controlPointDragged, this,
            &ItemController::onControlDragged);
    connect(m_attractor, &AttractorView::controlPointReleased, this,
            &ItemController::onControlReleased);
    connect(m_attractor, &AttractorView::startVertexPressed, this,
            &ItemController::onStartPressed);
    connect(m_attractor, &AttractorView::startVertexDragged, this,
            &ItemController::onStartDragged);
    connect(m_attractor, &AttractorView::startVertexReleased, this,
            &ItemController::onStartReleased);
    connect(m_matrices, &MatrixView::cellEdited, this, &ItemController::onCellEdited);
    connect(m_matrices, &MatrixView::addMapRequested, this, [this] { onMapCountEdited(-1); });
    connect(m_matrices, &MatrixView::removeMapRequested, this,
            &ItemController::onMapCountEdited);
    connect(m_attractor, &AttractorView::controlEdgeDoubleClicked, this,
            &ItemController::onEdgeDoubleClicked);
    connect(m_attractor, &AttractorView::contextMenuRequested, this,
            [this](const QPointF &screen, const QPoint &global) {
                QMenu menu(m_attractor);
                fillContextMenu(&menu, screen);
                menu.exec(global);
            });
}

Contractivity ItemController::stochasticContractivity(const Mat &S)
{
    // S acts on barycentric coordinates: restrict it to the sum-preserving part.
    Ifs arc;
    arc.maps.push_back({S, RowVec::Zero(S.rows())});
    arc.barycentricBlocks.push_back({0, int(S.rows())});
    return contractivity(arc.effectiveLinearPart(0));
}

ItemController::~ItemController()
{
    cancelAnalysis();
}

void ItemController::setItem(Item *item)
{
    for (const auto &c : m_connections)
        disconnect(c);
    m_connections.clear();
    m_item = item;
    m_frame.reset();
    endGesture();
    m_highlightedMap = -1;
    if (m_focusedVertex != -1) {
        m_focusedVertex = -1;
        if (m_surface)
            m_surface->setSelectedMarker(-1);
        emit focusedVertexChanged(-1);
    }
    if (item) {
        m_connections << connect(item, &Item::derivedChanged, this,
                                 &ItemController::scheduleRefresh);
        m_connections << connect(item, &Item::changed, this, &ItemController::scheduleRefresh);
    }
    // An eigenvalue plot draws its source: follow that item's edits (and a new source).
    if (qobject_cast<EigenvaluePlotItem *>(item) && item->project()) {
        const auto follow = [this](Item *changed) {
            if (changed && changed == drawnItem())
                scheduleRefresh();
        };
        m_connections << connect(item->project(), &Project::itemChanged, this, follow);
        m_connections << connect(item->project(), &Project::itemDerivedChanged, this, follow);
    }
    m_attractor->setAutoFit(true);
    refreshNow();
    m_attractor->fitToContents();
    if (m_surface && showsSurface())
        m_surface->resetCamera();
}

bool ItemController::showsSurface() const
{
    const AttractorItem *item = drawnItem();
    return m_surface && item && item->pointDimension() == 3;
}

void ItemController::showFrame(std::shared_ptr<Item> frame)
{
    if (frame && !m_frame)
        m_attractor->setAutoFit(false); // a moving attractor in a steady frame
    m_frame = std::move(frame);
    endGesture();
    refreshViews();
}

AttractorItem *ItemController::drawnItem() const
{
    if (m_frame)
        return qobject_cast<AttractorItem *>(m_frame.get());
    if (const auto *plot = qobject_cast<const EigenvaluePlotItem *>(m_item.data()))
        return plot->project() ? qobject_cast<AttractorItem *>(
                   plot->project()->findItem(plot->source()))
                               : nullptr;
    return qobject_cast<AttractorItem *>(m_item.data());
}

void ItemController::setSurfaceView(SurfaceView *view)
{
    m_surface = view;
    if (!view)
        return;
    connect(view, &SurfaceView::markerClicked, this, &ItemController::setFocusedVertex);
    connect(view, &SurfaceView::controlPointPressed, this, &ItemController::onSurfacePressed);
    connect(view, &SurfaceView::controlPointDragged, this, &ItemController::onControlDragged3D);
    connect(view, &SurfaceView::controlPointReleased, this,
            [this](int index, const QVector3D &start, const QVector3D &end) {
                if (start != end)
                    onControlDragged3D(index, end);
                endGesture();
                scheduleRefresh(); // the docks skipped during the drag
            });
    // The direction the user turned the view to becomes the item's camera (one undo step):
    // the Properties dock, exports and attractor-cli render look from there too.
    connect(view, &SurfaceView::cameraTurned, this, [this](double azimuth, double elevation) {
        auto *surface = qobject_cast<SubdivisionSurfaceItem *>(m_item.data());
        if (!surface || m_frame || !surface->project())
            return;
        Project *project = surface->project();
        const int turn = project->beginGesture();
        surface->setParameter(QStringLiteral("camera.azimuth"), azimuth, turn);
        surface->setParameter(QStringLiteral("camera.elevation"), elevation, turn);
        project->endGesture(turn);
    });
    connect(view, &SurfaceView::startVertexPressed, this, &ItemController::onSurfacePressed);
    connect(view, &SurfaceView::startVertexDragged, this, &ItemController::onStartDragged3D);
    connect(view, &SurfaceView::startVertexReleased, this,
            [this](int index, const QVector3D &start, const QVector3D &end) {
                if (start != end)
                    onStartDragged3D(index, end);
                endGesture();
                scheduleRefresh();
            });
}

// The derived data the docks show: of the drawn item, or nothing.
std::shared_ptr<const DerivedIfs> ItemController::drawnDerived() const
{
    AttractorItem *item = drawnItem();
    return item ? item->derivedIfs() : nullptr;
}

QList<MapSpectrum> ItemController::currentSpectra() const
{
    const auto d = drawnDerived();
    if (!d)
        return {};
    if (QList<MapSpectrum> vertex = focusedSpectra(); !vertex.isEmpty())
        return vertex;
    QList<MapSpectrum> spectra = mapSpectra(*d);
    const auto *plot = qobject_cast<const EigenvaluePlotItem *>(m_item.data());
    if (!plot)
        return spectra;
    // The plot's own choice of matrices; the verdicts on contractivity stay the maps'.
    const auto data = plot->eigenvalues();
    QList<MapSpectrum> chosen;
    for (std::size_t i = 0; data && i < data->spectra.size(); ++i) {
        MapSpectrum m = int(i) < spectra.size() ? spectra[int(i)] : MapSpectrum{};
        m.label = QStringLiteral("%1_%2").arg(data->symbol).arg(i + 1);
        m.spectrum = data->spectra[i];
        m.subdominant = data->subdominants[i];
        chosen.append(m);
    }
    return chosen;
}

void ItemController::showMatrices()
{
    const auto d = drawnDerived();
    const auto *plot = qobject_cast<const EigenvaluePlotItem *>(m_item.data());
    if (!d) {
        m_matrices->setMatrices({});
    } else if (QList<NamedMatrix> vertex = focusedMatrices(); !vertex.isEmpty()) {
        m_matrices->setEditable(false);
        m_matrices->setMatrices(vertex);
    } else if (plot) {
        const auto data = plot->eigenvalues();
        m_matrices->setEditable(false);
        m_matrices->setMatrices(data ? plotMatrices(*data) : QList<NamedMatrix>{});
    } else {
        const auto *curve = qobject_cast<const SubdivisionCurveItem *>(drawnItem());
        const bool editable = curve && curve->scheme().kind == SchemeSpec::Kind::Matrices
                              && !m_frame && !showsSurface();
        m_matrices->setEditable(editable);
        m_matrices->setMatrices(namedMatrices(*d, editable));
    }
}

void ItemController::showSpectrum()
{
    const QList<MapSpectrum> spectra = currentSpectra();
    // Whether an IFS with a map that does not contract contracts on average (a flame).
    std::optional<double> lyapunov;
    const auto d = drawnDerived();
    const bool contractive = std::all_of(spectra.begin(), spectra.end(), [](const auto &m) {
        return m.contractivity.eventuallyContractive;
    });
    if (d && d->chaos) {
        lyapunov = d->chaos.lyapunovExponent();  // a flame: along its own orbit
    } else if (!contractive && d && d->ifs.size() > 0 && !d->iterate
               && focusedSpectra().isEmpty()) {
        try {
            lyapunov = checkIfs(d->ifs).lyapunov;
        } catch (const std::exception &) {
        }
    }
    m_spectrum->setLyapunovExponent(lyapunov);
    m_spectrum->setAffineParts(d && d->chaos && focusedSpectra().isEmpty());
    m_spectrum->setMaps(spectra);
}

void ItemController::showCharts()
{
    QList<AnalysisCharts::MapModuli> moduli;
    for (const MapSpectrum &m : currentSpectra()) {
        AnalysisCharts::MapModuli mm{m.label, {}};
        for (const Complex &z : m.spectrum.values)
            mm.moduli.push_back(std::abs(z));
        moduli.append(mm);
    }
    m_charts->setModuli(moduli);
    updateRegularity();
    // The distances and dimensions of a curve (the slow part) wait until edits pause. A
    // surface has no exact curve to measure against: its charts say so, not the last curve's.
    if (drawnDerived() && !showsSurface()) {
        // What runs or waits in the inbox measures the data before this refresh (or another
        // item): dropped when it arrives, and its worker told to stop. (Joined by the next
        // start, not here: the GUI thread does not wait. Without this, a slow analysis of the
        // item shown before File > Open filled the charts of the opened one.)
        ++m_analysisTicket;
        m_cancel = true;
        m_analysisTimer.start();
    } else {
        cancelAnalysis();
        m_charts->setDistances({});
        m_charts->setPolygonLengths({});
        m_charts->setBoxCounting(BoxDimension{});
    }
}

void ItemController::refreshSurface(AttractorItem *item, const DerivedIfs &d)
{
    // The 2D view shows nothing of a surface; the 3D view gets the IFS, the net, the start
    // set and the classic route (the net after k rounds).
    m_attractor->setIfs(nullptr, StartSet{});
    m_attractor->setControlPolygons({});
    m_attractor->setExactCurve(Mat());
    m_attractor->setSubdivisionPolygons({});
    SurfaceView::RenderSettings rs = m_surface->renderSettings();
    rs.depth = m_maxDepth > 0 ? std::min(item->algorithm().depth, m_maxDepth)
                              : item->algorithm().depth;
    rs.colouring = attractorColouring(item->style());
    rs.pointSize = item->style().pointSize;
    if (rs.colouring.palette.isEmpty())
        rs.colouring.palette = m_palette;
    m_surface->setRenderSettings(rs);
    m_surface->setControlPointsEditable(item == m_item.data()); // a plot's source is only shown
    const Mat P = toMatrix(item->controlPoints(0), 3);
    std::vector<std::vector<int>> faces;
    std::vector<SharpEdge> sharp;
    std::vector<int> holes;
    Mat mesh;
    std::vector<std::vector<int>> meshFaces;
    OwnIteration own;
    if (const auto *meshItem = qobject_cast<const SubdivisionMeshItem *>(item)) {
        // The control mesh, and the pieces' own iteration (its identity: the derived data,
        // recomputed on every edit).
        faces = meshItem->inputs().faces;
        sharp = meshItem->inputs().tags.edges;
        holes = meshItem->inputs().tags.holes;
        showMeshMarkers(meshItem);
        own.iterate = d.iterate;
        own.pointCount = d.pointCount;
        own.identity = item->derivedIfs();
    } else if (const auto *surface = qobject_cast<const SubdivisionSurfaceItem *>(item)) {
        // The item's saved view (also the CLI's default camera) is where Home looks from.
        m_surface->setHomeDirection(surface->camera().azimuth, surface->camera().elevation);
        try {
            faces = surface->refinedMesh(0).faces;
            if (surface->meshRounds() > 0) {
                const LatticeMesh refined = surface->refinedMesh(surface->meshRounds());
                mesh = refined.points;
                meshFaces = refined.faces;
            }
        } catch (const std::exception &) {
            // No net faces: the handles still show (and move) the points.
        }
    }
    if (!qobject_cast<const SubdivisionMeshItem *>(item))
        m_surface->setMarkers({});
    m_surface->setControlNet(P, faces, std::move(sharp), std::move(holes));
    m_surface->setRefinedNet(mesh, meshFaces);
    m_surface->setStartVertices(toMatrix(item->startSet().points, 3));
    // A lattice surface is drawn from its net linearly: a net point's drag moves the mesh.
    m_surface->setNetCoordinates(d.surface ? d.surface->ifs.netCoordinates() : Projection{});
    m_surface->setStartFollowsNet(item->startSet().kind == StartSetSpec::Kind::Net);
    // Its corner limits tile it: the coarse meshes of a gesture are a closed surface.
    m_surface->setTilingStart(d.surface && d.surface->cornerLimitStart.rows() >= 3
                                  ? StartSet::polygon(d.surface->cornerLimitStart)
                                  : StartSet{});
    try {
        m_surface->setIfs(std::make_shared<const Ifs>(d.ifs), item->coreStartSet(d), d.mapIndex,
                          own);
    } catch (const std::exception &) {
        m_surface->setIfs(nullptr, StartSet{});
    }
}

void ItemController::setHighlightedMap(int map)
{
    if (map == m_highlightedMap)
        return;
    m_highlightedMap = map;
    refreshNow();
}

void ItemController::setSubdivisionSteps(int steps)
{
    m_subdivisionSteps = std::max(0, steps);
    refreshNow();
}

void ItemController::scheduleRefresh()
{
    // The signals of one edit (changed, derivedChanged) and the edits of one pointer event
    // make one update, at the next turn of the event loop; the docks follow by the budget.
    m_refreshTimer.start();
}

void ItemController::clearViews()
{
    m_attractor->setIfs(nullptr, StartSet{});
    m_attractor->setControlPoints(Mat());
    m_attractor->setExactCurve(Mat());
    m_attractor->setSubdivisionPolygons({});
    m_matrices->setMatrices({});
    m_spectrum->setMaps({});
    m_charts->setDistances({});
    m_charts->setPolygonLengths({});
    m_charts->setBoxCounting(BoxDimension{});
    m_charts->setModuli({});
    if (m_surface) {
        m_surface->setIfs(nullptr, StartSet{});
        m_surface->setControlNet(Mat(), {});
        m_surface->setRefinedNet(Mat(), {});
        m_surface->setStartVertices(Mat());
        m_surface->setMarkers({});
    }
}

void ItemController::refreshNow()
{
    refreshViews();
    m_budget->flush();
}

void ItemController::setPlotView(SpectrumView *view)
{
    m_plotView = view;
    m_plotPanel = m_budget->addPanel(view, [this] {
        m_plotView->setMaps(qobject_cast<const EigenvaluePlotItem *>(m_item.data())
                                ? currentSpectra()
                                : QList<MapSpectrum>{});
    });
    markPanelsDirty();
}

void ItemController::markPanelsDirty()
{
    m_budget->markDirty(m_plotPanel);
    m_budget->markDirty(m_matricesPanel);
    m_budget->markDirty(m_spectrumPanel);
    m_budget->markDirty(m_chartsPanel);
    m_budget->markDirty(m_vertexPanel);
}

void ItemController::refreshViews()
{
    m_refreshTimer.stop();
    const auto *plot = qobject_cast<const EigenvaluePlotItem *>(m_item.data());
    AttractorItem *item = drawnItem();
    // The plot's source is shown, not edited, in the views; lifted points and net points have
    // no plane points to drag (net points move with the net's handles).
    const bool planeStart = item && item->startSet().kind != StartSetSpec::Kind::Lifted
                            && item->startSet().kind != StartSetSpec::Kind::Net;
    m_attractor->setStartSetEditable(!plot && !m_frame && planeStart);
    QString problem;
    if (!item) {
        clearViews();
        problem = plot    ? tr("%1 shows nothing: %2").arg(plot->name(), plot->derivedError())
                  : m_item ? tr("%1 has no attractor to draw.").arg(m_item->name())
                           : QString();
    } else if (auto d = item->derivedIfs(); !d) {
        clearViews();
        problem = tr("%1 cannot be drawn: %2").arg(item->name(), item->derivedError());
    } else if (m_surface && item->pointDimension() == 3) {
        refreshSurface(item, *d);
        markPanelsDirty();
        if (!d->note.isEmpty())
            problem = d->note;
    } else {
        try {
            if (d->ifs.size() > 0 || d->iterate || d->chaos)
                m_attractor->setIfs(std::make_shared<const Ifs>(d->ifs), item->coreStartSet(*d),
                                    d->iterate, d->chaos);
            else // a polygon figure (normal-vector curve without an equivalent IFS)
                m_attractor->setIfs(nullptr, StartSet{});
        } catch (const std::exception &e) {
            problem = tr("%1 cannot be drawn: %2").arg(item->name(), QString::fromStdString(e.what()));
            m_attractor->setIfs(nullptr, StartSet{});
        }
        const Mat P = item->controlPointSetCount() > 0 ? toMatrix(item->controlPoints(0)) : Mat();
        std::vector<Mat> sets;
        std::vector<bool> closedSets;
        for (int k = 0; k < item->controlPointSetCount(); ++k) {
            sets.push_back(toMatrix(item->controlPoints(k)));
            closedSets.push_back(item->controlPointSetClosed(k));
        }
        m_attractor->setControlPolygons(sets, closedSets);
        m_attractor->setControlPointsEditable(!plot && !m_frame
                                              && item->controlPointSetCount() > 0);

        AttractorView::RenderSettings rs = m_attractor->renderSettings();
        const AlgorithmSpec &alg = item->algorithm();
        rs.mode = alg.mode == AlgorithmSpec::Mode::Random ? RenderRequest::Mode::Random
                                                           : RenderRequest::Mode::Deterministic;
        rs.depth = m_maxDepth > 0 ? std::min(alg.depth, m_maxDepth) : alg.depth;
        rs.samples = std::uint64_t(std::max<qint64>(1, alg.samples));
        rs.seed = std::uint64_t(alg.seed);
        rs.colouring = attractorColouring(item->style());
        rs.dotRadius = std::clamp(int(std::lround(item->style().pointSize / 2.0)), 0, 4);
        rs.tone.mode = item->style().densityTone(alg.mode == AlgorithmSpec::Mode::Random)
                           ? Accumulation::Density
                           : Accumulation::Hits;
        rs.tone.gamma = item->style().gamma;
        // Density shows the measure itself: no growing of the points.
        if (rs.tone.mode == Accumulation::Density)
            rs.dotRadius = 0;
        if (rs.colouring.palette.isEmpty())
            rs.colouring.palette = m_palette;
        if (m_highlightedMap >= 0) {
            // One map's part of the attractor: its colour, the rest in light grey, by map.
            QList<QColor> marked;
            const int maps = std::max(item->mapCount(), m_highlightedMap + 1);
            for (int i = 0; i < maps; ++i)
                marked << (i == m_highlightedMap
                               ? (rs.colouring.palette.isEmpty()
                                      ? AttractorRenderer::mapColor(i)
                                      : rs.colouring.palette[i % rs.colouring.palette.size()])
                               : QColor(205, 205, 205));
            rs.colouring.palette = marked;
            rs.colouring.mode = AttractorColorMode::ByMap;
        }
        m_attractor->setRenderSettings(rs);

        const auto scheme = realScheme(item);
        std::vector<Mat> polygons;
        if (scheme && P.rows() > 0) {
            try {
                for (int k = 1; k <= m_subdivisionSteps; ++k)
                    polygons.push_back(subdivide(*scheme, P, k));
            } catch (const std::exception &) {
                // No overlay: the attractor itself shows what the scheme does.
            }
        }
        std::vector<bool> polygonsClosed(polygons.size(), false);
        if (d->polygon) {
            polygons.push_back(*d->polygon);
            polygonsClosed.push_back(d->polygonClosed);
        }
        if (const auto exact = exactCurveOf(item, kExactSamples))
            m_attractor->setExactCurve(exact->points, exact->label);
        else
            m_attractor->setExactCurve(Mat());
        m_attractor->setSubdivisionPolygons(polygons, polygonsClosed);

        markPanelsDirty();
        if (!d->note.isEmpty() && problem.isEmpty())
            problem = d->note;
    }
    if (plot && !plot->eigenvalues())
        problem = tr("%1 shows nothing: %2").arg(plot->name(), plot->derivedError());
    m_attractor->setProblem(problem);
    if (problem != m_problem) {
        m_problem = problem;
        emit problemChanged(problem);
    }
    emit refreshed();
}

} // namespace awb
