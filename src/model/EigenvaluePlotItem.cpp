#include "model/EigenvaluePlotItem.h"

#include "model/AttractorItem.h"
#include "model/Commands.h"
#include "model/Project.h"
#include "model/ProjectIO.h"
#include "model/SubdivisionMeshItem.h"

#include "core/mesh/MeshAnalysis.h"

#include <cmath>

namespace awb {

namespace {
std::string toStd(const QString &s) { return s.toStdString(); }
} // namespace

EigenvaluePlotItem::EigenvaluePlotItem() : Item(tr("Eigenvalues")) {}

const QStringList &EigenvaluePlotItem::matrixKindNames()
{
    static const QStringList names{"S", "A", "M"};
    return names;
}

QStringList EigenvaluePlotItem::matrixKindDescriptions()
{
    return {tr("S_i, the subdivision matrices"), tr("A_i, the linear parts of M_i"),
            tr("M_i = P⁻¹S_iP, the lifted maps")};
}

bool EigenvaluePlotItem::setSource(const QString &name)
{
    applyProperty(&EigenvaluePlotItem::m_source, name, &EigenvaluePlotItem::sourceChanged,
                  tr("Change the source of %1").arg(this->name()));
    return true;
}

bool EigenvaluePlotItem::setMatrixKind(MatrixKind kind)
{
    applyProperty(&EigenvaluePlotItem::m_matrixKind, kind,
                  &EigenvaluePlotItem::matrixKindChanged,
                  tr("Analyse the matrices %1 in %2")
                      .arg(matrixKindNames().at(int(kind)), name()));
    return true;
}

bool EigenvaluePlotItem::setExtraordinary(int vertex, int face)
{
    const std::pair<int, int> to{std::max(-1, face >= 0 ? -1 : vertex), std::max(-1, face)};
    if (to == m_vertexFace)
        return true;
    const QString text = to.second >= 0   ? tr("Analyse the centre of face %1 in %2")
                                                  .arg(to.second).arg(name())
                         : to.first >= 0 ? tr("Analyse vertex %1 in %2").arg(to.first).arg(name())
                                         : tr("Analyse the mesh's matrices in %1").arg(name());
    applyProperty(&EigenvaluePlotItem::m_vertexFace, to, &EigenvaluePlotItem::extraordinaryChanged,
                  text);
    return true;
}

void EigenvaluePlotItem::renameReference(const QString &from, const QString &to)
{
    if (m_source == from)
        setSource(to);
}

std::shared_ptr<const EigenvalueData> EigenvaluePlotItem::eigenvalues() const
{
    return m_eigenvalues.get([this] { return compute(); });
}

QString EigenvaluePlotItem::derivedError() const
{
    eigenvalues();
    return m_eigenvalues.error();
}

AnalysisMatrices EigenvaluePlotItem::analysedMatrices(const DerivedIfs &derived, MatrixKind kind)
{
    switch (kind) {
    case MatrixKind::S: return derived.S;
    case MatrixKind::A: return derived.A;
    case MatrixKind::M: break;
    }
    AnalysisMatrices lifted;
    if (derived.subdivision)
        for (const auto &map : derived.subdivision->lifted)
            lifted.real.push_back(map.M);
    lifted.complex = derived.liftedComplex;
    if (lifted.count() == 0)
        lifted.unavailable = derived.A.unavailable.isEmpty()
                                 ? tr("M_i is defined only for a lifted subdivision IFS")
                                 : derived.A.unavailable;
    return lifted;
}

EigenvalueData EigenvaluePlotItem::compute() const
{
    if (m_source.isEmpty())
        throw InputError(toStd(tr("no item is chosen to analyse")));
    const Item *item = project() ? project()->findItem(m_source) : nullptr;
    if (!item)
        throw InputError(toStd(tr("there is no item called \"%1\"").arg(m_source)));
    const auto *source = dynamic_cast<const AttractorItem *>(item);
    if (!source)
        throw InputError(toStd(tr("\"%1\" (%2) has no matrices to analyse")
                                   .arg(m_source, item->typeName())));
    const auto derived = source->derivedIfs();
    if (!derived)
        throw InputError(toStd(tr("\"%1\" cannot be computed: %2")
                                   .arg(m_source, source->derivedError())));
    EigenvalueData out;
    out.symbol = matrixKindNames().at(int(m_matrixKind));
    out.matrices = analysedMatrices(*derived, m_matrixKind);
    if (vertex() >= 0 || face() >= 0) {
        const auto *mesh = dynamic_cast<const SubdivisionMeshItem *>(source);
        if (!mesh)
            throw InputError(toStd(tr("\"%1\" is not a mesh: it has no extraordinary vertices")
                                       .arg(m_source)));
        const auto list = mesh->extraordinary();
        const ExtraordinaryVertex *e = mesh->findExtraordinary(*list, vertex(), face());
        if (!e)
            throw InputError(toStd(
                (face() >= 0 ? tr("the centre of face %1 of \"%2\" is not an extraordinary "
                                  "vertex")
                                   .arg(face())
                             : tr("vertex %1 of \"%2\" is not an extraordinary vertex")
                                   .arg(vertex()))
                    .arg(m_source)));
        if (m_matrixKind != MatrixKind::S)
            throw InputError(toStd(tr("an extraordinary vertex has its local subdivision "
                                      "matrix S only")));
        out.matrices = AnalysisMatrices{};
        out.matrices.real.push_back(e->S);
    }
    const AnalysisMatrices &matrices = out.matrices;
    if (matrices.count() == 0)
        throw InputError(toStd(tr("\"%1\" has no matrices %2: %3")
                                   .arg(m_source, out.symbol, matrices.unavailable)));
    out.complexMatrices = matrices.isComplex();
    for (int i = 0; i < matrices.count(); ++i) {
        out.spectra.push_back(matrices.isComplex() ? spectrum(matrices.complex[size_t(i)])
                                                   : spectrum(matrices.real[size_t(i)]));
        // S_i is row-stochastic and M_i keeps the homogeneous coordinate: their eigenvalue 1
        // is affine invariance, not the curve's.
        out.subdominants.push_back(
            subdominant(out.spectra.back(), m_matrixKind != MatrixKind::A));
    }
    return out;
}

void EigenvaluePlotItem::write(QJsonObject &json) const
{
    Item::write(json);
    json["source"] = m_source;
    json["matrices"] = matrixKindNames().at(int(m_matrixKind));
    if (vertex() >= 0)
        json["vertex"] = vertex();
    if (face() >= 0)
        json["face"] = face();
}

void EigenvaluePlotItem::read(const FieldReader &fields)
{
    Item::read(fields);
    m_source = fields.string("source");
    m_matrixKind = MatrixKind(fields.choice("matrices", matrixKindNames(), int(m_matrixKind)));
    const auto index = [&fields](const char *key) {
        if (!fields.has(key))
            return -1;
        const double x = fields.number(key);
        if (x != std::floor(x) || x < 0 || x > 1e9)
            fields.fail(key, tr("expected a vertex or face number (0-based)"));
        return int(x);
    };
    m_vertexFace = {index("vertex"), index("face")};
    if (m_vertexFace.second >= 0)
        m_vertexFace.first = -1;
}

} // namespace awb
