#include "model/EigenvaluePlotItem.h"

#include "model/AttractorItem.h"
#include "model/Commands.h"
#include "model/Project.h"
#include "model/ProjectIO.h"

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
}

void EigenvaluePlotItem::read(const FieldReader &fields)
{
    Item::read(fields);
    m_source = fields.string("source");
    m_matrixKind = MatrixKind(fields.choice("matrices", matrixKindNames(), int(m_matrixKind)));
}

} // namespace awb
