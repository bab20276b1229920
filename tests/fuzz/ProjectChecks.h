#pragma once
// The checks of a project's bytes shared by the fuzz targets that end in the project loader
// (fuzz_project_loader, fuzz_item_ifs, fuzz_png_project, fuzz_svg_project). A refused file must
// come with a message; an accepted one must save, load again and save to the same bytes (the
// round trip of a user's file). With buildIfs every attractor item must also build its IFS or
// say why: the same inputs through the item readers and the schemes, about 3x slower per input.
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

#include <cstdio>
#include <cstdlib>

namespace awb::fuzz {

// Aborts (the fuzzer's crash) with the reason when a check fails.
[[noreturn]] inline void fail(const char *what, const QString &detail = {})
{
    std::fprintf(stderr, "%s%s%s\n", what, detail.isEmpty() ? "" : ": ", qPrintable(detail));
    std::abort();
}

inline void checkProjectBytes(const QByteArray &bytes, const QString &fileName, bool buildIfs)
{
    ProjectData parsed;
    QString error;
    if (!ProjectIO::parse(bytes, fileName, &parsed, &error)) {
        if (error.isEmpty())
            fail("refused without a message");
        return;
    }
    Project project;
    project.adopt(std::move(parsed), fileName, false);
    const QByteArray saved = project.serialize();
    ProjectData again;
    if (!ProjectIO::parse(saved, QStringLiteral("saved.awb"), &again, &error))
        fail("a saved project does not load", error);
    Project reloaded;
    reloaded.adopt(std::move(again), QStringLiteral("saved.awb"), false);
    if (reloaded.serialize() != saved)
        fail("save -> load -> save changed the bytes");
    if (!buildIfs)
        return;
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
            if (!a->derivedIfs() && a->derivedError().isEmpty())
                fail("an item has no IFS and no reason", a->name());
        }
}

} // namespace awb::fuzz
