// ItemController: the extraordinary vertices of a mesh item (issue 31) -- their markers in the
// 3D view, the vertex a click focuses, and what the docks show of it: its local subdivision
// matrix (Matrices), its eigenvalues (Spectrum), Reif's verdict and the characteristic map
// (Analysis > Vertex), the scheme's table of valences (Analysis > Valences).

#include "gui/app/ItemController.h"

#include "core/analysis/Spectrum.h"
#include "core/mesh/MeshAnalysis.h"
#include "core/mesh/VertexSpectrum.h"
#include "gui/app/FrameBudget.h"
#include "gui/views/SpectrumView.h"
#include "gui/views/SurfaceView.h"
#include "gui/views/VertexPanel.h"
#include "model/EigenvaluePlotItem.h"
#include "model/Project.h"

#include <set>
#include "model/SubdivisionMeshItem.h"

namespace awb {

void ItemController::setVertexViews(VertexPanel *panel, ValenceChart *chart)
{
    m_vertexView = panel;
    m_valences = chart;
    m_vertexPanel = m_budget->addPanel(panel, [this] { showVertex(); });
    connect(panel, &VertexPanel::plotRequested, this, [this] { addVertexPlot(); });
    markPanelsDirty();
}

void ItemController::setFocusedVertex(int index)
{
    std::shared_ptr<const std::vector<ExtraordinaryVertex>> list;
    const auto *mesh = qobject_cast<const SubdivisionMeshItem *>(drawnItem());
    if (mesh && !m_frame)
        list = mesh->extraordinary();
    if (!list || index < 0 || index >= int(list->size()))
        index = -1;
    if (m_surface)
        m_surface->setSelectedMarker(index);
    if (index == m_focusedVertex)
        return;
    m_focusedVertex = index;
    markPanelsDirty();
    emit focusedVertexChanged(index);
}

const ExtraordinaryVertex *ItemController::focused(
    std::shared_ptr<const std::vector<ExtraordinaryVertex>> *list) const
{
    if (m_focusedVertex < 0 || m_frame)
        return nullptr;
    const auto *mesh = qobject_cast<const SubdivisionMeshItem *>(drawnItem());
    if (!mesh || qobject_cast<const EigenvaluePlotItem *>(m_item.data()))
        return nullptr;
    *list = mesh->extraordinary();
    return m_focusedVertex < int((*list)->size()) ? &(**list)[std::size_t(m_focusedVertex)]
                                                   : nullptr;
}

QString ItemController::focusedVertexName() const
{
    std::shared_ptr<const std::vector<ExtraordinaryVertex>> list;
    const ExtraordinaryVertex *e = focused(&list);
    if (!e)
        return {};
    return e->vertex >= 0 ? tr("vertex %1").arg(e->vertex)
                          : tr("the centre of face %1").arg(e->face);
}

QList<MapSpectrum> ItemController::focusedSpectra() const
{
    std::shared_ptr<const std::vector<ExtraordinaryVertex>> list;
    const ExtraordinaryVertex *e = focused(&list);
    if (!e || e->S().size() == 0)
        return {};
    MapSpectrum m;
    m.label = tr("S at %1 (n = %2)").arg(focusedVertexName()).arg(e->valence);
    m.spectrum = spectrum(e->S());
    m.subdominant = subdominant(m.spectrum, true);
    m.contractivity = stochasticContractivity(e->S());
    return {m};
}

QList<NamedMatrix> ItemController::focusedMatrices() const
{
    std::shared_ptr<const std::vector<ExtraordinaryVertex>> list;
    const ExtraordinaryVertex *e = focused(&list);
    if (!e || e->S().size() == 0)
        return {};
    return {NamedMatrix(tr("S at %1 (n = %2)").arg(focusedVertexName()).arg(e->valence), e->S())};
}

void ItemController::showMeshMarkers(const SubdivisionMeshItem *mesh)
{
    const auto list = mesh->extraordinary();
    // A closed mesh (every edge between two faces) hides the markers on its far side; an open
    // one shows its back, so its markers always show.
    const auto pieces = mesh->pieces();  // the topology's identity: recomputed when it changes
    if (m_closedMeshKey != pieces.get()) {
        m_closedMeshKey = pieces.get();
        m_closedMesh = true;
        const Mesh m = mesh->mesh();
        std::set<std::pair<int, int>> edges;
        for (const auto &f : m.faces)
            for (std::size_t k = 0; k < f.size(); ++k)
                edges.insert({f[k], f[(k + 1) % f.size()]});
        for (const auto &[a, b] : edges)
            m_closedMesh = m_closedMesh && edges.count({b, a});
    }
    const bool closed = m_closedMesh;
    std::vector<SurfaceView::Marker> markers;
    markers.reserve(list->size());
    for (const ExtraordinaryVertex &e : *list) {
        if (e.limit.size() != 3)
            continue;
        const bool normal = closed && e.normal.size() == 3 && e.normal.norm() > 0.5;
        markers.push_back({QVector3D(float(e.limit(0)), float(e.limit(1)), float(e.limit(2))),
                           QString::number(e.valence),
                           normal ? QVector3D(float(e.normal(0)), float(e.normal(1)),
                                              float(e.normal(2)))
                                  : QVector3D()});
    }
    // One marker per entry, in the list's order (the focus is an index into it).
    if (markers.size() != list->size())
        markers.clear();
    m_surface->setMarkers(std::move(markers));
    m_surface->setSelectedMarker(m_focusedVertex);
}

void ItemController::showVertex()
{
    if (!m_vertexView)
        return;
    const auto *mesh = qobject_cast<const SubdivisionMeshItem *>(drawnItem());
    if (m_valences) {
        if (mesh) {
            std::vector<int> valences;
            const auto vertices = mesh->extraordinary();  // held: the loop reads it
            for (const ExtraordinaryVertex &e : *vertices)
                if (e.smoothInterior())
                    valences.push_back(e.valence);
            m_valences->setScheme(mesh->scheme(), std::move(valences));
        } else {
            m_valences->setScheme(MeshScheme::CatmullClark, {});
        }
    }
    std::shared_ptr<const std::vector<ExtraordinaryVertex>> list;
    const ExtraordinaryVertex *e = focused(&list);
    if (!e) {
        m_vertexView->clear(mesh ? QString()
                                 : tr("The Vertex tab analyses the extraordinary vertices of a "
                                      "mesh surface (Item > Add > Mesh surface, File > Import "
                                      "Mesh)."));
        return;
    }
    std::optional<VertexSpectrum> interior;
    if (e->smoothInterior() && ringAnalysable(e->valence))
        interior = *sharedVertexSpectrum(mesh->scheme(), e->valence);
    QString where = focusedVertexName();
    if (!where.isEmpty())
        where[0] = where[0].toUpper();
    m_vertexView->setVertex(*e, mesh->scheme(), interior, tr("%1 of %2").arg(where, mesh->name()));
}

Item *ItemController::addVertexPlot()
{
    std::shared_ptr<const std::vector<ExtraordinaryVertex>> list;
    const ExtraordinaryVertex *e = focused(&list);
    auto *mesh = qobject_cast<SubdivisionMeshItem *>(drawnItem());
    if (!e || !mesh || !mesh->project())
        return nullptr;
    Project *project = mesh->project();
    auto plot = std::make_unique<EigenvaluePlotItem>();
    plot->setSource(mesh->name());
    plot->setExtraordinary(e->vertex, e->face);
    plot->setName(tr("Eigenvalues at %1").arg(focusedVertexName()));
    return project->addItem(std::move(plot), mesh);
}

} // namespace awb
