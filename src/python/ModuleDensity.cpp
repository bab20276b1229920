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
            if (!size.is_none()) {
                const py::sequence wh = size.cast<py::sequence>();
                if (py::len(wh) != 2)
                    throw Error("frame(): size: expected (width, height) in pixels");
                o.width = int(intArg(wh[0], "frame(): width", 16, 20000));
                o.height = int(intArg(wh[1], "frame(): height", 16, 20000));
            }
            if (!bounds.is_none()) {
                const py::sequence b = bounds.cast<py::sequence>();
                if (py::len(b) != 4)
                    throw Error("frame(): bounds: expected (x0, y0, x1, y1)");
                o.bounds = QRectF(QPointF(realArg(b[0], "frame(): x0", -1e300, 1e300),
                                          realArg(b[1], "frame(): y0", -1e300, 1e300)),
                                  QPointF(realArg(b[2], "frame(): x1", -1e300, 1e300),
                                          realArg(b[3], "frame(): y1", -1e300, 1e300)));
            }
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
            if (!size.is_none()) {
                if (!py::isinstance<py::sequence>(size) || py::isinstance<py::str>(size) ||
                    py::len(size) != 2)
                    throw Error("density(): size: expected (width, height) in pixels");
                const py::sequence wh = size;
                o.width = int(intArg(wh[0], "density(): width", 16, 20000));
                o.height = int(intArg(wh[1], "density(): height", 16, 20000));
            }
            o.samples = std::uint64_t(realArg(samples, "density(): samples", 1, 1e12));
            if (!seed.is_none())
                o.seed = std::uint64_t(intArg(seed, "density(): seed", 0, (1LL << 62)));
            if (!threads.is_none())
                o.threads = int(intArg(threads, "density(): threads", 0, 256));
            if (!bounds.is_none()) {
                const py::sequence b = bounds.cast<py::sequence>();
                if (py::len(b) != 4)
                    throw Error("density(): bounds: expected (x0, y0, x1, y1)");
                const double x0 = realArg(b[0], "density(): x0", -1e300, 1e300);
                const double y0 = realArg(b[1], "density(): y0", -1e300, 1e300);
                const double x1 = realArg(b[2], "density(): x1", -1e300, 1e300);
                const double y1 = realArg(b[3], "density(): y1", -1e300, 1e300);
                if (!(x1 > x0) || !(y1 > y0))
                    throw Error("density(): bounds: expected x0 < x1 and y0 < y1");
                o.bounds = QRectF(QPointF(x0, y0), QPointF(x1, y1));
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
            const py::sequence wd = world.cast<py::sequence>();
            if (py::len(wd) != 4)
                throw Error("write_density(): world: expected (x0, y0, x1, y1)");
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
            const QPointF a(realArg(wd[0], "write_density(): x0", -1e300, 1e300),
                            realArg(wd[1], "write_density(): y0", -1e300, 1e300));
            const QPointF b(realArg(wd[2], "write_density(): x1", -1e300, 1e300),
                            realArg(wd[3], "write_density(): y1", -1e300, 1e300));
            raw.info.world = QRectF(a, b);
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
