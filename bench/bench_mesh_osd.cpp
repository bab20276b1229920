// attractor-bench-mesh's OpenSubdiv routes (bench_mesh.cpp has the others and the table).

#include "BenchMesh.h"

#include <opensubdiv/far/primvarRefiner.h>
#include <opensubdiv/far/stencilTable.h>
#include <opensubdiv/far/stencilTableFactory.h>
#include <opensubdiv/far/topologyDescriptor.h>

#include <memory>
#include <thread>

namespace awb::benchmesh {

namespace osd = OpenSubdiv;

namespace {

// OpenSubdiv's primvar: three doubles with the two members PrimvarRefiner and StencilTable use.
struct OsdPoint {
    double p[3];
    void Clear(void * = nullptr) { p[0] = p[1] = p[2] = 0; }
    void AddWithWeight(const OsdPoint &s, double w)
    {
        p[0] += w * s.p[0];
        p[1] += w * s.p[1];
        p[2] += w * s.p[2];
    }
};

// The mesh as OpenSubdiv's descriptor, with the options of tests/core/test_mesh_opensubdiv.cpp
// (the ones under which both agree): boundary vertices interpolated along edges only,
// triangles in a Catmull-Clark mesh by Catmull-Clark's rules.
struct OsdInput {
    explicit OsdInput(const Mesh &m, MeshScheme s) : scheme(s)
    {
        for (const auto &f : m.faces) {
            counts.push_back(int(f.size()));
            indices.insert(indices.end(), f.begin(), f.end());
        }
        desc.numVertices = int(m.vertices.rows());
        desc.numFaces = int(m.faces.size());
        desc.numVertsPerFace = counts.data();
        desc.vertIndicesPerFace = indices.data();
        control.resize(std::size_t(m.vertices.rows()));
        for (Eigen::Index v = 0; v < m.vertices.rows(); ++v)
            for (int k = 0; k < 3; ++k)
                control[std::size_t(v)].p[k] = m.vertices(v, k);
    }
    // Topology only: the factory and the uniform refinement to `levels`, with the full topology
    // of the last level (PrimvarRefiner::Limit needs it).
    std::unique_ptr<osd::Far::TopologyRefiner> refiner(int levels) const
    {
        osd::Sdc::Options options;
        options.SetVtxBoundaryInterpolation(osd::Sdc::Options::VTX_BOUNDARY_EDGE_ONLY);
        options.SetTriangleSubdivision(osd::Sdc::Options::TRI_SUB_CATMARK);
        using Factory = osd::Far::TopologyRefinerFactory<osd::Far::TopologyDescriptor>;
        const auto type =
            scheme == MeshScheme::Loop ? osd::Sdc::SCHEME_LOOP : osd::Sdc::SCHEME_CATMARK;
        std::unique_ptr<osd::Far::TopologyRefiner> r(
            Factory::Create(desc, Factory::Options(type, options)));
        osd::Far::TopologyRefiner::UniformOptions uniform(levels);
        uniform.fullTopologyInLastLevel = true;
        r->RefineUniform(uniform);
        return r;
    }

    MeshScheme scheme;
    std::vector<int> counts, indices;
    osd::Far::TopologyDescriptor desc;
    std::vector<OsdPoint> control;
};

// Route 3: refiner (setup), Interpolate level by level and Limit (data).

} // namespace

std::vector<Figures> osdRoute(const Case &c, int rounds, const Reference &ref)
{
    const OsdInput input(c.mesh, c.scheme);
    double setup = 1e300, interp = 1e300, limit = 1e300;
    std::vector<OsdPoint> limits;
    for (int r = 0; r < rounds; ++r) {
        std::unique_ptr<osd::Far::TopologyRefiner> refiner;
        setup = std::min(setup, timed([&] { refiner = input.refiner(c.depth); }));
        std::vector<OsdPoint> buffer;
        OsdPoint *src = nullptr;
        interp = std::min(interp, timed([&] {
            buffer.resize(std::size_t(refiner->GetNumVerticesTotal()));
            std::copy(input.control.begin(), input.control.end(), buffer.begin());
            osd::Far::PrimvarRefinerReal<double> primvar(*refiner);
            src = buffer.data();
            for (int level = 1; level <= c.depth; ++level) {
                OsdPoint *dst = src + refiner->GetLevel(level - 1).GetNumVertices();
                primvar.Interpolate(level, src, dst);
                src = dst;
            }
        }));
        limit = std::min(limit, timed([&] {
            limits.assign(std::size_t(refiner->GetLevel(c.depth).GetNumVertices()), OsdPoint{});
            osd::Far::PrimvarRefinerReal<double> primvar(*refiner);
            primvar.Limit(src, limits);
        }));
    }
    Figures f;
    std::snprintf(f.route, sizeof f.route, "OSD: Interpolate+Limit");
    f.setup = setup;
    f.data = interp + limit;
    f.total = setup + interp + limit;
    f.points = double(limits.size());
    f.peakMb = peakMbSinceFork();
    std::snprintf(f.notes, sizeof f.notes, "Interpolate %.4f s, Limit %.4f s", interp, limit);
    Check check(*ref.grid);
    for (const OsdPoint &p : limits)
        check.add(p.p);
    fillDiff(f, check, ref);
    return {f};
}

// Route 4: refiner and stencil table (setup), UpdateValues on 1 or 2 threads and Limit (data).
std::vector<Figures> osdTableRoute(const Case &c, int rounds, const Reference &ref)
{
    using Table = osd::Far::StencilTableReal<double>;
    using TableFactory = osd::Far::StencilTableFactoryReal<double>;
    const OsdInput input(c.mesh, c.scheme);
    double refine = 1e300, create = 1e300;
    std::unique_ptr<osd::Far::TopologyRefiner> refiner;
    std::unique_ptr<const Table> table;
    for (int r = 0; r < rounds; ++r) {
        table.reset();
        refiner.reset();
        refine = std::min(refine, timed([&] { refiner = input.refiner(c.depth); }));
        create = std::min(create, timed([&] {
            TableFactory::Options options;
            options.interpolationMode = TableFactory::INTERPOLATE_VERTEX;
            options.generateOffsets = true;  // UpdateValues on a range needs them
            options.generateControlVerts = false;
            options.generateIntermediateLevels = false;
            options.factorizeIntermediateLevels = true;
            options.maxLevel = unsigned(c.depth);
            table.reset(TableFactory::Create(*refiner, options));
        }));
    }
    const int n = table->GetNumStencils();
    std::vector<OsdPoint> level(static_cast<std::size_t>(n)), limits(static_cast<std::size_t>(n));
    double apply[3] = {0, 1e300, 1e300};
    for (int threads : {1, 2})
        for (int r = 0; r < rounds; ++r)
            apply[threads] = std::min(apply[threads], timed([&] {
                const OsdPoint *src = input.control.data();
                OsdPoint *dst = level.data();
                if (threads == 1) {
                    table->UpdateValues(src, dst);
                } else {
                    std::thread other([&] { table->UpdateValues(src, dst, n / 2, n); });
                    table->UpdateValues(src, dst, 0, n / 2);
                    other.join();
                }
            }));
    double limit = 1e300;
    const osd::Far::PrimvarRefinerReal<double> primvar(*refiner);
    for (int r = 0; r < rounds; ++r)
        limit = std::min(limit, timed([&] {
            const OsdPoint *src = level.data();
            primvar.Limit(src, limits);
        }));
    const double peak = peakMbSinceFork();
    Check check(*ref.grid);
    for (const OsdPoint &p : limits)
        check.add(p.p);
    std::vector<Figures> out;
    for (int threads : {1, 2}) {
        Figures f;
        std::snprintf(f.route, sizeof f.route, "OSD: stencil table+Limit");
        f.threads = threads;
        f.setup = refine + create;
        f.data = apply[threads] + limit;
        f.total = f.setup + f.data;
        f.points = double(n);
        f.peakMb = peak;
        std::snprintf(f.notes, sizeof f.notes,
                      "refiner %.4f s, table %.4f s (%.1f entries/stencil); UpdateValues "
                      "%.4f s, Limit %.4f s",
                      refine, create, double(table->GetWeights().size()) / std::max(n, 1),
                      apply[threads], limit);
        fillDiff(f, check, ref);
        out.push_back(f);
    }
    return out;
}

} // namespace awb::benchmesh
