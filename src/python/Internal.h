#pragma once
// What the files of src/python share: each defines a part of the module, and long calls run
// with the GIL released and Ctrl+C turned into the engine's cancellation.

#include "python/Conversions.h"
#include "python/Handles.h"

#include <QRectF>

#include <atomic>
#include <functional>

namespace awb {
struct FigureOptions;
}

namespace awb::python {

void defineProjectClass(py::module_ &m);
void defineItemClass(py::module_ &m);
void defineContainers(py::module_ &m);
void defineAtlas(py::module_ &m);
void defineDensity(py::module_ &m);  // after defineItemClass
// Figure arguments of the item's render(), frame() and density(): (width, height) into `o`
// (None leaves it), and a rectangle (x0, y0, x1, y1); Error naming `function` otherwise.
void figureSizeArg(const py::object &size, const char *function, FigureOptions &o);
QRectF rectArg(const py::object &rect, const char *function, const char *what);
// Text in figures needs a QGuiApplication: made on the first render, never at import.
void ensureGuiApplication();

// Runs `work` on a worker thread with the GIL released; every 50 ms the calling thread takes
// the GIL to look for a signal (Ctrl+C), and on one sets `cancel` (which `work` passes to the
// engine), waits for the worker and raises KeyboardInterrupt. Exceptions of `work` are
// re-raised on the calling thread.
void runInterruptible(const std::function<void()> &work, std::atomic<bool> &cancel);

// The text of a refused edit: the model's message, or `fallback` when it gave none.
QString refusal(const QString &message, const QString &fallback);

} // namespace awb::python
