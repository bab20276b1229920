#include "core/mesh/MeshAnalysis.h"

#include "core/analysis/Spectrum.h"
#include "core/mesh/VertexSpectrum.h"

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <Eigen/QR>

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>

namespace awb {

namespace {

// The left eigenvectors of S that give the limit (eigenvalue 1, weights summing to 1) and the
// tangent plane (the subdominant pair: two real eigenvectors, or the real and imaginary parts
// of one complex one).
struct LeftVectors {
    RowVec limit, tangentA, tangentB;
};

// A basis of the left eigenspace of S for the eigenvalue `value` (real, of multiplicity
// `count`), by inverse iteration with a shift just beside it: one LU of S^T - shift I, a few
// solves (the big matrices of high valences, where a full eigendecomposition takes seconds).
Mat leftEigenspace(const Mat &S, double value, int count)
{
    const Eigen::Index n = S.rows();
    const double shift = value + 1e-9 * std::max(1.0, std::abs(value));
    const Eigen::PartialPivLU<Mat> lu(Mat(S.transpose()) - shift * Mat::Identity(n, n));
    Mat x = Mat::Zero(n, count);
    for (int k = 0; k < count; ++k)  // fixed, distinct starting vectors: the same on every run
        for (Eigen::Index i = 0; i < n; ++i)
            x(i, k) = 1.0 + std::sin(double((k + 1) * (i + 1)));
    for (int step = 0; step < 3; ++step) {
        x = lu.solve(x);
        x = Eigen::HouseholderQR<Mat>(x).householderQ() * Mat::Identity(n, count);
    }
    return x;
}

LeftVectors leftVectors(const Mat &S, std::optional<double> subdominant = std::nullopt)
{
    if (subdominant && S.rows() > 200) {
        LeftVectors out;
        out.limit = leftEigenspace(S, 1.0, 1).col(0).transpose();
        out.limit /= out.limit.sum();
        const Mat tangents = leftEigenspace(S, *subdominant, 2);
        out.tangentA = tangents.col(0).transpose();
        out.tangentB = tangents.col(1).transpose();
        return out;
    }
    const Spectrum left = spectrum(Mat(S.transpose()), 1e-9);  // by modulus, largest first
    LeftVectors out;
    out.limit = left.vectors[0].real().transpose();
    out.limit /= out.limit.sum();
    out.tangentA = left.vectors[1].real().transpose();
    out.tangentB = left.vectors[1].imag().transpose();
    if (out.tangentB.norm() < 1e-12 * out.tangentA.norm())
        out.tangentB = left.vectors[2].real().transpose();
    return out;
}

// `outward`: the sum of the normals of the faces at the vertex (counter-clockwise seen from
// outside), which orients the normal.
void limitAndNormal(const LeftVectors &v, const Mat &net, const Eigen::Vector3d &outward,
                    ExtraordinaryVertex &out)
{
    out.limit = v.limit * net;
    const Eigen::Vector3d ta = (v.tangentA * net).transpose();
    const Eigen::Vector3d tb = (v.tangentB * net).transpose();
    Eigen::Vector3d n = ta.cross(tb);
    if (n.dot(outward) < 0)
        n = -n;
    out.normal = n.norm() > 1e-300 ? RowVec(n.normalized().transpose()) : RowVec::Zero(3);
}

} // namespace

const Mat &ExtraordinaryVertex::S() const
{
    static const Mat none;
    return matrix ? matrix->S : none;
}

const std::vector<Complex> &ExtraordinaryVertex::eigenvalues() const
{
    static const std::vector<Complex> none;
    return matrix ? matrix->eigenvalues : none;
}

namespace {

// Whether a piece's root is one of the extraordinary vertices listed: a vertex root (not a
// face's), not a corner of one face (the crease rule), and a point of the input (a vertex, or
// a Catmull-Clark face's centre), not one the isolating steps made.
bool listed(const MeshPieces &pieces, const MeshPieceRoot &root)
{
    if (root.vertex < 0)
        return false;
    const MeshPieceType &type = pieces.types[std::size_t(root.type)];
    if (type.boundary && type.valence == 2)
        return false;
    return pieces.origin[std::size_t(root.vertex)] != MeshPieces::kNewPoint;
}

} // namespace

int extraordinaryCount(const MeshPieces &pieces)
{
    int n = 0;
    for (const MeshPieceRoot &root : pieces.roots)
        n += listed(pieces, root);
    return n;
}

std::vector<ExtraordinaryVertex> extraordinaryVertices(const MeshPieces &pieces,
                                                       const Mat &inputVertices)
{
    const Mat level = isolatedPositions(pieces, inputVertices);
    std::map<int, LeftVectors> left;         // by settled type
    // By vertex of the isolated mesh: the sum of its faces' corner normals (vertex roots only).
    std::vector<Eigen::Vector3d> outward(std::size_t(level.rows()), Eigen::Vector3d::Zero());
    std::vector<char> rooted(std::size_t(level.rows()), 0);
    for (const MeshPieceRoot &root : pieces.roots)
        if (root.vertex >= 0)
            rooted[std::size_t(root.vertex)] = 1;
    for (const auto &face : pieces.isolatedFaces)
        for (std::size_t k = 0; k < face.size(); ++k)
            if (rooted[std::size_t(face[k])]) {
                const Eigen::Vector3d p = level.row(face[k]).transpose();
                const Eigen::Vector3d a = level.row(face[(k + 1) % face.size()]).transpose();
                const Eigen::Vector3d b =
                    level.row(face[(k + face.size() - 1) % face.size()]).transpose();
                outward[std::size_t(face[k])] += (a - p).cross(b - p);
            }
    // One array of the count listed (a large mesh lists a hundred thousand of these: two
    // growing arrays, then one joined from them, held three copies at once).
    std::vector<ExtraordinaryVertex> vertices;
    vertices.reserve(std::size_t(extraordinaryCount(pieces)));
    std::map<int, std::shared_ptr<const AnalysedMatrix>> ringMatrices;   // by valence
    std::map<int, std::shared_ptr<const AnalysedMatrix>> pieceMatrices;  // by settled type
    for (const MeshPieceRoot &root : pieces.roots) {
        if (!listed(pieces, root))
            continue;
        const MeshPieceType &type = pieces.types[std::size_t(root.type)];
        const int origin = pieces.origin[std::size_t(root.vertex)];
        ExtraordinaryVertex e;
        if (origin >= 0)
            e.vertex = origin;
        else
            e.face = -1 - origin;
        e.valence = type.valence;
        e.boundary = type.boundary;
        // The net of the settled type, and its S.
        const auto rootNet = pieces.net(root);
        Mat net(Eigen::Index(rootNet.size()), 3);
        for (std::size_t i = 0; i < rootNet.size(); ++i)
            net.row(Eigen::Index(i)) = level.row(rootNet[i]);
        int t = root.type;
        const int settled = settledType(pieces, t);
        while (settled >= 0 && t != settled) {
            const MeshPieceType::Child &c = pieces.types[std::size_t(t)].children.front();
            net = c.S * net;
            t = c.type;
        }
        e.rule = toString(pieces.types[std::size_t(settled >= 0 ? settled : t)].rule);
        if (settled >= 0) {
            auto it = left.find(settled);
            if (it == left.end()) {
                // A smooth interior vertex: its subdominant eigenvalue in closed form (double,
                // the tangent plane), and for a high valence the eigenvectors of those two
                // eigenvalues alone.
                const MeshPieceType &type = pieces.types[std::size_t(settled)];
                std::optional<double> lambda;
                if (!type.boundary && type.rule == VertexRule::Smooth)
                    lambda = closedFormSubdominant(pieces.scheme, type.valence);
                it = left.emplace(settled, leftVectors(type.children[0].S, lambda)).first;
            }
            limitAndNormal(it->second, net, outward[std::size_t(root.vertex)], e);
        }
        if (e.smoothInterior() && !ringAnalysable(e.valence)) {
            e.ring = "none";
            e.note = formatMessage(
                coreTranslate("awb::mesh", "the ring analysis takes interior valences 3 to 64; "
                                           "this vertex has %1"),
                e.valence);
        } else if (e.smoothInterior()) {
            const auto shared = sharedVertexSpectrum(pieces.scheme, e.valence);
            const VertexSpectrum &s = *shared;
            e.ring = "ring";
            e.ringSize = int(s.S.rows());
            auto &matrix = ringMatrices[e.valence];
            if (!matrix)
                matrix = std::make_shared<const AnalysedMatrix>(AnalysedMatrix{s.S, s.eigenvalues});
            e.matrix = matrix;
            e.subdominant = s.subdominant;
            e.subsubdominant = s.subsubdominant;
            e.c1 = s.c1;
            e.curvature = s.curvature;
        } else if (settled >= 0) {
            const Mat &S = pieces.types[std::size_t(settled)].children.front().S;
            e.ring = "piece";
            e.ringSize = int(S.rows());
            auto &matrix = pieceMatrices[settled];
            if (!matrix)
                matrix = std::make_shared<const AnalysedMatrix>(
                    AnalysedMatrix{S, spectrum(S, 1e-9).values});
            e.matrix = matrix;
            const auto &values = matrix->eigenvalues;
            if (values.size() > 1)
                e.subdominant = std::abs(values[1]);
            for (std::size_t k = 2; k < values.size(); ++k)
                if (std::abs(values[k]) < e.subdominant - 1e-9) {
                    e.subsubdominant = std::abs(values[k]);
                    break;
                }
            // Reif's criterion sector by sector, on the canonical star of this neighbourhood.
            const MeshPieceType &type = pieces.types[std::size_t(settled)];
            SharpNeighbourhood star;
            star.valence = type.valence;
            star.boundary = type.boundary;
            for (float sharpness : type.ringSharpness)
                star.sharpEdges.push_back(crease::isInfinite(sharpness) ? 1 : 0);
            star.sharpVertex = crease::isInfinite(type.vertexSharpness);
            if (ringAnalysable(star.valence) && int(star.sharpEdges.size()) == star.valence) {
                e.sharp = sharedSharpVertexSpectrum(pieces.scheme, star);
                e.c1 = e.sharp->c1;
                e.curvature = e.sharp->curvature;
            }
        }
        vertices.push_back(std::move(e));
    }
    // The input's vertices by number, then the faces' centres by face.
    const auto order = [](const ExtraordinaryVertex &e) {
        return e.vertex >= 0 ? std::pair{0, e.vertex} : std::pair{1, e.face};
    };
    std::sort(vertices.begin(), vertices.end(),
              [&](const auto &a, const auto &b) { return order(a) < order(b); });
    return vertices;
}

} // namespace awb
