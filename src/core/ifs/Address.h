#pragma once
// Addresses of an IFS attractor (layer 1, core): a word w = w_1 w_2 .. w_k of map numbers names
// the sub-copy f_w(A) = f_{w_1}(f_{w_2}(..f_{w_k}(A))) of the attractor A. w_1 is the map
// applied last, i.e. which of the N top-level pieces the sub-copy lies in; it is address[0] of
// AttractorSink::consume. Symbols are 0-based (symbol i is the map of S_{i+1}).
//
// For a subdivision IFS f_i(X) = X P^-1 S_i P the point B(u) P of the limit curve (B: the basis
// functions, 1 x m) goes to B(u) S_i P, so f_w(A) is the limit curve of the control points
//     S_w P = S_{w_k} .. S_{w_2} S_{w_1} P
// (the piece w_1 of the curve, then its piece w_2, ...). The curve parameter of the sub-copy is
// phi_{w_1}(phi_{w_2}(..phi_{w_k}([0, 1]))), with phi_i the affine map of [0, 1] onto the
// parameter interval of piece i; for N equal pieces that is the address read in base N.

#include "core/ifs/Attractor.h"

#include <cstdint>
#include <string>
#include <vector>

namespace awb {

using Address = std::vector<int>;

// Longest address accepted (the deepest iteration is 64 too).
inline constexpr int kMaxAddressLength = 64;

// "0,1,1" (commas, spaces or both between symbols); with at most 10 maps also "011". Throws
// InputError for an empty text, a symbol that is not a whole number, a map number outside
// 0..maps-1 or more than kMaxAddressLength symbols; the message names the culprit.
Address parseAddress(const std::string &text, int maps);
// "0,1,1"; "" for the empty address.
std::string formatAddress(const Address &w);
// Throws InputError (as parseAddress) when a symbol is outside 0..maps-1 or w is too long.
void checkAddress(const Address &w, int maps);

// f_w as one affine map (row convention x |-> x A + b): f_{w_1} o .. o f_{w_k}; the identity
// for the empty word. Throws InputError for a bad address.
AffineMap composeAddress(const Ifs &ifs, const Address &w);
// S_{w_k} .. S_{w_1} (m x m): S_w P are the control points of f_w(A) (see above). The identity
// for the empty word. Throws InputError for a bad address or matrices of different sizes.
Mat addressMatrix(const std::vector<Mat> &S, const Address &w);

// ---- the curve parameter ------------------------------------------------------------------

struct ParameterInterval {
    double t0 = 0.0, t1 = 1.0;
    bool operator==(const ParameterInterval &o) const { return t0 == o.t0 && t1 == o.t1; }
};
// [i/N, (i+1)/N] for i = 0..N-1: the pieces of a uniform scheme (B-splines, four-point, ...).
std::vector<ParameterInterval> uniformPieces(int maps);
// The parameter interval of f_w(A): phi_{w_1} o .. o phi_{w_k} applied to [0, 1], computed
// from the inside out. For N = 2 equal pieces every step is exact in binary floating point, so
// t0 is exactly the dyadic rational 0.w_1 w_2 .. w_k (base 2) for k <= 52.
ParameterInterval addressInterval(const std::vector<ParameterInterval> &pieces,
                                  const Address &w);
// The address of length `length` whose interval holds t (half-open [t0, t1), the last piece
// also takes t = 1). Throws InputError for t outside [0, 1], a bad length or bad pieces.
Address addressOfParameter(const std::vector<ParameterInterval> &pieces, double t, int length);
// The largest addresses (at most maxLength symbols) whose intervals lie inside [t0, t1], in
// parameter order: the standard N-adic cover of the interval (exact when t0, t1 are multiples
// of N^-maxLength for equal pieces). Throws InputError when not 0 <= t0 < t1 <= 1.
std::vector<Address> coverInterval(const std::vector<ParameterInterval> &pieces, double t0,
                                   double t1, int maxLength);

// ---- finding the address of a point --------------------------------------------------------

// Points f_w(x*) of the attractor for every word w of one length (x* the fixed point of map 0,
// the start of a curve), each with its address: what a hover looks up.
struct AddressedPoints {
    int length = 0;                      // symbols per address
    int maps = 0;
    Mat space;                           // n x D: the points in the IFS space
    std::vector<Mat> shown;              // per view: n x k, the points as drawn
    std::vector<std::uint8_t> symbols;   // n * length, row-major, address[0] first
    Eigen::Index size() const { return space.rows(); }
    Address address(Eigen::Index i) const;
};
// Samples the attractor at the deepest length with at most maxPoints points (N^length), from
// the fixed point of map 0 (found by iterating it from `seed`, a point of the IFS space: 1 x D).
// Throws InputError for an invalid IFS or a seed of the wrong size.
AddressedPoints sampleAddresses(const Ifs &ifs, const RowVec &seed, int maxPoints = 1 << 15);

struct NearestAddress {
    Eigen::Index index = -1;   // -1: no sample
    int view = 0;
    double distance = 0.0;     // in shown coordinates
};
// The sample nearest to the shown point (x, y) over all views (the first two coordinates).
NearestAddress nearestAddress(const AddressedPoints &samples, double x, double y);

} // namespace awb
