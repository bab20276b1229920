#pragma once
// The IFS files of other tools in and out of projects (issue 34; layer 2, model): Fractint's
// .ifs entries become custom fractals with control points (FractalItem: the attractor's
// bounding box as their cage, random iteration with the entry's probabilities, in the plane
// and in space), and any item whose maps are
// affine maps of the plane or of space goes out as an entry. The CLI (import, export --format
// ifs) and the window (File > Import, File > Export Item As) call these.

#include "core/exchange/FractintIfs.h"

#include <QString>
#include <QStringList>

#include <memory>
#include <optional>
#include <vector>

namespace awb {

class AttractorItem;
class Item;

struct ImportedItems {
    std::vector<std::unique_ptr<Item>> items;
    // Entries left out, each with the file, line and column ("fern.ifs, line 4, column 9:
    // entry fern: ...").
    QStringList problems;
};

// Every entry of a .ifs file; InputError when the file cannot be read at all.
ImportedItems importFractint(const QString &fileName);
// The same from text (`fileName` names it in the messages).
ImportedItems importFractintText(const QByteArray &text, const QString &fileName);

// The entry of an item: a custom fractal's own maps, or the maps of an IFS that acts in the
// plane or in space as drawn; nullopt with *why for anything else (a lifted subdivision IFS,
// an automaton). The probabilities are the item's random-iteration ones (equal when it has
// none).
std::optional<FractintEntry> fractintEntryOf(const AttractorItem &item, QString *why);

} // namespace awb
