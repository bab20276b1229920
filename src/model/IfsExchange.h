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
    // What was imported with a loss, with where ("a.flame, line 7, column 4: flame 'x', xform
    // 2: variation 'spherical' (0.5) dropped"): never silent.
    QStringList warnings;
};

// A custom fractal of an imported entry: its maps, the attractor's bounding box as control
// points, random iteration with the entry's probabilities (`samples` of them; 0: the
// application's default), coloured by map with `colours` ("#rrggbb"; empty: the views' own).
// Throws LoadError or InputError (maps that leave every bound).
std::unique_ptr<Item> importedFractal(const FractintEntry &entry, const QStringList &colours = {},
                                      int samples = 0);

// The bytes of another tool's file: InputError when it cannot be read or is larger than a
// project may be (ProjectIO::maxFileBytes).
QByteArray readExchangeFile(const QString &fileName);

// Every entry of a .ifs file; InputError when the file cannot be read at all.
ImportedItems importFractint(const QString &fileName);
// The same from text (`fileName` names it in the messages).
ImportedItems importFractintText(const QByteArray &text, const QString &fileName);

// The entry of an item: a custom fractal's own maps, the maps of an IFS that acts in the plane
// or in space as drawn, or those a lifted IFS gives the drawn coordinates when they are
// decoupled from the free ones (000 §2); nullopt with *why for anything else (an automaton, a
// lifted IFS whose maps mix the coordinates), the message naming `format` (the file format at
// hand). The probabilities are the item's random-iteration ones (equal when it has none).
std::optional<FractintEntry> fractintEntryOf(const AttractorItem &item, QString *why,
                                             const QString &format = QStringLiteral(
                                                 "a Fractint .ifs entry"));

} // namespace awb
