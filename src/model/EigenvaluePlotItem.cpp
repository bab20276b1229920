#include "model/EigenvaluePlotItem.h"

#include "model/AttractorItem.h"
#include "model/Commands.h"
#include "model/Project.h"
#include "model/ProjectIO.h"
#include "model/PropertyDeclaration.h"
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
        out.matrices.real.push_back(e->S());
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

// ---- declared properties ----------------------------------------------------------------------

namespace {

// The source choices: "(none)", the project's attractor items, and a name that is no item
// (yet), shown as it is. Spellings are the names ("" for none).
struct SourceChoices {
    QStringList names, texts;
};

SourceChoices sourceChoices(const EigenvaluePlotItem &plot, const QString &source)
{
    SourceChoices c;
    c.names << QString();
    c.texts << EigenvaluePlotItem::tr("(none)");
    if (const Project *project = plot.project())
        for (Item *item : project->items())
            if (qobject_cast<AttractorItem *>(item)) {
                c.names << item->name();
                c.texts << item->name();
            }
    if (!c.names.contains(source)) {
        c.names << source;
        c.texts << EigenvaluePlotItem::tr("%1 (missing)").arg(source);
    }
    return c;
}

// The mesh the plot analyses, if its source is one.
const SubdivisionMeshItem *meshSource(const EigenvaluePlotItem &plot)
{
    return plot.project()
               ? qobject_cast<const SubdivisionMeshItem *>(plot.project()->findItem(plot.source()))
               : nullptr;
}

// A mesh's choices of analysed matrices: its own, then each extraordinary vertex (and one
// that no longer is, shown as it is).
std::vector<std::pair<int, int>> vertexChoices(const EigenvaluePlotItem &plot, QStringList *texts)
{
    std::vector<std::pair<int, int>> at{{-1, -1}};
    *texts = QStringList{EigenvaluePlotItem::tr("(the mesh's matrices)")};
    // The list is held here: the mesh may drop its cached one while it is read.
    const auto list = meshSource(plot) ? meshSource(plot)->extraordinary() : nullptr;
    if (list)
        for (const ExtraordinaryVertex &e : *list) {
            at.push_back({e.vertex >= 0 ? e.vertex : -1, e.face});
            *texts << (e.vertex >= 0
                           ? EigenvaluePlotItem::tr("vertex %1 (n = %2)").arg(e.vertex).arg(e.valence)
                           : EigenvaluePlotItem::tr("centre of face %1 (n = %2)")
                                 .arg(e.face)
                                 .arg(e.valence));
        }
    const std::pair<int, int> chosen{plot.face() >= 0 ? -1 : plot.vertex(), plot.face()};
    if (std::find(at.begin(), at.end(), chosen) == at.end()) {
        at.push_back(chosen);
        *texts << (plot.face() >= 0
                       ? EigenvaluePlotItem::tr("centre of face %1 (missing)").arg(plot.face())
                       : EigenvaluePlotItem::tr("vertex %1 (missing)").arg(plot.vertex()));
    }
    return at;
}

// "vertex" and "face" of the file: 0-based, absent for none.
QJsonValue indexToJson(int i) { return i >= 0 ? QJsonValue(i) : QJsonValue(); }

int indexFromJson(const QJsonValue &v, const QString &where)
{
    const double x = FieldReader::toNumber(v, where);
    if (x != std::floor(x) || x < 0 || x > 1e9)
        throw LoadError{where, EigenvaluePlotItem::tr("expected a vertex or face number (0-based)")};
    return int(x);
}

} // namespace

const PropertyTable &EigenvaluePlotItem::declaration()
{
    static const PropertyTable table = [] {
        using P = EigenvaluePlotItem;
        Declaration<P> d(&Item::itemProperties());
        auto source = d.part<QString>(
            [](const P &p) -> const QString & { return p.m_source; },
            [](P &p, QString &&s) { p.m_source = std::move(s); }, nullptr,
            [](P &p, const QString &s, int) { p.setSource(s); });
        // A choice among the project's items; the file keeps the name, whatever the project
        // holds.
        source
            .choiceBy(
                "source", {}, {}, [](const QString &) { return 0; }, [](QString &, int) {})
            .label(QT_TR_NOOP("Source"))
            .group(QT_TR_NOOP("Eigenvalues"))
            .tip(QT_TR_NOOP("The item whose matrices are analysed"))
            .required()
            .choicesFrom([](const P &p, const QString &s) { return sourceChoices(p, s).texts; })
            .spellingsFrom([](const P &p, const QString &s) { return sourceChoices(p, s).names; })
            .getter([](const P &p, const QString &s) {
                return int(sourceChoices(p, s).names.indexOf(s));
            })
            .assigner([](const P &p, QString &s, const QVariant &v) -> MaybeProblem {
                const QStringList names = sourceChoices(p, s).names;
                std::optional<qint64> i = property::toWhole(v);
                if (!i && v.typeId() == QMetaType::QString && names.contains(v.toString()))
                    i = names.indexOf(v.toString());
                if (!i || *i < 0 || *i >= names.size())
                    return Problem{"source", property::notValid(v, QStringLiteral("source"))};
                s = names.at(int(*i));
                return std::nullopt;
            })
            .codec([](const P &, const QString &s) { return QJsonValue(s); },
                   [](const P &, QString &s, const QJsonValue &v, const QString &where) {
                       if (!v.isString())
                           throw LoadError{where, QCoreApplication::translate(
                                                      "awb::FieldReader", "expected a string")};
                       s = v.toString();
                   });

        auto kind = d.part<MatrixKind>(
            [](const P &p) -> const MatrixKind & { return p.m_matrixKind; },
            [](P &p, MatrixKind &&k) { p.m_matrixKind = k; }, nullptr,
            [](P &p, const MatrixKind &k, int) { p.setMatrixKind(k); });
        kind.choice("matrices", [](MatrixKind &k) -> MatrixKind & { return k; },
                    matrixKindNames(), {})
            .label(QT_TR_NOOP("Matrices"))
            .group(QT_TR_NOOP("Eigenvalues"))
            .tip(QT_TR_NOOP("S_i: the subdivision matrices (their eigenvalue 1 is affine "
                            "invariance); A_i: the linear parts of the lifted maps, whose "
                            "subdominant eigenvalue decides the tangents; M_i: the lifted maps "
                            "themselves (003 §4, 004 §2.1)"))
            .choicesFrom([](const P &, const MatrixKind &) { return matrixKindDescriptions(); });

        // For a mesh source: the mesh's own matrices, or the local subdivision matrix of one
        // of its extraordinary vertices (issue 31).
        using VF = std::pair<int, int>;
        auto vertex = d.part<VF>(
            [](const P &p) -> const VF & { return p.m_vertexFace; },
            [](P &p, VF &&v) { p.m_vertexFace = v; }, nullptr,
            [](P &p, const VF &v, int) { p.setExtraordinary(v.first, v.second); });
        vertex.startsFrom([](const P &) { return VF{-1, -1}; });
        vertex.structured(
                  "vertex", QStringLiteral("integer"),
                  [](const P &, const VF &v) { return indexToJson(v.first); },
                  [](const P &, VF &v, const QJsonValue &j, const QString &where) {
                      v.first = indexFromJson(j, where);
                  })
            .label(QT_TR_NOOP("Vertex"))
            .savedWhen([](const VF &v) { return v.first >= 0 || v.second < 0; })
            .omitWhenDefault();
        vertex.structured(
                  "face", QStringLiteral("integer"),
                  [](const P &, const VF &v) { return indexToJson(v.second); },
                  [](const P &, VF &v, const QJsonValue &j, const QString &where) {
                      v.second = indexFromJson(j, where);
                      v.first = -1;  // a face centre, not a vertex
                  })
            .label(QT_TR_NOOP("Face"))
            .omitWhenDefault();
        vertex
            .choiceBy(
                "extraordinary", {}, {}, [](const VF &) { return 0; }, [](VF &, int) {})
            .label(QT_TR_NOOP("Vertex"))
            .group(QT_TR_NOOP("Eigenvalues"))
            .tip(QT_TR_NOOP("For a mesh surface: the extraordinary vertex whose local "
                            "subdivision matrix is analysed"))
            .notSaved()
            .shownWhen([](const P &p, const VF &) { return meshSource(p) != nullptr; })
            .choicesFrom([](const P &p, const VF &) {
                QStringList texts;
                vertexChoices(p, &texts);
                return texts;
            })
            .getter([](const P &p, const VF &v) {
                QStringList texts;
                const auto at = vertexChoices(p, &texts);
                const VF chosen{v.second >= 0 ? -1 : v.first, v.second};
                return int(std::find(at.begin(), at.end(), chosen) - at.begin());
            })
            .assigner([](const P &p, VF &v, const QVariant &value) -> MaybeProblem {
                QStringList texts;
                const auto at = vertexChoices(p, &texts);
                const auto i = property::toWhole(value);
                if (!i || *i < 0 || *i >= qint64(at.size()))
                    return Problem{"extraordinary",
                                   property::notValid(value, QStringLiteral("extraordinary"))};
                v = at[size_t(*i)];
                return std::nullopt;
            });
        return d.table();
    }();
    return table;
}

} // namespace awb
