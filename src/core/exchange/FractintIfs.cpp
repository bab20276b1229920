#include "core/exchange/FractintIfs.h"

#include "core/Messages.h"
#include "core/ifs/Attractor.h"

#include <Eigen/SVD>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <array>
#include <charconv>
#include <cstdint>
#include <limits>
#include <istream>
#include <optional>

namespace awb {

namespace {

// A word of the file with where it starts.
struct Token {
    std::string text;
    int line = 0, column = 0;
};

// The file as words, one at a time (a file of many megabytes is never held as a list of
// words): '{' and '}' are words of their own, ';' starts a comment, whitespace and commas
// separate.
class Tokenizer {
public:
    explicit Tokenizer(std::istream &in) : m_in(in) {}

    bool next(Token *token)
    {
        if (!m_pending.empty()) {
            *token = std::move(m_pending.back());
            m_pending.pop_back();
            return true;
        }
        for (;;) {
            while (m_at < m_line.size()) {
                const char c = m_line[m_at];
                if (c == ';') {
                    m_at = m_line.size();
                    break;
                }
                if (std::isspace(static_cast<unsigned char>(c)) || c == ',') {
                    ++m_at;
                    continue;
                }
                token->line = m_number;
                token->column = int(m_at) + 1;
                if (c == '{' || c == '}') {
                    token->text.assign(1, c);
                    ++m_at;
                    return true;
                }
                const std::size_t begin = m_at;
                while (m_at < m_line.size()) {
                    const char d = m_line[m_at];
                    if (d == ';' || d == ',' || d == '{' || d == '}'
                        || std::isspace(static_cast<unsigned char>(d)))
                        break;
                    ++m_at;
                }
                token->text.assign(m_line, begin, m_at - begin);
                return true;
            }
            if (!std::getline(m_in, m_line))
                return false;
            ++m_number;
            m_at = 0;
        }
    }

    // Words read ahead, given again by next() in their order.
    void giveBack(std::vector<Token> tokens)
    {
        for (auto t = tokens.rbegin(); t != tokens.rend(); ++t)
            m_pending.push_back(std::move(*t));
    }

private:
    std::istream &m_in;
    std::vector<Token> m_pending;  // last first
    std::string m_line;
    std::size_t m_at = 0;
    int m_number = 0;
};

// A finite number in the C locale ("1", "-.04", "1.6e-3", "+2"): the whole word.
bool toNumber(const std::string &text, double *value)
{
    const char *first = text.data(), *last = text.data() + text.size();
    if (first != last && *first == '+')
        ++first;
    if (first != last && (*first == '+' || *first == '-') && text[0] == '+')
        return false;  // "+-1"
    const auto [end, error] = std::from_chars(first, last, *value);
    return error == std::errc() && end == last && std::isfinite(*value);
}

std::string lowered(std::string s)
{
    for (char &c : s)
        c = char(std::tolower(static_cast<unsigned char>(c)));
    return s;
}

// At most this many problems and warnings are kept (a file of a million stray '}' is one
// problem per brace: the rest are counted in a last line).
constexpr std::size_t kMaxReports = 100;

// Where the reader records, within kMaxReports.
struct Reports {
    std::vector<FractintProblem> *list;
    std::size_t dropped = 0;
    int lastLine = 0;

    void add(FractintProblem p)
    {
        lastLine = p.line;
        if (list->size() < kMaxReports)
            list->push_back(std::move(p));
        else
            ++dropped;
    }
    void close(const std::string &pattern)  // "%1 more problems"
    {
        if (dropped > 0)
            list->push_back({lastLine, 1, "", formatMessage(pattern, dropped)});
    }
};

// The rows of one entry, read number by number: at most kMaxMaps maps are kept (the engine's
// limit), the rest only counted; a row must start at the start of a line unless it ends on the
// line it starts on (rows of 6 or 8 numbers laid out one per line are not read as rows of 7
// across lines).
class RowReader {
public:
    RowReader(std::string name, int dimension) : m_width(dimension == 2 ? 7 : 13)
    {
        m_entry.name = std::move(name);
        m_entry.dimension = dimension;
    }
    FractintEntry &entry() { return m_entry; }
    std::optional<FractintProblem> &problem() { return m_problem; }
    std::size_t numbers() const { return m_count; }

    void add(const Token &t)
    {
        if (m_problem)
            return;
        double v = 0;
        if (!toNumber(t.text, &v)) {
            m_problem = FractintProblem{
                t.line, t.column, m_entry.name,
                formatMessage(coreTranslate("awb::exchange", "'%1' is not a finite number"),
                              t.text)};
            return;
        }
        const std::size_t pos = m_count % m_width;
        const bool newLine = t.line != m_lineOfLast;
        if (pos == 0) {
            m_rowStart = t;
            m_rowStartsLine = newLine;
        } else if (newLine && !m_rowStartsLine) {
            // This row began in the middle of a line and goes on on the next one.
            m_problem = FractintProblem{
                m_rowStart.line, m_rowStart.column, m_entry.name,
                formatMessage(coreTranslate("awb::exchange",
                                            "the row starting here runs on to the next line: "
                                            "a %1D entry has rows of %2 numbers (the map's "
                                            "coefficients, then its probability), one row "
                                            "per line"),
                              m_entry.dimension, m_width)};
            return;
        }
        m_lineOfLast = t.line;
        ++m_count;
        if (m_entry.maps.size() >= std::size_t(kMaxMaps)) {
            if (pos + 1 == m_width)
                ++m_extraMaps;
            return;
        }
        m_row[pos] = v;
        if (pos + 1 == m_width)
            completeRow();
    }

    // At the entry's '}' (or the file's end for bare rows): the last checks.
    void finish(const Token &at)
    {
        if (m_problem)
            return;
        if (m_count == 0) {
            m_problem = FractintProblem{at.line, at.column, m_entry.name,
                                        coreTranslate("awb::exchange", "the entry has no maps")};
        } else if (m_count % m_width != 0) {
            m_problem = FractintProblem{
                m_rowStart.line, m_rowStart.column, m_entry.name,
                formatMessage(coreTranslate("awb::exchange",
                                            "%1 numbers: a %2D entry has rows of %3 (the map's "
                                            "coefficients, then its probability), %4 left over"),
                              m_count, m_entry.dimension, m_width, m_count % m_width)};
        } else if (m_extraMaps > 0) {
            m_problem = FractintProblem{
                m_entry.line, 1, m_entry.name,
                formatMessage(coreTranslate("awb::exchange",
                                            "%1 maps: at most %2 maps are supported"),
                              std::size_t(kMaxMaps) + m_extraMaps, kMaxMaps)};
        }
    }

    // A warning for probabilities that are not a distribution (they are used as weights).
    std::optional<FractintProblem> probabilityWarning() const
    {
        double sum = 0;
        for (double p : m_entry.probabilities)
            sum += p;
        if (std::abs(sum - 1) <= 0.01)
            return std::nullopt;
        return FractintProblem{
            m_entry.line, 1, m_entry.name,
            sum > 0 ? formatMessage(coreTranslate("awb::exchange",
                                                  "the probabilities sum to %1, not 1: they are "
                                                  "used as relative weights"),
                                    streamedNumber(sum))
                    : coreTranslate("awb::exchange",
                                    "the probabilities are all 0: the maps are chosen with "
                                    "equal probabilities")};
    }

private:
    void completeRow()
    {
        const int d = m_entry.dimension;
        const double *c = m_row.data();
        AffineMap f{Mat(d, d), RowVec(d)};
        if (d == 2) {
            // x' = a x + b y + e, y' = c x + d y + f: the row convention's A is the transpose
            // of [[a, b], [c, d]].
            f.A << c[0], c[2], c[1], c[3];
            f.b << c[4], c[5];
        } else {
            f.A << c[0], c[3], c[6], c[1], c[4], c[7], c[2], c[5], c[8];
            f.b << c[9], c[10], c[11];
        }
        const double p = c[m_width - 1];
        if (p < 0) {
            m_problem = FractintProblem{
                m_rowStart.line, m_rowStart.column, m_entry.name,
                formatMessage(coreTranslate("awb::exchange",
                                            "map %1 has the negative probability %2"),
                              m_entry.maps.size() + 1, streamedNumber(p))};
            return;
        }
        m_entry.maps.push_back(std::move(f));
        m_entry.probabilities.push_back(p);
    }

    std::size_t m_width;
    FractintEntry m_entry;
    std::optional<FractintProblem> m_problem;
    std::array<double, 13> m_row{};
    std::size_t m_count = 0, m_extraMaps = 0;
    Token m_rowStart;
    int m_lineOfLast = 0;
    bool m_rowStartsLine = true;
};

} // namespace

std::string FractintProblem::describe(const std::string &fileName) const
{
    std::string place = formatMessage(coreTranslate("awb::exchange", "%1, line %2, column %3"),
                                      fileName, line, column);
    if (!entry.empty())
        place += formatMessage(coreTranslate("awb::exchange", ": entry %1"), entry);
    return place + ": " + message;
}

namespace {

// Fractint 10 and 15 kept one IFS per file as bare rows, without NAME { }: the whole file is
// one entry named `name`, of rows of 7 (2D) or 13 (3D) numbers, its dimension told by the
// first line.
void readBareRows(Tokenizer &tokens, Token first, const std::string &name, FractintFile *file,
                  Reports &problems)
{
    // The first line's numbers, at most a row of them kept (a one-line file of millions of
    // numbers is counted, not held).
    std::vector<Token> firstLine{first};
    std::size_t n = 1;
    Token t;
    bool more = false;
    while ((more = tokens.next(&t)) && t.line == first.line)
        if (++n <= 13)
            firstLine.push_back(t);
    if (n != 7 && n != 13) {
        problems.add({first.line, first.column, name,
                      formatMessage(coreTranslate("awb::exchange",
                                                  "a file of bare rows (Fractint 10 and 15: "
                                                  "one IFS, no NAME { }) has rows of 7 (2D) or "
                                                  "13 (3D) numbers, its first line %1"),
                                    n)});
        return;
    }
    RowReader rows(name, n == 7 ? 2 : 3);
    rows.entry().line = first.line;
    for (const Token &f : firstLine)
        rows.add(f);
    Token last = firstLine.back();
    for (; more; more = tokens.next(&t)) {
        if (rows.problem())
            break;
        if (t.text == "{" || t.text == "}") {
            problems.add({t.line, t.column, name,
                          coreTranslate("awb::exchange",
                                        "a file of bare rows (Fractint 10 and 15) has no "
                                        "braces: an entry is NAME { rows } throughout")});
            return;
        }
        rows.add(t);
        last = t;
    }
    rows.finish(last);
    if (rows.problem()) {
        problems.add(*rows.problem());
        return;
    }
    file->entries.push_back(std::move(rows.entry()));
}

} // namespace

FractintFile readFractintIfs(std::istream &in, const std::string &bareName)
{
    Tokenizer tokens(in);
    FractintFile file;
    Reports problems{&file.problems}, warnings{&file.warnings};
    Token t;
    if (!tokens.next(&t))
        return file;
    // A file whose first line is numbers without a brace is bare rows.
    double ignored = 0;
    if (toNumber(t.text, &ignored)) {
        // At most a row and one word read ahead (a bare row has 7 or 13 numbers).
        std::vector<Token> line{t};
        Token u;
        bool braces = false;
        while (line.size() <= 14 && tokens.next(&u)) {
            line.push_back(u);
            if (u.line != t.line)
                break;
            braces = braces || u.text == "{" || u.text == "}";
        }
        const Token first = line.front();
        tokens.giveBack(std::vector<Token>(line.begin() + 1, line.end()));
        if (!braces) {
            readBareRows(tokens, first, bareName.empty() ? "ifs" : bareName, &file, problems);
            problems.close(coreTranslate("awb::exchange", "%1 more problems"));
            return file;
        }
    }
    // The words since the last entry: the name is the words on the line of its '{', or on the
    // line before when the '{' starts its line; earlier words are strays.
    std::vector<Token> words;
    std::size_t excess = 0;
    const auto stray = [&](const Token &w) {
        problems.add({w.line, w.column, "",
                      formatMessage(coreTranslate("awb::exchange",
                                                  "'%1' is not followed by '{': an entry is "
                                                  "NAME { rows }"),
                                    w.text)});
    };
    bool more = true;
    while (more) {
        if (t.text == "}") {
            for (const Token &w : words)
                stray(w);
            words.clear();
            problems.add({t.line, t.column, "",
                          coreTranslate("awb::exchange", "a '}' without its '{'")});
        } else if (t.text != "{") {
            // Words of an earlier line than this one's and its predecessor's are strays.
            if (!words.empty() && words.back().line != t.line) {
                const int keepFrom = words.back().line;
                std::size_t k = 0;
                while (k < words.size() && words[k].line < keepFrom)
                    stray(words[k++]);
                words.erase(words.begin(), words.begin() + std::ptrdiff_t(k));
            }
            if (words.size() < 64)
                words.push_back(t);
        } else {
            const Token open = t;
            std::vector<Token> nameWords;
            for (const Token &w : words)
                if (w.line == open.line)
                    nameWords.push_back(w);
            if (nameWords.empty() && !words.empty() && words.back().line == open.line - 1)
                for (const Token &w : words)
                    if (w.line == open.line - 1)
                        nameWords.push_back(w);
            for (const Token &w : words)
                if (w.line != (nameWords.empty() ? -1 : nameWords.front().line))
                    stray(w);
            words.clear();
            // The name, maybe marked "(3D)" (apart or attached).
            int dimension = 2;
            std::string name;
            for (std::size_t k = 0; k < nameWords.size(); ++k) {
                std::string w = nameWords[k].text;
                if (k + 1 == nameWords.size() && w.size() >= 4
                    && lowered(w.substr(w.size() - 4)) == "(3d)") {
                    w.resize(w.size() - 4);
                    dimension = 3;
                }
                if (!w.empty())
                    name += (name.empty() ? "" : " ") + w;
            }
            const int line = nameWords.empty() ? open.line : nameWords.front().line;
            if (name.empty())
                name = formatMessage(coreTranslate("awb::exchange", "entry at line %1"), line);
            RowReader rows(name, dimension);
            rows.entry().line = line;
            Token last = open;
            bool closed = false;
            while ((more = tokens.next(&t))) {
                if (t.text == "}") {
                    closed = true;
                    break;
                }
                if (t.text == "{")
                    break;
                rows.add(t);
                last = t;
            }
            if (!closed) {
                problems.add({more ? t.line : last.line, more ? t.column : last.column, name,
                              more ? coreTranslate("awb::exchange",
                                                   "a '{' inside an entry: its '}' is missing")
                                   : coreTranslate("awb::exchange",
                                                   "the file ends before the entry's '}'")});
                if (more)
                    continue;  // the '{' starts the next entry's reading
                break;
            }
            rows.finish(t);
            if (rows.problem()) {
                problems.add(*rows.problem());
            } else {
                if (file.entries.size() >= kMaxFractintEntries) {
                    ++excess;
                } else {
                    if (const auto w = rows.probabilityWarning())
                        warnings.add(*w);
                    file.entries.push_back(std::move(rows.entry()));
                }
            }
        }
        more = tokens.next(&t);
    }
    for (const Token &w : words)
        stray(w);
    if (excess > 0)
        problems.add({t.line, 1, "",
                      formatMessage(coreTranslate("awb::exchange",
                                                  "%1 more entries after the first %2: one "
                                                  "file gives at most %2"),
                                    excess, kMaxFractintEntries)});
    problems.close(coreTranslate("awb::exchange", "%1 more problems"));
    warnings.close(coreTranslate("awb::exchange", "%1 more warnings"));
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
    std::string name = entry.name;
    // The name is the words before '{' on its line: no braces, comment marks or commas in it,
    // no line breaks; a last word "(3D)" would read as the mark.
    for (char &c : name)
        if (c == '{' || c == '}' || c == ';' || c == ',')
            c = '_';
        else if (std::isspace(static_cast<unsigned char>(c)))
            c = ' ';
    if (name.find_first_not_of(' ') == std::string::npos)
        name = "ifs";
    if (name.size() >= 4 && lowered(name.substr(name.size() - 4)) == "(3d)")
        name += '_';
    std::string out = name + (entry.dimension == 3 ? " (3D)" : "") + " {\n";
    for (std::size_t i = 0; i < entry.maps.size(); ++i) {
        const std::vector<double> c = fractintCoefficients(entry.maps[i]);
        if (int(c.size()) != (entry.dimension == 3 ? 12 : 6))
            throw InputError(coreTranslate("awb::exchange",
                                           "the entry's maps are not all of its dimension"));
        out += ' ';
        for (double v : c) {
            out += ' ';
            out += shortestNumber(v);
        }
        const double p = i < entry.probabilities.size() ? entry.probabilities[i]
                                                        : 1.0 / double(entry.maps.size());
        out += "  ";
        out += shortestNumber(p);
        out += '\n';
    }
    return out + "}\n";
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
