#pragma once
// What `attractor-cli analyse --json` says of one item (layer 2, model), shared by the CLI and
// the Python module (attractor_workbench: Item.analyse()): per map S_i (values and exact
// fractions), M_i = P^-1 S_i P with its blocks A_i, b_i, the eigenvalues of S_i and A_i,
// spectral radius, contractivity and fixed point; per item the subdominant eigenvalues, the
// certified Hausdorff distance to the exact curve, the box-counting dimension, a mesh's
// extraordinary vertices and a subdivision curve's certified Hölder regularity.

#include <QJsonObject>

namespace awb {

class AttractorItem;
struct Regularity;

// `regularity`, when given, receives the curve's regularity (its certificate for
// `analyse --certificate`); left as is for other items.
QJsonObject analyseItemJson(const AttractorItem *item, Regularity *regularity = nullptr);

} // namespace awb
