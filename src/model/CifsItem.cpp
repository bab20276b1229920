#include "model/CifsItem.h"

#include "core/analysis/CifsAnalysis.h"
#include "core/ifs/Cifs.h"
#include "core/schemes/ControlPointFractal.h"
#include "core/schemes/Scheme.h"
#include "model/ProjectIO.h"
#include "model/PropertyDeclaration.h"
#include "model/SchemeSpec.h"

#include <QJsonArray>

#include <cmath>

namespace awb {

namespace {

QString quoted(const QString &s) { return QStringLiteral("\"%1\"").arg(s); }

QJsonValue matrixToJson(const Mat &M) { return property::matricesToJson({M}).toArray().first(); }

Mat matrixFromJson(const QJsonValue &v, const QString &where)
{
    const QJsonArray rows = v.toArray();
    if (!v.isArray() || rows.isEmpty())
        throw LoadError{where, CifsSpec::tr("expected a matrix: a non-empty array of rows")};
    const qsizetype cols = rows[0].toArray().size();
    if (rows.size() > CifsSpec::maxStatePoints || cols > CifsSpec::maxStatePoints)
        throw LoadError{where, CifsSpec::tr("a %1 x %2 matrix: a state has at most %3 points")
                                   .arg(rows.size()).arg(cols).arg(CifsSpec::maxStatePoints)};
    Mat M(rows.size(), cols);
    for (qsizetype r = 0; r < rows.size(); ++r) {
        const QString at = where + QStringLiteral("[%1]").arg(r + 1);
        const QJsonArray row = rows[r].toArray();
        if (!rows[r].isArray() || row.size() != cols || cols == 0)
            throw LoadError{at, CifsSpec::tr("expected a row of %1 numbers, like row 1")
                                    .arg(cols)};
        for (qsizetype c = 0; c < cols; ++c)
            M(r, c) = FieldReader::toExactNumber(row[c], at + QStringLiteral("[%1]").arg(c + 1));
    }
    return M;
}

// A state named by the file: its name (or a 1-based number, as the messages count).
int stateFromJson(const CifsSpec &s, const QJsonValue &v, const QString &where)
{
    if (v.isString()) {
        const int k = s.stateIndex(v.toString());
        if (k >= 0)
            return k;
        throw LoadError{where, CifsSpec::tr("no state %1; the states are %2")
                                   .arg(quoted(v.toString()),
                                        s.stateNames().isEmpty()
                                            ? CifsSpec::tr("none")
                                            : quoted(s.stateNames().join("\", \"")))};
    }
    if (v.isDouble() && v.toDouble() == std::floor(v.toDouble()) && v.toDouble() >= 1
        && v.toDouble() <= double(s.states.size()))
        return int(v.toDouble()) - 1;
    throw LoadError{where, CifsSpec::tr("expected a state's name")};
}

} // namespace

// ---- arcs -------------------------------------------------------------------------------------

bool CifsArcSpec::operator==(const CifsArcSpec &o) const
{
    return name == o.name && from == o.from && to == o.to && weight == o.weight
           && S.rows() == o.S.rows() && S.cols() == o.S.cols() && S == o.S;
}

Mat cifsArcMatrixFromJson(const QJsonObject &arc, const CifsStateSpec &from,
                          const CifsStateSpec &to, const QString &where)
{
    const QStringList forms{"matrix", "columns", "affine", "scheme"};
    QStringList given;
    for (const QString &f : forms)
        if (arc.contains(f))
            given << f;
    if (given.size() != 1)
        throw LoadError{where, given.isEmpty()
                                   ? CifsSpec::tr("missing: give the arc's map as \"matrix\", "
                                                  "\"columns\", \"affine\" or \"scheme\"")
                                   : CifsSpec::tr("give the arc's map one way, not as %1")
                                         .arg(given.join(CifsSpec::tr(" and ")))};
    const QString form = given.front();
    const QString at = where + form;
    const int nTo = int(to.points.size()), nFrom = int(from.points.size());
    if (form == QLatin1String("matrix"))
        return matrixFromJson(arc.value(form), at);
    if (form == QLatin1String("columns"))
        return matrixFromJson(arc.value(form), at).transpose();
    if (form == QLatin1String("affine")) {
        if (nTo != 3 || nFrom != 3)
            throw LoadError{at, CifsSpec::tr("a plane affine map needs both states to have 3 "
                                             "control points (a frame triangle): %1 has %2, %3 "
                                             "has %4")
                                    .arg(quoted(from.name)).arg(nFrom)
                                    .arg(quoted(to.name)).arg(nTo)};
        if (!arc.value(form).isObject())
            throw LoadError{at, CifsSpec::tr("expected {\"A\": [[a11, a12], [a21, a22]], "
                                             "\"b\": [b1, b2]}")};
        const QJsonObject o = arc.value(form).toObject();
        const Mat A = matrixFromJson(o.value("A"), at + QStringLiteral(".A"));
        const Mat b = matrixFromJson(QJsonArray{o.value("b")}, at + QStringLiteral(".b"));
        if (A.rows() != 2 || A.cols() != 2 || b.cols() != 2)
            throw LoadError{at, CifsSpec::tr("A must be 2 x 2 and b two numbers")};
        try {
            return barycentricMatrix(AffineMap{A, RowVec(b.row(0))}, toMatrix(to.points),
                                     toMatrix(from.points));
        } catch (const InputError &e) {
            throw LoadError{at, QString::fromStdString(e.what())};
        }
    }
    // A piece of a curve scheme, for the states' number of points.
    if (!arc.value(form).isObject())
        throw LoadError{at, CifsSpec::tr("expected a curve scheme, as a curve item's "
                                         "\"scheme\"")};
    const FieldReader r(arc, where);
    const SchemeSpec scheme = SchemeSpec::fromJson(*r.object("scheme", true));
    if (nTo != nFrom)
        throw LoadError{at, CifsSpec::tr("a scheme's matrix is square: %1 has %2 points, %3 "
                                         "has %4")
                                .arg(quoted(from.name)).arg(nFrom).arg(quoted(to.name))
                                .arg(nTo)};
    try {
        const SubdivisionMatrices m = scheme.makeScheme()->matrices(nFrom);
        const qint64 piece = r.integer("piece", 1, 1, qint64(m.S.size()));
        return m.S[size_t(piece - 1)];
    } catch (const InputError &e) {
        throw LoadError{at, QString::fromStdString(e.what())};
    }
}

// ---- CifsSpec ---------------------------------------------------------------------------------

QStringList CifsSpec::stateNames() const
{
    QStringList out;
    for (const CifsStateSpec &s : states)
        out << s.name;
    return out;
}

int CifsSpec::stateIndex(const QString &name) const
{
    for (size_t i = 0; i < states.size(); ++i)
        if (states[i].name == name)
            return int(i);
    return -1;
}

int CifsSpec::branching() const
{
    std::vector<int> out(states.size(), 0);
    int most = 1;
    for (const CifsArcSpec &a : arcs)
        if (a.from >= 0 && a.from < int(out.size()))
            most = std::max(most, ++out[size_t(a.from)]);
    return most;
}

MaybeProblem CifsSpec::check() const
{
    if (states.empty())
        return Problem{"states", tr("an automaton needs at least one state")};
    if (int(states.size()) > maxStates)
        return Problem{"states", tr("%1 states: at most %2").arg(states.size()).arg(maxStates)};
    for (size_t i = 0; i < states.size(); ++i) {
        const QString at = QStringLiteral("states[%1]").arg(i + 1);
        const CifsStateSpec &s = states[i];
        if (s.name.trimmed().isEmpty())
            return Problem{at + ".name", tr("a state needs a name")};
        if (s.name == allStates)
            return Problem{at + ".name", tr("\"%1\" names all states; call the state otherwise")
                                             .arg(allStates)};
        if (stateIndex(s.name) != int(i))
            return Problem{at + ".name", tr("two states are called %1").arg(quoted(s.name))};
        if (s.points.empty() || int(s.points.size()) > maxStatePoints)
            return Problem{at + ".control_points",
                           tr("a state needs 1 to %1 control points, got %2")
                               .arg(maxStatePoints).arg(s.points.size())};
        for (const Point &p : s.points)
            if (!std::isfinite(p.x) || !std::isfinite(p.y))
                return Problem{at + ".control_points",
                               tr("state %1 has a control point that is not finite")
                                   .arg(quoted(s.name))};
    }
    if (arcs.size() > size_t(kMaxMaps))
        return Problem{"arcs", tr("%1 arcs: at most %2 (addresses are bytes)")
                                   .arg(arcs.size()).arg(kMaxMaps)};
    QStringList names;
    for (size_t i = 0; i < arcs.size(); ++i) {
        const QString at = QStringLiteral("arcs[%1]").arg(i + 1);
        const CifsArcSpec &a = arcs[i];
        if (a.name.trimmed().isEmpty())
            return Problem{at + ".name", tr("an arc needs a name")};
        if (names.contains(a.name))
            return Problem{at + ".name", tr("two arcs are called %1").arg(quoted(a.name))};
        names << a.name;
        const int N = int(states.size());
        if (a.from < 0 || a.from >= N || a.to < 0 || a.to >= N)
            return Problem{at, tr("arc %1 leads between states that do not exist")
                                   .arg(quoted(a.name))};
        const int nTo = int(states[size_t(a.to)].points.size());
        const int nFrom = int(states[size_t(a.from)].points.size());
        if (a.S.rows() != nTo || a.S.cols() != nFrom)
            return Problem{at + ".matrix",
                           tr("arc %1 has a %2 x %3 matrix; from %4 (%5 points) to %6 (%7 "
                              "points) it must be %7 x %5: a row per point of %6")
                               .arg(quoted(a.name)).arg(a.S.rows()).arg(a.S.cols())
                               .arg(quoted(states[size_t(a.from)].name)).arg(nFrom)
                               .arg(quoted(states[size_t(a.to)].name)).arg(nTo)};
        if (!a.S.allFinite())
            return Problem{at + ".matrix", tr("arc %1 has a matrix entry that is not finite")
                                               .arg(quoted(a.name))};
        for (Eigen::Index r = 0; r < a.S.rows(); ++r) {
            const double sum = a.S.row(r).sum();
            if (std::abs(sum - 1.0) > 1e-9 * std::max(1.0, a.S.row(r).cwiseAbs().sum()))
                return Problem{at + ".matrix",
                               tr("row %1 of arc %2 sums to %3, not 1: the map would not keep "
                                  "barycentric coordinates")
                                   .arg(r + 1).arg(quoted(a.name)).arg(sum, 0, 'g', 12)};
        }
        if (!std::isfinite(a.weight) || a.weight <= 0)
            return Problem{at + ".weight", tr("the weight of arc %1 must be a number > 0")
                                               .arg(quoted(a.name))};
    }
    if (drawn != allStates && stateIndex(drawn) < 0)
        return Problem{"state", tr("no state %1 to draw; the states are %2")
                                    .arg(quoted(drawn), quoted(stateNames().join("\", \"")))};
    return std::nullopt;
}

Cifs CifsSpec::toCore() const
{
    Cifs c;
    for (const CifsStateSpec &s : states)
        c.addState(s.name.toStdString(), toMatrix(s.points));
    for (const CifsArcSpec &a : arcs)
        c.addTransition(a.name.toStdString(), a.from, a.to, a.S, a.weight);
    return c;
}

CifsSpec CifsSpec::fernOfGaskets(int redirected)
{
    const Cifs core = fernSierpinskiCifs(redirected);
    CifsSpec s;
    for (const CifsState &q : core.states)
        s.states.push_back({QString::fromStdString(q.name), toPointList(q.controlPoints)});
    for (const CifsTransition &t : core.transitions)
        s.arcs.push_back({QString::fromStdString(t.name), t.from, t.to, t.S, t.weight});
    s.drawn = s.states.front().name;
    return s;
}

Mat CifsSpec::defaultArcMatrix(int nTo, int nFrom, int k)
{
    if (nTo == nFrom) {
        Mat S = 0.5 * Mat::Identity(nTo, nTo);
        S.col(k % nTo).array() += 0.5;
        return S;
    }
    // Every point of the to-space goes halfway from the from-space's centroid to one vertex.
    Mat S = Mat::Constant(nTo, nFrom, 0.5 / nFrom);
    for (int r = 0; r < nTo; ++r)
        S(r, (r + k) % nFrom) += 0.5;
    return S;
}

QString CifsSpec::freshStateName() const
{
    for (int k = 1;; ++k)
        if (stateIndex(QStringLiteral("S%1").arg(k)) < 0)
            return QStringLiteral("S%1").arg(k);
}

QString CifsSpec::freshArcName() const
{
    for (int k = 1;; ++k) {
        const QString n = QStringLiteral("t%1").arg(k);
        if (std::none_of(arcs.begin(), arcs.end(), [&](const CifsArcSpec &a) {
                return a.name == n;
            }))
            return n;
    }
}

// ---- CifsItem ---------------------------------------------------------------------------------

CifsItem::CifsItem() : AttractorItem(tr("Fern of gaskets")), m_spec(CifsSpec::fernOfGaskets()) {}

MaybeProblem CifsItem::checkSpec(const CifsSpec &spec) const
{
    return checkWithMaps(spec.check(), spec.branching());
}

bool CifsItem::setSpec(const CifsSpec &spec, int gesture, QString *error)
{
    if (const MaybeProblem p = checkSpec(spec)) {
        if (error)
            *error = p->message;
        return false;
    }
    return setDeclared(*this, spec, gesture);
}

std::shared_ptr<const CifsAnalysis> CifsItem::automatonAnalysis(QString *error) const
{
    std::vector<int> dims;
    for (const CifsStateSpec &q : m_spec.states)
        dims.push_back(int(q.points.size()));
    if (!(m_analysis || !m_analysisError.isEmpty()) || m_analysedArcs != m_spec.arcs
        || m_analysedDimensions != dims) {
        m_analysedArcs = m_spec.arcs;
        m_analysedDimensions = dims;
        m_analysis.reset();
        m_analysisError.clear();
        try {
            m_analysis = std::make_shared<const CifsAnalysis>(analyseCifs(m_spec.toCore()));
        } catch (const std::exception &e) {
            m_analysisError = QString::fromStdString(e.what());
        }
    }
    if (error)
        *error = m_analysisError;
    return m_analysis;
}

QJsonObject CifsItem::upgradedFields(const QJsonObject &json) const
{
    // Version 1 files before the general automaton: the one preset, its redirected arc and
    // the frame both states shared.
    if (json.contains("states") || json.value("preset") != QLatin1String("fern-sierpinski"))
        return json;
    QJsonObject out = json;
    const QJsonValue redirected = json.value("redirected");
    const int k = redirected.isDouble() ? int(redirected.toDouble()) : 2;
    if (k < 0 || k > 3 || (redirected.isDouble() && redirected.toDouble() != k))
        return json; // read as it is: "states" missing names the problem
    CifsSpec s = CifsSpec::fernOfGaskets(k);
    if (json.contains("control_points")) {
        const PointList frame =
            property::pointsFromJson(json.value("control_points"), "control_points", 2);
        for (CifsStateSpec &q : s.states)
            q.points = frame;
    }
    QJsonArray states, arcs;
    for (const CifsStateSpec &q : s.states)
        states.append(QJsonObject{{"name", q.name},
                                  {"control_points", ProjectIO::pointsToJson(q.points)}});
    for (const CifsArcSpec &a : s.arcs)
        arcs.append(QJsonObject{{"name", a.name},
                                {"from", s.states[size_t(a.from)].name},
                                {"to", s.states[size_t(a.to)].name},
                                {"matrix", matrixToJson(a.S)},
                                {"weight", a.weight}});
    out.remove("preset");
    out.remove("redirected");
    out.remove("control_points");
    out["states"] = states;
    out["arcs"] = arcs;
    return out;
}

DerivedIfs CifsItem::computeIfs() const
{
    if (!algorithm().probabilities.empty())
        throw InputError(tr("a controlled IFS draws its arcs by their own weights (\"arcs\"): "
                            "leave the algorithm's probabilities empty")
                             .toStdString());
    std::vector<int> drawn;
    if (m_spec.drawn == CifsSpec::allStates)
        for (int q = 0; q < int(m_spec.states.size()); ++q)
            drawn.push_back(q);
    else
        drawn.push_back(m_spec.stateIndex(m_spec.drawn));
    Cifs core = m_spec.toCore();
    // A state being built (no arc leaves it yet) that the drawn states do not reach does not
    // stop the picture: it gets a collapsing self-loop after the real arcs (whose indices, the
    // addresses and colours, stay), never walked.
    std::vector<bool> reached(core.states.size(), false), leaves(core.states.size(), false);
    std::vector<int> queue = drawn;
    for (int q : drawn)
        reached[size_t(q)] = true;
    for (const CifsTransition &t : core.transitions)
        leaves[size_t(t.from)] = true;
    while (!queue.empty()) {
        const int q = queue.back();
        queue.pop_back();
        for (const CifsTransition &t : core.transitions)
            if (t.from == q && !reached[size_t(t.to)]) {
                reached[size_t(t.to)] = true;
                queue.push_back(t.to);
            }
    }
    for (int q = 0; q < int(core.states.size()); ++q)
        if (!reached[size_t(q)] && !leaves[size_t(q)]) {
            const int n = core.states[size_t(q)].dim();
            core.addTransition("-", q, q, Mat::Constant(n, n, 1.0 / n));
        }
    const auto cifs = std::make_shared<const Cifs>(std::move(core));
    // Validates (a drawn state without arcs, ...); 2000 cycles at most, each a spectrum of up
    // to 64 x 64: a hostile file costs a second, not minutes.
    const CifsCheck check = checkCifs(*cifs, 2000);
    if (!check.contractive)
        throw InputError(check.message);
    const auto stacking = std::make_shared<const CifsStacking>(stackingOf(*cifs));
    DerivedIfs out;
    bool square = true;
    for (const CifsArcSpec &a : m_spec.arcs)
        square = square && a.S.rows() == a.S.cols();
    for (const CifsArcSpec &a : m_spec.arcs)
        if (square)
            out.S.real.push_back(a.S);
    if (!square)
        out.S.unavailable = tr("arcs between states of different dimensions have rectangular "
                               "matrices: see the automaton's analysis");
    out.A.unavailable = tr("a controlled IFS has no single lifted IFS");
    out.ifs.space = m_spec.drawn == CifsSpec::allStates
                        ? std::string("barycentric (all states)")
                        : "barycentric (" + m_spec.drawn.toStdString() + ")";
    out.ifs.views.push_back(Projection{stacking->points, RowVec::Zero(2)});
    out.note = m_spec.drawn == CifsSpec::allStates
                   ? tr("The union of the attractors of the automaton's %1 states (003 §2.2).")
                         .arg(cifs->states.size())
                   : tr("The attractor of state %1 of the automaton (003 §2.2).")
                         .arg(quoted(m_spec.drawn));
    // Plane points go into the first drawn state's block.
    const int first = drawn.front();
    out.toIfsSpace = [stacking, cifs, first](const Mat &X) {
        Mat out = Mat::Zero(X.rows(), stacking->dimension);
        out.middleCols(stacking->offsets[size_t(first)], cifs->states[size_t(first)].dim()) =
            leastNormWeightsOfRows(cifs->states[size_t(first)].controlPoints, X);
        return out;
    };
    const AlgorithmSpec a = algorithm();
    if (a.mode == AlgorithmSpec::Mode::Random) {
        // Random iteration: the core's Markov chain on the states, `samples` points at the
        // item's depth and a quarter as many per level below it (the views' coarse frames).
        const auto count = [a](int depth) {
            return std::max(1.0, double(a.samples) / std::pow(4.0, std::max(0, a.depth - depth)));
        };
        out.iterate = [cifs, stacking, drawn, a, count](const StartSet &, int depth,
                                                        const std::vector<AttractorSink *> &sinks,
                                                        const IterationControl &control) {
            IterationStats stats;
            for (size_t k = 0; k < drawn.size() && !stats.cancelled; ++k) {
                ChaosOptions o;
                o.samples = std::uint64_t(count(depth) / double(drawn.size())) + 1;
                o.seed = std::uint64_t(a.seed) + k;
                StackedSink sink(*sinks.front(), stacking->dimension);
                sink.offset = stacking->offsets[size_t(drawn[k])];
                const IterationStats s = chaosGame(*cifs, drawn[k], o, sink, control);
                stats.images += s.images;
                stats.cancelled = s.cancelled;
            }
            return stats;
        };
        out.pointCount = [count](const StartSet &, int depth) { return count(depth); };
        return out;
    }
    // Deterministic: the start set comes in the stacked space; every state gets the same plane
    // points in its own coordinates.
    out.iterate = [cifs, stacking, drawn](const StartSet &start, int depth,
                                          const std::vector<AttractorSink *> &sinks,
                                          const IterationControl &control) {
        const Mat plane = start.vertices * stacking->points;
        std::vector<StartSet> starts;
        for (const CifsState &s : cifs->states)
            starts.push_back({start.kind, leastNormWeightsOfRows(s.controlPoints, plane)});
        IterationStats stats;
        for (int q : drawn) {
            StackedSink sink(*sinks.front(), stacking->dimension);
            sink.offset = stacking->offsets[size_t(q)];
            const IterationStats s = iterate(*cifs, q, starts, depth, sink, control);
            stats.images += s.images;
            if ((stats.cancelled = s.cancelled))
                break;
        }
        return stats;
    };
    out.pointCount = [cifs, drawn](const StartSet &start, int depth) {
        double n = 0;
        for (int q : drawn)
            n += pathCount(*cifs, q, depth);
        return n * double(std::max<Eigen::Index>(1, start.vertices.rows()));
    };
    return out;
}

// ---- declared properties ----------------------------------------------------------------------

const PropertyTable &CifsItem::declaration()
{
    static const PropertyTable table = [] {
        using S = CifsSpec;
        Declaration<CifsItem> d(&AttractorItem::attractorProperties());
        auto spec = d.part(&CifsItem::m_spec, &CifsItem::checkSpec, &CifsItem::specChanged,
                           QT_TR_NOOP("Change automaton of %1"));
        spec.checkedOnRead([](const CifsItem &, const S &s) { return s.check(); });
        spec.structured(
                "states", QStringLiteral("states"),
                [](const CifsItem &, const S &s) {
                    QJsonArray list;
                    for (const CifsStateSpec &q : s.states)
                        list.append(QJsonObject{
                            {"name", q.name},
                            {"control_points", ProjectIO::pointsToJson(q.points)}});
                    return QJsonValue(list);
                },
                [](const CifsItem &, S &s, const QJsonValue &v, const QString &where) {
                    const QJsonArray list = v.toArray();
                    if (!v.isArray() || list.isEmpty())
                        throw LoadError{where, CifsSpec::tr("expected a non-empty array of states "
                                                     "{\"name\": text, \"control_points\": "
                                                     "[...]}")};
                    if (list.size() > S::maxStates)
                        throw LoadError{where, CifsSpec::tr("%1 states: at most %2")
                                                   .arg(list.size()).arg(S::maxStates)};
                    std::vector<CifsStateSpec> states;
                    for (qsizetype k = 0; k < list.size(); ++k) {
                        const QString at = where + QStringLiteral("[%1]").arg(k + 1);
                        if (!list[k].isObject())
                            throw LoadError{at, CifsSpec::tr("expected an object with \"name\" and "
                                                      "\"control_points\"")};
                        const FieldReader state(list[k].toObject(), at + QLatin1Char('.'));
                        CifsStateSpec q;
                        q.name = state.string("name");
                        q.points = state.points("control_points");
                        if (const QJsonObject rest = state.unread(); !rest.isEmpty())
                            state.fail(rest.begin().key(), CifsSpec::tr("unknown field of a state"));
                        states.push_back(std::move(q));
                    }
                    // The arcs stay as they are: where they no longer fit the new states, the
                    // check names the first misfit (give "arcs" in the same update). The drawn
                    // state stays when it still exists, else it is the first.
                    s.states = std::move(states);
                    if (s.drawn != S::allStates && s.stateIndex(s.drawn) < 0)
                        s.drawn = s.states.front().name;
                })
            .label(QT_TR_NOOP("States"))
            .group(QT_TR_NOOP("Automaton"))
            .tip(QT_TR_NOOP("Each state's name and control points (its barycentric space)"))
            .required();
        spec.structured(
                "arcs", QStringLiteral("arcs"),
                [](const CifsItem &, const S &s) {
                    QJsonArray list;
                    for (const CifsArcSpec &a : s.arcs) {
                        QJsonObject o{{"name", a.name},
                                      {"from", s.states.at(size_t(a.from)).name},
                                      {"to", s.states.at(size_t(a.to)).name},
                                      {"matrix", matrixToJson(a.S)}};
                        if (a.weight != 1.0)
                            o["weight"] = a.weight;
                        list.append(o);
                    }
                    return QJsonValue(list);
                },
                [](const CifsItem &, S &s, const QJsonValue &v, const QString &where) {
                    const QJsonArray list = v.toArray();
                    if (!v.isArray())
                        throw LoadError{where, CifsSpec::tr("expected an array of arcs {\"name\", "
                                                     "\"from\", \"to\", \"matrix\"}")};
                    if (list.size() > kMaxMaps)
                        throw LoadError{where, CifsSpec::tr("%1 arcs: at most %2 (addresses are "
                                                     "bytes)")
                                                   .arg(list.size()).arg(kMaxMaps)};
                    std::vector<CifsArcSpec> arcs;
                    for (qsizetype k = 0; k < list.size(); ++k) {
                        const QString at = where + QStringLiteral("[%1]").arg(k + 1);
                        if (!list[k].isObject())
                            throw LoadError{at, CifsSpec::tr("expected an object with \"from\", "
                                                      "\"to\" and the arc's map")};
                        const QJsonObject o = list[k].toObject();
                        const FieldReader arc(o, at + QLatin1Char('.'));
                        CifsArcSpec a;
                        a.name = arc.string("name", QStringLiteral("t%1").arg(k + 1));
                        a.from = stateFromJson(s, arc.value("from"), arc.path("from"));
                        a.to = stateFromJson(s, arc.value("to"), arc.path("to"));
                        a.weight = arc.number("weight", 1.0);
                        for (const char *form : {"matrix", "columns", "affine", "scheme", "piece"})
                            arc.value(form);
                        a.S = cifsArcMatrixFromJson(o, s.states[size_t(a.from)],
                                                    s.states[size_t(a.to)], at + QLatin1Char('.'));
                        if (const QJsonObject rest = arc.unread(); !rest.isEmpty())
                            arc.fail(rest.begin().key(), CifsSpec::tr("unknown field of an arc"));
                        arcs.push_back(std::move(a));
                    }
                    s.arcs = std::move(arcs);
                })
            .label(QT_TR_NOOP("Arcs"))
            .group(QT_TR_NOOP("Automaton"))
            .tip(QT_TR_NOOP("Each arc's states and matrix S (a row per point of the state it "
                            "leads to, rows summing to 1) and weight"))
            .required();
        spec.choiceBy(
                "state", {}, {},
                [](const S &s) {
                    return s.drawn == S::allStates ? int(s.states.size())
                                                   : s.stateIndex(s.drawn);
                },
                [](S &s, int i) {
                    s.drawn = i >= 0 && i < int(s.states.size()) ? s.states[size_t(i)].name
                                                                 : S::allStates;
                })
            .label(QT_TR_NOOP("Drawn state"))
            .group(QT_TR_NOOP("Automaton"))
            .tip(QT_TR_NOOP("The state whose attractor is drawn, or the union of all"))
            .spellingsFrom([](const CifsItem &, const S &s) {
                return s.stateNames() << S::allStates;
            })
            .choicesFrom([](const CifsItem &, const S &s) {
                return s.stateNames() << CifsSpec::tr("All states");
            });
        return d.table();
    }();
    return table;
}

} // namespace awb
