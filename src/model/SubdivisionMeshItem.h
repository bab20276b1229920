#pragma once
// Document item "subdivision-mesh" (layer 2, model; issue 30): a polygon mesh of any topology
// -- vertices in R^3, faces as vertex loops -- and its Catmull-Clark or Loop limit surface,
// drawn as the attractor of the mesh's IFS with condensation (core/mesh/MeshPieces.h): regular
// patches as their 4 maps, the neighbourhood of each extraordinary vertex as its ring's map
// with the annulus of patches as condensation set. The mesh's vertices are the item's control
// points (moving one is one undo step); the faces and the scheme change together with them.

#include "model/AttractorItem.h"

#include "core/mesh/Mesh.h"

#include <mutex>

namespace awb {

struct MeshPieces;
struct ExtraordinaryVertex;

// Every input that changes together: the faces index the vertices, the scheme takes them.
struct MeshInputs {
    Q_DECLARE_TR_FUNCTIONS(awb::MeshInputs)
public:
    MeshScheme scheme = MeshScheme::CatmullClark;
    PointList vertices;
    std::vector<std::vector<int>> faces;
    // Sharp features and rule options (creases, corners, holes, boundary, crease method,
    // triangles: core/mesh/MeshTags.h), as OpenSubdiv takes them.
    MeshTags tags;
    // Colours: by map (false), or the neighbourhoods of extraordinary vertices by level
    // (C, f(C), f^2(C), ... in turn; MeshStart::levelAddresses).
    bool levelColours = false;

    bool operator==(const MeshInputs &) const = default;
    Mesh mesh() const;
    // The core's checks (checkMesh): field "faces" or "vertices" with its message.
    MaybeProblem check() const;
    // JSON spellings of the schemes, in MeshScheme order.
    static const QStringList &schemeNames();
};

class SubdivisionMeshItem : public AttractorItem {
    Q_OBJECT
public:
    SubdivisionMeshItem();
    ~SubdivisionMeshItem() override;

    static QString staticType() { return QStringLiteral("subdivision-mesh"); }
    static QString staticTypeName() { return tr("Mesh surface"); }
    QString type() const override { return staticType(); }
    QString typeName() const override { return staticTypeName(); }

    const MeshInputs &inputs() const { return m_inputs; }
    MeshScheme scheme() const { return m_inputs.scheme; }
    Mesh mesh() const { return m_inputs.mesh(); }
    MaybeProblem checkInputs(const MeshInputs &inputs) const { return inputs.check(); }
    // Undoable, one step; refused (false, *error says why) when checkInputs() complains.
    bool setInputs(const MeshInputs &inputs, QString *error = nullptr, int gesture = 0);
    bool setScheme(MeshScheme scheme, QString *error = nullptr);
    // A new mesh (an import, a starting mesh), with its scheme.
    bool setMesh(const Mesh &mesh, MeshScheme scheme, QString *error = nullptr);
    // The sharpness of the edge joining a and b (0: smooth, the crease removed; 10 or more:
    // infinitely sharp), or of vertex v (a corner while it lasts): one undo step each, refused
    // when no edge joins a and b or v is not a vertex. The current values: 0 when untagged.
    bool setEdgeSharpness(int a, int b, float sharpness, QString *error = nullptr);
    bool setVertexSharpness(int v, float sharpness, QString *error = nullptr);
    float edgeSharpness(int a, int b) const;
    float vertexSharpness(int v) const;
    // Face f made a hole (refined with the others, drawn as nothing: OpenSubdiv's hole tag) or
    // filled again: one undo step, refused when f is not a face.
    bool setHole(int face, bool hole, QString *error = nullptr);
    bool isHole(int face) const;

    // The pieces of the mesh's IFS: they depend on the faces and the scheme only, so moving a
    // vertex keeps them. Null when the mesh is refused (derivedError() says why).
    std::shared_ptr<const MeshPieces> pieces() const;
    // The extraordinary vertices with their spectra (empty when the mesh is refused); kept
    // until the mesh changes.
    std::shared_ptr<const std::vector<ExtraordinaryVertex>> extraordinary() const;
    // How many extraordinary() lists, without analysing them (0 when the mesh is refused).
    int extraordinaryCount() const;
    // The one at input vertex `vertex` (or, with `face` >= 0, at the centre of that face), or
    // null.
    const ExtraordinaryVertex *findExtraordinary(
        const std::vector<ExtraordinaryVertex> &list, int vertex, int face = -1) const;

    // The mesh after `rounds` steps of its scheme, every vertex at its exact limit position, as
    // OBJ text (File > Export Mesh, attractor-cli export --format obj). InputError when the
    // mesh is refused or the steps give more than maxExportVertices vertices.
    static constexpr int maxExportRounds = 8;
    static constexpr Eigen::Index maxExportVertices = 50'000'000;
    std::string limitObj(int rounds) const;

    // Declared: "scheme.kind" (Catmull-Clark, Loop), "vertices", "faces", the sharp features
    // "creases" ([a, b, sharpness] each), "corners" ([vertex, sharpness]), "holes" (faces),
    // the options "boundary", "crease-method", "triangles", and "colouring" (by map, by level). docs/adding-an-item-kind.md walks through this declaration.
    static const PropertyTable &declaration();
    const PropertyTable &properties() const override { return declaration(); }

    int mapCount() const override { return 4; }
    int pointDimension() const override { return 3; }
    int controlPointSetCount() const override { return 1; }
    bool pointCountEditable(int) const override { return false; }
    static constexpr int maxVertices = 2000000;
    int maxPointCount(int) const override { return maxVertices; }
    bool startsAtVertexLimits() const override { return true; }

signals:
    void meshChanged();

protected:
    DerivedIfs computeIfs() const override;
    PointList &pointStorage(int) override { return m_inputs.vertices; }

private:
    MeshInputs m_inputs;
    // The pieces for (faces, scheme), kept across vertex moves.
    mutable std::mutex m_piecesMutex;
    mutable std::shared_ptr<const MeshPieces> m_pieces;
    mutable std::vector<std::vector<int>> m_piecesFaces;
    mutable MeshTags m_piecesTags;
    mutable MeshScheme m_piecesScheme = MeshScheme::CatmullClark;
    // extraordinary() for m_extraordinaryOf.
    mutable std::shared_ptr<const std::vector<ExtraordinaryVertex>> m_extraordinary;
    mutable MeshInputs m_extraordinaryOf;
};

} // namespace awb
