// libFuzzer targets (issue 29): any bytes as a figure exported with its project
// (model/FigureMetadata.h), as File > Open and attractor-cli read it: fuzz_png_project from
// PNG seeds (text chunks, zTXt and iTXt inflated within 64 MB), fuzz_svg_project from SVG seeds
// (the <metadata> element, XML parsed by QXmlStreamReader). A figure without a project must be
// refused with a message; the project found goes through the project loader's checks
// (ProjectChecks.h): loaded, saved and reloaded to the same bytes, or refused with a message.
#include "ProjectChecks.h"

#include "model/FigureMetadata.h"

#include <cstdint>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    const QByteArray bytes(reinterpret_cast<const char *>(data), qsizetype(size));
    QString error;
    const QByteArray project = awb::embeddedProject(bytes, QStringLiteral("fuzz.figure"), &error);
    if (project.isEmpty()) {
        if (error.isEmpty())
            awb::fuzz::fail("a figure refused without a message");
        return 0;
    }
    awb::fuzz::checkProjectBytes(project, QStringLiteral("fuzz.figure"), false);
    return 0;
}
