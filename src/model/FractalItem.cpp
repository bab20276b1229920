#include "model/FractalItem.h"

#include "core/ifs/Attractor.h"
#include "core/schemes/ControlPointFractal.h"
#include "model/Commands.h"
#include "model/ProjectIO.h"

#include <cmath>

namespace awb {

namespace {

// lupdate takes the context of FractalItemTr::tr() from the macro (a free tr() would get the
// enclosing namespace as its context).
struct FractalItemTr {
    Q_DECLARE_TR_FUNCTIONS(awb::FractalItem)
};

bool sameMatrix(const Mat &a, const Mat &b)
{
    return a.rows() == b.rows() && a.cols() == b.cols() && (a.array() == b.array()).all();
}

ControlPointFractal presetFractal(FractalSpec::Preset preset)
{
    return preset == FractalSpec::Preset::Sierpinski ? sierpinskiControlPointFractal()
                                                     : kochControlPointFractal();
}

PointList toPoints(const Mat &P)
{
    PointList out;
    for (Eigen::Index r = 0; r < P.rows(); ++r)
        out.push_back({P(r, 0), P(r, 1)});
    return out;
}

// A row of `n` finite numbers at `where` (1-based indices in messages, like the points).
RowVec readRow(const QJsonValue &v, int n, const QString &where)
{
    const QJsonArray a = v.toArray();
    if (!v.isArray() || a.size() != n)
        throw LoadError{where, FractalItemTr::tr("expected an array of %1 numbers").arg(n)};
    RowVec out(n);
    for (int i = 0; i < n; ++i)
        out(i) = FieldReader::toNumber(a[i], where + QStringLiteral("[%1]").arg(i + 1));
    return out;
}

std::vector<AffineMap> readMaps(const FieldReader &fields)
{
    const QJsonValue v = fields.value("maps");
    if (v.isUndefined())
        fields.fail("maps", FractalItemTr::tr("missing (the custom form needs its maps)"));
    if (!v.isArray() || v.toArray().isEmpty())
        fields.fail("maps", FractalItemTr::tr("expected a non-empty array of maps {\"A\": [[a11, a12], "
                               "[a21, a22]], \"b\": [b1, b2]}"));
    std::vector<AffineMap> maps;
    const QJsonArray list = v.toArray();
    for (qsizetype k = 0; k < list.size(); ++k) {
        const QString where = fields.path("maps") + QStringLiteral("[%1]").arg(k + 1);
        if (!list[k].isObject())
            throw LoadError{where, FractalItemTr::tr("expected an object with \"A\" and \"b\"")};
        const FieldReader map(list[k].toObject(), where + QLatin1Char('.'));
        const QJsonValue A = map.value("A");
        if (A.isUndefined())
            map.fail("A", FractalItemTr::tr("missing"));
        // The first map's rows fix the dimension: 2 (the plane) or 3 (space).
        const int d = maps.empty() ? int(A.toArray().size()) : maps.front().dim();
        if (!A.isArray() || A.toArray().size() != d || (d != 2 && d != 3))
            map.fail("A", maps.empty()
                              ? FractalItemTr::tr("expected a 2 x 2 matrix [[a11, a12], [a21, "
                                                  "a22]] or a 3 x 3 one")
                              : FractalItemTr::tr("expected a %1 x %1 matrix, as the first map")
                                    .arg(d));
        AffineMap f{Mat(d, d), RowVec(d)};
        for (int r = 0; r < d; ++r)
            f.A.row(r) = readRow(A.toArray()[r], d, map.path("A") + QStringLiteral("[%1]")
                                                                        .arg(r + 1));
        const QJsonValue b = map.value("b");
        if (b.isUndefined())
            map.fail("b", FractalItemTr::tr("missing"));
        f.b = readRow(b, d, map.path("b"));
        maps.push_back(f);
    }
    return maps;
}

} // namespace

// ---- FractalSpec ------------------------------------------------------------------------------

const QStringList &FractalSpec::presetNames()
{
    static const QStringList names{"koch", "sierpinski", "custom"};
    return names;
}

const QStringList &FractalSpec::weightNames()
{
    static const QStringList names{"nearest", "least-norm"};
    return names;
}

bool FractalSpec::operator==(const FractalSpec &o) const
{
    if (preset != o.preset || weights != o.weights || reference != o.reference
        || maps.size() != o.maps.size())
        return false;
    for (size_t i = 0; i < maps.size(); ++i)
        if (!sameMatrix(maps[i].A, o.maps[i].A) || !sameMatrix(maps[i].b, o.maps[i].b))
            return false;
    return true;
}

MaybeProblem FractalSpec::check() const
{
    if (preset != Preset::Custom)
        return std::nullopt;
    if (maps.empty())
        return Problem{"maps", FractalItemTr::tr("the custom form needs at least one map")};
    for (size_t i = 0; i < maps.size(); ++i) {
        const AffineMap &f = maps[i];
        const Eigen::Index d = maps.front().A.rows();
        if ((d != 2 && d != 3) || f.A.rows() != d || f.A.cols() != d || f.b.size() != d)
            return Problem{"maps", FractalItemTr::tr("map %1 is not a map of the plane or of "
                                                     "space like the first")
                                       .arg(i + 1)};
        if (!f.A.allFinite() || !f.b.allFinite())
            return Problem{"maps", FractalItemTr::tr("map %1 has a non-finite entry").arg(i + 1)};
    }
    if (!allFinite(reference))
        return Problem{"reference_points", FractalItemTr::tr("a reference point is not finite")};
    if (!reference.empty() && reference.size() < 3)
        return Problem{"reference_points",
                       FractalItemTr::tr("need at least 3 reference points (000 §4), got %1")
                           .arg(reference.size())};
    return std::nullopt;
}

int FractalSpec::dimension() const
{
    return preset == Preset::Custom && !maps.empty() ? maps.front().dim() : 2;
}

int FractalSpec::mapCount() const
{
    if (preset == Preset::Custom)
        return int(maps.size());
    static const int koch = int(kochControlPointFractal().S.size());
    static const int sierpinski = int(sierpinskiControlPointFractal().S.size());
    return preset == Preset::Koch ? koch : sierpinski;
}

// ---- FractalItem ------------------------------------------------------------------------------

FractalItem::FractalItem()
    : AttractorItem(FractalItemTr::tr("Fractal")), m_points(toPoints(kochControlPointFractal().controlPoints))
{
}

MaybeProblem FractalItem::checkFractal(const FractalSpec &spec) const
{
    if (auto p = spec.check())
        return p;
    if (auto p = algorithm().check(spec.mapCount()))
        return Problem{"algorithm." + p->field, p->message};
    return std::nullopt;
}

bool FractalItem::setFractal(const FractalSpec &spec, int gesture)
{
    if (checkFractal(spec))
        return false;
    applyProperty(&FractalItem::m_fractal, spec, &FractalItem::fractalChanged,
                  FractalItemTr::tr("Change fractal of %1").arg(name()), gesture);
    return true;
}

DerivedIfs FractalItem::computeIfs() const
{
    const int dim = m_fractal.dimension();
    const Mat P = toMatrix(m_points, dim);
    std::shared_ptr<const SubdivisionIfs> s;
    DerivedIfs out;
    if (m_fractal.preset == FractalSpec::Preset::Custom) {
        const Mat R = m_fractal.reference.empty() ? P : toMatrix(m_fractal.reference, dim);
        if (R.rows() != P.rows())
            throw InputError(FractalItemTr::tr("the %1 reference points and the %2 control points must be "
                                "equally many")
                                 .arg(R.rows()).arg(P.rows()).toStdString());
        const AffineWeights mode = m_fractal.weights == FractalSpec::Weights::LeastNorm
                                       ? AffineWeights::LeastNorm
                                       : AffineWeights::NearestBarycentric;
        const ControlPointMatrices cpm = controlPointMatrices(m_fractal.maps, R, mode);
        s = std::make_shared<const SubdivisionIfs>(buildSubdivisionIfs(cpm.S, cpm.overlap, P));
        if (cpm.maxResidual > 1e-9) // S_i R = f_i(R) only approximately: say so
            out.note = FractalItemTr::tr("the reference points are ill-conditioned: S_i R differs from "
                          "f_i(R) by up to %1").arg(cpm.maxResidual);
    } else {
        s = std::make_shared<const SubdivisionIfs>(
            controlPointFractalIfs(presetFractal(m_fractal.preset), P));
    }
    out.S.real = s->matrices.S;
    for (const LiftedMap &l : s->lifted)
        out.A.real.push_back(l.A);
    if (s->lifted.empty())
        out.A.unavailable = QString::fromStdString(s->lifting.reason);
    out.note = QString::fromStdString(s->lifting.note());
    out.ifs = s->ifs;
    out.toIfsSpace = [s](const Mat &X) { return s->toIfsSpace(X); };
    out.subdivision = s;
    applyAlgorithm(out.ifs);
    if (dim == 3 && algorithm().mode == AlgorithmSpec::Mode::Random) {
        // The 3D view iterates its start set level by level; a fractal of space drawn by random
        // iteration (an imported Fractint 3D entry, whose maps contract very unevenly) streams
        // the chaos game instead: `samples` points at the item's depth and a quarter as many
        // per level below it (the view's coarse frames while something moves).
        const Ifs ifs = out.ifs;
        const AlgorithmSpec a = algorithm();
        const auto count = [a](int depth) {
            return std::max(1.0, double(a.samples) / std::pow(4.0, std::max(0, a.depth - depth)));
        };
        out.iterate = [ifs, a, count](const StartSet &start, int depth,
                                      const std::vector<AttractorSink *> &sinks,
                                      const IterationControl &control) {
            ChaosOptions o;
            o.samples = std::uint64_t(count(depth));
            o.seed = std::uint64_t(a.seed);
            const RowVec x0 = start.vertices.rows() > 0 ? RowVec(start.vertices.row(0))
                                                        : RowVec(RowVec::Zero(ifs.dim()));
            return chaosGameParallel(ifs, x0, o, sinks, control);
        };
        out.pointCount = [count](const StartSet &, int depth) { return count(depth); };
    }
    return out;
}

void FractalItem::write(QJsonObject &json) const
{
    AttractorItem::write(json);
    json["preset"] = FractalSpec::presetNames().at(int(m_fractal.preset));
    const int dim = m_fractal.dimension();
    json["control_points"] = ProjectIO::pointsToJson(m_points, dim);
    if (m_fractal.preset != FractalSpec::Preset::Custom)
        return;
    QJsonArray maps;
    for (const AffineMap &f : m_fractal.maps) {
        QJsonArray A;
        for (Eigen::Index r = 0; r < f.A.rows(); ++r)
            A.append(ProjectIO::rowToJson(f.A.row(r)));
        maps.append(QJsonObject{{"A", A}, {"b", ProjectIO::rowToJson(f.b)}});
    }
    json["maps"] = maps;
    json["weights"] = FractalSpec::weightNames().at(int(m_fractal.weights));
    if (!m_fractal.reference.empty())
        json["reference_points"] = ProjectIO::pointsToJson(m_fractal.reference, dim);
}

void FractalItem::read(const FieldReader &fields)
{
    // The maps first: their dimension is that of every point, the start set's too.
    FractalSpec spec;
    spec.preset = FractalSpec::Preset(fields.choice("preset", FractalSpec::presetNames()));
    if (spec.preset == FractalSpec::Preset::Custom) {
        spec.maps = readMaps(fields);
        spec.weights = FractalSpec::Weights(
            fields.choice("weights", FractalSpec::weightNames(), int(spec.weights)));
        spec.reference = fields.points("reference_points", PointList{}, spec.dimension());
    }
    fields.require(spec.check());
    m_fractal = spec;
    AttractorItem::read(fields);
    m_points = fields.points("control_points", std::nullopt, spec.dimension());
}

// ---- generic parameters ---------------------------------------------------------------------

QList<ParameterInfo> FractalItem::parameters() const
{
    using P = ParameterInfo;
    const QString group = FractalItemTr::tr("Fractal");
    QList<ParameterInfo> list;
    list << P::make("preset", FractalItemTr::tr("Fractal"), P::Type::Choice)
                .options({FractalItemTr::tr("Koch curve (000 §4.1)"),
                          FractalItemTr::tr("Sierpinski triangle (000 §4.2)"),
                          FractalItemTr::tr("Own maps")})
                .in(group)
                .tip(FractalItemTr::tr("The presets use the paper's printed matrices S_i"));
    if (m_fractal.preset == FractalSpec::Preset::Custom) {
        list << P::make("weights", FractalItemTr::tr("Affine weights"), P::Type::Choice)
                    .options({FractalItemTr::tr("Nearest control points"), FractalItemTr::tr("Least norm (all points)")})
                    .in(group)
                    .tip(FractalItemTr::tr("How f_i(P_j) is written as an affine combination of the control "
                            "points (000 eq. (5)): nearest points keep edits local, least norm "
                            "lets every point move the whole fractal"));
    }
    return list;
}

QVariant FractalItem::parameter(const QString &key) const
{
    if (key == "preset")
        return int(m_fractal.preset);
    if (key == "weights")
        return int(m_fractal.weights);
    return {};
}

bool FractalItem::setParameter(const QString &key, const QVariant &value, int gesture,
                               QString *error)
{
    FractalSpec next = m_fractal;
    bool ok = true;
    const int index = value.toInt(&ok);
    if (key == "preset") {
        ok = ok && index >= 0 && index < FractalSpec::presetNames().size();
        if (ok)
            next.preset = FractalSpec::Preset(index);
        if (ok && next.preset == FractalSpec::Preset::Custom && next.maps.empty()) {
            // Start from the preset shown, so that the picture does not jump.
            const ControlPointFractal f = presetFractal(m_fractal.preset);
            next.maps = f.classicMaps;
            next.reference = toPoints(f.controlPoints);
        }
    } else if (key == "weights") {
        ok = ok && index >= 0 && index < FractalSpec::weightNames().size();
        if (ok)
            next.weights = FractalSpec::Weights(index);
    } else {
        return Item::setParameter(key, value, gesture, error);
    }
    return commitParameter(key, value, ok, checkFractal(next),
                           [&] { return setFractal(next, gesture); }, error);
}

} // namespace awb
