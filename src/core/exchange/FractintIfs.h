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
// is the one word before its '{' (and its "(3D)" mark). Plain C++, no Qt.

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
};

// Reads every entry; a malformed one (a row of the wrong length, a word that is no number, a
// missing '}', a probability that is negative or not finite, no rows) is left out and named in
// `problems` with its line and column, the others are kept.
FractintFile readFractintIfs(std::istream &in);

// One entry as text (its name as one word, the 2D or 3D rows of its maps with 8 significant
// digits, the probabilities as given; empty probabilities: equal ones). InputError for maps
// that are neither 2D nor 3D.
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
