#pragma once
// What `attractor-cli analyse --json` says of one item (layer 2, model), shared by the CLI and
// the Python module (attractor_workbench: Item.analyse()): per map S_i (values and exact
// fractions), M_i = P^-1 S_i P with its blocks A_i, b_i, the eigenvalues of S_i and A_i,
// spectral radius, contractivity and fixed point; per item the subdominant eigenvalues, the
// certified Hausdorff distance to the exact curve, the box-counting dimension, a mesh's
// extraordinary vertices and a subdivision curve's certified Hölder regularity.

#include <QJsonArray>
#include <QJsonObject>
#include <QJsonValue>
#include <QString>

#include <functional>
#include <map>

namespace awb {

class AttractorItem;
struct Regularity;

// A member too large to hold as one JSON tree -- a mesh lists a hundred thousand extraordinary
// vertices -- given as its size and its members one at a time, each made when it is asked for.
struct JsonList {
    qsizetype size = 0;
    std::function<QJsonValue(qsizetype)> at;
    QJsonArray whole() const;
};

// An analysis: its JSON, and its large arrays apart (`lists`, by key; not in `json`).
struct ItemAnalysis {
    QJsonObject json;
    std::map<QString, JsonList> lists;
    QJsonObject whole() const;  // the lists filled in
};

// `regularity`, when given, receives the curve's regularity (its certificate for
// `analyse --certificate`); left as is for other items.
ItemAnalysis analyseItem(const AttractorItem *item, Regularity *regularity = nullptr);

// Why an item drawn by its own chaos game (a flame) has no box-counting dimension here: its
// maps are not the affine parts whose IFS the analysis holds (the window's Analysis tab says
// the same).
QString flameBoxDimensionNote();
inline QJsonObject analyseItemJson(const AttractorItem *item, Regularity *regularity = nullptr)
{
    return analyseItem(item, regularity).whole();
}

} // namespace awb
