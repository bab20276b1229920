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

} // namespace awb::test
