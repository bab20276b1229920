#include "model/FractalItem.h"

#include "core/ifs/Attractor.h"
#include "core/schemes/ControlPointFractal.h"
#include "model/Commands.h"
#include "model/PointSetProperty.h"
#include "model/ProjectIO.h"
#include "model/PropertyDeclaration.h"

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

// The maps of the custom form, {"A": [[a11, a12], [a21, a22]], "b": [b1, b2]} each (or 3 x 3
// and 3 for space), from the file's value at `where`.
std::vector<AffineMap> readMaps(const QJsonValue &v, const QString &where)
{
    if (!v.isArray() || v.toArray().isEmpty())
        throw LoadError{where, FractalItemTr::tr("expected a non-empty array of maps {\"A\": "
                                                 "[[a11, a12], [a21, a22]], \"b\": [b1, b2]}")};
    std::vector<AffineMap> maps;
    const QJsonArray list = v.toArray();
    for (qsizetype k = 0; k < list.size(); ++k) {
        const QString at = where + QStringLiteral("[%1]").arg(k + 1);
        if (!list[k].isObject())
            throw LoadError{at, FractalItemTr::tr("expected an object with \"A\" and \"b\"")};
        const FieldReader map(list[k].toObject(), at + QLatin1Char('.'));
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

QJsonValue mapsToJson(const std::vector<AffineMap> &maps)
{
    QJsonArray list;
    for (const AffineMap &f : maps) {
        QJsonArray A;
        for (Eigen::Index r = 0; r < f.A.rows(); ++r)
            A.append(ProjectIO::rowToJson(f.A.row(r)));
        list.append(QJsonObject{{"A", A}, {"b", ProjectIO::rowToJson(f.b)}});
    }
    return list;
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
    if (maps.size() > std::size_t(kMaxMaps))
        return Problem{"maps", FractalItemTr::tr("%1 maps: at most %2 maps are supported")
                                   .arg(maps.size())
                                   .arg(kMaxMaps)};
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
    return checkWithMaps(spec.check(), spec.mapCount());
}

bool FractalItem::setFractal(const FractalSpec &spec, int gesture)
{
    return setDeclared(*this, spec, gesture);
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
        out.iterateDrawsIfs = true;
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

// ---- declared properties ----------------------------------------------------------------------

const PropertyTable &FractalItem::declaration()
{
    static const PropertyTable table = [] {
        using Preset = FractalSpec::Preset;
        const auto custom = [](const FractalSpec &f) { return f.preset == Preset::Custom; };
        Declaration<FractalItem> d(&AttractorItem::attractorProperties());
        // The maps first: their dimension is that of every point, the start set's too.
        auto fractal = d.part(&FractalItem::m_fractal, &FractalItem::checkFractal,
                              &FractalItem::fractalChanged, QT_TR_NOOP("Change fractal of %1"));
        fractal.checkedOnRead([](const FractalItem &, const FractalSpec &f) { return f.check(); });
        fractal
            .choice("preset", &FractalSpec::preset, FractalSpec::presetNames(),
                    {QT_TR_NOOP("Koch curve (000 §4.1)"),
                     QT_TR_NOOP("Sierpinski triangle (000 §4.2)"), QT_TR_NOOP("Own maps")})
            .label(QT_TR_NOOP("Fractal"))
            .group(QT_TR_NOOP("Fractal"))
            .tip(QT_TR_NOOP("The presets use the paper's printed matrices S_i"))
            .required()
            // Own maps start from the preset shown, so that the picture does not jump.
            .onEdit([](const FractalItem &item, FractalSpec &next) -> MaybeProblem {
                if (next.preset == Preset::Custom && next.maps.empty()) {
                    const ControlPointFractal f = presetFractal(item.m_fractal.preset);
                    next.maps = f.classicMaps;
                    next.reference = toPoints(f.controlPoints);
                }
                return std::nullopt;
            });
        fractal
            .structured(
                "maps", QStringLiteral("affine maps"),
                [](const FractalItem &, const FractalSpec &f) { return mapsToJson(f.maps); },
                [](const FractalItem &, FractalSpec &f, const QJsonValue &v,
                   const QString &where) { f.maps = readMaps(v, where); })
            .label(QT_TR_NOOP("Maps"))
            .tip(QT_TR_NOOP("x ↦ x A + b: {\"A\": [[a11, a12], [a21, a22]], \"b\": [b1, b2]} "
                            "each, or 3 x 3 and 3 numbers in space"))
            .when(custom)
            .required(QT_TR_NOOP("missing (the custom form needs its maps)"));
        fractal
            .choice("weights", &FractalSpec::weights, FractalSpec::weightNames(),
                    {QT_TR_NOOP("Nearest control points"), QT_TR_NOOP("Least norm (all points)")})
            .label(QT_TR_NOOP("Affine weights"))
            .group(QT_TR_NOOP("Fractal"))
            .tip(QT_TR_NOOP("How f_i(P_j) is written as an affine combination of the control "
                            "points (000 eq. (5)): nearest points keep edits local, least norm "
                            "lets every point move the whole fractal"))
            .when(custom);
        // Points of the maps' dimension (the spec's, already read: not yet the item's).
        fractal
            .structured(
                "reference_points", QStringLiteral("points"),
                [](const FractalItem &, const FractalSpec &f) -> QJsonValue {
                    return ProjectIO::pointsToJson(f.reference, f.dimension());
                },
                [](const FractalItem &, FractalSpec &f, const QJsonValue &v,
                   const QString &where) {
                    f.reference = property::pointsFromJson(v, where, f.dimension());
                })
            .label(QT_TR_NOOP("Reference points"))
            .tip(QT_TR_NOOP("The points the S_i are built for (S_i R = f_i(R)); none: the "
                            "control points themselves"))
            .when(custom)
            .omitWhenDefault();
        declarePointSet(d, 0, QStringLiteral("control_points"), QT_TR_NOOP("Control points"));
        return d.table();
    }();
    return table;
}

} // namespace awb
