#pragma once
// Messages: the core's hook into the application's translations, without Qt. The core writes
// every user-facing sentence (InputError messages, notes, verdicts, scheme names) as an
// English source text with %1..%9 placeholders:
//
//     throw InputError(formatMessage(
//         coreTranslate("awb::schemes", "B-spline degree must be at least 1, got %1"), degree));
//
// coreTranslate returns the source text unchanged until the application installs a translator
// (the GUI and the CLI install one that calls QCoreApplication::translate, src/i18n). lupdate
// extracts the calls as translate(context, source[, disambiguation, n]) through
// `-tr-function-alias translate+=coreTranslate` (translations/CMakeLists.txt): the context and
// the source text must be string literals at the call site. translations/README.md lists the
// contexts and the conventions.

#include <initializer_list>
#include <string>
#include <string_view>
#include <type_traits>

namespace awb {

// A translator of the core's messages: returns the translation of `sourceText` (UTF-8) in
// `context`, or the source text itself; `disambiguation` may be null; `n` >= 0 selects a
// plural form and replaces %n. It is called from any thread.
using MessageTranslator = std::string (*)(const char *context, const char *sourceText,
                                          const char *disambiguation, int n);

// Installs `translator` for every later coreTranslate call (nullptr: the English sources).
void setMessageTranslator(MessageTranslator translator);

// The translation of `sourceText` in `context` by the installed translator; without one, the
// source text with %n replaced by n (when n >= 0).
std::string coreTranslate(const char *context, const char *sourceText,
                          const char *disambiguation = nullptr, int n = -1);

// `pattern` with %1..%9 replaced by args[0..8] in one pass (a replacement is never scanned
// again); any other '%' stays as it is.
std::string formatMessageArgs(std::string_view pattern,
                              std::initializer_list<std::string_view> args);

namespace detail {
inline std::string_view messageArg(std::string_view s) { return s; }
inline std::string_view messageArg(const std::string &s) { return s; }
inline std::string_view messageArg(const char *s) { return s; }
// Whole numbers as std::to_string and `os << n` write them. Floating-point numbers are not
// accepted: each message keeps the number format it had (fmt(), num(), a stream's default),
// so the caller formats them.
template<class T, std::enable_if_t<std::is_integral_v<T> && !std::is_same_v<T, bool>
                                       && !std::is_same_v<T, char>, int> = 0>
std::string messageArg(T n)
{
    return std::to_string(n);
}
} // namespace detail

// formatMessage(pattern, a, b, ...): `pattern` with %1 = a, %2 = b, ...; arguments are
// strings or whole numbers (format floating-point numbers before).
template<class... Args>
std::string formatMessage(std::string_view pattern, const Args &...args)
{
    static_assert(sizeof...(Args) <= 9, "formatMessage takes at most 9 arguments");
    // Keeps the temporaries of whole-number arguments alive during the call.
    return [&](const auto &...text) {
        return formatMessageArgs(pattern, {std::string_view(text)...});
    }(detail::messageArg(args)...);
}

// The text `os << v` writes for v with `digits` significant digits in the classic locale (the
// stream's default: 6): the one number formatter of the core's messages and notes.
std::string streamedNumber(double v, int digits = 6);

// The shortest text that reads back as exactly v (std::to_chars; "0.1", "1e-07", "-2.5"): the
// numbers of the files written for other tools (.ifs, .flame), whose round trips are exact
// (-0 is written "0", equal to it).
std::string shortestNumber(double v);

} // namespace awb
