#pragma once
// The .ifs files of Fractint, xfractint and Riddle's IFS Construction Kit (issue 34): named
// entries of affine maps with probabilities,
//
//     ; a comment to the end of the line
//     fern {
//       0     0    0     .16 0 0    .01
//       .85  .04 -.04  .85  0 1.6  .85
//       ...
//     }
//     tetra (3D) { a b c d e f g h i j k l p ... }
//
// A 2D row a b c d e f p means x' = a x + b y + e, y' = c x + d y + f, chosen with probability
// p; a 3D row a b c d e f g h i j k l p means x' = a x + b y + c z + j, y' = d x + e y + f z + k,
// z' = g x + h y + i z + l. Numbers are separated by any whitespace or commas; an entry's name
// is the words before its '{' on its line (or on the line before, when the '{' starts its
// line), less the "(3D)" mark. Fractint 10 and 15 kept one IFS per file as bare rows without
// NAME { }: such a file is one entry. Plain C++, no Qt.

#include "core/ifs/Attractor.h"
#include "core/ifs/Ifs.h"

#include <iosfwd>
#include <string>
#include <vector>

namespace awb {

struct FractintEntry {
    std::string name;
    int dimension = 2;                // 2 or 3
    std::vector<AffineMap> maps;      // row convention x |-> x A + b (Ifs.h)
    std::vector<double> probabilities;  // as written (not normalised)
    int line = 0;                     // where the entry starts (1-based)
};

// A refused entry (or a stray piece of text between entries), with where it is.
struct FractintProblem {
    int line = 0, column = 0;  // 1-based
    std::string entry;         // the entry's name, "" outside entries
    std::string message;       // without the place
    // "FILE, line L, column C: entry NAME: MESSAGE"
    std::string describe(const std::string &fileName) const;
};

struct FractintFile {
    std::vector<FractintEntry> entries;  // every well-formed entry, in file order
    std::vector<FractintProblem> problems;
    // Entries kept with a remark: probabilities that do not sum to 1 (used as weights).
    std::vector<FractintProblem> warnings;
};

// The most entries one file gives (Fractint's largest libraries hold a few hundred); the rest
// are counted in a problem.
inline constexpr std::size_t kMaxFractintEntries = 4096;

// Reads every entry in one pass over the words (time linear in the file, memory in its
// largest entry); a malformed one (a row of the wrong length, a row begun in the middle of a
// line that runs on to the next, a word that is no number, a missing '}', a negative
// probability, no rows, more than kMaxMaps maps) is left out and named in `problems` with its
// line and column, the others are kept. At most 100 problems and 100 warnings are listed, and
// a last line counts the rest. A file of bare rows is one entry named `bareName`.
FractintFile readFractintIfs(std::istream &in, const std::string &bareName = "ifs");

// One entry as text: its name (braces, semicolons and commas replaced by '_', line breaks by
// spaces), the 2D or 3D rows of its maps and the probabilities as the shortest numbers that
// read back exactly (empty probabilities: equal ones). InputError for maps that are neither 2D
// nor 3D.
std::string fractintEntryText(const FractintEntry &entry);

// The coefficients of map `f` in Fractint's order (a b c d e f or a ... l, without p).
std::vector<double> fractintCoefficients(const AffineMap &f);

// Control points for an imported IFS: the corners of the attractor's bounding box (4 in the
// plane, counter-clockwise from the lower left; 8 in space, the low corner and its three
// neighbours last), found by a short orbit of random iteration with the entry's probabilities
// and rounded outward (a flat attractor's box is widened to a tenth of its largest side).
// InputError when the orbit leaves every bound (maps that do not contract).
Mat fractintControlCage(const FractintEntry &entry);

} // namespace awb
