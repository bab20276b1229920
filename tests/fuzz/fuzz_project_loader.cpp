// libFuzzer targets (issue 14): any bytes as a project file, through the checks of
// ProjectChecks.h: fuzz_project_loader reads, saves and reloads; fuzz_item_ifs
// (AWB_FUZZ_BUILD_IFS) also builds every attractor item's IFS or its reason, about 3x slower
// per input, so the loader's own target runs without it.
#include "ProjectChecks.h"

#include <cstdint>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    const QByteArray bytes(reinterpret_cast<const char *>(data), qsizetype(size));
#ifdef AWB_FUZZ_BUILD_IFS
    awb::fuzz::checkProjectBytes(bytes, QStringLiteral("fuzz.awb"), true);
#else
    awb::fuzz::checkProjectBytes(bytes, QStringLiteral("fuzz.awb"), false);
#endif
    return 0;
}
