#include "model/BezierUnionItem.h"

#include "core/ifs/BezierAttractor.h"
#include "model/Commands.h"
#include "model/ProjectIO.h"
#include "model/PropertyDeclaration.h"

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
    if (u.size() != points.size())
        return Problem{"curves", tr("%1 split parameters for %2 curves")
                                     .arg(u.size()).arg(points.size())};
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

BezierUnionItem::BezierUnionItem() : AttractorItem(tr("Bézier union"))
{
    m_spec.u = {0.5, 0.5};
    m_spec.points = {{{0, 0}, {0.5, 1}, {1, 0}}, {{1, 0}, {1.5, -1}, {2, 0}}};
}

MaybeProblem BezierUnionItem::checkSpec(const BezierUnionSpec &spec) const
{
    return checkWithMaps(spec.check(), spec.mapCount());
}

bool BezierUnionItem::setSpec(const BezierUnionSpec &spec, int gesture)
{
    return setDeclared(*this, spec, gesture);
}

DerivedIfs BezierUnionItem::computeIfs() const
{
    std::vector<BezierCurveSpec> curves;
    for (size_t k = 0; k < m_spec.points.size(); ++k)
        curves.push_back({toMatrix(m_spec.points[k]), m_spec.u[k]});
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

// ---- declared properties ----------------------------------------------------------------------

const PropertyTable &BezierUnionItem::declaration()
{
    static const PropertyTable table = [] {
        using S = BezierUnionSpec;
        Declaration<BezierUnionItem> d(&AttractorItem::attractorProperties());
        auto spec = d.part(&BezierUnionItem::m_spec, &BezierUnionItem::checkSpec,
                           &BezierUnionItem::specChanged, QT_TR_NOOP("Change Bézier union %1"));
        spec.checkedOnRead([](const BezierUnionItem &, const S &s) { return s.check(); });
        spec.choice("mode", &S::mode, S::modeNames(),
                    {QT_TR_NOOP("Exact union (block IFS, 000 §2.2)"),
                     QT_TR_NOOP("All maps together (dusty fractal, 002 §6)")})
            .label(QT_TR_NOOP("Union"))
            .group(QT_TR_NOOP("Union"));
        spec.structured(
                "curves", QStringLiteral("curves"),
                [](const BezierUnionItem &, const S &s) {
                    QJsonArray curves;
                    for (size_t k = 0; k < s.points.size(); ++k)
                        curves.append(
                            QJsonObject{{"control_points", ProjectIO::pointsToJson(s.points[k])},
                                        {"u", s.u[k]}});
                    return QJsonValue(curves);
                },
                [](const BezierUnionItem &, S &s, const QJsonValue &v, const QString &where) {
                    if (!v.isArray() || v.toArray().isEmpty())
                        throw LoadError{where, tr("expected a non-empty array of curves "
                                                  "{\"control_points\": [...], \"u\": number}")};
                    s.points.clear();
                    s.u.clear();
                    const QJsonArray list = v.toArray();
                    for (qsizetype k = 0; k < list.size(); ++k) {
                        const QString at = where + QStringLiteral("[%1]").arg(k + 1);
                        if (!list[k].isObject())
                            throw LoadError{at, tr("expected an object with \"control_points\" "
                                                   "and \"u\"")};
                        const FieldReader curve(list[k].toObject(), at + QLatin1Char('.'));
                        s.points.push_back(curve.points("control_points"));
                        s.u.push_back(curve.number("u", 0.5));
                    }
                })
            .label(QT_TR_NOOP("Curves"))
            .tip(QT_TR_NOOP("Each curve's control points and split parameter u"))
            .required()
            .elements(
                QStringLiteral("curves.%1.u"), QT_TR_NOOP("Split parameter u"),
                ParameterInfo::Type::Real, [](const S &s) { return int(s.u.size()); },
                [](const S &s, int k) { return QVariant(s.u[size_t(k)]); },
                [](S &s, int k, const QVariant &v) -> MaybeProblem {
                    const auto x = property::toReal(v);
                    if (!x)
                        return Problem{"u", property::notValid(v, QStringLiteral("u"))};
                    s.u[size_t(k)] = *x;
                    return std::nullopt;
                },
                QT_TR_NOOP("Curve %1"))
            .range(0, 1)
            .slider(0.01, 0.99)
            .tip(QT_TR_NOOP("de Casteljau split at u, 0 < u < 1 (002 eqs. (9)-(10)); the curve "
                            "is the same for every u, the IFS is not"));
        return d.table();
    }();
    return table;
}

} // namespace awb
