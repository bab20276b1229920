#include "model/AutomatonAnalysisJson.h"

#include "core/analysis/CifsAnalysis.h"
#include "core/ifs/Cifs.h"
#include "model/CifsItem.h"
#include "model/NumberFormat.h"

#include <QCoreApplication>
#include <QJsonArray>

#include <algorithm>
#include <cmath>

namespace awb {

namespace {

QString tr(const char *text) { return QCoreApplication::translate("awb::AutomatonAnalysis", text); }

QJsonArray arcNames(const CifsSpec &s, const std::vector<int> &arcs)
{
    QJsonArray out;
    for (int t : arcs)
        if (t >= 0 && t < int(s.arcs.size()))
            out.append(s.arcs[size_t(t)].name);
    return out;
}

// w = r^k with r shortest: a product's spectral radius per letter is its root's.
std::vector<int> primitiveRoot(const std::vector<int> &w)
{
    const size_t n = w.size();
    for (size_t p = 1; p < n; ++p)
        if (n % p == 0 && std::equal(w.begin() + std::ptrdiff_t(p), w.end(), w.begin()))
            return {w.begin(), w.begin() + std::ptrdiff_t(p)};
    return w;
}

QString pathText(const CifsSpec &s, int from, const std::vector<int> &arcs)
{
    QString out = s.states.at(size_t(from)).name;
    for (int t : arcs)
        out += QStringLiteral(" -%1-> %2").arg(s.arcs.at(size_t(t)).name,
                                               s.states.at(size_t(s.arcs.at(size_t(t)).to)).name);
    return out;
}

QString number(double x) { return QString::number(x, 'g', 10); }

} // namespace

QJsonObject automatonAnalysisJson(const CifsItem &item)
{
    QString error;
    const auto a = item.automatonAnalysis(&error);
    if (!a)
        return {{"error", error}};
    const CifsSpec &s = item.spec();
    QJsonObject o;
    o["states"] = int(s.states.size());
    o["arcs"] = int(s.arcs.size());
    QJsonObject jsr;
    jsr["lower"] = a->lower();
    jsr["upper"] = std::isfinite(a->upper()) ? QJsonValue(a->upper()) : QJsonValue();
    jsr["exact"] = a->exact();
    jsr["word"] = arcNames(s, primitiveRoot(a->exact() ? a->polytope.smp : a->bounds.product));
    jsr["method"] = a->exact()
                        ? QStringLiteral("invariant polytope of the lifted arcs")
                        : QStringLiteral("cycles and Gripenberg's branch and bound on the lifted "
                                         "arcs");
    if (!a->exact() && !a->polytope.message.empty())
        jsr["polytope"] = QString::fromStdString(a->polytope.message);
    jsr["lifted_dimension"] = liftedArcs(s.toCore()).dimension;
    o["constrained_jsr"] = jsr;
    QJsonArray cycles;
    for (const CifsCycle &c : a->cycles) {
        QJsonArray values;
        for (const Complex &z : c.eigenvalues)
            values.append(QJsonArray{z.real(), z.imag()});
        cycles.append(QJsonObject{{"path", pathText(s, c.state, c.arcs)},
                                  {"arcs", arcNames(s, c.arcs)},
                                  {"eigenvalues", values},
                                  {"spectral_radius", c.spectralRadius},
                                  {"per_arc", c.perArc}});
    }
    o["cycles"] = cycles;
    o["cycles_complete"] = a->cyclesComplete;
    o["lyapunov_exponent"] = a->lyapunov ? QJsonValue(*a->lyapunov) : QJsonValue();
    o["lyapunov_from"] = s.states.at(size_t(a->lyapunovState)).name;
    o["contractive"] = a->contractive();
    o["contractive_on_average"] = a->lyapunov ? QJsonValue(*a->lyapunov < 0) : QJsonValue();
    return o;
}

QStringList automatonSummary(const CifsItem &item, int cycles)
{
    QString error;
    const auto a = item.automatonAnalysis(&error);
    if (!a)
        return {error};
    return automatonSummary(item.spec(), *a, cycles);
}

QStringList automatonSummary(const CifsSpec &s, const CifsAnalysis &analysis, int cycles)
{
    const CifsAnalysis *a = &analysis;
    QStringList lines;
    if (a->exact())
        lines << tr("constrained JSR ρ = %1 exactly (invariant polytope; extremal cycle %2)")
                     .arg(number(a->lower()),
                          a->polytope.smp.empty()
                              ? QString()
                              : pathText(s, s.arcs[size_t(a->polytope.smp.front())].from,
                                         a->polytope.smp));
    else
        lines << tr("constrained JSR ρ in [%1, %2]")
                     .arg(number(a->lower()),
                          std::isfinite(a->upper()) ? number(a->upper()) : QStringLiteral("∞"));
    lines.back() += a->contractive() ? tr(": every long path contracts")
                    : a->lower() >= 1 ? tr(": some path does not contract")
                                      : tr(": not decided");
    if (a->lyapunov)
        lines << tr("Lyapunov exponent of random iteration %1 (%2)")
                     .arg(QString::number(*a->lyapunov, 'g', 4),
                          *a->lyapunov < 0 ? tr("contracts on average")
                                           : tr("does not contract on average"));
    for (int k = 0; k < std::min(cycles, int(a->cycles.size())); ++k) {
        const CifsCycle &c = a->cycles[size_t(k)];
        QStringList values;
        for (const Complex &z : c.eigenvalues)
            values << formatComplex(z, 4);
        lines << tr("cycle %1: ρ = %2 (%3 per arc); eigenvalues %4")
                     .arg(pathText(s, c.state, c.arcs), QString::number(c.spectralRadius, 'g', 6),
                          QString::number(c.perArc, 'g', 6), values.join(QStringLiteral(", ")));
    }
    if (cycles > 0 && int(a->cycles.size()) > cycles)
        lines << tr("… and %1 more cycles").arg(a->cycles.size() - size_t(cycles));
    return lines;
}

} // namespace awb
