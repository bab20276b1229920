#include "core/ifs/Address.h"

#include "core/Messages.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>

namespace awb {

namespace {

[[noreturn]] void fail(const std::string &message) { throw InputError(message); }

std::string mapRange(int maps)
{
    return maps == 1 ? coreTranslate("awb::ifs", "the IFS has 1 map (0)")
                     : formatMessage(coreTranslate("awb::ifs", "the IFS has %1 maps (0..%2)"),
                                     maps, maps - 1);
}

void checkPieces(const std::vector<ParameterInterval> &pieces)
{
    if (pieces.empty())
        fail(coreTranslate("awb::ifs", "no parameter intervals"));
    for (const ParameterInterval &p : pieces)
        if (!(std::isfinite(p.t0) && std::isfinite(p.t1) && p.t0 < p.t1))
            fail(coreTranslate("awb::ifs", "a parameter interval is empty or not finite"));
}

} // namespace

void checkAddress(const Address &w, int maps)
{
    if (int(w.size()) > kMaxAddressLength)
        fail(formatMessage(
            coreTranslate("awb::ifs", "the address has %1 symbols, more than %2"), w.size(),
            kMaxAddressLength));
    for (std::size_t k = 0; k < w.size(); ++k)
        if (w[k] < 0 || w[k] >= maps)
            fail(formatMessage(
                coreTranslate("awb::ifs", "symbol %1 of the address is map %2, but %3"), k + 1,
                w[k], mapRange(maps)));
}

Address parseAddress(const std::string &text, int maps)
{
    if (maps < 1)
        fail(coreTranslate("awb::ifs", "the IFS has no maps"));
    std::vector<std::string> tokens;
    std::string token;
    const bool separated = text.find_first_of(", \t") != std::string::npos;
    bool comma = false;  // a comma since the last symbol
    for (char c : text + ' ') {
        if (c != ',' && c != ' ' && c != '\t') {
            token += c;
            continue;
        }
        if (!token.empty()) {
            tokens.push_back(token);
            token.clear();
            comma = false;
        }
        if (c == ',') {
            if (tokens.empty() || comma)
                fail(formatMessage(coreTranslate("awb::ifs", "the address '%1' has an empty "
                                                             "symbol (a comma too many)"),
                                   text));
            comma = true;
        }
    }
    if (comma)
        fail(formatMessage(coreTranslate("awb::ifs", "the address '%1' ends with a comma"),
                           text));
    if (tokens.empty())
        fail(coreTranslate("awb::ifs", "the address is empty: give map numbers such as 0,1,1"));
    // "011" with at most ten maps: one digit per symbol.
    if (!separated && maps <= 10 && tokens.size() == 1 && tokens[0].size() > 1) {
        const std::string digits = tokens[0];
        tokens.clear();
        for (char c : digits)
            tokens.emplace_back(1, c);
    }
    if (int(tokens.size()) > kMaxAddressLength)
        fail(formatMessage(
            coreTranslate("awb::ifs", "the address has %1 symbols, more than %2"), tokens.size(),
            kMaxAddressLength));
    Address w;
    w.reserve(tokens.size());
    for (std::size_t k = 0; k < tokens.size(); ++k) {
        const std::string &s = tokens[k];
        const bool digits = std::all_of(s.begin(), s.end(), [](char c) {
            return std::isdigit(static_cast<unsigned char>(c)) != 0;
        });
        if (!digits)
            fail(formatMessage(coreTranslate("awb::ifs", "symbol %1 of the address, '%2', is "
                                                         "not a map number (0-based whole "
                                                         "number)"),
                               k + 1, s));
        if (s.size() > 9 || std::stoi(s) >= maps)
            fail(formatMessage(
                coreTranslate("awb::ifs", "symbol %1 of the address is map %2, but %3"), k + 1,
                s, mapRange(maps)));
        w.push_back(std::stoi(s));
    }
    return w;
}

std::string formatAddress(const Address &w)
{
    std::string s;
    for (std::size_t k = 0; k < w.size(); ++k) {
        if (k > 0)
            s += ',';
        s += std::to_string(w[k]);
    }
    return s;
}

AffineMap composeAddress(const Ifs &ifs, const Address &w)
{
    checkAddress(w, ifs.size());
    const int D = ifs.dim();
    AffineMap f{Mat::Identity(D, D), RowVec::Zero(D)};
    // f_{w_1} o (f_{w_2} o ..): x |-> (x A' + b') A_{w_1} + b_{w_1}, innermost map first.
    for (auto it = w.rbegin(); it != w.rend(); ++it) {
        const AffineMap &g = ifs.maps[std::size_t(*it)];
        f.b = f.b * g.A + g.b;
        f.A = f.A * g.A;
    }
    return f;
}

Mat addressMatrix(const std::vector<Mat> &S, const Address &w)
{
    checkAddress(w, int(S.size()));
    if (S.empty())
        fail(coreTranslate("awb::ifs", "no subdivision matrices"));
    const Eigen::Index m = S.front().rows();
    for (const Mat &s : S)
        if (s.rows() != m || s.cols() != m)
            fail(coreTranslate("awb::ifs", "the subdivision matrices differ in size"));
    Mat product = Mat::Identity(m, m);
    // S_{w_k} .. S_{w_1}: the coarse piece w_1 acts on P first.
    for (int symbol : w)
        product = S[std::size_t(symbol)] * product;
    return product;
}

std::vector<ParameterInterval> uniformPieces(int maps)
{
    std::vector<ParameterInterval> pieces;
    for (int i = 0; i < maps; ++i)
        pieces.push_back({double(i) / maps, double(i + 1) / maps});
    return pieces;
}

ParameterInterval addressInterval(const std::vector<ParameterInterval> &pieces,
                                  const Address &w)
{
    checkPieces(pieces);
    checkAddress(w, int(pieces.size()));
    ParameterInterval r{0.0, 1.0};
    for (auto it = w.rbegin(); it != w.rend(); ++it) {
        const ParameterInterval &p = pieces[std::size_t(*it)];
        const double len = p.t1 - p.t0;
        r = {p.t0 + len * r.t0, p.t0 + len * r.t1};
    }
    return r;
}

Address addressOfParameter(const std::vector<ParameterInterval> &pieces, double t, int length)
{
    checkPieces(pieces);
    if (!(t >= 0.0 && t <= 1.0))
        fail(formatMessage(coreTranslate("awb::ifs", "the parameter %1 is outside [0, 1]"),
                           std::to_string(t)));
    if (length < 0 || length > kMaxAddressLength)
        fail(formatMessage(coreTranslate("awb::ifs", "an address has 0..%1 symbols"),
                           kMaxAddressLength));
    Address w;
    for (int k = 0; k < length; ++k) {
        int i = int(pieces.size()) - 1;
        for (int j = 0; j + 1 < int(pieces.size()); ++j)
            if (t < pieces[std::size_t(j)].t1) {
                i = j;
                break;
            }
        const ParameterInterval &p = pieces[std::size_t(i)];
        w.push_back(i);
        t = std::clamp((t - p.t0) / (p.t1 - p.t0), 0.0, 1.0);
    }
    return w;
}

std::vector<Address> coverInterval(const std::vector<ParameterInterval> &pieces, double t0,
                                   double t1, int maxLength)
{
    checkPieces(pieces);
    if (!(t0 >= 0.0 && t0 < t1 && t1 <= 1.0))
        fail(coreTranslate("awb::ifs", "the parameter interval must satisfy 0 <= t0 < t1 <= 1"));
    if (maxLength < 0 || maxLength > kMaxAddressLength)
        fail(formatMessage(coreTranslate("awb::ifs", "an address has 0..%1 symbols"),
                           kMaxAddressLength));
    std::vector<Address> cover;
    // Depth first in parameter order: a piece inside [t0, t1] is taken whole, one that only
    // overlaps it is split until maxLength.
    struct Frame {
        Address w;
        ParameterInterval range;
    };
    std::vector<Frame> stack{{{}, {0.0, 1.0}}};
    while (!stack.empty()) {
        Frame f = std::move(stack.back());
        stack.pop_back();
        if (f.range.t1 <= t0 || f.range.t0 >= t1)
            continue;
        if (f.range.t0 >= t0 && f.range.t1 <= t1) {
            cover.push_back(std::move(f.w));
            continue;
        }
        if (int(f.w.size()) == maxLength)
            continue;
        const double len = f.range.t1 - f.range.t0;
        for (int i = int(pieces.size()) - 1; i >= 0; --i) {
            Frame child{f.w, {f.range.t0 + len * pieces[std::size_t(i)].t0,
                              f.range.t0 + len * pieces[std::size_t(i)].t1}};
            child.w.push_back(i);
            stack.push_back(std::move(child));
        }
    }
    // Pieces of a scheme that does not run through [0, 1] in map order (a reversed piece)
    // come out of order: sort by parameter.
    std::stable_sort(cover.begin(), cover.end(), [&](const Address &a, const Address &b) {
        return addressInterval(pieces, a).t0 < addressInterval(pieces, b).t0;
    });
    return cover;
}

Address AddressedPoints::address(Eigen::Index i) const
{
    const auto *first = symbols.data() + std::size_t(i) * std::size_t(length);
    return Address(first, first + length);
}

AddressedPoints sampleAddresses(const Ifs &ifs, const RowVec &seed, int maxPoints)
{
    ifs.validate();
    if (ifs.size() < 1)
        fail(coreTranslate("awb::ifs", "the IFS has no maps"));
    if (seed.size() != ifs.dim())
        fail(formatMessage(
            coreTranslate("awb::ifs", "the seed point has %1 coordinates, the IFS %2"),
            seed.size(), ifs.dim()));
    // x* = f_0(x*): iterate (the barycentric form has no b to solve with, and a map that
    // contracts slowly still gets within rounding in a few hundred steps).
    RowVec x = seed;
    for (int k = 0; k < 400; ++k)
        x = x * ifs.maps[0].A + ifs.maps[0].b;
    if (!x.allFinite())
        fail(coreTranslate("awb::ifs", "map 0 does not converge to a fixed point"));
    const int N = ifs.size();
    int length = 0;
    double count = 1;
    while (N > 1 && length < kMaxAddressLength && count * N <= maxPoints) {
        count *= N;
        ++length;
    }
    AddressedPoints out;
    out.length = length;
    out.maps = N;
    const auto n = Eigen::Index(count);
    out.space.resize(n, ifs.dim());
    out.symbols.reserve(std::size_t(n) * std::size_t(length));
    Eigen::Index row = 0;
    CallbackSink sink([&](const Mat &v, StartSet::Kind, const std::uint8_t *a, int len) {
        out.space.row(row++) = v.row(0);
        out.symbols.insert(out.symbols.end(), a, a + len);
    });
    iterate(ifs, StartSet::points(x), length, sink);
    for (const Projection &view : ifs.views)
        out.shown.push_back(project(view, out.space));
    return out;
}

NearestAddress nearestAddress(const AddressedPoints &samples, double x, double y)
{
    NearestAddress best;
    double bestD2 = std::numeric_limits<double>::infinity();
    for (std::size_t v = 0; v < samples.shown.size(); ++v) {
        const Mat &p = samples.shown[v];
        if (p.cols() < 2)
            continue;
        for (Eigen::Index i = 0; i < p.rows(); ++i) {
            const double dx = p(i, 0) - x, dy = p(i, 1) - y;
            const double d2 = dx * dx + dy * dy;
            if (d2 < bestD2) {
                bestD2 = d2;
                best = {i, int(v), 0.0};
            }
        }
    }
    if (best.index >= 0)
        best.distance = std::sqrt(bestD2);
    return best;
}

} // namespace awb
