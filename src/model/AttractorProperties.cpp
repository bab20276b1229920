// The declared properties of every attractor item (an item kind is a declaration: the file
// format, undo, the Properties dock, Python and the CLI's `set` come from this table;
// docs/adding-an-item-kind.md). Split from AttractorItem.cpp, whose edits it calls.
#include "model/AttractorItem.h"

#include "model/Commands.h"
#include "model/NumberFormat.h"
#include "model/PointSetProperty.h"
#include "model/Project.h"
#include "model/ProjectIO.h"
#include "model/StartSetDefaults.h"
#include "model/StartSetText.h"

#include <algorithm>
#include <cmath>
#include <optional>

namespace awb {

namespace {

QString liftedText(const std::vector<std::vector<double>> &points)
{
    QStringList text;
    for (const auto &p : points) {
        QStringList c;
        for (double v : p)
            c << editableNumber(v);  // exact: the text reads back to the same point
        text << c.join(QStringLiteral(", "));
    }
    return text.join(QStringLiteral("; "));
}

QString netText(const std::vector<int> &net)
{
    QStringList text;
    for (int i : net)
        text << QString::number(i);
    return text.join(QStringLiteral(", "));
}

} // namespace

const PropertyTable &AttractorItem::attractorProperties()
{
    static const PropertyTable table = [] {
        Declaration<AttractorItem> d(&Item::itemProperties(), PartBase::Place::Inputs);
        using K = StartSetSpec::Kind;
        auto start = d.part(&AttractorItem::m_startSet, &AttractorItem::checkStartSet,
                            &AttractorItem::startSetChanged,
                            QT_TR_NOOP("Change start set of %1"));
        start.checkedOnRead([](const AttractorItem &, const StartSetSpec &s) { return s.check(); },
                            QStringLiteral("start_set"));
        start.choice("start_set.kind", &StartSetSpec::kind, StartSetSpec::kindNames(),
                     {QT_TR_NOOP("Point"), QT_TR_NOOP("Segment"), QT_TR_NOOP("Triangle"),
                      QT_TR_NOOP("Polygon"), QT_TR_NOOP("Points"), QT_TR_NOOP("Lifted points"),
                      QT_TR_NOOP("Vertex limits"), QT_TR_NOOP("Net points")})
            .label(QT_TR_NOOP("Kind"))
            .group(QT_TR_NOOP("Start set X0"))
            .shownWhen([](const AttractorItem &item, const StartSetSpec &) {
                return item.hasStartSet();
            })
            .tip(QT_TR_NOOP("The set X0 deterministic iteration starts from; drag its vertices "
                            "in the attractor view. Lifted points are points of the lifted "
                            "space of 000 §2; vertex limits, a mesh's vertices' limit "
                            "positions; net points, control points by index, which the set "
                            "follows when they move."))
            // A new kind starts where the curve is: from the control points, or the
            // centroid lifted with zero extra coordinates.
            .onEdit([](const AttractorItem &item, StartSetSpec &s) -> MaybeProblem {
                const PointList control =
                    item.controlPointSetCount() ? item.controlPoints(0) : PointList{};
                s.lifted.clear();
                s.net.clear();
                if (s.kind == K::VertexLimits) {
                    s.points.clear();
                    return std::nullopt;
                }
                if (s.kind == K::Net) {
                    // The largest triangle of the net (the lifting's first free rows, 000 §2):
                    // the start of 000 Fig. 7.
                    s.points.clear();
                    if (control.empty())
                        return Problem{"kind", tr("The item has no control points.")};
                    s.net = largestNetTriangle(control, item.pointDimension());
                    return std::nullopt;
                }
                if (s.kind != K::Lifted) {
                    s.points = startPointsFor(s.kind, control);
                    return std::nullopt;
                }
                const auto derived = item.derivedIfs();
                if (!derived)
                    return Problem{"kind", item.derivedError()};
                if (control.empty())
                    return Problem{"kind", tr("The item has no control points.")};
                const Mat centroid =
                    toMatrix(control, item.pointDimension()).colwise().mean();
                try {
                    const Mat X = derived->toIfsSpace(centroid);
                    s.lifted = {std::vector<double>(X.data(), X.data() + X.size())};
                } catch (const std::exception &e) {
                    return Problem{"kind", QString::fromUtf8(e.what())};
                }
                s.points.clear();
                return std::nullopt;
            });
        start
            .structured(
                "start_set.points", QStringLiteral("points"),
                [](const AttractorItem &item, const StartSetSpec &s) -> QJsonValue {
                    if (s.kind == K::VertexLimits)
                        return QJsonArray();
                    if (s.kind == K::Net) {
                        QJsonArray indices;
                        for (int i : s.net)
                            indices.append(i);
                        return indices;
                    }
                    if (s.kind != K::Lifted)
                        return ProjectIO::pointsToJson(s.points, item.pointDimension());
                    QJsonArray points;
                    for (const auto &p : s.lifted) {
                        QJsonArray c;
                        for (double v : p)
                            c.append(v);
                        points.append(c);
                    }
                    return points;
                },
                [](const AttractorItem &item, StartSetSpec &s, const QJsonValue &v,
                   const QString &where) {
                    s.net.clear();
                    if (s.kind == K::Net) {
                        if (!v.isArray())
                            throw LoadError{where, QCoreApplication::translate(
                                                       "awb::ProjectIO",
                                                       "expected an array of net point indices "
                                                       "[0, 9, 18]")};
                        const QJsonArray a = v.toArray();
                        if (a.size() > StartSetSpec::maxNetPoints)
                            throw LoadError{where, QCoreApplication::translate(
                                                       "awb::ProjectIO",
                                                       "%1 net point indices; a start set takes "
                                                       "at most %2")
                                                       .arg(a.size())
                                                       .arg(StartSetSpec::maxNetPoints)};
                        s.points.clear();
                        s.lifted.clear();
                        for (qsizetype i = 0; i < a.size(); ++i) {
                            const QString at = where + QStringLiteral("[%1]").arg(i + 1);
                            const double n = FieldReader::toNumber(a[i], at);
                            if (n != std::floor(n) || n < 0 || n > 1e9)
                                throw LoadError{at, QCoreApplication::translate(
                                                        "awb::ProjectIO",
                                                        "expected a net point index (an integer "
                                                        "from 0)")};
                            s.net.push_back(int(n));
                        }
                        return;
                    }
                    if (s.kind == K::Lifted) {
                        if (!v.isArray())
                            throw LoadError{where, QCoreApplication::translate(
                                                       "awb::ProjectIO",
                                                       "expected an array of lifted points "
                                                       "[x, y, c1, ...]")};
                        const QJsonArray a = v.toArray();
                        s.points.clear();
                        s.lifted.clear();
                        for (qsizetype i = 0; i < a.size(); ++i) {
                            const QString at = where + QStringLiteral("[%1]").arg(i + 1);
                            if (!a[i].isArray())
                                throw LoadError{at, QCoreApplication::translate(
                                                        "awb::ProjectIO",
                                                        "expected a lifted point [x, y, c1, "
                                                        "...]")};
                            s.lifted.push_back(property::numbersFromJson(a[i], at));
                        }
                        return;
                    }
                    s.points = property::pointsFromJson(v, where, item.pointDimension());
                    if (s.kind == K::VertexLimits && !s.points.empty())
                        throw LoadError{where, QCoreApplication::translate(
                                                   "awb::ProjectIO",
                                                   "a \"vertex-limits\" start set has no points "
                                                   "(it starts at the limit positions of the "
                                                   "mesh's vertices)")};
                })
            .label(QT_TR_NOOP("Vertices"));
        start
            .text(
                "start_set.lifted",
                [](const AttractorItem &, const StartSetSpec &s) { return liftedText(s.lifted); },
                [](const AttractorItem &, StartSetSpec &s, const QString &text) -> MaybeProblem {
                    std::vector<std::vector<double>> points;
                    for (const QString &point : text.split(';', Qt::SkipEmptyParts)) {
                        std::vector<double> p;
                        for (const QString &n : point.split(',', Qt::SkipEmptyParts)) {
                            const auto v = parseNumber(n.trimmed());
                            if (!v)
                                return Problem{"points",
                                               tr("'%1' is not a number.").arg(n.trimmed())};
                            p.push_back(*v);
                        }
                        points.push_back(std::move(p));
                    }
                    // Typed lifted points make the start set lifted.
                    s.kind = K::Lifted;
                    s.lifted = points;
                    s.points.clear();
                    return std::nullopt;
                })
            .notSaved()
            .label(QT_TR_NOOP("Lifted"))
            .group(QT_TR_NOOP("Start set X0"))
            .tip(QT_TR_NOOP("Points of the lifted space of 000 §2: x, y, then the extra "
                            "coordinates of the lifting, the homogeneous 1 implied. Commas "
                            "between coordinates, ';' between points."))
            .enabledWhen([](const AttractorItem &, const StartSetSpec &s) {
                return s.kind == K::Lifted;
            })
            // A mesh starts at its vertices' limits: no lifted space to type points of.
            .shownWhen([](const AttractorItem &item, const StartSetSpec &) {
                return !item.startsAtVertexLimits() && item.hasStartSet();
            });
        start
            .text(
                "start_set.net",
                [](const AttractorItem &, const StartSetSpec &s) { return netText(s.net); },
                [](const AttractorItem &, StartSetSpec &s, const QString &text) -> MaybeProblem {
                    try {
                        s.net = netIndicesFromText(text);
                    } catch (const StartSetTextError &e) {
                        return Problem{"points", e.message};
                    }
                    // Typed indices make the start set one of net points.
                    s.kind = K::Net;
                    s.points.clear();
                    s.lifted.clear();
                    return std::nullopt;
                })
            .notSaved()
            .label(QT_TR_NOOP("Net points"))
            .group(QT_TR_NOOP("Start set X0"))
            .tip(QT_TR_NOOP("Control points by index, counted from 0 (commas between them): "
                            "the start set is their point, segment or polygon in the lifted "
                            "space, and it follows them when they move."))
            .enabledWhen([](const AttractorItem &, const StartSetSpec &s) {
                return s.kind == K::Net;
            })
            .shownWhen([](const AttractorItem &item, const StartSetSpec &) {
                return item.startsAtNetPoints();
            });

        auto algorithm = d.part(&AttractorItem::m_algorithm, &AttractorItem::checkAlgorithm,
                                &AttractorItem::algorithmChanged,
                                QT_TR_NOOP("Change algorithm of %1"));
        // The bound from the number of maps: checkLoaded(), once the maps are known.
        algorithm.checkedOnRead(
            [](const AttractorItem &, const AlgorithmSpec &a) { return a.check(-1); },
            QStringLiteral("algorithm"));
        using M = AlgorithmSpec::Mode;
        algorithm
            .choice("algorithm.mode", &AlgorithmSpec::mode, AlgorithmSpec::modeNames(),
                    {QT_TR_NOOP("Deterministic"), QT_TR_NOOP("Random (chaos game)")})
            .label(QT_TR_NOOP("Mode"))
            .group(QT_TR_NOOP("Algorithm"))
            .tip(QT_TR_NOOP("Deterministic iteration draws F^k(X0) at the depth k; random "
                            "iteration plays the chaos game with the samples"));
        algorithm.integer("algorithm.depth", &AlgorithmSpec::depth)
            .label(QT_TR_NOOP("Depth"))
            .group(QT_TR_NOOP("Algorithm"))
            .tip(QT_TR_NOOP("The level k of F^k(X0): N^k images of the start set, at most 2^31"))
            .notAnimated()
            .enabledWhen([](const AttractorItem &, const AlgorithmSpec &a) {
                return a.mode == M::Deterministic;
            })
            // The deepest level this item's maps allow: typing more is refused with that
            // number.
            .adjust([](const AttractorItem &item, const AlgorithmSpec &a, ParameterInfo &i) {
                i.minimum = 0;
                i.maximum = std::max(a.depth, AlgorithmSpec::maxDepthFor(item.branching()));
            });
        algorithm.integer("algorithm.samples", &AlgorithmSpec::samples)
            .label(QT_TR_NOOP("Samples"))
            .group(QT_TR_NOOP("Algorithm"))
            .range(1, double(AlgorithmSpec::maxSamples))
            .tip(QT_TR_NOOP("Points of the chaos game"))
            .notAnimated()
            .enabledWhen([](const AttractorItem &, const AlgorithmSpec &a) {
                return a.mode == M::Random;
            });
        algorithm.numbers("algorithm.probabilities", &AlgorithmSpec::probabilities)
            .label(QT_TR_NOOP("Probabilities"))
            .tip(QT_TR_NOOP("One weight per map for the chaos game; none: uniform"));
        algorithm.integer("algorithm.seed", &AlgorithmSpec::seed)
            .label(QT_TR_NOOP("Seed"))
            .group(QT_TR_NOOP("Algorithm"))
            .range(0, double(AlgorithmSpec::maxSeed))
            .tip(QT_TR_NOOP("The chaos game's random stream: the same seed, the same picture"))
            .notAnimated()
            .enabledWhen([](const AttractorItem &, const AlgorithmSpec &a) {
                return a.mode == M::Random;
            });
        return d.table();
    }();
    return table;
}

} // namespace awb
