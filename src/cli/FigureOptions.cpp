// The options of `render` and `animate`: how a figure of an item is drawn (the drawing itself:
// render/ItemFigure).

#include "cli/FigureOptions.h"

#include "cli/CommandSupport.h"
#include "core/ifs/Attractor.h"

#include <QRegularExpression>

#include <cmath>

namespace awb::cli {

// The options of `render` that `animate` shares: how a figure of an item is drawn.
QList<QCommandLineOption> frameOptionList()
{
    return {{"size", CliTr::tr("Image size in pixels (default 900x700)."), "WxH", "900x700"},
            {"bounds", CliTr::tr("Plane figures: the world rectangle to frame (padded by 6%), e.g. to "
                              "compare figures at one scale (default: fit the content)."),
             "x0,y0,x1,y1"}};
}

QList<QCommandLineOption> figureOptionList()
{
    QList<QCommandLineOption> list = frameOptionList();
    list += QList<QCommandLineOption>{
            {"depth", CliTr::tr("Deterministic iteration depth (default: the item's)."), "k"},
            {"samples", CliTr::tr("Random iteration with this many points (up to 1e12; "
                               "memory stays that of the raster)."), "n"},
            {"tone", CliTr::tr("Raster tone: 'hits' (every lit pixel opaque, the papers' "
                            "look) or 'density' (log density of the invariant measure, "
                            "gamma and vibrancy as flame renderers). Default: the item's "
                            "style (auto: hits for deterministic, density for random "
                            "iteration)."),
             "hits|density"},
            {"gamma", CliTr::tr("Density tone: display gamma (default: the item's, 2.2)."), "g"},
            {"vibrancy", CliTr::tr("Density tone: 1 saturated colours, 0 per-channel "
                                "gamma (default 1)."), "v", "1"},
            {"supersample", CliTr::tr("Histogram cells per pixel side, 1..4 (default 1; "
                                   "2 or 3 anti-alias edges)."), "s", "1"},
            {"threads", CliTr::tr("Threads of the raster engine (default: all cores)."), "n"},
            {"view", CliTr::tr("Surfaces: the camera's azimuth and elevation in degrees "
                            "(orthographic; default: the item's camera)."),
             "az,el"},
            {"format", CliTr::tr("The output's format when its name has no suffix (e.g. /dev/stdout): "
                              "png, svg, pdf or exr (default: the suffix)."),
             "png|svg|pdf|exr"},
            {"bits", CliTr::tr("PNG: 8 (the figure, default) or 16 (the attractor's raw density: "
                               "alpha = log(1 + hits) / log(1 + most hits), the colour the "
                               "hits' mean; no title, polygons or margins). An .exr file always "
                               "holds the raw density, as float32 counts."),
             "8|16", "8"}};
    return list;
}


void readFrameOptions(const QCommandLineParser &parser, FigureOptions &o)
{
    const QRegularExpression sizeRe("^(\\d+)x(\\d+)$");
    const auto sm = sizeRe.match(parser.value("size"));
    if (!sm.hasMatch() || sm.captured(1).toInt() < 64 || sm.captured(2).toInt() < 64
        || sm.captured(1).toInt() > 16384 || sm.captured(2).toInt() > 16384)
        throw Failure{CliTr::tr("--size must be WxH with 64..16384 pixels each, got '%1'")
                          .arg(parser.value("size"))};
    o.width = sm.captured(1).toInt();
    o.height = sm.captured(2).toInt();
    o.sizeGiven = parser.isSet("size");
    if (parser.isSet("bounds")) {
        const QStringList parts = parser.value("bounds").split(',');
        double v[4] = {};
        bool ok = parts.size() == 4;
        for (int i = 0; ok && i < 4; ++i)
            v[i] = parts[i].trimmed().toDouble(&ok), ok = ok && std::isfinite(v[i]);
        if (!ok || !(v[2] > v[0]) || !(v[3] > v[1]))
            throw Failure{CliTr::tr("--bounds must be x0,y0,x1,y1 with x0 < x1 and y0 < y1, got '%1'")
                              .arg(parser.value("bounds"))};
        o.bounds = QRectF(QPointF(v[0], v[1]), QPointF(v[2], v[3]));
    }
}

FigureOptions figureOptions(const QCommandLineParser &parser)
{
    FigureOptions o;
    if (parser.isSet("depth") && parser.isSet("samples"))
        throw Failure{CliTr::tr("--depth and --samples exclude each other"), 2};
    readFrameOptions(parser, o);
    if (parser.isSet("depth"))
        o.depth = intOption(parser, "depth", 0, 64);
    if (parser.isSet("samples"))
        o.samples = countOption(parser, "samples", 1, double(kMaxChaosSamples));
    o.tone = parser.value("tone");
    if (!o.tone.isEmpty() && o.tone != "hits" && o.tone != "density")
        throw Failure{CliTr::tr("--tone must be 'hits' or 'density', got '%1'").arg(o.tone), 2};
    if (parser.isSet("gamma"))
        o.gamma = realOption(parser, "gamma", 0.2, 10);
    o.vibrancy = realOption(parser, "vibrancy", 0, 1);
    o.supersample = intOption(parser, "supersample", 1, 4);
    if (parser.isSet("threads"))
        o.threads = intOption(parser, "threads", 1, 64);
    if (parser.isSet("view")) {
        const QStringList view = parser.value("view").split(',');
        bool okA = false, okE = false;
        const double az = view.value(0).toDouble(&okA), el = view.value(1).toDouble(&okE);
        if (view.size() != 2 || !okA || !okE || !std::isfinite(az) || !std::isfinite(el)
            || std::abs(el) > 90)
            throw Failure{CliTr::tr("--view must be AZ,EL in degrees with |EL| <= 90, got '%1'")
                              .arg(parser.value("view"))};
        o.view = std::pair{az, el};
    }
    if (parser.isSet("format")) {
        o.format = parser.value("format").toLower();
        if (o.format != "png" && o.format != "svg" && o.format != "pdf" && o.format != "exr")
            throw Failure{CliTr::tr("--format must be png, svg, pdf or exr, got '%1'")
                              .arg(parser.value("format")), 2};
    }
    o.bits = intOption(parser, "bits", 8, 16);
    if (o.bits != 8 && o.bits != 16)
        throw Failure{CliTr::tr("--bits must be 8 or 16, got '%1'").arg(parser.value("bits")), 2};
    return o;
}

} // namespace awb::cli
