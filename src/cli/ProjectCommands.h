#pragma once
// The commands of attractor-cli, one file each (Render.cpp, Animate.cpp, Analyse.cpp, Points.cpp,
// Set.cpp, Check.cpp, Rewrite.cpp, Export.cpp, Polygon.cpp, ImportMesh.cpp, ...), listed in
// main.cpp's table. Each takes the command's
// arguments (argv[0] = "attractor-cli <command>") and returns the exit code:
// 0 success, 1 bad input (file, item, option values), 2 usage error, 3 the project loads but an
// item cannot be computed (check).

#include <QStringList>

namespace awb::cli {

int render(const QStringList &args);
// The frames of an item's animation: PNG files, or an MP4/GIF through ffmpeg.
int animate(const QStringList &args);
int analyse(const QStringList &args);
int points(const QStringList &args);
int check(const QStringList &args);
// Set.cpp: an item's declared properties set (KEY=VALUE ...) and saved, or listed.
int set(const QStringList &args);
// Examples.cpp: the built-in paper figures rendered to PNG (no project).
int examples(const QStringList &args);
int rewrite(const QStringList &args);
int exportData(const QStringList &args);
int polygon(const QStringList &args);
// ImportMesh.cpp: a mesh file as a project with one mesh item.
int importMesh(const QStringList &args);
// Valences.cpp: the valence explorer's table of a mesh scheme (no project).
int valences(const QStringList &args);
// Import.cpp: another tool's IFS file (Fractint .ifs) as a project.
int importFile(const QStringList &args);
// RegularityInterval.cpp: where a curve scheme is C^k as a parameter moves (bisection).
int regularityInterval(const QStringList &args);
// VerifyRegularity.cpp: re-checks a certificate of an exact Hölder exponent.
int verifyRegularity(const QStringList &args);

} // namespace awb::cli
