#pragma once
// What `attractor-cli analyse --json`, Python's Item.analyse(), the Analysis dock and the
// printed sheet say of an automaton item (layer 2, model): for a controlled IFS (CifsItem) its
// constrained joint spectral radius, exact where an invariant polytope of the lifted arcs
// closes, the spectra of its simple cycles and the Lyapunov exponent of random iteration
// (core/analysis/CifsAnalysis.h).

#include <QJsonObject>
#include <QStringList>

namespace awb {

class BcifsJunctionItem;
class CifsItem;
struct CifsAnalysis;
struct CifsSpec;

// {"states", "arcs", "constrained_jsr": {"lower", "upper", "exact", "word", "method",
// "lifted_dimension"}, "cycles": [{"path", "arcs", "eigenvalues", "spectral_radius",
// "per_arc"}], "cycles_complete", "lyapunov_exponent", "contractive",
// "contractive_on_average"}; {"error": why} for an automaton that cannot be analysed.
QJsonObject automatonAnalysisJson(const CifsItem &item);

// A junction (003 §4.1, §5): the matrices in 003's column convention with their spectra --
// "T_i" (cubic-quadratic; "T_il", "T_ir" refined) with eigenvalues and eigenvectors (T v =
// lambda v; the eigenvalue 1's scaled to sum 1, the others to unit length), and "T_l", "T_r"
// with their vertex blocks V^l (top left) and V^r (bottom right) and the blocks' spectra.
QJsonObject junctionAnalysisJson(const BcifsJunctionItem &item);

// The same in a few lines for people: the radius and how it is known, the Lyapunov exponent,
// the cycles (the first `cycles` of them; 0: none).
QStringList automatonSummary(const CifsItem &item, int cycles = 0);
// The same of an analysis computed elsewhere (the window's worker thread).
QStringList automatonSummary(const CifsSpec &spec, const CifsAnalysis &analysis, int cycles);

} // namespace awb
