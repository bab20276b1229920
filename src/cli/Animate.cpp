// attractor-cli animate: the frames of an item's animation, as PNG files or a movie.

#include "cli/FigureOptions.h"
#include "cli/CommandSupport.h"
#include "cli/ProjectCommands.h"

#include "render/FigureRenderer.h"
#include "core/analysis/Geometry.h"
#include "core/analysis/Spectrum.h"
#include "model/Animation.h"
#include "model/FigureMetadata.h"
#include "model/AttractorItem.h"
#include "model/ExactCurve.h"
#include "model/FileWriting.h"
#include "model/ItemAddress.h"
#include "model/NumberFormat.h"
#include "model/PointExport.h"
#include "model/Project.h"
#include "model/SchemeRegularity.h"
#include "model/NormalVectorItem.h"
#include "model/SubdivisionCurveItem.h"
#include "core/schemes/NormalVectorScheme.h"
#include "core/schemes/Scheme.h"
#include "model/SubdivisionSurfaceItem.h"
#include "model/SubdivisionMeshItem.h"
#include "model/MeshAnalysisJson.h"
#include "core/mesh/MeshFiles.h"
#include "core/mesh/MeshRefine.h"
#include "core/ifs/SurfaceIfs.h"
#include "render/SurfaceFigure.h"

#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QProcess>
#include <QStandardPaths>
#include <QTemporaryDir>

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QRegularExpression>
#include <QTextStream>

#include <sstream>

namespace awb::cli {

int animate(const QStringList &args)
{
    return guarded([&] {
        QCommandLineParser parser;
        parser.setApplicationDescription(
            CliTr::tr("Render the frames of an item's animation (its keyframed parameters): numbered "
                   "PNG files in a folder, or an MP4 or GIF movie through ffmpeg. Frame k is the "
                   "item with its parameters at time k / fps, drawn exactly as `render` draws "
                   "it."));
        parser.addPositionalArgument("project", CliTr::tr("The .awb project file."));
        parser.addOptions(
            {{"item", CliTr::tr("The animated item (default: the first item with an "
                             "animation)."), "name"},
             {"out", CliTr::tr("A folder for frame-0000.png, frame-0001.png, ... (made if missing), a "
                            "movie .mp4 or .gif (made by ffmpeg), or with --frame one "
                            ".png/.svg/.pdf."),
              "dir|file"},
             {"fps", CliTr::tr("Frames per second (default: the animation's)."), "n"},
             {"frame", CliTr::tr("Render only frame K (0 = the start) to the file --out."), "k"},
             {"no-caption-values", CliTr::tr("Captions without the frame's time and values.")}});
        parser.addOptions(figureOptionList());
        parseOrFail(parser, args, 1);
        if (!parser.isSet("out"))
            throw Failure{CliTr::tr("--out DIR|FILE is required"), 2};
        const FigureOptions options = figureOptions(parser);
        Project project;
        load(project, parser.positionalArguments().first());
        AttractorItem *item = nullptr;
        if (parser.isSet("item")) {
            item = attractorItem(project, parser.value("item"));
        } else {
            for (Item *i : project.items())
                if (auto *a = qobject_cast<AttractorItem *>(i); a && !a->animation().isEmpty()) {
                    item = a;
                    break;
                }
            if (!item)
                throw Failure{CliTr::tr("%1 has no animated item").arg(project.fileName())};
        }
        if (item->animation().isEmpty())
            throw Failure{CliTr::tr("item '%1' has no animation: key its parameters in the "
                                 "Animation dock, or give it an \"animation\" field "
                                 "(docs/file-format.md)")
                              .arg(item->name())};
        for (const QString &target : inactiveAnimationTargets(*item))
            err() << CliTr::tr("attractor-cli: note: the track of %1 is skipped: item '%2' has no "
                            "such input now")
                         .arg(target, item->name())
                  << "\n";
        AnimationSpec timing = item->animation();
        if (parser.isSet("fps"))
            timing.fps = realOption(parser, "fps", 1, AnimationSpec::maxFps);
        const int frames = timing.frameCount();
        FigureOptions frameOptions = options;
        // One framing for every frame (the union of their contents): the attractor moves, the
        // frame stays. --bounds sets it.
        if (!frameOptions.bounds.isValid()) {
            QRectF all(0, 0, -1, -1);
            for (int k = 0; k < frames; ++k) {
                QString error;
                std::unique_ptr<Item> copy = animatedCopy(*item, timing.frameTime(k), &error);
                QRectF r(0, 0, -1, -1);
                if (copy)
                    try {
                        renderItemFigure(project, static_cast<AttractorItem *>(copy.get()), options,
                                     {}, &r);
                    } catch (const Failure &) {
                        // reported when the frame is drawn
                    }
                if (r.width() >= 0)
                    all = all.width() < 0 ? r : all.united(r);
            }
            if (all.width() > 0 && all.height() > 0)
                frameOptions.bounds = all;
        }
        const auto boundsText = [&] {
            const QRectF &b = frameOptions.bounds;
            return b.isValid() ? CliTr::tr("%1,%2,%3,%4")
                                     .arg(b.left(), 0, 'g', 17)
                                     .arg(b.top(), 0, 'g', 17)
                                     .arg(b.right(), 0, 'g', 17)
                                     .arg(b.bottom(), 0, 'g', 17)
                               : CliTr::tr("fitted per frame");
        };
        const auto renderFrame = [&](int k, const QString &file) {
            QString error;
            std::unique_ptr<Item> copy = animatedCopy(*item, timing.frameTime(k), &error);
            if (!copy)
                throw Failure{CliTr::tr("frame %1 (t = %2 s): %3")
                                  .arg(k)
                                  .arg(timing.frameTime(k))
                                  .arg(error)};
            FigureOptions o = frameOptions;
            if (!parser.isSet("no-caption-values"))
                o.captionSuffix = " — " + animationCaption(*item, timing.frameTime(k));
            try {
                renderItemFigure(project, static_cast<AttractorItem *>(copy.get()), o, file);
            } catch (const Failure &f) {
                throw Failure{CliTr::tr("frame %1 (t = %2 s): %3")
                                  .arg(k)
                                  .arg(timing.frameTime(k))
                                  .arg(f.message),
                              f.code};
            }
        };
        const QString outPath = parser.value("out");
        if (parser.isSet("frame")) {
            renderFrame(intOption(parser, "frame", 0, frames - 1), outPath);
            out() << outPath << "\nbounds: " << boundsText() << "\n";
            return 0;
        }
        const QString suffix = QFileInfo(outPath).suffix().toLower();
        const bool movie = suffix == "mp4" || suffix == "gif";
        QString ffmpeg;
        if (movie) {
            ffmpeg = qEnvironmentVariableIsSet("AWB_FFMPEG")
                         ? qEnvironmentVariable("AWB_FFMPEG")
                         : QStandardPaths::findExecutable("ffmpeg");
            if (ffmpeg.isEmpty() || !QFileInfo(ffmpeg).isExecutable())
                throw Failure{CliTr::tr("writing %1 needs ffmpeg, which is not installed (Debian: "
                                     "apt-get install ffmpeg); give --out a folder to get the "
                                     "frames as PNG files")
                                  .arg(outPath)};
        }
        QTemporaryDir scratch;
        const QString dir = movie ? scratch.path() : outPath;
        if (movie && !scratch.isValid())
            throw Failure{CliTr::tr("cannot make a temporary folder for the frames: %1")
                              .arg(scratch.errorString())};
        if (!movie && QFileInfo(dir).exists() && !QFileInfo(dir).isDir())
            throw Failure{CliTr::tr("%1 is a file, not a folder (a movie needs .mp4 or .gif)")
                              .arg(dir)};
        if (!QDir().mkpath(dir))
            throw Failure{CliTr::tr("cannot make the folder %1").arg(dir)};
        const int digits = std::max(4, int(QString::number(frames - 1).size()));
        const QString pattern = "frame-%0" + QString::number(digits) + "d.png"; // ffmpeg's
        QElapsedTimer clock;
        clock.start();
        for (int k = 0; k < frames; ++k)
            renderFrame(k, QDir(dir).filePath(
                               CliTr::tr("frame-%1.png").arg(k, digits, 10, QLatin1Char('0'))));
        const double seconds = clock.elapsed() / 1000.0;
        if (movie) {
            QStringList ffArgs{"-y", "-loglevel", "error", "-framerate",
                               QString::number(timing.fps), "-i", QDir(dir).filePath(pattern)};
            if (suffix == "gif")
                ffArgs << "-vf" << "split[a][b];[a]palettegen[p];[b][p]paletteuse";
            else
                ffArgs << "-c:v" << "libx264" << "-pix_fmt" << "yuv420p" << "-vf"
                       << "pad=ceil(iw/2)*2:ceil(ih/2)*2";
            ffArgs << outPath;
            QProcess process;
            process.start(ffmpeg, ffArgs);
            if (!process.waitForFinished(-1) || process.exitStatus() != QProcess::NormalExit
                || process.exitCode() != 0)
                throw Failure{CliTr::tr("ffmpeg could not write %1: %2")
                                  .arg(outPath, QString::fromLocal8Bit(process.readAllStandardError())
                                                    .trimmed())};
        }
        out() << CliTr::tr("%1: %2 frames of %3x%4 at %5 frames/s (%6 s); rendered in %7 s, "
                        "%8 frames/s\nbounds: %9\n")
                     .arg(outPath)
                     .arg(frames)
                     .arg(options.width)
                     .arg(options.height)
                     .arg(timing.fps)
                     .arg(timing.duration)
                     .arg(seconds, 0, 'f', 2)
                     .arg(frames / std::max(seconds, 1e-9), 0, 'f', 1)
                     .arg(boundsText());
        return 0;
    });
}

} // namespace awb::cli
