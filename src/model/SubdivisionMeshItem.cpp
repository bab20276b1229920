#include "model/SubdivisionMeshItem.h"

#include "core/mesh/MeshAnalysis.h"
#include "core/mesh/MeshExamples.h"
#include "core/mesh/MeshFiles.h"
#include "core/mesh/MeshIterate.h"
#include "core/mesh/MeshPieces.h"
#include "core/mesh/MeshRefine.h"
#include "core/mesh/MeshSheets.h"
#include "model/ProjectIO.h"
#include "model/PropertyDeclaration.h"

#include <QJsonArray>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace awb {

// ---- MeshInputs -------------------------------------------------------------------------------

const QStringList &MeshInputs::schemeNames()
{
    static const QStringList names{"catmull-clark", "loop"};
    return names;
}

Mesh MeshInputs::mesh() const { return {toMatrix(vertices, 3), faces, tags}; }

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
        checkDrawnMesh(mesh(), scheme);
    } catch (const InputError &e) {
        const QString message = QString::fromStdString(e.what());
        const bool aboutVertices = message.startsWith("vertex") && message.contains("finite");
        // The tags' problems name their field (Mesh.cpp's applyTags words).
        const QString field = message.contains("a crease") || message.contains("the crease")
                                  ? "creases"
                              : message.contains("a corner") || message.contains("the corner")
                                  ? "corners"
                              : message.contains("a hole") ? "holes"
                              : aboutVertices || vertices.empty() ? "vertices"
                                                                  : "faces";
        return Problem{field, message};
    }
    return std::nullopt;
}

// ---- the sharp features' file form -----------------------------------------------------------

namespace {

// An array of rows of `width` numbers (width 1: plain numbers).
QList<QList<double>> tagRows(const QJsonValue &v, const QString &where, int width,
                             const QString &what)
{
    if (!v.isArray())
        throw LoadError{where, SubdivisionMeshItem::tr("expected an array, each entry %1")
                                   .arg(what)};
    QList<QList<double>> rows;
    const QJsonArray array = v.toArray();
    for (qsizetype k = 0; k < array.size(); ++k) {
        const QString at = where + QStringLiteral("[%1]").arg(k + 1);
        QList<double> row;
        if (width == 1) {
            row.append(FieldReader::toNumber(array[k], at));
        } else {
            if (!array[k].isArray() || array[k].toArray().size() != width)
                throw LoadError{at, SubdivisionMeshItem::tr("expected %1").arg(what)};
            for (const QJsonValue &x : array[k].toArray())
                row.append(FieldReader::toNumber(x, at));
        }
        rows.append(row);
    }
    return rows;
}

int wholeIn(double x, const QString &where)
{
    if (x != std::floor(x) || std::abs(x) > 1e9)
        throw LoadError{where, SubdivisionMeshItem::tr("vertex and face numbers are whole "
                                                       "numbers (0-based)")};
    return int(x);
}

float sharpnessIn(double x, const QString &where)
{
    if (!(x >= 0.0) || !std::isfinite(x))
        throw LoadError{where, SubdivisionMeshItem::tr("a sharpness is a number of 0 or more "
                                                       "(10 or more: infinitely sharp)")};
    return float(x);
}

} // namespace

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
    next.tags = mesh.tags;
    return setInputs(next, error);
}

bool SubdivisionMeshItem::setEdgeSharpness(int a, int b, float sharpness, QString *error)
{
    if (!(sharpness >= 0.0f) || !std::isfinite(sharpness)) {
        if (error)
            *error = tr("a sharpness is a number of 0 or more (10 or more: infinitely sharp)");
        return false;
    }
    MeshInputs next = m_inputs;
    auto &edges = next.tags.edges;
    const auto same = [a, b](const SharpEdge &e) {
        return (e.a == a && e.b == b) || (e.a == b && e.b == a);
    };
    edges.erase(std::remove_if(edges.begin(), edges.end(), same), edges.end());
    if (sharpness > 0.0f)
        edges.push_back({a, b, sharpness});
    return next == m_inputs || setInputs(next, error);
}

bool SubdivisionMeshItem::setVertexSharpness(int v, float sharpness, QString *error)
{
    if (!(sharpness >= 0.0f) || !std::isfinite(sharpness)) {
        if (error)
            *error = tr("a sharpness is a number of 0 or more (10 or more: infinitely sharp)");
        return false;
    }
    MeshInputs next = m_inputs;
    auto &vertices = next.tags.vertices;
    vertices.erase(std::remove_if(vertices.begin(), vertices.end(),
                                  [v](const SharpVertex &c) { return c.vertex == v; }),
                   vertices.end());
    if (sharpness > 0.0f)
        vertices.push_back({v, sharpness});
    return next == m_inputs || setInputs(next, error);
}

float SubdivisionMeshItem::edgeSharpness(int a, int b) const
{
    for (const SharpEdge &e : m_inputs.tags.edges)
        if ((e.a == a && e.b == b) || (e.a == b && e.b == a))
            return e.sharpness;
    return kSharpnessSmooth;
}

bool SubdivisionMeshItem::setHole(int face, bool hole, QString *error)
{
    if (face < 0 || face >= int(m_inputs.faces.size())) {
        if (error)
            *error = tr("face %1: the mesh has %2 faces (0 to %3)")
                         .arg(face)
                         .arg(m_inputs.faces.size())
                         .arg(int(m_inputs.faces.size()) - 1);
        return false;
    }
    MeshInputs next = m_inputs;
    auto &holes = next.tags.holes;
    holes.erase(std::remove(holes.begin(), holes.end(), face), holes.end());
    if (hole)
        holes.push_back(face);
    return next == m_inputs || setInputs(next, error);
}

bool SubdivisionMeshItem::isHole(int face) const
{
    const auto &holes = m_inputs.tags.holes;
    return std::find(holes.begin(), holes.end(), face) != holes.end();
}

float SubdivisionMeshItem::vertexSharpness(int v) const
{
    for (const SharpVertex &c : m_inputs.tags.vertices)
        if (c.vertex == v)
            return c.sharpness;
    return kSharpnessSmooth;
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

int SubdivisionMeshItem::extraordinaryCount() const
{
    const auto p = pieces();
    return p ? awb::extraordinaryCount(*p) : 0;
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
    refined.tags = {};  // the points are on the limit surface: not a control mesh to crease
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
        if (!m_pieces || m_piecesFaces != m_inputs.faces || m_piecesScheme != m_inputs.scheme
            || !(m_piecesTags == m_inputs.tags)) {
            m_pieces.reset();
            m_pieces = std::make_shared<const MeshPieces>(
                buildMeshPieces(m_inputs.mesh(), m_inputs.scheme));
            m_piecesFaces = m_inputs.faces;
            m_piecesScheme = m_inputs.scheme;
            m_piecesTags = m_inputs.tags;
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
    // piece's map 0, once settled) whose valence is at most 64 -- the analysis of a pole of
    // valence 360 (a 721 x 721 matrix) takes a minute; the first of any valence when none is --
    // then the 4 maps of the first patch that maps to itself.
    const Mat *shown = nullptr, *first = nullptr;
    for (const MeshPieceRoot &root : pieces->roots)
        if (const int settled = root.vertex >= 0 ? settledType(*pieces, root.type) : -1;
            settled >= 0) {
            const MeshPieceType &type = pieces->types[std::size_t(settled)];
            first = first ? first : &type.children.front().S;
            if (type.valence <= 64) {
                shown = &type.children.front().S;
                break;
            }
        }
    shown = shown ? shown : first;
    if (shown)
        out.S.real.push_back(*shown);
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
                        // Where a problem is, made only for the message (10^5 faces).
                        const auto at = [&] { return where + QStringLiteral("[%1]").arg(k + 1); };
                        if (!rows[k].isArray())
                            throw LoadError{at(), tr("expected a face: an array of vertex "
                                                     "numbers (0-based)")};
                        const QJsonArray loop = rows[k].toArray();
                        std::vector<int> face;
                        face.reserve(std::size_t(loop.size()));
                        for (qsizetype i = 0; i < loop.size(); ++i) {
                            const QJsonValue n = loop[i];
                            const double x =
                                n.isDouble() && std::isfinite(n.toDouble())
                                    ? n.toDouble()
                                    : FieldReader::toNumber(
                                          n, at() + QStringLiteral("[%1]").arg(i + 1));
                            if (x != std::floor(x) || std::abs(x) > 1e9)
                                throw LoadError{at(), tr("vertex numbers are whole numbers "
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
        // Sharp features (issue 44), each written only when the mesh has it.
        inputs
            .structured(
                "creases", QStringLiteral("creases"),
                [](const I &, const MeshInputs &m) {
                    QJsonArray out;
                    for (const SharpEdge &e : m.tags.edges)
                        out.append(QJsonArray{e.a, e.b, double(e.sharpness)});
                    return QJsonValue(out);
                },
                [](const I &, MeshInputs &m, const QJsonValue &v, const QString &where) {
                    m.tags.edges.clear();
                    for (const QList<double> &row : tagRows(v, where, 3, tr("a crease: [first "
                                                                             "vertex, second "
                                                                             "vertex, sharpness]")))
                        m.tags.edges.push_back({wholeIn(row[0], where), wholeIn(row[1], where),
                                                sharpnessIn(row[2], where)});
                })
            .label(QT_TR_NOOP("Creases"))
            .group(QT_TR_NOOP("Sharp features"))
            .tip(QT_TR_NOOP("Sharp edges as [first vertex, second vertex, sharpness]: sharp for "
                            "that many levels (10 or more: for ever), as OpenSubdiv's creases"))
            .omitWhenDefault();
        inputs
            .structured(
                "corners", QStringLiteral("corners"),
                [](const I &, const MeshInputs &m) {
                    QJsonArray out;
                    for (const SharpVertex &c : m.tags.vertices)
                        out.append(QJsonArray{c.vertex, double(c.sharpness)});
                    return QJsonValue(out);
                },
                [](const I &, MeshInputs &m, const QJsonValue &v, const QString &where) {
                    m.tags.vertices.clear();
                    for (const QList<double> &row :
                         tagRows(v, where, 2, tr("a corner: [vertex, sharpness]")))
                        m.tags.vertices.push_back(
                            {wholeIn(row[0], where), sharpnessIn(row[1], where)});
                })
            .label(QT_TR_NOOP("Corners"))
            .group(QT_TR_NOOP("Sharp features"))
            .tip(QT_TR_NOOP("Sharp vertices as [vertex, sharpness]: the surface passes through "
                            "them while the sharpness lasts"))
            .omitWhenDefault();
        inputs
            .structured(
                "holes", QStringLiteral("numbers"),
                [](const I &, const MeshInputs &m) {
                    QJsonArray out;
                    for (int f : m.tags.holes)
                        out.append(f);
                    return QJsonValue(out);
                },
                [](const I &, MeshInputs &m, const QJsonValue &v, const QString &where) {
                    m.tags.holes.clear();
                    for (const QList<double> &row :
                         tagRows(v, where, 1, tr("a face number (0-based)")))
                        m.tags.holes.push_back(wholeIn(row[0], where));
                })
            .label(QT_TR_NOOP("Holes"))
            .group(QT_TR_NOOP("Sharp features"))
            .tip(QT_TR_NOOP("Faces (0-based) left out of the surface; they still shape their "
                            "neighbours"))
            .omitWhenDefault();
        inputs
            .choice(
                "boundary", [](auto &m) -> auto & { return m.tags.options.boundary; },
                {"none", "edge-only", "edge-and-corner"},
                {QT_TR_NOOP("None (faces at the boundary are left out)"), QT_TR_NOOP("Edges"),
                 QT_TR_NOOP("Edges and corners")})
            .label(QT_TR_NOOP("Boundary"))
            .group(QT_TR_NOOP("Sharp features"))
            .tip(QT_TR_NOOP("How the boundary is interpolated (OpenSubdiv's "
                            "VtxBoundaryInterpolation): with corners, a vertex of one face is a "
                            "corner of the surface"))
            .omitWhenDefault();
        inputs
            .choice(
                "crease-method", [](auto &m) -> auto & { return m.tags.options.creaseMethod; },
                {"uniform", "chaikin"}, {QT_TR_NOOP("Uniform"), QT_TR_NOOP("Chaikin")})
            .label(QT_TR_NOOP("Crease method"))
            .group(QT_TR_NOOP("Sharp features"))
            .tip(QT_TR_NOOP("How a semi-sharp crease decays: by 1 per level, or Chaikin's "
                            "average with its neighbours"))
            .omitWhenDefault();
        inputs
            .choice(
                "triangles", [](auto &m) -> auto & { return m.tags.options.triangles; },
                {"catmark", "smooth"},
                {QT_TR_NOOP("Catmull–Clark"), QT_TR_NOOP("Smooth triangles")})
            .label(QT_TR_NOOP("Triangles"))
            .group(QT_TR_NOOP("Sharp features"))
            .tip(QT_TR_NOOP("Catmull–Clark's edge points next to triangles: as for any face, or "
                            "OpenSubdiv's smoother weights"))
            .omitWhenDefault();
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
