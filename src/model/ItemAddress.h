#pragma once
// Addresses of an item's attractor (layer 2, model): what a symbol of an address means for an
// item (its maps, numbered 0..N-1 as the IFS numbers them), the curve parameter t of a
// subdivision curve's address, and the control points S_w P of a sub-copy f_w(A). The core's
// ifs/Address.h does the arithmetic; the GUI's address panel and `attractor-cli points
// --address` use this. Nothing here is saved: a selected address is view state.

#include "core/ifs/Address.h"

#include <QString>

#include <optional>

namespace awb {

class AttractorItem;
struct DerivedIfs;

// The parameter interval of each map's piece, when the item is a subdivision curve with a
// real parameter: [0, t], [t, 1] for a Bézier curve split at a real t (the Bernstein parameter
// u), N equal intervals for every other scheme. Empty when the item has no real curve
// parameter (a complex Bézier split, fractals, surfaces, automata).
std::vector<ParameterInterval> parameterPieces(const AttractorItem &item);
// What t means for the item, in a few words for a tooltip (empty without a parameter).
QString parameterMeaning(const AttractorItem &item);

// Parses an address for the item drawn by `d` (maps 0..N-1 of d.ifs). Throws InputError with
// the reason; items drawn by an automaton (CIFS, junctions) have no single-IFS addresses.
Address parseItemAddress(const QString &text, const DerivedIfs &d);

// The control points S_w P (m x d) of f_w(A) when the item is a real subdivision scheme (or a
// fractal with control points); std::nullopt otherwise.
std::optional<Mat> addressControlPoints(const DerivedIfs &d, const Address &w);

// "[t0, t1]" to a parameter interval; nullopt when the text is not of that form
// (then it may be an address). Throws InputError for numbers outside 0 <= t0 < t1 <= 1.
std::optional<ParameterInterval> parseParameterInterval(const QString &text);

} // namespace awb
