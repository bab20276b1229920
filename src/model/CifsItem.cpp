#include "model/CifsItem.h"

#include "core/schemes/ControlPointFractal.h"
#include "core/ifs/Cifs.h"
#include "model/Commands.h"
#include "model/ProjectIO.h"

namespace awb {

namespace {

PointList toPoints(const Mat &P)
{
    PointList out;
    for (Eigen::Index r = 0; r < P.rows(); ++r)
        out.push_back({P(r, 0), P(r, 1)});
    return out;
}

} // namespace

// ---- CifsSpec ---------------------------------------------------------------------------------

const QStringList &CifsSpec::presetNames()
{
    static const QStringList names{"fern-sierpinski"};
    return names;
}

const QStringList &CifsSpec::stateNames()
{
    static const QStringList names = [] {
        QStringList out;
        for (const CifsState &s : fernSierpinskiCifs().states)
            out << QString::fromStdString(s.name);
        return out;
    }();
    return names;
}

MaybeProblem CifsSpec::check() const
{
    if (redirected < 0 || redirected > 3)
        return Problem{"redirected", tr("the redirected fern arc must be 0 … 3 (T0 … T3), got %1")
                                         .arg(redirected)};
    if (!stateNames().contains(state))
        return Problem{"state", tr("no state \"%1\"; the states are \"%2\"")
                                    .arg(state, stateNames().join("\", \""))};
    return std::nullopt;
}

// ---- CifsItem ---------------------------------------------------------------------------------

CifsItem::CifsItem() : AttractorItem(tr("Fern of gaskets")), m_frame(toPoints(fernFrame())) {}

bool CifsItem::setSpec(const CifsSpec &spec, int gesture)
{
    if (checkSpec(spec))
        return false;
    applyProperty(&CifsItem::m_spec, spec, &CifsItem::specChanged,
                  tr("Change automaton of %1").arg(name()), gesture);
    return true;
}

DerivedIfs CifsItem::computeIfs() const
{
    const Mat frame = toMatrix(m_frame);
    if (frame.rows() != 3)
        throw InputError(tr("the frame needs exactly 3 points, got %1").arg(frame.rows())
                             .toStdString());
    const auto cifs = std::make_shared<const Cifs>(fernSierpinskiCifs(m_spec.redirected, frame));
    const CifsCheck check = checkCifs(*cifs);
    if (!check.contractive)
        throw InputError(check.message);
    const int state = cifs->stateIndex(m_spec.state.toStdString());
    DerivedIfs out;
    for (const CifsTransition &t : cifs->transitions)
        out.S.real.push_back(t.S);
    out.A.unavailable = tr("a controlled IFS has no single lifted IFS");
    out.ifs.space = "barycentric (" + cifs->states[size_t(state)].name + ")";
    out.ifs.views.push_back(cifs->view(state));
    out.note = tr("Arc T%1 of the fern leads into the Sierpiński state (003 §2.2, Fig. 4).")
                   .arg(m_spec.redirected);
    const Mat P = cifs->states[size_t(state)].controlPoints;
    out.toIfsSpace = [P](const Mat &X) { return leastNormWeightsOfRows(P, X); };
    // The start set comes in the drawn state's space; every other state gets the same plane
    // points in its own coordinates.
    out.iterate = [cifs, state](const StartSet &start, int depth,
                                const std::vector<AttractorSink *> &sinks,
                                const IterationControl &control) {
        const Mat plane = start.vertices * cifs->states[size_t(state)].controlPoints;
        std::vector<StartSet> starts;
        for (const CifsState &s : cifs->states)
            starts.push_back({start.kind, leastNormWeightsOfRows(s.controlPoints, plane)});
        return iterate(*cifs, state, starts, depth, *sinks.front(), control);
    };
    return out;
}

void CifsItem::write(QJsonObject &json) const
{
    AttractorItem::write(json);
    json["preset"] = CifsSpec::presetNames().front();
    json["redirected"] = m_spec.redirected;
    json["state"] = m_spec.state;
    json["control_points"] = ProjectIO::pointsToJson(m_frame);
}

void CifsItem::read(const FieldReader &fields)
{
    AttractorItem::read(fields);
    fields.choice("preset", CifsSpec::presetNames());
    CifsSpec spec;
    spec.redirected = int(fields.integer("redirected", spec.redirected, 0, 3));
    spec.state = CifsSpec::stateNames().at(
        fields.choice("state", CifsSpec::stateNames(), 0));
    fields.require(spec.check());
    m_spec = spec;
    m_frame = fields.points("control_points", toPoints(fernFrame()));
}

QList<ParameterInfo> CifsItem::parameters() const
{
    using P = ParameterInfo;
    const QString group = tr("Automaton");
    return {P::make("redirected", tr("Redirected arc"), P::Type::Integer)
                .range(0, 3)
                .slider(0, 3)
                .in(group)
                .tip(tr("The fern map (0 stem, 1 main frond, 2 left, 3 right leaflet) whose arc "
                        "leads into the Sierpiński state (003 Fig. 4)")),
            P::make("state", tr("Drawn state"), P::Type::Choice)
                .options(CifsSpec::stateNames())
                .in(group)
                .tip(tr("The state whose attractor is drawn"))};
}

QVariant CifsItem::parameter(const QString &key) const
{
    if (key == "redirected")
        return m_spec.redirected;
    if (key == "state")
        return int(CifsSpec::stateNames().indexOf(m_spec.state));
    return {};
}

bool CifsItem::setParameter(const QString &key, const QVariant &value, int gesture,
                            QString *error)
{
    CifsSpec next = m_spec;
    bool ok = true;
    if (key == "redirected") {
        next.redirected = value.toInt(&ok);
    } else if (key == "state") {
        const int index = value.toInt(&ok);
        ok = ok && index >= 0 && index < CifsSpec::stateNames().size();
        if (ok)
            next.state = CifsSpec::stateNames().at(index);
    } else {
        return Item::setParameter(key, value, gesture, error);
    }
    return commitParameter(key, value, ok, checkSpec(next),
                           [&] { return setSpec(next, gesture); }, error);
}

} // namespace awb
