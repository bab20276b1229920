#include "model/AutomatonAnalysisJson.h"

#include "core/analysis/CifsAnalysis.h"
#include "core/analysis/JointSpectralRadius.h"
#include "core/analysis/Spectrum.h"
#include "core/ifs/Bcifs.h"
#include "core/ifs/Cifs.h"
#include "model/BcifsJunctionItem.h"
#include "model/CifsItem.h"
#include "model/NumberFormat.h"
#include "model/PropertyPart.h"

#include <QCoreApplication>
#include <QJsonArray>

#include <algorithm>
#include <cmath>

namespace awb {

namespace {

struct AutomatonTr {
    Q_DECLARE_TR_FUNCTIONS(awb::AutomatonAnalysis)
};

QJsonArray arcNames(const CifsSpec &s, const std::vector<int> &arcs)
{
    QJsonArray out;
    for (int t : arcs)
        if (t >= 0 && t < int(s.arcs.size()))
            out.append(s.arcs[size_t(t)].name);
    return out;
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

QJsonValue rowsJson(const Mat &M) { return property::matricesToJson({M}).toArray().first(); }

QJsonValue complexJson(const Complex &z)
{
    return std::abs(z.imag()) <= 1e-12 * std::max(1.0, std::abs(z.real()))
               ? QJsonValue(z.real())
               : QJsonValue(QJsonArray{z.real(), z.imag()});
}

// Eigenvalues and (right, column convention) eigenvectors of a square matrix: the eigenvalue
// 1's vector scaled to sum 1 (a barycentric fixed point), the others to unit length with their
// largest component positive.
QJsonObject spectrumJson(const Mat &T)
{
    const Spectrum s = spectrum(T);
    QJsonArray values, vectors;
    for (size_t k = 0; k < s.values.size(); ++k) {
        values.append(complexJson(s.values[k]));
        CVec v = s.vectors[k];
        const Complex sum = v.sum();
        if (std::abs(s.values[k] - Complex(1.0)) < 1e-9 && std::abs(sum) > 1e-9) {
            v /= sum;
        } else {
            Eigen::Index big = 0;
            v.cwiseAbs().maxCoeff(&big);
            v *= std::abs(v(big)) / v(big) / v.norm();
        }
        QJsonArray vector;
        for (Eigen::Index i = 0; i < v.size(); ++i)
            vector.append(complexJson(v(i)));
        vectors.append(vector);
    }
    return {{"eigenvalues", values}, {"eigenvectors", vectors}};
}

QJsonObject squareJson(const Mat &T)
{
    QJsonObject o = spectrumJson(T);
    o["matrix"] = rowsJson(T);
    return o;
}

// T^l = [[V^l; 0] | X] and T^r = [Y | [0; V^r]] with one free column each (003 §4.1, §5).
QJsonObject blockJson(const Mat &T, bool left)
{
    const Eigen::Index n = T.cols() - 1;
    const Mat V = left ? Mat(T.topLeftCorner(n, n)) : Mat(T.bottomRightCorner(n, n));
    QJsonObject block = spectrumJson(V);
    block["matrix"] = rowsJson(V);
    return {{"matrix", rowsJson(T)}, {"block", block}};
}

} // namespace

QJsonObject junctionAnalysisJson(const BcifsJunctionItem &item)
{
    QJsonObject o;
    o["convention"] = QStringLiteral("columns (003): T v = lambda v, T = S^T");
    try {
        if (item.spec().variant == JunctionSpec::Variant::CubicQuadratic) {
            const JunctionMatrices m = cubicQuadraticMatrices(item.spec().free);
            o["T_i"] = squareJson(m.Ti);
            o["T_l"] = blockJson(m.Tl, true);
            o["T_r"] = blockJson(m.Tr, false);
        } else {
            const RefinedMatrices m = refinedMatrices(item.spec().refined);
            o["T_il"] = squareJson(m.Til);
            o["T_ir"] = squareJson(m.Tir);
            o["T_l"] = blockJson(m.Tl, true);
            o["T_r"] = blockJson(m.Tr, false);
        }
    } catch (const std::exception &e) {
        o["error"] = QString::fromStdString(e.what());
    }
    return o;
}

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
    const std::vector<int> root = primitiveRoot(a->exact() ? a->polytope.smp : a->bounds.product);
    jsr["word"] = root.size() <= 24 ? QJsonValue(arcNames(s, root)) : QJsonValue();
    jsr["word_length"] = int(root.size());
    jsr["method"] = a->exact()
                        ? QStringLiteral("invariant polytope of the lifted arcs")
                        : QStringLiteral("cycles and Gripenberg's branch and bound on the lifted "
                                         "arcs");
    if (!a->exact() && !a->polytope.message.empty())
        jsr["polytope"] = QString::fromStdString(a->polytope.message);
    jsr["lifted_dimension"] = liftedArcs(s.toCore()).dimension;
    o["constrained_jsr"] = jsr;
    // The report is sized by what it says, not by the automaton: at most 200 cycles, the
    // first 20 with their whole product (a 64-point state's is 4096 numbers and 64
    // eigenvectors), then the count.
    constexpr std::size_t listed = 200, withProduct = 20;
    QJsonArray cycles;
    for (const CifsCycle &c : a->cycles) {
        if (std::size_t(cycles.size()) == listed)
            break;
        QJsonArray values;
        for (const Complex &z : c.eigenvalues)
            values.append(QJsonArray{z.real(), z.imag()});
        QJsonObject cycle{{"path", pathText(s, c.state, c.arcs)},
                          {"arcs", arcNames(s, c.arcs)},
                          {"eigenvalues", values},
                          {"spectral_radius", c.spectralRadius},
                          {"per_arc", c.perArc}};
        if (std::size_t(cycles.size()) >= withProduct) {
            cycles.append(cycle);
            continue;
        }
        // The cycle's product in 003's column form T = (S_{t_m} .. S_{t_1})^T, whole: its
        // eigenvalue 1 and fixed point too.
        Mat M = Mat::Identity(Eigen::Index(s.states[size_t(c.state)].points.size()),
                              Eigen::Index(s.states[size_t(c.state)].points.size()));
        for (int t : c.arcs)
            M = (s.arcs[size_t(t)].S * M).eval();
        cycle["product"] = squareJson(M.transpose());
        cycles.append(cycle);
    }
    o["cycles"] = cycles;
    o["cycle_count"] = int(a->cycles.size());
    o["cycles_complete"] = a->cyclesComplete && a->cycles.size() <= listed;
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
    const QString verdict = a->contractive() ? AutomatonTr::tr("every long path contracts")
                            : a->lower() >= 1 ? AutomatonTr::tr("some path does not contract")
                                              : AutomatonTr::tr("not decided");
    if (a->exact())
        lines << AutomatonTr::tr("constrained JSR ρ = %1 exactly (invariant polytope, extremal cycle %2): "
                       "%3")
                     .arg(number(a->lower()),
                          a->polytope.smp.empty()
                              ? QString()
                              : pathText(s, s.arcs[size_t(a->polytope.smp.front())].from,
                                         a->polytope.smp),
                          verdict);
    else
        lines << AutomatonTr::tr("constrained JSR ρ in [%1, %2]: %3")
                     .arg(number(a->lower()),
                          std::isfinite(a->upper()) ? number(a->upper()) : QStringLiteral("∞"),
                          verdict);
    if (a->lyapunov)
        lines << AutomatonTr::tr("Lyapunov exponent of random iteration %1 (%2)")
                     .arg(QString::number(*a->lyapunov, 'g', 4),
                          *a->lyapunov < 0 ? AutomatonTr::tr("contracts on average")
                                           : AutomatonTr::tr("does not contract on average"));
    for (int k = 0; k < std::min(cycles, int(a->cycles.size())); ++k) {
        const CifsCycle &c = a->cycles[size_t(k)];
        QStringList values;
        for (const Complex &z : c.eigenvalues)
            values << formatComplex(z, 4);
        lines << AutomatonTr::tr("cycle %1: ρ = %2 (%3 per arc); eigenvalues %4")
                     .arg(pathText(s, c.state, c.arcs), QString::number(c.spectralRadius, 'g', 6),
                          QString::number(c.perArc, 'g', 6), values.join(QStringLiteral(", ")));
    }
    if (cycles > 0 && int(a->cycles.size()) > cycles)
        lines << AutomatonTr::tr("… and %1 more cycles").arg(a->cycles.size() - size_t(cycles));
    return lines;
}

} // namespace awb
