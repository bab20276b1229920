#pragma once
// The matrices of one map of an item (layer 2, model), as the Matrices dock shows them, for
// attractor-cli analyse's "maps" (ItemAnalysisJson) and attractor_workbench's Item.maps(): S_i;
// M_i = P^-1 S_i P with its blocks A_i, b_i for a lifted subdivision IFS (000 §2), the complex
// M_i of a complex Bézier split (004 §3.7), or the IFS map itself (A, b) where there is no S_i.

#include "core/Types.h"

#include <optional>
#include <vector>

namespace awb {

struct DerivedIfs;

struct MapMatrices {
    std::optional<Mat> S, M, A;
    std::optional<RowVec> b;
    std::optional<CMat> complexS, complexM, complexA, complexB;
    std::vector<Complex> eigenvaluesA;  // of A (an IFS map: of its effective linear part)
    int ifsMap = -1;                    // the IFS map that is this map (-1: the IFS skips it)
};

// The maps an item lists: its S_i, or the IFS's maps when it has none.
int listedMapCount(const DerivedIfs &d);
// Map i (0 <= i < listedMapCount(d)).
MapMatrices mapMatrices(const DerivedIfs &d, int i);

} // namespace awb
