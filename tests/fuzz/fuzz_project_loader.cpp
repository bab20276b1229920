// libFuzzer target (issue 14): any bytes as a project file. A refused file must come with a
// message; an accepted one must save, load again and save to the same bytes (the round trip
// of a user's file). With AWB_FUZZ_BUILD_IFS (target fuzz_item_ifs) every attractor item must
// also build its IFS or say why: the same inputs through the item readers and the schemes,
// about 3x slower per input, so the loader's own target runs without it.
//
// Work that a valid file may legitimately ask for is bounded here, not by the timeout: a
// normal-vector item draws its subdivided polygon, whose size grows as p^steps up to the
// scheme's own limit (NormalVectorScheme::maxPoints(), 5e7 points, refused above it and tested
// in core_test_normal_vector). Items of more than kMaxPolygonPoints points in all are read, saved
// and reloaded like any other, but their polygon is not built: at 2^20 points that takes
// over 1 s under ASan and coverage, linear work that is not a hang.
#include "core/schemes/NormalVectorScheme.h"
#include "model/AttractorItem.h"
#include "model/NormalVectorItem.h"
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
#ifdef AWB_FUZZ_BUILD_IFS
    constexpr double kMaxPolygonPoints = 1 << 17;
    double polygonPoints = 0;
    for (Item *item : project.items())
        if (auto *a = qobject_cast<AttractorItem *>(item)) {
            if (auto *nv = qobject_cast<NormalVectorItem *>(a)) {
                const NormalVectorSpec &spec = nv->spec();
                const ControlPolygon poly{toMatrix(nv->controlPoints()), spec.closed};
                polygonPoints += spec.makeScheme().pointCount(poly, spec.steps);
                if (polygonPoints > kMaxPolygonPoints)
                    continue;
            }
            if (!a->derivedIfs() && a->derivedError().isEmpty()) {
                std::fprintf(stderr, "item %s: no IFS and no reason\n", qPrintable(a->name()));
                std::abort();
            }
        }
#endif
    return 0;
}
