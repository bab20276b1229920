// What a Dask cluster renders (issue 48): the frames of an animation, each drawn as
// `attractor-cli animate --frame K` draws it (attractor_workbench/animate.py), and
// the raw density of an item's figure as a numpy array, and the file of a summed one:
// what attractor_workbench/render.py splits over a Dask cluster. Item.density() renders one
// chunk -- the figure's frame, `samples` points from `seed` -- through renderItemFigure, the
// path of `attractor-cli render --out F.exr`; write_density() writes a sum of chunks with the
// same writers (float32 EXR, 16-bit log-density PNG), the item's project in the file.

#include "python/Internal.h"

#include "model/Animation.h"
#include "model/AttractorItem.h"
#include "model/Project.h"
#include "render/FigureFile.h"
#include "render/ItemFigure.h"

#include <QFile>
#include <QFileInfo>
#include <QTemporaryDir>

#include <cstring>

namespace awb::python {

namespace {

// The item as it is at `time` seconds of its animation (an animated copy; the item itself
// when time is None). Error when the item has no animation or the copy cannot be made.
std::unique_ptr<Item> frameItem(AttractorItem &a, const py::object &time)
{
    const double t = realArg(time, "time", 0, AnimationSpec::maxDuration);
    if (a.animation().isEmpty())
        throw Error(QString("item '%1' has no animation").arg(a.name()));
    QString error;
    std::unique_ptr<Item> copy = animatedCopy(a, t, &error);
    if (!copy)
        throw Error(QString("t = %1 s: %2").arg(t).arg(error));
    return copy;
}

} // namespace

void figureSizeArg(const py::object &size, const char *function, FigureOptions &o)
{
    if (size.is_none())
        return;
    if (!py::isinstance<py::sequence>(size) || py::isinstance<py::str>(size) || py::len(size) != 2)
        throw Error(QString("%1: size: expected (width, height) in pixels").arg(function));
    const py::sequence wh = size;
    const QByteArray width = QByteArray(function) + ": width";
    const QByteArray height = QByteArray(function) + ": height";
    o.width = int(intArg(wh[0], width.constData(), 16, 20000));
    o.height = int(intArg(wh[1], height.constData(), 16, 20000));
}

QRectF rectArg(const py::object &rect, const char *function, const char *what)
{
    if (!py::isinstance<py::sequence>(rect) || py::isinstance<py::str>(rect) || py::len(rect) != 4)
        throw Error(QString("%1: %2: expected (x0, y0, x1, y1)").arg(function, what));
    const py::sequence r = rect;
    double v[4];
    for (int k = 0; k < 4; ++k) {
        const QByteArray name = QByteArray(function) + ": " + what;
        v[k] = realArg(r[k], name.constData(), -1e300, 1e300);
    }
    return QRectF(QPointF(v[0], v[1]), QPointF(v[2], v[3]));
}

void defineDensity(py::module_ &m)
{
    auto item = py::reinterpret_borrow<py::class_<ItemHandle>>(m.attr("Item"));
    item.def_property_readonly(
        "project", [](const ItemHandle &h) { return h.project; },
        "The Project the item belongs to.");
    item.def(
        "animation_times",
        [](const ItemHandle &h, const py::object &fps) {
            AttractorItem &a = h.attractor();
            if (a.animation().isEmpty())
                throw Error(QString("item '%1' has no animation").arg(a.name()));
            AnimationSpec timing = a.animation();
            if (!fps.is_none())
                timing.fps = realArg(fps, "animation_times(): fps", 1, AnimationSpec::maxFps);
            py::list times;
            for (int k = 0; k < timing.frameCount(); ++k)
                times.append(timing.frameTime(k));
            return times;
        },
        py::arg("fps") = py::none(),
        "animation_times(fps=None) -> list\n\nThe times (s) of the frames of the item's "
        "animation, at `fps` frames per second (default: the animation's), as attractor-cli "
        "animate numbers them.");
    item.def(
        "frame",
        [](const ItemHandle &h, const py::object &time, const py::object &size,
           const py::object &bounds, const py::object &measure) -> py::object {
            AttractorItem &a = h.attractor();
            std::unique_ptr<Item> copy = frameItem(a, time);
            FigureOptions o;
            figureSizeArg(size, "frame()", o);
            if (!bounds.is_none())
                o.bounds = rectArg(bounds, "frame()", "bounds");
            const double t = realArg(time, "time", 0, AnimationSpec::maxDuration);
            o.captionSuffix = " — " + animationCaption(a, t);
            ensureGuiApplication();
            Project &project = h.project->get();
            auto *frame = static_cast<AttractorItem *>(copy.get());
            if (py::cast<bool>(measure)) {
                QRectF r;
                {
                    py::gil_scoped_release release;
                    renderItemFigure(project, frame, o, QString(), &r);
                }
                if (!r.isValid())
                    return py::none();
                return py::make_tuple(r.left(), r.top(), r.right(), r.bottom());
            }
            QTemporaryDir dir;
            const QString file = dir.filePath(QStringLiteral("frame.png"));
            std::atomic<bool> cancel{false};
            o.cancel = &cancel;
            runInterruptible([&] { renderItemFigure(project, frame, o, file); }, cancel);
            QFile f(file);
            if (!f.open(QIODevice::ReadOnly))
                throw Error("frame(): the frame was not written");
            const QByteArray png = f.readAll();
            return py::bytes(png.constData(), size_t(png.size()));
        },
        py::arg("time"), py::arg("size") = py::none(), py::arg("bounds") = py::none(),
        py::arg("measure") = false,
        "frame(time, size=None, bounds=None, measure=False) -> bytes\n\nThe PNG of the "
        "item's animation at `time` seconds, drawn as attractor-cli animate draws a frame "
        "(the time and values in the caption) in `bounds` (x0, y0, x1, y1; default: fitted). "
        "With measure=True: the frame's content rectangle instead (None for a surface), whose "
        "union over the frames gives an animation one framing.");
    item.def(
        "density",
        [](const ItemHandle &h, const py::object &size, const py::object &samples,
           const py::object &seed, const py::object &threads, const py::object &bounds) {
            AttractorItem &a = h.attractor();
            FigureOptions o;
            figureSizeArg(size, "density()", o);
            o.samples = std::uint64_t(realArg(samples, "density(): samples", 1, 1e12));
            if (!seed.is_none())
                o.seed = std::uint64_t(intArg(seed, "density(): seed", 0, (1LL << 62)));
            if (!threads.is_none())
                o.threads = int(intArg(threads, "density(): threads", 0, 256));
            if (!bounds.is_none()) {
                o.bounds = rectArg(bounds, "density()", "bounds");
                if (!(o.bounds.width() > 0) || !(o.bounds.height() > 0))
                    throw Error("density(): bounds: expected x0 < x1 and y0 < y1");
            }
            o.format = QStringLiteral("exr");
            RawDensity raw;
            o.rawDensity = &raw;
            ensureGuiApplication();
            Project &project = h.project->get();
            std::atomic<bool> cancel{false};
            o.cancel = &cancel;
            runInterruptible([&] { renderItemFigure(project, &a, o, QString()); }, cancel);
            const int w = raw.density.frame.width, hgt = raw.density.frame.height;
            py::array_t<float> rgba({hgt, w, 4});
            std::memcpy(rgba.mutable_data(), raw.density.rgba.data(),
                        sizeof(float) * size_t(w) * size_t(hgt) * 4);
            const QRectF world = raw.info.world;
            py::dict d;
            d["rgba"] = rgba;
            d["world"] = py::make_tuple(world.left(), world.top(), world.right(), world.bottom());
            d["images"] = raw.density.images;
            d["caption"] = toPy(raw.info.what);
            return d;
        },
        py::arg("size") = py::none(), py::arg("samples"), py::arg("seed") = py::none(),
        py::arg("threads") = py::none(), py::arg("bounds") = py::none(),
        "density(size=None, samples, seed=None, threads=None, bounds=None) -> dict\n\nThe raw "
        "density of the item's figure, as render(\"F.exr\") writes it: {\"rgba\": float32 "
        "array (height, width, 4) -- A the hits of each pixel, R, G, B the hits times their "
        "colour --, \"world\": the frame (x0, y0, x1, y1), \"images\", \"caption\"}. `samples` "
        "random points from `seed` (default: the item's seed), in `bounds` (default: the "
        "attractor's). The same seed gives the same array on every machine and any number of "
        "threads: the chunks of attractor_workbench.render.");
    m.def(
        "write_density",
        [](const py::object &path, const py::array_t<double, py::array::c_style |
                                                           py::array::forcecast> &rgba,
           const ItemHandle &h, const py::object &world, const py::object &caption) {
            const QString file = pathArg(path, "write_density()");
            if (rgba.ndim() != 3 || rgba.shape(2) != 4 || rgba.shape(0) < 1 || rgba.shape(1) < 1)
                throw Error("write_density(): rgba: expected an array (height, width, 4)");
            RawDensity raw;
            raw.density.frame.height = int(rgba.shape(0));
            raw.density.frame.width = int(rgba.shape(1));
            raw.density.rgba.resize(size_t(rgba.size()));
            const double *src = rgba.data();
            for (size_t i = 0; i < raw.density.rgba.size(); ++i) {
                if (!std::isfinite(src[i]) || src[i] < 0)
                    throw Error("write_density(): rgba has a negative or non-finite value");
                raw.density.rgba[i] = float(src[i]);
            }
            raw.info.world = rectArg(world, "write_density()", "world");
            raw.info.what = caption.is_none() ? QString() : toQString(caption, "caption");
            raw.info.metadata = itemFigureMetadata(h.project->get(), h.get());
            const QString suffix = QFileInfo(file).suffix().toLower();
            QString error;
            bool ok = false;
            {
                py::gil_scoped_release release;
                ensureGuiApplication();
                if (suffix == QLatin1String("exr"))
                    ok = writeDensityExr(file, raw.density, raw.info, &error);
                else if (suffix == QLatin1String("png"))
                    ok = writeDensityPng16(file, raw.density, raw.info, &error);
                else
                    error = QString("write_density(): '%1': the density is written to .exr or "
                                    "(16-bit log density) .png")
                                .arg(file);
            }
            if (!ok)
                throw Error(error);
        },
        py::arg("path"), py::arg("rgba"), py::arg("item"), py::arg("world"),
        py::arg("caption") = py::none(),
        "write_density(path, rgba, item, world, caption=None)\n\nWrites a density (an array "
        "(height, width, 4) as Item.density gives, or a sum of them) as render(\"F.exr\") "
        "does: float32 OpenEXR, or the 16-bit log-density PNG for .png, with `item`'s "
        "project in the file.");
}

} // namespace awb::python
