#include "model/SubdivisionMeshItem.h"

#include "core/mesh/MeshAnalysis.h"
#include "core/mesh/MeshExamples.h"
#include "core/mesh/MeshFiles.h"
#include "core/mesh/MeshIterate.h"
#include "core/mesh/MeshPieces.h"
#include "core/mesh/MeshRefine.h"
#include "model/ProjectIO.h"
#include "model/PropertyDeclaration.h"

#include <QJsonArray>

#include <cmath>
#include <sstream>

namespace awb {

// ---- MeshInputs -------------------------------------------------------------------------------

const QStringList &MeshInputs::schemeNames()
{
    static const QStringList names{"catmull-clark", "loop"};
    return names;
}

Mesh MeshInputs::mesh() const { return {toMatrix(vertices, 3), faces}; }

MaybeProblem MeshInputs::check() const
{
    if (int(vertices.size()) > SubdivisionMeshItem::maxVertices)
        return Problem{"vertices", tr("%1 vertices; a mesh item takes at most %2")
                                       .arg(vertices.size())
                                       .arg(SubdivisionMeshItem::maxVertices)};
    if (faces.size() > std::size_t(2 * SubdivisionMeshItem::maxVertices))
        return Problem{"faces", tr("%1 faces; a mesh item takes at most %2")
                                    .arg(faces.size())
                                    .arg(2 * SubdivisionMeshItem::maxVertices)};
    try {
        checkMesh(mesh(), scheme);
    } catch (const InputError &e) {
        const QString message = QString::fromStdString(e.what());
        const bool aboutVertices = message.startsWith("vertex") && message.contains("finite");
        return Problem{aboutVertices || vertices.empty() ? "vertices" : "faces", message};
    }
    return std::nullopt;
}

// ---- SubdivisionMeshItem ----------------------------------------------------------------------

SubdivisionMeshItem::SubdivisionMeshItem() : AttractorItem(tr("Mesh surface"))
{
    const Mesh cube = cubeMesh();
    m_inputs.vertices = toPointList(cube.vertices);
    m_inputs.faces = cube.faces;
    StartSetSpec start;
    start.kind = StartSetSpec::Kind::VertexLimits;
    start.points.clear();
    setInitialStartSet(start);
    AlgorithmSpec algorithm;
    algorithm.depth = 4;
    setAlgorithm(algorithm);
}

SubdivisionMeshItem::~SubdivisionMeshItem() = default;

bool SubdivisionMeshItem::setInputs(const MeshInputs &inputs, QString *error, int gesture)
{
    return setDeclared(*this, inputs, gesture, error);
}

bool SubdivisionMeshItem::setScheme(MeshScheme scheme, QString *error)
{
    MeshInputs next = m_inputs;
    next.scheme = scheme;
    return next == m_inputs || setInputs(next, error);
}

bool SubdivisionMeshItem::setMesh(const Mesh &mesh, MeshScheme scheme, QString *error)
{
    MeshInputs next;
    next.scheme = scheme;
    next.vertices = toPointList(mesh.vertices);
    next.faces = mesh.faces;
    return setInputs(next, error);
}

std::shared_ptr<const MeshPieces> SubdivisionMeshItem::pieces() const
{
    const auto d = derivedIfs();
    if (!d)
        return nullptr;
    std::lock_guard<std::mutex> lock(m_piecesMutex);
    return m_pieces;
}

std::shared_ptr<const std::vector<ExtraordinaryVertex>> SubdivisionMeshItem::extraordinary() const
{
    const auto p = pieces();
    if (!p)
        return std::make_shared<const std::vector<ExtraordinaryVertex>>();
    {
        std::lock_guard<std::mutex> lock(m_piecesMutex);
        if (m_extraordinary && m_extraordinaryOf == m_inputs)
            return m_extraordinary;
    }
    auto list = std::make_shared<const std::vector<ExtraordinaryVertex>>(
        extraordinaryVertices(*p, toMatrix(m_inputs.vertices, 3)));
    std::lock_guard<std::mutex> lock(m_piecesMutex);
    m_extraordinary = list;
    m_extraordinaryOf = m_inputs;
    return list;
}

std::string SubdivisionMeshItem::limitObj(int rounds) const
{
    if (const MaybeProblem p = m_inputs.check())
        throw InputError((p->field + ": " + p->message).toStdString());
    if (rounds < 0 || rounds > maxExportRounds)
        throw InputError(tr("the steps before the limit positions must be 0 to %1, got %2")
                             .arg(maxExportRounds)
                             .arg(rounds)
                             .toStdString());
    // Each step multiplies the vertices by about 4: refuse before refining, not after.
    const Mesh mesh = m_inputs.mesh();
    const double estimate =
        double(mesh.vertices.rows() + Eigen::Index(mesh.faces.size())) * std::pow(4.0, rounds);
    if (estimate > double(maxExportVertices))
        throw InputError(tr("%1 steps give about %2 vertices: more than %3")
                             .arg(rounds)
                             .arg(estimate, 0, 'g', 3)
                             .arg(double(maxExportVertices), 0, 'g', 3)
                             .toStdString());
    Mesh refined = refineMesh(mesh, m_inputs.scheme, rounds);
    refined.vertices = limitPositions(refined, m_inputs.scheme);
    std::ostringstream text;
    writeObj(text, refined,
             tr("Attractor Workbench: item %1, %2 after %3 steps, every vertex at its limit "
                "position")
                 .arg(name(), MeshInputs::schemeNames().at(int(m_inputs.scheme)))
                 .arg(rounds)
                 .toStdString());
    return text.str();
}

const ExtraordinaryVertex *SubdivisionMeshItem::findExtraordinary(
    const std::vector<ExtraordinaryVertex> &list, int vertex, int face) const
{
    for (const ExtraordinaryVertex &e : list)
        if (face >= 0 ? e.face == face : (vertex >= 0 && e.vertex == vertex))
            return &e;
    return nullptr;
}

DerivedIfs SubdivisionMeshItem::computeIfs() const
{
    if (const MaybeProblem p = m_inputs.check())
        throw InputError((p->field + ": " + p->message).toStdString());
    if (algorithm().mode == AlgorithmSpec::Mode::Random)
        throw InputError(tr("a mesh surface is drawn by deterministic iteration: random "
                            "iteration of its pieces is not implemented")
                             .toStdString());
    std::shared_ptr<const MeshPieces> pieces;
    {
        std::lock_guard<std::mutex> lock(m_piecesMutex);
        if (!m_pieces || m_piecesFaces != m_inputs.faces || m_piecesScheme != m_inputs.scheme) {
            m_pieces.reset();
            m_pieces = std::make_shared<const MeshPieces>(
                buildMeshPieces(m_inputs.mesh(), m_inputs.scheme));
            m_piecesFaces = m_inputs.faces;
            m_piecesScheme = m_inputs.scheme;
        }
        pieces = m_pieces;
    }
    DerivedIfs out;
    out.ifs.space = "R^3";
    out.ifs.views.push_back({Mat::Identity(3, 3), RowVec::Zero(3)});
    out.toIfsSpace = [](const Mat &X) { return X; };
    out.vertexLimitStart = true;
    const Mat vertices = toMatrix(m_inputs.vertices, 3);
    const bool levels = m_inputs.levelColours;
    const auto startOf = [levels](const StartSet &start) {
        MeshStart s;
        s.levelAddresses = levels;
        if (start.vertices.rows() > 0) {
            s.kind = MeshStart::Kind::Points;
            s.points = start;
        }
        return s;
    };
    out.iterate = [pieces, vertices, startOf](const StartSet &start, int depth,
                                              const std::vector<AttractorSink *> &sinks,
                                              const IterationControl &control) {
        return iterateMesh(*pieces, vertices, startOf(start), depth, sinks, control);
    };
    out.pointCount = [pieces, startOf](const StartSet &start, int depth) {
        return meshPointCount(*pieces, startOf(start), depth);
    };
    // The matrices shown: the local subdivision matrix of the first extraordinary vertex (its
    // piece's map 0, once settled), then the 4 maps of the first patch that maps to itself.
    for (const MeshPieceRoot &root : pieces->roots)
        if (const int settled = root.vertex >= 0 ? settledType(*pieces, root.type) : -1;
            settled >= 0) {
            out.S.real.push_back(pieces->types[std::size_t(settled)].children.front().S);
            break;
        }
    for (const MeshPieceType &type : pieces->types) {
        if (type.kind != MeshPieceType::Kind::Face || type.children.empty())
            continue;
        bool square = true;
        for (const MeshPieceType::Child &c : type.children)
            square = square && c.S.rows() == c.S.cols();
        if (!square)
            continue;
        for (const MeshPieceType::Child &c : type.children)
            out.S.real.push_back(c.S);
        break;
    }
    out.A.unavailable = tr("a mesh has no single lifted space: each of its pieces is lifted "
                           "over its own control net");
    out.note = pieces->steps == 1
                   ? tr("%1 pieces of %2 kinds after one step that isolates the extraordinary "
                        "vertices")
                         .arg(pieces->roots.size())
                         .arg(pieces->types.size())
                   : tr("%1 pieces of %2 kinds after %3 steps that isolate the extraordinary "
                        "vertices")
                         .arg(pieces->roots.size())
                         .arg(pieces->types.size())
                         .arg(pieces->steps);
    return out;
}

// ---- declared properties ----------------------------------------------------------------------
// The worked example of docs/adding-an-item-kind.md: one part (the inputs that change
// together), four fields. Each field's declaration gives the file form, the undoable edit with
// its refusal message, the Properties dock's row, Python's item.parameters and
// `attractor-cli set`.

const PropertyTable &SubdivisionMeshItem::declaration()
{
    static const PropertyTable table = [] {
        using I = SubdivisionMeshItem;
        Declaration<I> d(&AttractorItem::attractorProperties());
        auto inputs = d.part(&I::m_inputs, &I::checkInputs, &I::meshChanged,
                             QT_TR_NOOP("Change mesh of %1"));
        inputs.checkedOnRead([](const I &, const MeshInputs &m) { return m.check(); });
        inputs
            .choice("scheme.kind", &MeshInputs::scheme, MeshInputs::schemeNames(),
                    {QT_TR_NOOP("Catmull–Clark"), QT_TR_NOOP("Loop")})
            .label(QT_TR_NOOP("Scheme"))
            .group(QT_TR_NOOP("Scheme"))
            .tip(QT_TR_NOOP("Loop takes triangle meshes only"));
        inputs.points("vertices", &MeshInputs::vertices, [](const I &) { return 3; })
            .label(QT_TR_NOOP("Vertices"))
            .tip(QT_TR_NOOP("The mesh's vertices [x, y, z]: its control points"))
            .required();
        inputs
            .structured(
                "faces", QStringLiteral("faces"),
                [](const I &, const MeshInputs &m) {
                    QJsonArray faces;
                    for (const auto &f : m.faces) {
                        QJsonArray loop;
                        for (int v : f)
                            loop.append(v);
                        faces.append(loop);
                    }
                    return QJsonValue(faces);
                },
                [](const I &, MeshInputs &m, const QJsonValue &v, const QString &where) {
                    if (!v.isArray())
                        throw LoadError{where, tr("expected an array of faces, each an array "
                                                  "of vertex numbers")};
                    const QJsonArray rows = v.toArray();
                    m.faces.clear();
                    m.faces.reserve(std::size_t(rows.size()));
                    for (qsizetype k = 0; k < rows.size(); ++k) {
                        const QString at = where + QStringLiteral("[%1]").arg(k + 1);
                        if (!rows[k].isArray())
                            throw LoadError{at, tr("expected a face: an array of vertex "
                                                   "numbers (0-based)")};
                        const QJsonArray loop = rows[k].toArray();
                        std::vector<int> face;
                        for (qsizetype i = 0; i < loop.size(); ++i) {
                            const double x = FieldReader::toNumber(
                                loop[i], at + QStringLiteral("[%1]").arg(i + 1));
                            if (x != std::floor(x) || std::abs(x) > 1e9)
                                throw LoadError{at, tr("vertex numbers are whole numbers "
                                                       "(0-based)")};
                            face.push_back(int(x));
                        }
                        m.faces.push_back(std::move(face));
                    }
                })
            .label(QT_TR_NOOP("Faces"))
            .tip(QT_TR_NOOP("Each face as the loop of its vertex numbers (0-based)"))
            .required(QT_TR_NOOP("expected an array of faces, each an array of vertex "
                                 "numbers"));
        inputs
            .choice("colouring", &MeshInputs::levelColours, {"maps", "levels"},
                    {QT_TR_NOOP("By map"), QT_TR_NOOP("By level around extraordinary vertices")})
            // Not "Colour(s)": the style's "Colour" (by map, by address, single) is beside it.
            .label(QT_TR_NOOP("Pieces coloured"))
            .group(QT_TR_NOOP("Style"))
            .tip(QT_TR_NOOP("By level: around an extraordinary vertex, the rings C, f(C), f²(C), "
                            "… of its IFS with condensation get colours in turn"));
        return d.table();
    }();
    return table;
}

} // namespace awb
