#include "core/Messages.h"

#include <atomic>
#include <charconv>
#include <sstream>

namespace awb {

namespace {
std::atomic<MessageTranslator> g_translator{nullptr};

// "%n" -> n, as QCoreApplication::translate does for a count.
std::string replaceCount(std::string text, int n)
{
    const std::string count = std::to_string(n);
    for (size_t at = text.find("%n"); at != std::string::npos; at = text.find("%n", at)) {
        text.replace(at, 2, count);
        at += count.size();
    }
    return text;
}
} // namespace

void setMessageTranslator(MessageTranslator translator) { g_translator.store(translator); }

std::string coreTranslate(const char *context, const char *sourceText, const char *disambiguation,
                          int n)
{
    if (const MessageTranslator translate = g_translator.load())
        return translate(context, sourceText, disambiguation, n);
    return n >= 0 ? replaceCount(sourceText, n) : std::string(sourceText);
}

std::string formatMessageArgs(std::string_view pattern,
                              std::initializer_list<std::string_view> args)
{
    std::string out;
    out.reserve(pattern.size() + 16 * args.size());
    for (size_t i = 0; i < pattern.size(); ++i) {
        const char c = pattern[i];
        if (c == '%' && i + 1 < pattern.size() && pattern[i + 1] >= '1' && pattern[i + 1] <= '9'
            && size_t(pattern[i + 1] - '1') < args.size()) {
            out += *(args.begin() + (pattern[i + 1] - '1'));
            ++i;
        } else {
            out += c;
        }
    }
    return out;
}

std::string shortestNumber(double v)
{
    if (v == 0)
        return "0";  // -0 too: the files of other tools have no signed zero worth a '-'
    char buffer[32];
    const auto end = std::to_chars(buffer, buffer + sizeof buffer, v).ptr;
    return std::string(buffer, end);
}

std::string streamedNumber(double v, int digits)
{
    std::ostringstream os;
    os.imbue(std::locale::classic());
    os.precision(digits);
    os << v;
    return os.str();
}

} // namespace awb
