#include "model/BcifsJunctionItem.h"

#include "core/schemes/ControlPointFractal.h"
#include "model/Commands.h"
#include "model/PointSetProperty.h"
#include "model/ProjectIO.h"
#include "model/PropertyDeclaration.h"

#include <cmath>

namespace awb {

namespace {

} // namespace

// ---- JunctionSpec -----------------------------------------------------------------------------

const QStringList &JunctionSpec::variantNames()
{
    static const QStringList names{"cubic-quadratic", "refined"};
    return names;
}

const QStringList &JunctionSpec::freeKeys()
{
    static const QStringList keys{"a", "b", "c", "d", "k", "l", "m", "n"};
    return keys;
}

double *JunctionSpec::freeSlot(int index)
{
    double *values[] = {&free.a, &free.b, &free.c, &free.d,
                        &free.k, &free.l, &free.m, &free.n};
    return index >= 0 && index < 8 ? values[index] : nullptr;
}

bool JunctionSpec::operator==(const JunctionSpec &o) const
{
    for (int i = 0; i < 8; ++i)
        if (freeValue(i) != o.freeValue(i))
            return false;
    return variant == o.variant && refined.j == o.refined.j && refined.r == o.refined.r;
}

MaybeProblem JunctionSpec::check() const
{
    for (int i = 0; i < 8; ++i)
        if (!std::isfinite(freeValue(i)))
            return Problem{freeKeys()[i], tr("the junction parameter %1 must be a finite number")
                                              .arg(freeKeys()[i])};
    if (variant == Variant::Refined) {
        const ParameterRange j = refinedRangeJ(), r = refinedRangeR();
        for (const auto &[key, value, range] :
             {std::tuple{"j", refined.j, j}, std::tuple{"r", refined.r, r}})
            if (!(std::isfinite(value) && value > range.lo && value < range.hi))
                return Problem{key, tr("%1 = %2 is outside (%3, %4): %5")
                                        .arg(key).arg(value).arg(range.lo).arg(range.hi)
                                        .arg(QString::fromStdString(range.why))};
    }
    return std::nullopt;
}

// ---- BcifsJunctionItem ------------------------------------------------------------------------

BcifsJunctionItem::BcifsJunctionItem()
    : AttractorItem(tr("Junction")),
      m_points{PointList{{0, 0}, {1, 1}, {2, 1}, {3, 0}}, PointList{{4, -1}, {5, -1}, {6, 0}},
               PointList{{2.5, 0.5}, {3, 0}, {3.5, -0.5}}}
{
}

int BcifsJunctionItem::controlPointSetCount() const
{
    return m_spec.variant == JunctionSpec::Variant::Refined ? 3 : 2;
}

bool BcifsJunctionItem::setSpec(const JunctionSpec &spec, int gesture)
{
    return setDeclared(*this, spec, gesture);
}

DerivedIfs BcifsJunctionItem::computeIfs() const
{
    const Mat Pl = toMatrix(m_points[0]), Pr = toMatrix(m_points[1]);
    DerivedIfs out;
    Bcifs bcifs;
    if (m_spec.variant == JunctionSpec::Variant::CubicQuadratic) {
        bcifs = cubicQuadraticJunction(m_spec.free, Pl, Pr);
        out.S.real.push_back(cubicQuadraticMatrices(m_spec.free).Ti.transpose());
        const JunctionAnalysis a = analyseCubicQuadratic(m_spec.free, Pl, Pr);
        out.note = tr("e = %1, p = %2 (column sums). %3")
                       .arg(m_spec.free.e()).arg(m_spec.free.p())
                       .arg(QString::fromStdString(a.verdict));
    } else {
        const Mat H = toMatrix(m_points[2]);
        bcifs = refinedJunction(m_spec.refined, Pl, Pr, H);
        const RefinedMatrices m = refinedMatrices(m_spec.refined);
        out.S.real = {m.Til.transpose(), m.Tir.transpose()};
        out.note = QString::fromStdString(analyseRefined(m_spec.refined, Pl, Pr, H).verdict);
    }
    out.A.unavailable = tr("a junction is drawn by an automaton, not by one lifted IFS");
    const auto cifs = std::make_shared<const Cifs>(toCifs(bcifs));
    const CifsCheck check = checkCifs(*cifs);
    if (!check.contractive)
        throw InputError(check.message);

    // The item's space: the edge states' barycentric spaces side by side; one view draws a
    // point of state s (zero outside its block) at lambda_s P_s.
    const CifsStacking stacking = stackingOf(*cifs);
    const std::vector<int> offsets = stacking.offsets;
    const int D = stacking.dimension;
    out.ifs.space = "cifs states";
    out.ifs.views.push_back({stacking.points, RowVec::Zero(2)});
    out.toIfsSpace = [cifs, offsets, D](const Mat &X) {
        Mat Y(X.rows(), D);
        for (size_t s = 0; s < cifs->states.size(); ++s)
            Y.middleCols(offsets[s], cifs->states[s].dim()) =
                leastNormWeightsOfRows(cifs->states[s].controlPoints, X);
        return Y;
    };
    // Every edge state's attractor in turn, on the first sink (the states are few, their
    // images many: the core's iterate is the bottleneck either way).
    out.iterate = [cifs, offsets, D](const StartSet &start, int depth,
                                     const std::vector<AttractorSink *> &sinks,
                                     const IterationControl &control) {
        const int count = int(cifs->states.size());
        std::vector<StartSet> starts;
        for (int s = 0; s < count; ++s)
            starts.push_back({start.kind, start.vertices.middleCols(offsets[size_t(s)],
                                                                    cifs->states[s].dim())});
        StackedSink sink(*sinks.front(), D);
        IterationStats total;
        for (int s = 0; s < count && !total.cancelled; ++s) {
            IterationControl part{control.cancel, {}};
            if (control.progress)
                part.progress = [&control, s, count](double f) {
                    control.progress((s + f) / count);
                };
            sink.offset = offsets[size_t(s)];
            const IterationStats stats = iterate(*cifs, s, starts, depth, sink, part);
            total.images += stats.images;
            total.cancelled = stats.cancelled;
        }
        return total;
    };
    return out;
}

// ---- declared properties ----------------------------------------------------------------------

const PropertyTable &BcifsJunctionItem::declaration()
{
    static const PropertyTable table = [] {
        using V = JunctionSpec::Variant;
        Declaration<BcifsJunctionItem> d(&AttractorItem::attractorProperties());
        auto spec = d.part(&BcifsJunctionItem::m_spec, &BcifsJunctionItem::checkSpec,
                           &BcifsJunctionItem::specChanged, QT_TR_NOOP("Change junction of %1"));
        spec.checkedOnRead(
            [](const BcifsJunctionItem &, const JunctionSpec &s) { return s.check(); });
        spec.choice("variant", &JunctionSpec::variant, JunctionSpec::variantNames(),
                    {QT_TR_NOOP("Cubic–quadratic (003 §4.1)"),
                     QT_TR_NOOP("Refined, with handles (003 §5)")})
            .label(QT_TR_NOOP("Junction"))
            .group(QT_TR_NOOP("Junction"))
            .required();
        const auto cubicQuadratic = [](const JunctionSpec &s) {
            return s.variant == V::CubicQuadratic;
        };
        const auto refined = [](const JunctionSpec &s) { return s.variant == V::Refined; };
        for (int i = 0; i < 8; ++i)
            spec.real(JunctionSpec::freeKeys()[i],
                      [i](JunctionSpec &s) -> double & { return *s.freeSlot(i); })
                .slider(-0.5, 1)
                .group(QT_TR_NOOP("Junction"))
                .tip(i < 4 ? QT_TR_NOOP("Last column (a, b, c, d, e) of T^l; e = 1 − a − b − c "
                                        "− d (003 §4.1)")
                           : QT_TR_NOOP("First column (k, l, m, n, p) of T^r; p = 1 − k − l − m "
                                        "− n (003 §4.1)"))
                .when(cubicQuadratic);
        const ParameterRange j = refinedRangeJ(), r = refinedRangeR();
        spec.real("j", [](JunctionSpec &s) -> double & { return s.refined.j; })
            .label(QT_TR_NOOP("Left eigenvalue j"))
            .group(QT_TR_NOOP("Junction"))
            .range(j.lo, j.hi)
            .slider(j.lo, j.hi)
            .tip(QT_TR_NOOP("Tangent eigenvalue of T^il (003 §5)"))
            .when(refined);
        spec.real("r", [](JunctionSpec &s) -> double & { return s.refined.r; })
            .label(QT_TR_NOOP("Right eigenvalue r"))
            .group(QT_TR_NOOP("Junction"))
            .range(r.lo, r.hi)
            .slider(r.lo, r.hi)
            .tip(QT_TR_NOOP("Tangent eigenvalue of T^ir (003 §5)"))
            .when(refined);
        declarePointSet(d, 0, QStringLiteral("left_points"), QT_TR_NOOP("Left cubic"));
        declarePointSet(d, 1, QStringLiteral("right_points"), QT_TR_NOOP("Right quadratic"));
        declarePointSet(d, 2, QStringLiteral("handles"), QT_TR_NOOP("Handles"));
        return d.table();
    }();
    return table;
}

} // namespace awb
