#pragma once
// Wall-clock limits of the tests (waiting for a render, a worker, a batch), scaled for slow
// builds: AWB_TEST_TIME_SCALE=N multiplies them by N. scripts/sanitizer-env.sh sets it for the
// instrumented build, whose code runs several times slower; the normal suite keeps its limits.
#include <QtGlobal>

#include <algorithm>

namespace awb::test {

inline int ms(int limit)
{
    static const int scale = std::max(1, qEnvironmentVariableIntValue("AWB_TEST_TIME_SCALE"));
    return limit * scale;
}

// Built with ThreadSanitizer (scripts/sanitize.sh thread), whose suite looks for races: there a
// test function that starts no thread is left to the AddressSanitizer and normal suites
// (AWB_SKIP_WITHOUT_THREADS), and a test over many inputs may take one per kind of worker.
#if defined(__SANITIZE_THREAD__)
#define AWB_TEST_TSAN 1
#elif defined(__has_feature)
#if __has_feature(thread_sanitizer)
#define AWB_TEST_TSAN 1
#endif
#endif
#ifndef AWB_TEST_TSAN
#define AWB_TEST_TSAN 0
#endif
inline constexpr bool kThreadSanitizer = AWB_TEST_TSAN;

} // namespace awb::test

// At the top of a test function that starts no thread (tests/CMakeLists.txt, AWB_THREADED_TESTS
// labels whole files): skipped under ThreadSanitizer only. Which functions start none was
// measured as scripts/threaded-tests.py measures files, per function (`strace -f -e
// trace=clone,clone3 build/tests/<layer>_tests <file> <function>`, no CLONE_THREAD); a function
// whose code comes to start threads must lose the mark.
#define AWB_SKIP_WITHOUT_THREADS()                                                               \
    do {                                                                                       \
        if (awb::test::kThreadSanitizer)                                                       \
            QSKIP("starts no thread: the AddressSanitizer and normal suites run it");           \
    } while (false)
