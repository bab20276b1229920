#include "model/BcifsJunctionItem.h"

#include "core/schemes/ControlPointFractal.h"
#include "model/Commands.h"
#include "model/ProjectIO.h"

#include <cmath>

namespace awb {

namespace {

const char *const pointKeys[3] = {"left_points", "right_points", "handles"};

// Passes a state's images on, written into that state's block of the item's space (the
// concatenation of all edge states' barycentric spaces), so that one view draws them all.
class BlockSink : public AttractorSink {
public:
    BlockSink(AttractorSink &target, int dim) : m_target(target), m_dim(dim) {}
    int offset = 0;
    void consume(const Mat &vertices, StartSet::Kind kind, const std::uint8_t *address,
                 int length) override
    {
        Mat Y = Mat::Zero(vertices.rows(), m_dim);
        Y.middleCols(offset, vertices.cols()) = vertices;
        m_target.consume(Y, kind, address, length);
    }

private:
    AttractorSink &m_target;
    int m_dim;
};

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
    if (checkSpec(spec))
        return false;
    applyProperty(&BcifsJunctionItem::m_spec, spec, &BcifsJunctionItem::specChanged,
                  tr("Change junction of %1").arg(name()), gesture);
    return true;
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
    std::vector<int> offsets;
    int D = 0;
    for (const CifsState &s : cifs->states) {
        offsets.push_back(D);
        D += s.dim();
    }
    Mat V(D, 2);
    for (size_t s = 0; s < cifs->states.size(); ++s)
        V.middleRows(offsets[s], cifs->states[s].dim()) = cifs->states[s].controlPoints;
    out.ifs.space = "cifs states";
    out.ifs.views.push_back({V, RowVec::Zero(2)});
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
        BlockSink sink(*sinks.front(), D);
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

void BcifsJunctionItem::write(QJsonObject &json) const
{
    AttractorItem::write(json);
    json["variant"] = JunctionSpec::variantNames().at(int(m_spec.variant));
    if (m_spec.variant == JunctionSpec::Variant::CubicQuadratic) {
        for (int i = 0; i < 8; ++i)
            json[JunctionSpec::freeKeys()[i]] = m_spec.freeValue(i);
    } else {
        json["j"] = m_spec.refined.j;
        json["r"] = m_spec.refined.r;
    }
    for (int set = 0; set < controlPointSetCount(); ++set)
        json[pointKeys[set]] = ProjectIO::pointsToJson(m_points[size_t(set)]);
}

void BcifsJunctionItem::read(const FieldReader &fields)
{
    AttractorItem::read(fields);
    JunctionSpec spec;
    spec.variant = JunctionSpec::Variant(fields.choice("variant", JunctionSpec::variantNames()));
    if (spec.variant == JunctionSpec::Variant::CubicQuadratic) {
        for (int i = 0; i < 8; ++i)
            *spec.freeSlot(i) = fields.number(JunctionSpec::freeKeys()[i], spec.freeValue(i));
    } else {
        spec.refined.j = fields.number("j", spec.refined.j);
        spec.refined.r = fields.number("r", spec.refined.r);
    }
    fields.require(spec.check());
    m_spec = spec;
    m_points[0] = fields.points(pointKeys[0]);
    m_points[1] = fields.points(pointKeys[1]);
    if (spec.variant == JunctionSpec::Variant::Refined)
        m_points[2] = fields.points(pointKeys[2]);
}

// ---- generic parameters ---------------------------------------------------------------------

QList<ParameterInfo> BcifsJunctionItem::parameters() const
{
    using P = ParameterInfo;
    const QString group = tr("Junction");
    QList<ParameterInfo> list;
    list << P::make("variant", tr("Junction"), P::Type::Choice)
                .options({tr("Cubic–quadratic (003 §4.1)"), tr("Refined, with handles (003 §5)")})
                .in(group);
    if (m_spec.variant == JunctionSpec::Variant::CubicQuadratic) {
        for (int i = 0; i < 8; ++i) {
            const QString key = JunctionSpec::freeKeys()[i];
            list << P::make(key, key, P::Type::Real)
                        .slider(-0.5, 1)
                        .in(group)
                        .tip(i < 4 ? tr("Last column (a, b, c, d, e) of T^l; e = 1 − a − b − c "
                                        "− d (003 §4.1)")
                                   : tr("First column (k, l, m, n, p) of T^r; p = 1 − k − l − m "
                                        "− n (003 §4.1)"));
        }
    } else {
        const ParameterRange j = refinedRangeJ(), r = refinedRangeR();
        list << P::make("j", tr("Left eigenvalue j"), P::Type::Real)
                    .range(j.lo, j.hi).slider(j.lo, j.hi).in(group)
                    .tip(tr("Tangent eigenvalue of T^il (003 §5)"));
        list << P::make("r", tr("Right eigenvalue r"), P::Type::Real)
                    .range(r.lo, r.hi).slider(r.lo, r.hi).in(group)
                    .tip(tr("Tangent eigenvalue of T^ir (003 §5)"));
    }
    return list;
}

QVariant BcifsJunctionItem::parameter(const QString &key) const
{
    if (key == "variant")
        return int(m_spec.variant);
    if (key == "j")
        return m_spec.refined.j;
    if (key == "r")
        return m_spec.refined.r;
    const int i = int(JunctionSpec::freeKeys().indexOf(key));
    return i >= 0 ? QVariant(m_spec.freeValue(i)) : QVariant();
}

bool BcifsJunctionItem::setParameter(const QString &key, const QVariant &value, int gesture,
                                     QString *error)
{
    JunctionSpec next = m_spec;
    bool ok = true;
    const int i = int(JunctionSpec::freeKeys().indexOf(key));
    if (key == "variant") {
        const int v = value.toInt(&ok);
        ok = ok && v >= 0 && v < JunctionSpec::variantNames().size();
        if (ok)
            next.variant = JunctionSpec::Variant(v);
    } else if (key == "j") {
        next.refined.j = value.toDouble(&ok);
    } else if (key == "r") {
        next.refined.r = value.toDouble(&ok);
    } else if (i >= 0) {
        *next.freeSlot(i) = value.toDouble(&ok);
    } else {
        return Item::setParameter(key, value, gesture, error);
    }
    return commitParameter(key, value, ok, checkSpec(next),
                           [&] { return setSpec(next, gesture); }, error);
}

} // namespace awb
