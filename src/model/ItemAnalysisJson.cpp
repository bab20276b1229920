// The analysis of one item as JSON (ItemAnalysisJson.h): attractor-cli analyse and
// attractor_workbench's Item.analyse() print the same object.

#include "model/ItemAnalysisJson.h"

#include "model/AutomatonAnalysisJson.h"
#include "model/BcifsJunctionItem.h"
#include "model/BezierUnionItem.h"
#include "core/analysis/InvariantPolytope.h"
#include "model/CifsItem.h"

#include "core/analysis/Geometry.h"
#include "core/analysis/HausdorffBracket.h"
#include "core/analysis/Spectrum.h"
#include "core/ifs/SurfaceIfs.h"
#include "model/AttractorItem.h"
#include "model/ExactCurve.h"
#include "model/MapMatrices.h"
#include "model/MeshAnalysisJson.h"
#include "model/NumberFormat.h"
#include "model/SchemeRegularity.h"
#include "model/SubdivisionCurveItem.h"
#include "model/SubdivisionMeshItem.h"
#include "model/SubdivisionSurfaceItem.h"

#include <QCoreApplication>
#include <QJsonArray>

namespace awb {

namespace {

QJsonArray complexJson(Complex z) { return {z.real(), z.imag()}; }

// A real matrix as numbers and as exact text ("3/8" where rational): {"values", "exact"}.
QJsonObject matrixJson(const Mat &m)
{
    QJsonArray values, exact;
    for (Eigen::Index r = 0; r < m.rows(); ++r) {
        QJsonArray v, e;
        for (Eigen::Index c = 0; c < m.cols(); ++c) {
            v.append(m(r, c));
            e.append(exactText(m(r, c)));
        }
        values.append(v);
        exact.append(e);
    }
    return {{"values", values}, {"exact", exact}};
}

// A complex matrix as [re, im] pairs: {"values"}.
QJsonObject matrixJson(const CMat &m)
{
    QJsonArray values;
    for (Eigen::Index r = 0; r < m.rows(); ++r) {
        QJsonArray v;
        for (Eigen::Index c = 0; c < m.cols(); ++c)
            v.append(complexJson(m(r, c)));
        values.append(v);
    }
    return {{"values", values}};
}

QJsonArray eigenvaluesJson(const std::vector<Complex> &values)
{
    QJsonArray ev;
    for (const Complex &z : values)
        ev.append(complexJson(z));
    return ev;
}

// The map matrices of analysis map i (MapMatrices.h) as JSON.
void addMapMatrices(QJsonObject &o, const MapMatrices &m)
{
    if (m.S)
        o["S"] = matrixJson(*m.S);
    else if (m.complexS)
        o["S"] = matrixJson(*m.complexS);
    if (m.M)
        o["M"] = matrixJson(*m.M);
    else if (m.complexM)
        o["M"] = matrixJson(*m.complexM);
    if (m.A)
        o["A"] = matrixJson(*m.A);
    else if (m.complexA)
        o["A"] = matrixJson(*m.complexA);
    if (m.b)
        o["b"] = matrixJson(Mat(*m.b));
    else if (m.complexB)
        o["b"] = matrixJson(*m.complexB);
    if (m.A || m.complexA)
        o["eigenvalues_A"] = eigenvaluesJson(m.eigenvaluesA);
}

// d_H(F^depth(X0), exact curve) at the item's depth (or the deepest depth under 2e6 points),
// certified (core HausdorffBracket: the curve refined adaptively by enclosures of its exact
// pieces, not sampled). "value" and "one_sided" are the midpoints of their brackets:
//   value_bracket      contains d_H(F^depth(X0), C) = max of the two one-sided distances,
//   one_sided_bracket  contains sup over the points a of dist(a, C),
//   curve_side_bracket contains sup over the curve points c of dist(c, F^depth(X0)),
// "width" is the largest relative width (upper - lower) / upper reached (requested 1e-3;
// "converged" false if the budget stopped the refinement first).
QJsonValue hausdorffToExact(const AttractorItem *item, const DerivedIfs &d)
{
    const auto exact = certifiedExactCurveOf(item);
    if (!exact || d.iterate || d.ifs.views.empty() || d.ifs.size() == 0)
        return QJsonValue::Null;
    const StartSet start = item->coreStartSet(d);
    int depth = item->algorithm().depth;
    while (depth > 0 && imageCount(d.ifs, depth) * double(start.vertices.rows()) > 2e6)
        --depth;
    PointCollector c(d.ifs.views.front());
    iterate(d.ifs, StartSet::points(start.vertices), depth, c);
    const Mat pts = c.points();
    const HausdorffBracket h = hausdorffBracket(pts, *exact->curve);
    auto bracket = [](const DistanceBracket &b) { return QJsonArray{b.lower, b.upper}; };
    return QJsonObject{{"depth", depth},
                       {"points", double(pts.rows())},
                       {"value", h.value.mid()},
                       {"one_sided", h.oneSided.mid()},
                       {"value_bracket", bracket(h.value)},
                       {"one_sided_bracket", bracket(h.oneSided)},
                       {"curve_side_bracket", bracket(h.curveToPoints)},
                       {"width", h.width},
                       {"converged", h.converged},
                       {"curve", exact->label}};
}

// The JSR of the maps' linear parts (on the directions the iteration moves in): Gripenberg's
// bounds, exact where an invariant polytope closes (the regularity analysis's two routes).
QJsonObject jointSpectralRadiusJson(const Ifs &ifs)
{
    std::vector<Mat> A;
    for (int i = 0; i < ifs.size(); ++i)
        A.push_back(ifs.effectiveLinearPart(i));
    JsrOptions jo;
    jo.timeBudget = 1.0;
    const JsrBounds b = jointSpectralRadius(A, jo);
    PolytopeOptions po;
    po.timeBudget = 1.0;
    const PolytopeResult p = invariantPolytope(A, po);
    const bool exact = p.closed;
    // The product of the lower bound, 1-based; a long one (the branch and bound's deepest,
    // not a cycle worth naming) only by its length.
    const std::vector<int> root = primitiveRoot(exact ? p.smp : b.product);
    QJsonArray word;
    for (int k : root)
        word.append(k + 1);
    QJsonObject o{{"lower", exact ? p.lower : b.lower},
                  {"upper", exact ? p.upper : b.upper},
                  {"exact", exact},
                  {"word", root.size() <= 24 ? QJsonValue(word) : QJsonValue()},
                  {"word_length", int(root.size())},
                  {"method", exact ? QStringLiteral("invariant polytope (certified)")
                                   : QStringLiteral("Gripenberg's branch and bound")}};
    if (!exact && !p.message.empty())
        o["polytope"] = QString::fromStdString(p.message);
    o["contractive"] = (exact ? p.upper : b.upper) < 1.0;
    return o;
}

} // namespace

QJsonArray JsonList::whole() const
{
    QJsonArray a;
    for (qsizetype i = 0; i < size; ++i)
        a.append(at(i));
    return a;
}

QJsonObject ItemAnalysis::whole() const
{
    QJsonObject o = json;
    for (const auto &[key, list] : lists)
        o[key] = list.whole();
    return o;
}

// `regularity`, when given, receives the curve's regularity (its certificate for --certificate).
ItemAnalysis analyseItem(const AttractorItem *item, Regularity *regularity)
{
    ItemAnalysis analysis;
    QJsonObject &o = analysis.json;
    o["name"] = item->name();
    o["type"] = item->type();
    // An automaton's contraction, also when it has no attractor (issue 46).
    if (const auto *cifs = qobject_cast<const CifsItem *>(item))
        o["automaton"] = automatonAnalysisJson(*cifs);
    if (const auto *junction = qobject_cast<const BcifsJunctionItem *>(item))
        o["junction"] = junctionAnalysisJson(*junction);
    auto d = item->derivedIfs();
    if (!d) {
        o["error"] = item->derivedError();
        return analysis;
    }
    if (!d->note.isEmpty())
        o["note"] = d->note;
    // Per map: the eigenvalues of S_i as the item defines them, contractivity of f_i, and
    // its fixed point in the plane.
    QJsonArray maps, subdominants;
    double worstSub = -1;
    // Items without subdivision matrices (an equivalent IFS of a normal-vector scheme) list
    // the IFS's maps: "eigenvalues" are then those of the linear parts A_i.
    const bool hasS = d->S.count() > 0;
    const int count = listedMapCount(*d);
    for (int i = 0; i < count; ++i) {
        const Spectrum s = !hasS            ? spectrum(d->ifs.effectiveLinearPart(i))
                           : d->S.isComplex() ? spectrum(d->S.complex[i])
                                              : spectrum(d->S.real[i]);
        QJsonObject m;
        m["eigenvalues"] = eigenvaluesJson(s.values);
        m["spectral_radius"] = s.spectralRadius;
        const Subdominant sub = subdominant(s, hasS);
        m["subdominant"] = [&] {
            QJsonArray a;
            for (const Complex &z : sub.values)
                a.append(complexJson(z));
            return a;
        }();
        m["subdominant_kind"] = QString::fromStdString(toString(sub.kind));
        const MapMatrices matrices = mapMatrices(*d, i);
        const int k = matrices.ifsMap;
        if (d->surface)
            m["used"] = k >= 0;
        addMapMatrices(m, matrices);
        // A flame's affine part says nothing of how its xform contracts, nor where it is fixed.
        if (d->chaos)
            m["affine_part"] = true;
        if (k >= 0 && !d->chaos) {
            const Contractivity c = contractivity(d->ifs.effectiveLinearPart(k));
            m["contractive"] = c.eventuallyContractive;
            m["contraction_norm"] = c.normFactor;
            // A flame's affine part has a fixed point that its xform does not have.
            const auto fp = d->chaos ? std::nullopt : fixedPoint(d->ifs.maps[k]);
            Mat p;
            if (fp && !d->ifs.views.empty()) {
                p = project(d->ifs.views.front(), Mat(*fp));
            } else if (d->subdivision && i < int(d->S.real.size())) {
                // No lifted fixed point (barycentric form of a singular P): the fixed weights
                // of S_i (eigenvalue 1) applied to the control points give the same point.
                if (const auto l = fixedWeights(d->S.real[size_t(i)]))
                    p = *l * d->subdivision->controlPoints;
            }
            if (p.size() > 0) {
                QJsonArray xy;
                for (Eigen::Index c2 = 0; c2 < p.cols(); ++c2)
                    xy.append(p(0, c2));
                m["fixed_point"] = xy;
            } else {
                m["fixed_point"] = QJsonValue::Null;
            }
        }
        maps.append(m);
        if (sub.modulus > worstSub + 1e-12) {
            worstSub = sub.modulus;
            subdominants = QJsonArray();
            for (const Complex &z : sub.values)
                subdominants.append(complexJson(z));
        }
    }
    o["maps"] = maps;
    // A map that does not contract: whether the IFS contracts on average (the top Lyapunov
    // exponent of its random products with the item's probabilities, core IfsCheck), which is
    // what random iteration needs.
    if (d->chaos) {
        // Its own chaos game (a flame): the maps above are its affine parts; whether it
        // contracts on average is the exponent along its own orbit.
        const std::optional<double> l = d->chaos.lyapunovExponent();
        o["contractive_on_average"] = l ? QJsonValue(*l < -1e-3) : QJsonValue();
        o["lyapunov_exponent"] = l ? QJsonValue(*l) : QJsonValue(QJsonValue::Null);
        o["lyapunov_of"] = QStringLiteral("orbit");
    } else if (!d->iterate && d->ifs.size() > 0)
        if (const IfsCheck check = checkIfs(d->ifs); !check.contractive) {
            o["contractive_on_average"] = check.contractsOnAverage();
            o["lyapunov_exponent"] =
                check.lyapunov ? QJsonValue(*check.lyapunov) : QJsonValue(QJsonValue::Null);
        }
    o["subdominant"] = subdominants;
    // A union of Bézier curves (002 §6): its maps need not contract one by one, only jointly;
    // the joint spectral radius of their linear parts says whether they do (issue 46).
    if (qobject_cast<const BezierUnionItem *>(item) && d->ifs.size() > 0)
        o["joint_spectral_radius"] = jointSpectralRadiusJson(d->ifs);
    // A mesh: its extraordinary vertices and the pieces of its IFS with condensation.
    if (const auto *mesh = qobject_cast<const SubdivisionMeshItem *>(item)) {
        ItemAnalysis m = meshAnalysis(*mesh);
        for (auto it = m.json.begin(); it != m.json.end(); ++it)
            o[it.key()] = it.value();
        analysis.lists.merge(m.lists);
    }
    // The scheme's certified Hölder regularity (issue 16): an interval, its class C^n, how;
    // exact with an invariant polytope's certificate where one closes (issue 32).
    if (const auto *curve = qobject_cast<const SubdivisionCurveItem *>(item)) {
        const Regularity r = itemRegularity(*curve);
        o["regularity"] = regularityJson(r);
        if (regularity)
            *regularity = r;
    }
    if (const auto *s = qobject_cast<const SubdivisionSurfaceItem *>(item)) {
        o["kind"] = item->type();
        o["scheme"] = SurfaceSchemeSpec::kindNames().at(int(s->scheme().kind));
        o["layout"] = s->scheme().layout;
        o["map_count"] = int(d->S.real.size());
        QJsonArray used, points, lattice;
        for (int i : s->mapsUsed())
            used.append(i);
        o["maps_used"] = used;
        for (const Point &q : s->controlPoints())
            points.append(QJsonArray{q.x, q.y, q.z});
        o["control_points"] = points;
        for (const LatticePoint &q : s->lattice())
            lattice.append(QJsonArray{q.i, q.j});
        o["lattice"] = lattice;
        o["lifted_dimension"] = d->ifs.dim();
    }
    if (d->subdivision) {
        o["lifting_invertible"] = d->subdivision->lifting.invertible;
        if (!d->subdivision->lifting.invertible)
            o["lifting_problem"] = QString::fromStdString(d->subdivision->lifting.reason);
    }
    try {
        o["hausdorff_to_exact"] = hausdorffToExact(item, *d);
    } catch (const InputError &e) {
        o["hausdorff_to_exact"] = QJsonValue::Null;
        o["hausdorff_error"] = QString::fromStdString(e.what());
    }
    // Box-counting dimension of the attractor at a depth giving about 2^18 points.
    o["box_dimension"] = QJsonValue::Null;
    if (d->chaos)  // a flame: the IFS here is of its affine parts, not of its maps
        o["box_dimension_note"] = flameBoxDimensionNote();
    try {
        if (d->ifs.size() > 1 && !d->iterate && !d->chaos && !d->ifs.views.empty()) {
            const StartSet start = item->coreStartSet(*d);
            int depth = 1;
            while (imageCount(d->ifs, depth + 1) * start.vertices.rows() <= 300000)
                ++depth;
            PointCollector c(d->ifs.views.front());
            if (d->surface) {
                // The images of a surface's overlapping pieces coincide at lattice points:
                // random iteration gives distinct points for the count.
                ChaosOptions options;
                options.samples = 300000;
                chaosGame(d->ifs, start.vertices.row(0), options, c);
            } else {
                iterate(d->ifs, StartSet::points(start.vertices), depth, c);
            }
            const BoxDimension b = boxCountingDimension(c.points());
            if (b.valid) {
                o["box_dimension"] = b.dimension;
                o["box_dimension_fit"] = QJsonObject{{"r2", b.r2},
                                                     {"levels", QJsonArray{b.levelFrom, b.levelTo}},
                                                     {"points", double(c.points().rows())}};
            }
        }
    } catch (const InputError &e) {
        o["box_dimension_error"] = QString::fromStdString(e.what());
    }
    return analysis;
}


QString flameBoxDimensionNote()
{
    return QCoreApplication::translate(
        "awb::ItemAnalysis",
        "not measured: the flame's maps are not their affine parts, whose attractor the "
        "analysis would count");
}

} // namespace awb
