// libFuzzer target (issue 14): any bytes as a project file. A refused file must come with a
// message; an accepted one must save, load again and save to the same bytes (the round trip
// of a user's file), and every attractor item must either build its IFS or say why.
#include "model/AttractorItem.h"
#include "model/Project.h"
#include "model/ProjectIO.h"

#include <cstdint>
#include <cstdlib>
#include <cstdio>

using namespace awb;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    const QByteArray bytes(reinterpret_cast<const char *>(data), qsizetype(size));
    ProjectData parsed;
    QString error;
    if (!ProjectIO::parse(bytes, QStringLiteral("fuzz.awb"), &parsed, &error)) {
        if (error.isEmpty()) {
            std::fprintf(stderr, "refused without a message\n");
            std::abort();
        }
        return 0;
    }
    Project project;
    project.adopt(std::move(parsed), QStringLiteral("fuzz.awb"), false);
    const QByteArray saved = project.serialize();
    ProjectData again;
    if (!ProjectIO::parse(saved, QStringLiteral("saved.awb"), &again, &error)) {
        std::fprintf(stderr, "a saved project does not load: %s\n", qPrintable(error));
        std::abort();
    }
    Project reloaded;
    reloaded.adopt(std::move(again), QStringLiteral("saved.awb"), false);
    if (reloaded.serialize() != saved) {
        std::fprintf(stderr, "save -> load -> save changed the bytes\n");
        std::abort();
    }
    for (Item *item : project.items())
        if (auto *a = qobject_cast<AttractorItem *>(item))
            if (!a->derivedIfs() && a->derivedError().isEmpty()) {
                std::fprintf(stderr, "item %s: no IFS and no reason\n", qPrintable(a->name()));
                std::abort();
            }
    return 0;
}
