#include "model/BezierUnionItem.h"

#include "core/ifs/BezierAttractor.h"
#include "model/Commands.h"
#include "model/ProjectIO.h"

#include <cmath>

namespace awb {

namespace {

// diag(blocks): the spectrum of the union's i-th matrix is the union of the curves' spectra.
Mat blockDiagonal(const std::vector<Mat> &blocks)
{
    Eigen::Index n = 0;
    for (const Mat &b : blocks)
        n += b.rows();
    Mat out = Mat::Zero(n, n);
    Eigen::Index off = 0;
    for (const Mat &b : blocks) {
        out.block(off, off, b.rows(), b.cols()) = b;
        off += b.rows();
    }
    return out;
}

// Plane points into the IFS space of one curve's split (plane maps or lifted / barycentric).
Mat curveSpace(const BezierSplit &split, const Mat &X)
{
    return split.planar ? X : split.lifted.toIfsSpace(X);
}

bool parseCurveKey(const QString &key, int curves, int *index)
{
    const QStringList parts = key.split(QLatin1Char('.'));
    if (parts.size() != 3 || parts[0] != "curves" || parts[2] != "u")
        return false;
    bool ok = false;
    *index = parts[1].toInt(&ok);
    return ok && *index >= 0 && *index < curves;
}

} // namespace

// ---- BezierUnionSpec --------------------------------------------------------------------------

const QStringList &BezierUnionSpec::modeNames()
{
    static const QStringList names{"block", "combined"};
    return names;
}

MaybeProblem BezierUnionSpec::check() const
{
    if (u.empty())
        return Problem{"curves", tr("a union needs at least one curve")};
    for (size_t i = 0; i < u.size(); ++i)
        if (!(std::isfinite(u[i]) && u[i] > 0.0 && u[i] < 1.0))
            return Problem{QStringLiteral("curves[%1].u").arg(i + 1),
                           tr("the split parameter u = %1 must satisfy 0 < u < 1 (002 §3)")
                               .arg(u[i])};
    return std::nullopt;
}

int BezierUnionSpec::mapCount() const
{
    return mode == Mode::Block ? 2 : 2 * int(u.size());
}

// ---- BezierUnionItem --------------------------------------------------------------------------

BezierUnionItem::BezierUnionItem()
    : AttractorItem(tr("Bézier union")),
      m_points{{{0, 0}, {0.5, 1}, {1, 0}}, {{1, 0}, {1.5, -1}, {2, 0}}}
{
    m_spec.u = {0.5, 0.5};
}

MaybeProblem BezierUnionItem::checkSpec(const BezierUnionSpec &spec) const
{
    if (auto p = spec.check())
        return p;
    if (spec.u.size() != m_points.size())
        return Problem{"curves", tr("%1 split parameters for %2 curves")
                                     .arg(spec.u.size()).arg(m_points.size())};
    if (auto p = algorithm().check(spec.mapCount()))
        return Problem{"algorithm." + p->field, p->message};
    return std::nullopt;
}

bool BezierUnionItem::setSpec(const BezierUnionSpec &spec, int gesture)
{
    if (checkSpec(spec))
        return false;
    applyProperty(&BezierUnionItem::m_spec, spec, &BezierUnionItem::specChanged,
                  tr("Change Bézier union %1").arg(name()), gesture);
    return true;
}

DerivedIfs BezierUnionItem::computeIfs() const
{
    std::vector<BezierCurveSpec> curves;
    for (size_t k = 0; k < m_points.size(); ++k)
        curves.push_back({toMatrix(m_points[k]), m_spec.u[k]});
    DerivedIfs out;
    if (m_spec.mode == BezierUnionSpec::Mode::Block) {
        const BezierUnion u = bezierUnion(curves);
        out.ifs = u.ifs;
        for (int i = 0; i < 2; ++i) {
            std::vector<Mat> S;
            for (const BezierSplit &c : u.curves)
                S.push_back(c.S[size_t(i)]);
            out.S.real.push_back(blockDiagonal(S));
            out.A.real.push_back(u.ifs.maps[size_t(i)].A);
        }
        const auto splits = std::make_shared<const std::vector<BezierSplit>>(u.curves);
        out.toIfsSpace = [splits](const Mat &X) {
            std::vector<Mat> parts;
            Eigen::Index D = 0;
            for (const BezierSplit &c : *splits) {
                parts.push_back(curveSpace(c, X));
                D += parts.back().cols();
            }
            Mat Y(X.rows(), D);
            Eigen::Index off = 0;
            for (const Mat &p : parts) {
                Y.middleCols(off, p.cols()) = p;
                off += p.cols();
            }
            return Y;
        };
        QStringList lifted;
        for (size_t k = 0; k < u.curves.size(); ++k)
            if (!u.curves[k].planar)
                lifted << tr("curve %1: %2").arg(k + 1).arg(
                    QString::fromStdString(u.curves[k].planarReason));
        if (!lifted.isEmpty())
            out.note = tr("curves drawn in the lifted space of 000 §2: %1")
                           .arg(lifted.join(QLatin1String("; ")));
    } else {
        const CombinedBezierIfs c = combinedBezierIfs(curves);
        out.ifs = c.ifs;
        for (const BezierSplit &s : c.curves)
            for (const Mat &S : s.S)
                out.S.real.push_back(S);
        for (const AffineMap &f : c.ifs.maps)
            out.A.real.push_back(f.A);
        out.toIfsSpace = [](const Mat &X) { return X; };
        out.note = c.joint.contractive
                       ? tr("every composition of %1 maps contracts (factor %2): the dusty "
                            "fractal of 002 §6 is the unique attractor")
                             .arg(c.joint.length).arg(c.joint.factor)
                       : tr("no contraction was proven (best bound %1 at length %2): the "
                            "picture may not be an attractor")
                             .arg(c.joint.factor).arg(c.joint.length);
    }
    applyAlgorithm(out.ifs);
    return out;
}

void BezierUnionItem::write(QJsonObject &json) const
{
    AttractorItem::write(json);
    json["mode"] = BezierUnionSpec::modeNames().at(int(m_spec.mode));
    QJsonArray curves;
    for (size_t k = 0; k < m_points.size(); ++k)
        curves.append(QJsonObject{{"control_points", ProjectIO::pointsToJson(m_points[k])},
                                  {"u", m_spec.u[k]}});
    json["curves"] = curves;
}

void BezierUnionItem::read(const FieldReader &fields)
{
    AttractorItem::read(fields);
    BezierUnionSpec spec;
    spec.mode = BezierUnionSpec::Mode(
        fields.choice("mode", BezierUnionSpec::modeNames(), int(spec.mode)));
    const QJsonValue v = fields.value("curves");
    if (v.isUndefined())
        fields.fail("curves", tr("missing"));
    if (!v.isArray() || v.toArray().isEmpty())
        fields.fail("curves", tr("expected a non-empty array of curves "
                                 "{\"control_points\": [...], \"u\": number}"));
    std::vector<PointList> points;
    const QJsonArray list = v.toArray();
    for (qsizetype k = 0; k < list.size(); ++k) {
        const QString where = fields.path("curves") + QStringLiteral("[%1]").arg(k + 1);
        if (!list[k].isObject())
            throw LoadError{where, tr("expected an object with \"control_points\" and \"u\"")};
        const FieldReader curve(list[k].toObject(), where + QLatin1Char('.'));
        points.push_back(curve.points("control_points"));
        spec.u.push_back(curve.number("u", 0.5));
    }
    fields.require(spec.check());
    m_spec = spec;
    m_points = points;
}

// ---- generic parameters ---------------------------------------------------------------------

QList<ParameterInfo> BezierUnionItem::parameters() const
{
    using P = ParameterInfo;
    QList<ParameterInfo> list;
    list << P::make("mode", tr("Union"), P::Type::Choice)
                .options({tr("Exact union (block IFS, 000 §2.2)"),
                          tr("All maps together (dusty fractal, 002 §6)")})
                .in(tr("Union"));
    for (int k = 0; k < int(m_spec.u.size()); ++k)
        list << P::make(QStringLiteral("curves.%1.u").arg(k), tr("Split parameter u"),
                        P::Type::Real)
                    .range(0, 1)
                    .slider(0.01, 0.99)
                    .in(tr("Curve %1").arg(k + 1))
                    .tip(tr("de Casteljau split at u, 0 < u < 1 (002 eqs. (9)-(10)); the "
                            "curve is the same for every u, the IFS is not"));
    return list;
}

QVariant BezierUnionItem::parameter(const QString &key) const
{
    if (key == "mode")
        return int(m_spec.mode);
    int k = 0;
    if (parseCurveKey(key, int(m_spec.u.size()), &k))
        return m_spec.u[size_t(k)];
    return {};
}

bool BezierUnionItem::setParameter(const QString &key, const QVariant &value, int gesture,
                                   QString *error)
{
    BezierUnionSpec next = m_spec;
    bool ok = true;
    int k = 0;
    if (key == "mode") {
        const int index = value.toInt(&ok);
        ok = ok && index >= 0 && index < BezierUnionSpec::modeNames().size();
        if (ok)
            next.mode = BezierUnionSpec::Mode(index);
    } else if (parseCurveKey(key, int(m_spec.u.size()), &k)) {
        next.u[size_t(k)] = value.toDouble(&ok);
    } else {
        return Item::setParameter(key, value, gesture, error);
    }
    return commitParameter(key, value, ok, checkSpec(next),
                           [&] { return setSpec(next, gesture); }, error);
}

} // namespace awb
