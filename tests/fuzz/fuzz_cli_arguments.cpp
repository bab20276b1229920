// libFuzzer target (issue 14): the command line of `attractor-cli points` — start sets
// (point:, segment:, triangle:, polygon:, points:, lifted:), addresses, depths, item names,
// --max-points — on a real example project. One argument per line of the input. Whatever the
// arguments, the command answers with an exit status (0, 1 or 2), never a crash or a hang.
#include "cli/ProjectCommands.h"

#include <QCoreApplication>
#include <QString>

#include <cstdint>
#include <cstdio>
#include <cstdlib>

extern "C" int LLVMFuzzerInitialize(int *, char ***)
{
    // The CSV goes nowhere: the fuzzer's own output stays readable.
    if (!std::freopen("/dev/null", "w", stdout))
        std::abort();
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    static const QString project = QStringLiteral(AWB_FUZZ_PROJECT);
    const QString text = QString::fromUtf8(reinterpret_cast<const char *>(data), qsizetype(size));
    QStringList args{QStringLiteral("attractor-cli points"), project};
    const QStringList lines = text.split(QLatin1Char('\n'));
    for (const QString &line : lines)
        if (args.size() < 12)
            args << line;
    const int status = awb::cli::points(args);
    if (status < 0 || status > 3) {
        std::fprintf(stderr, "exit status %d\n", status);
        std::abort();
    }
    return 0;
}
