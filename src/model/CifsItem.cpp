#include "model/CifsItem.h"

#include "core/schemes/ControlPointFractal.h"
#include "core/ifs/Cifs.h"
#include "model/Commands.h"
#include "model/PointSetProperty.h"
#include "model/ProjectIO.h"
#include "model/PropertyDeclaration.h"

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
    return setDeclared(*this, spec, gesture);
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

// ---- declared properties ----------------------------------------------------------------------

const PropertyTable &CifsItem::declaration()
{
    static const PropertyTable table = [] {
        Declaration<CifsItem> d(&AttractorItem::attractorProperties());
        auto spec = d.part(&CifsItem::m_spec, &CifsItem::checkSpec, &CifsItem::specChanged,
                           QT_TR_NOOP("Change automaton of %1"));
        spec.checkedOnRead([](const CifsItem &, const CifsSpec &s) { return s.check(); });
        spec.choiceBy(
                "preset", CifsSpec::presetNames(),
                {QT_TR_NOOP("Fern of gaskets (003 Fig. 4)")}, [](const CifsSpec &) { return 0; },
                [](CifsSpec &, int) {})
            .label(QT_TR_NOOP("Automaton"))
            .group(QT_TR_NOOP("Automaton"))
            .shownOnly()
            .required();
        spec.integer("redirected", &CifsSpec::redirected)
            .label(QT_TR_NOOP("Redirected arc"))
            .group(QT_TR_NOOP("Automaton"))
            .range(0, 3)
            .slider(0, 3)
            .tip(QT_TR_NOOP("The fern map (0 stem, 1 main frond, 2 left, 3 right leaflet) whose "
                            "arc leads into the Sierpiński state (003 Fig. 4)"));
        spec.choiceBy(
                "state", CifsSpec::stateNames(), {},
                [](const CifsSpec &s) { return int(CifsSpec::stateNames().indexOf(s.state)); },
                [](CifsSpec &s, int i) { s.state = CifsSpec::stateNames().at(i); })
            .label(QT_TR_NOOP("Drawn state"))
            .group(QT_TR_NOOP("Automaton"))
            .tip(QT_TR_NOOP("The state whose attractor is drawn"))
            .choicesFrom([](const CifsItem &, const CifsSpec &) {
                return CifsSpec::stateNames();
            });
        declarePointSet(d, 0, QStringLiteral("control_points"), QT_TR_NOOP("Frame"))
            .fallback = [](const AttractorItem &) { return toPoints(fernFrame()); };
        return d.table();
    }();
    return table;
}

} // namespace awb
