#include "core/exchange/FractintIfs.h"

#include "core/Messages.h"
#include "core/ifs/Attractor.h"

#include <Eigen/SVD>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <iomanip>
#include <limits>
#include <istream>
#include <locale>
#include <optional>
#include <sstream>

namespace awb {

namespace {

// A word of the file with where it starts.
struct Token {
    std::string text;
    int line = 0, column = 0;
};

// The file as words: '{' and '}' are words of their own, ';' starts a comment, whitespace and
// commas separate.
std::vector<Token> tokenize(std::istream &in)
{
    std::vector<Token> out;
    std::string line;
    int number = 0;
    while (std::getline(in, line)) {
        ++number;
        Token current;
        const auto flush = [&] {
            if (!current.text.empty())
                out.push_back(current);
            current = Token{};
        };
        for (std::size_t k = 0; k < line.size(); ++k) {
            const char c = line[k];
            if (c == ';')
                break;
            if (std::isspace(static_cast<unsigned char>(c)) || c == ',') {
                flush();
                continue;
            }
            if (c == '{' || c == '}') {
                flush();
                out.push_back({std::string(1, c), number, int(k) + 1});
                continue;
            }
            if (current.text.empty()) {
                current.line = number;
                current.column = int(k) + 1;
            }
            current.text += c;
        }
        flush();
    }
    return out;
}

bool toNumber(const std::string &text, double *value)
{
    std::istringstream s(text);
    s.imbue(std::locale::classic());
    s >> *value;
    return s && s.peek() == std::char_traits<char>::eof() && std::isfinite(*value);
}


std::string lowered(std::string s)
{
    for (char &c : s)
        c = char(std::tolower(static_cast<unsigned char>(c)));
    return s;
}

} // namespace

std::string FractintProblem::describe(const std::string &fileName) const
{
    std::string place = formatMessage(coreTranslate("awb::exchange", "%1, line %2, column %3"),
                                      fileName, line, column);
    if (!entry.empty())
        place += formatMessage(coreTranslate("awb::exchange", ": entry %1"), entry);
    return place + ": " + message;
}

FractintFile readFractintIfs(std::istream &in)
{
    const std::vector<Token> tokens = tokenize(in);
    FractintFile file;
    std::size_t k = 0;
    while (k < tokens.size()) {
        const Token &first = tokens[k];
        if (first.text == "}") {
            file.problems.push_back({first.line, first.column, "",
                                     coreTranslate("awb::exchange", "a '}' without its '{'")});
            ++k;
            continue;
        }
        // The name is one word, maybe marked "(3D)" (apart or attached).
        std::string name = first.text;
        int dimension = 2;
        std::size_t open = k + 1;
        if (name.size() > 4 && lowered(name.substr(name.size() - 4)) == "(3d)") {
            name.resize(name.size() - 4);
            dimension = 3;
        } else if (open < tokens.size() && lowered(tokens[open].text) == "(3d)") {
            dimension = 3;
            ++open;
        }
        if (first.text == "{") {
            name.clear();
            open = k;
        }
        if (open >= tokens.size() || tokens[open].text != "{") {
            file.problems.push_back(
                {first.line, first.column, "",
                 formatMessage(coreTranslate("awb::exchange",
                                             "'%1' is not followed by '{': an entry is NAME { "
                                             "rows }"),
                               first.text)});
            k = k + 1;
            continue;
        }
        if (name.empty())
            name = formatMessage(coreTranslate("awb::exchange", "entry at line %1"), first.line);
        std::size_t close = open + 1;
        while (close < tokens.size() && tokens[close].text != "}" && tokens[close].text != "{")
            ++close;
        if (close >= tokens.size() || tokens[close].text != "}") {
            const Token &at = close < tokens.size() ? tokens[close] : tokens[open];
            file.problems.push_back(
                {at.line, at.column, name,
                 close < tokens.size()
                     ? coreTranslate("awb::exchange", "a '{' inside an entry: its '}' is missing")
                     : coreTranslate("awb::exchange", "the file ends before the entry's '}'")});
            k = close;
            continue;
        }
        // The rows: 7 (2D) or 13 (3D) numbers each.
        const std::size_t width = dimension == 2 ? 7 : 13;
        FractintEntry entry;
        entry.name = name;
        entry.dimension = dimension;
        entry.line = first.line;
        std::vector<double> values;
        std::optional<FractintProblem> problem;
        for (std::size_t t = open + 1; t < close && !problem; ++t) {
            double v = 0;
            if (!toNumber(tokens[t].text, &v))
                problem = FractintProblem{
                    tokens[t].line, tokens[t].column, name,
                    formatMessage(coreTranslate("awb::exchange", "'%1' is not a finite number"),
                                  tokens[t].text)};
            values.push_back(v);
        }
        const std::size_t count = close - open - 1;
        if (!problem && (count == 0 || count % width != 0)) {
            const Token &at = count == 0 ? tokens[open] : tokens[open + 1 + count / width * width];
            problem = FractintProblem{
                at.line, at.column, name,
                count == 0
                    ? coreTranslate("awb::exchange", "the entry has no maps")
                    : formatMessage(coreTranslate("awb::exchange",
                                                  "%1 numbers: a %2D entry has rows of %3 "
                                                  "(the map's coefficients, then its "
                                                  "probability), %4 left over"),
                                    count, dimension, width, count % width)};
        }
        for (std::size_t r = 0; !problem && r < count / width; ++r) {
            const double *c = values.data() + r * width;
            AffineMap f{Mat(dimension, dimension), RowVec(dimension)};
            if (dimension == 2) {
                // x' = a x + b y + e, y' = c x + d y + f: the row convention's A is the
                // transpose of [[a, b], [c, d]].
                f.A << c[0], c[2], c[1], c[3];
                f.b << c[4], c[5];
            } else {
                f.A << c[0], c[3], c[6], c[1], c[4], c[7], c[2], c[5], c[8];
                f.b << c[9], c[10], c[11];
            }
            const double p = c[width - 1];
            if (p < 0) {
                const Token &at = tokens[open + 1 + r * width + width - 1];
                problem = FractintProblem{
                    at.line, at.column, name,
                    formatMessage(coreTranslate("awb::exchange",
                                                "map %1 has the negative probability %2"),
                                  r + 1, streamedNumber(p))};
                break;
            }
            entry.maps.push_back(f);
            entry.probabilities.push_back(p);
        }
        if (problem)
            file.problems.push_back(*problem);
        else
            file.entries.push_back(std::move(entry));
        k = close + 1;
    }
    return file;
}

std::vector<double> fractintCoefficients(const AffineMap &f)
{
    const Mat &A = f.A;
    if (f.dim() == 2)
        return {A(0, 0), A(1, 0), A(0, 1), A(1, 1), f.b(0), f.b(1)};
    if (f.dim() == 3)
        return {A(0, 0), A(1, 0), A(2, 0), A(0, 1), A(1, 1), A(2, 1),
                A(0, 2), A(1, 2), A(2, 2), f.b(0), f.b(1), f.b(2)};
    throw InputError(formatMessage(
        coreTranslate("awb::exchange", "a Fractint entry holds maps of the plane or of space, "
                                       "not of dimension %1"),
        f.dim()));
}

std::string fractintEntryText(const FractintEntry &entry)
{
    std::ostringstream out;
    out.imbue(std::locale::classic());
    std::string name = entry.name;
    // A name is one word before '{': no spaces, braces, commas or comment marks in it.
    for (char &c : name)
        if (c == '{' || c == '}' || c == ';' || c == ','
            || std::isspace(static_cast<unsigned char>(c)))
            c = '_';
    if (name.empty())
        name = "ifs";
    out << name << (entry.dimension == 3 ? " (3D)" : "") << " {\n";
    for (std::size_t i = 0; i < entry.maps.size(); ++i) {
        const std::vector<double> c = fractintCoefficients(entry.maps[i]);
        if (int(c.size()) != (entry.dimension == 3 ? 12 : 6))
            throw InputError(coreTranslate("awb::exchange",
                                           "the entry's maps are not all of its dimension"));
        out << " ";
        for (double v : c)
            out << " " << std::setprecision(8) << v;
        const double p = i < entry.probabilities.size() ? entry.probabilities[i]
                                                        : 1.0 / double(entry.maps.size());
        out << "  " << std::setprecision(8) << p << "\n";
    }
    out << "}\n";
    return out.str();
}

Mat fractintControlCage(const FractintEntry &entry)
{
    const int d = entry.dimension;
    if (entry.maps.empty())
        throw InputError(coreTranslate("awb::exchange", "the entry has no maps"));
    // The cumulative probabilities (equal ones when they sum to nothing).
    std::vector<double> cumulative;
    double total = 0;
    for (std::size_t i = 0; i < entry.maps.size(); ++i) {
        total += i < entry.probabilities.size() ? entry.probabilities[i] : 0.0;
        cumulative.push_back(total);
    }
    if (!(total > 0)) {
        for (std::size_t i = 0; i < cumulative.size(); ++i)
            cumulative[i] = double(i + 1);
        total = double(cumulative.size());
    }
    // Maps that contract one by one: the orbit's bounding box. Otherwise (a flame's IFS that
    // contracts on average only) the orbit has heavy tails: the box of 99% of its points.
    bool contractive = true;
    for (const AffineMap &f : entry.maps)
        contractive = contractive
                      && Eigen::JacobiSVD<Mat>(f.A).singularValues()(0) < 1.0 - 1e-12;
    RowVec x = RowVec::Zero(d);
    RowVec lo = RowVec::Constant(d, std::numeric_limits<double>::infinity()), hi = -lo;
    std::vector<std::vector<double>> seen(static_cast<std::size_t>(d));
    std::uint64_t state = 0x9e3779b97f4a7c15ull;  // a fixed seed: the same cage every time
    for (int step = 0; step < 6000; ++step) {
        state = state * 6364136223846793005ull + 1442695040888963407ull;
        const double u = double(state >> 11) * 0x1.0p-53 * total;
        std::size_t i = 0;
        while (i + 1 < cumulative.size() && u >= cumulative[i])
            ++i;
        x = x * entry.maps[i].A + entry.maps[i].b;
        if (!x.allFinite() || x.cwiseAbs().maxCoeff() > 1e12)
            throw InputError(formatMessage(
                coreTranslate("awb::exchange", "entry %1: random iteration leaves every bound "
                                               "(its maps do not contract)"),
                entry.name));
        if (step >= 50) {
            lo = lo.cwiseMin(x);
            hi = hi.cwiseMax(x);
            for (int k = 0; k < d; ++k)
                seen[std::size_t(k)].push_back(x(k));
        }
    }
    if (!contractive) {
        lo = QuantileBoundsSink::columnQuantile(seen, 0.005);
        hi = QuantileBoundsSink::columnQuantile(std::move(seen), 0.995);
    }
    const double largest = std::max((hi - lo).maxCoeff(), 1e-9);
    for (int k = 0; k < d; ++k)
        if (hi(k) - lo(k) < 1e-6 * largest) {
            lo(k) -= 0.05 * largest;
            hi(k) += 0.05 * largest;
        }
    // Outward to round numbers (a tenth of the largest side's decade): the orbit's box is a
    // little inside the attractor's, and round corners give the S_i round weights.
    const double step = std::pow(10.0, std::floor(std::log10(largest)) - 1);
    for (int k = 0; k < d; ++k) {
        lo(k) = step * std::floor(lo(k) / step + 1e-9);
        hi(k) = step * std::ceil(hi(k) / step - 1e-9);
    }
    if (d == 2) {
        Mat P(4, 2);
        P << lo(0), lo(1), hi(0), lo(1), hi(0), hi(1), lo(0), hi(1);
        return P;
    }
    // Corner c has hi in coordinate k when bit k of c is set. The last four span space (the
    // lifting of 000 §2 takes its free rows there): the low corner and its three neighbours.
    const int order[8] = {3, 5, 6, 7, 0, 1, 2, 4};
    Mat P(8, 3);
    for (int r = 0; r < 8; ++r)
        for (int k = 0; k < 3; ++k)
            P(r, k) = ((order[r] >> k) & 1) ? hi(k) : lo(k);
    return P;
}

} // namespace awb
