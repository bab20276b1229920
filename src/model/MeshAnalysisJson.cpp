#include "model/MeshAnalysisJson.h"

#include "core/mesh/MeshAnalysis.h"
#include "core/mesh/MeshPieces.h"
#include "core/mesh/VertexSpectrum.h"
#include "model/ProjectIO.h"
#include "model/SubdivisionMeshItem.h"

#include <QJsonArray>

#include <map>
#include <tuple>

namespace awb {

namespace {

QJsonObject characteristicJson(const VertexSpectrum &s)
{
    const CharacteristicMap &m = s.characteristic;
    if (!s.spectralC1)
        return {};
    return {{"regular", s.characteristicRegular},
            {"injective", s.characteristicInjective},
            {"winding", m.winding},
            {"min_area", m.minArea},
            {"max_area", m.maxArea},
            {"cells", int(m.cells.size())}};
}

// What the matrix of an extraordinary vertex says, the same for every vertex of its kind.
QJsonObject kindJson(const ExtraordinaryVertex &e, MeshScheme scheme)
{
    QJsonObject o;
    o["valence"] = e.valence;
    o["boundary"] = e.boundary;
    o["rule"] = QString::fromStdString(e.rule);
    // Smooth inside: the ring of every point within two faces; on the boundary and at sharp
    // features: the vertex piece's net (its S_0), and the verdicts sector by sector ("sectors",
    // on the canonical star of the neighbourhood, VertexSpectrum.h).
    o["ring"] = QString::fromStdString(e.ring);
    o["ring_size"] = e.ringSize;
    QJsonArray ev;
    for (const Complex &z : e.eigenvalues())
        ev.append(QJsonArray{z.real(), z.imag()});
    o["eigenvalues"] = ev;
    o["subdominant"] = e.subdominant;
    o["subsubdominant"] = e.subsubdominant;
    o["c1"] = e.c1 ? QJsonValue(*e.c1) : QJsonValue(QJsonValue::Null);
    o["curvature"] = e.curvature.empty() ? QJsonValue(QJsonValue::Null)
                                         : QJsonValue(QString::fromStdString(e.curvature));
    if (e.smoothInterior() && ringAnalysable(e.valence))
        o["characteristic_map"] = characteristicJson(*sharedVertexSpectrum(scheme, e.valence));
    if (e.sharp) {
        QJsonArray sectors;
        for (const SectorVerdict &v : e.sharp->sectors) {
            QJsonObject j{{"first_face", v.firstFace},
                          {"faces", v.faces},
                          {"lambda1", v.lambda1},
                          {"lambda2", v.lambda2},
                          {"mu", v.mu},
                          {"spectral", v.spectral},
                          {"crease_in_plane", v.creaseInPlane},
                          {"regular", v.regular},
                          {"injective", v.injective},
                          {"c1", v.decided ? QJsonValue(v.c1()) : QJsonValue(QJsonValue::Null)},
                          {"curvature", QString::fromStdString(v.curvature)}};
            if (!v.reason.empty())
                j["reason"] = QString::fromStdString(v.reason);
            if (!v.chain.empty())
                j["jordan"] = QString::fromStdString(v.chain);
            sectors.append(j);
        }
        o["sectors"] = sectors;
    }
    if (!e.note.empty())
        o["note"] = QString::fromStdString(e.note);
    return o;
}

// A vertex: where it is, and its kind (an index into "vertex_kinds"). Its keys are inserted
// in the object's own (sorted) order, each an append, as Latin-1 views (no QString each): a
// large mesh lists a hundred thousand of these, and the unsorted inserts were a sixth of
// `analyse`.
QJsonObject vertexJson(const ExtraordinaryVertex &e, int kind)
{
    using namespace Qt::StringLiterals;
    QJsonObject o;
    if (e.vertex < 0)
        o.insert("face"_L1, e.face);
    o.insert("kind"_L1, kind);
    if (e.limit.size() == 3) {
        o.insert("limit"_L1, ProjectIO::rowToJson(e.limit));
        o.insert("normal"_L1, ProjectIO::rowToJson(e.normal));
    }
    o.insert("rule"_L1, QString::fromStdString(e.rule));
    o.insert("valence"_L1, e.valence);
    if (e.vertex >= 0)
        o.insert("vertex"_L1, e.vertex);
    return o;
}

QJsonObject piecesJson(const MeshPieces &pieces)
{
    QJsonArray types;
    for (std::size_t t = 0; t < pieces.types.size(); ++t) {
        const MeshPieceType &type = pieces.types[t];
        const bool vertex = type.kind == MeshPieceType::Kind::Vertex;
        QJsonObject o{{"index", int(t)},
                      {"kind", vertex ? "vertex" : "face"},
                      {"net_size", type.netSize},
                      {"boundary", type.boundary},
                      {"roots", type.roots}};
        if (vertex) {
            o["valence"] = type.valence;
            o["rule"] = QString::fromStdString(toString(type.rule));
            o["settles_in"] = settledType(pieces, int(t));
        }
        QJsonArray maps;
        for (const MeshPieceType::Child &c : type.children)
            maps.append(QJsonObject{{"to", c.type},
                                    {"rows", int(c.S.rows())},
                                    {"columns", int(c.S.cols())}});
        o["maps"] = maps;
        types.append(o);
    }
    return {{"isolation_steps", pieces.steps},
            {"roots", int(pieces.roots.size())},
            {"lone_vertices", int(pieces.loneVertices.size())},
            {"types", types}};
}

} // namespace

ItemAnalysis meshAnalysis(const SubdivisionMeshItem &item)
{
    ItemAnalysis analysis;
    const auto pieces = item.pieces();
    if (!pieces)
        return analysis;
    QJsonObject &o = analysis.json;
    o["kind"] = item.type();
    o["scheme"] = MeshInputs::schemeNames().at(int(item.scheme()));
    o["vertex_count"] = int(item.inputs().vertices.size());
    o["face_count"] = int(item.inputs().faces.size());
    // The vertices, and their kinds once each: a mesh of a million faces has hundreds of
    // thousands of extraordinary vertices and a few kinds (the output's size is what it says).
    // The vertices' JSON is made one at a time, when asked for (a list: printed as it goes).
    QJsonArray kinds;
    std::vector<int> counts;
    std::map<std::tuple<const AnalysedMatrix *, int, bool, std::string, std::string>, int> kindOf;
    const auto vertices = item.extraordinary();  // held by the list's members
    auto kindOfVertex = std::make_shared<std::vector<int>>();
    kindOfVertex->reserve(vertices->size());
    for (const ExtraordinaryVertex &e : *vertices) {
        const auto [it, added] = kindOf.emplace(
            std::make_tuple(e.matrix.get(), e.valence, e.boundary, e.rule, e.note),
            int(kinds.size()));
        if (added) {
            QJsonObject kind = kindJson(e, item.scheme());
            kind["index"] = it->second;
            kinds.append(kind);
            counts.push_back(0);
        }
        ++counts[std::size_t(it->second)];
        kindOfVertex->push_back(it->second);
    }
    for (auto &&kind : kinds) {  // how many vertices each kind has
        QJsonObject k = kind.toObject();
        k["vertices"] = counts[std::size_t(k["index"].toInt())];
        kind = k;
    }
    analysis.lists["extraordinary"] = {
        qsizetype(vertices->size()), [vertices, kindOfVertex](qsizetype i) -> QJsonValue {
            return vertexJson((*vertices)[std::size_t(i)], (*kindOfVertex)[std::size_t(i)]);
        }};
    o["vertex_kinds"] = kinds;
    o["pieces"] = piecesJson(*pieces);
    return analysis;
}

QJsonArray valenceTableJson(MeshScheme scheme, int from, int to)
{
    QJsonArray rows;
    for (int n = from; n <= to; ++n) {
        const auto s = sharedVertexSpectrum(scheme, n);
        rows.append(QJsonObject{{"valence", n},
                                {"subdominant", s->subdominant},
                                {"closed_form", closedFormSubdominant(scheme, n)},
                                {"subsubdominant", s->subsubdominant},
                                {"lambda_squared", s->subdominant * s->subdominant},
                                {"spectral_c1", s->spectralC1},
                                {"characteristic_map", characteristicJson(*s)},
                                {"c1", s->c1},
                                {"curvature", QString::fromStdString(s->curvature)},
                                {"ring_size", int(s->S.rows())}});
    }
    return rows;
}

} // namespace awb
