// defineModule: the exception, the module functions, and the parts each file defines.

#include "python/Bindings.h"
#include "python/Internal.h"

#include "core/Types.h"
#include "model/Item.h"
#include "model/Project.h"
#include "model/ProjectIO.h"

#include <condition_variable>
#include <exception>
#include <mutex>
#include <thread>

namespace awb::python {

ProjectHandle::ProjectHandle() : owned(std::make_unique<Project>()), project(owned.get()) {}
ProjectHandle::ProjectHandle(Project *borrowed) : project(borrowed) {}
ProjectHandle::~ProjectHandle() = default;

Project &ProjectHandle::get() const
{
    if (!project)
        throw Error("the project was closed");
    return *project;
}

ItemHandle::ItemHandle(ProjectRef of, Item *which)
    : project(std::move(of)), item(which), name(which ? which->name() : QString())
{
}

Item &ItemHandle::get() const
{
    Project &p = project->get();
    auto *self = const_cast<ItemHandle *>(this);
    if ((!item || item->project() != &p) && previous && previous->project() == &p)
        self->item = previous;
    if (!item || item->project() != &p)
        self->item = p.findItem(name);
    if (!item)
        throw Error(QString("item '%1' is no longer in the project").arg(name));
    self->name = item->name();
    return *item;
}

QString refusal(const QString &message, const QString &fallback)
{
    return message.isEmpty() ? fallback : message;
}

void runInterruptible(const std::function<void()> &work, std::atomic<bool> &cancel)
{
    std::mutex mutex;
    std::condition_variable finished;
    bool done = false;
    bool interrupted = false;
    std::exception_ptr failure;
    {
        py::gil_scoped_release release;
        std::thread worker([&] {
            try {
                work();
            } catch (...) {
                failure = std::current_exception();
            }
            std::lock_guard<std::mutex> lock(mutex);
            done = true;
            finished.notify_all();
        });
        std::unique_lock<std::mutex> lock(mutex);
        while (!done) {
            finished.wait_for(lock, std::chrono::milliseconds(50));
            if (done || interrupted)
                continue;
            lock.unlock();
            {
                py::gil_scoped_acquire acquire;
                if (PyErr_CheckSignals() != 0) {
                    interrupted = true;
                    cancel.store(true);
                }
            }
            lock.lock();
        }
        lock.unlock();
        worker.join();
    }
    if (interrupted)
        throw py::error_already_set();  // the KeyboardInterrupt PyErr_CheckSignals set
    if (failure)
        std::rethrow_exception(failure);
}

py::object borrowProject(Project *project)
{
    return py::cast(std::make_shared<ProjectHandle>(project));
}

py::object itemObject(const py::object &project, Item *item)
{
    if (!item)
        return py::none();
    ItemHandle h(project.cast<ProjectRef>(), item);
    return py::cast(h);
}

void defineModule(py::module_ &m)
{
    m.doc() = "Attractor Workbench: subdivision schemes and iterated function systems, their "
              "attractors, matrices and spectra, in the projects (.awb) of the application.";
    static py::handle errorType;
    auto &error = py::register_exception<Error>(m, "Error", PyExc_ValueError);
    error.attr("__doc__") =
        "A refused input or edit, with the application's message (a ValueError).";
    errorType = error;
    py::register_exception_translator([](std::exception_ptr p) {
        auto raise = [](const QString &message) {
            PyErr_SetString(errorType.ptr(), message.toUtf8().constData());
        };
        try {
            if (p)
                std::rethrow_exception(p);
        } catch (const InputError &e) {
            raise(QString::fromUtf8(e.what()));
        } catch (const LoadError &e) {
            raise(e.field.isEmpty() ? e.message : e.field + ": " + e.message);
        } catch (const py::cast_error &e) {
            PyErr_SetString(PyExc_TypeError,
                            (std::string("an argument has the wrong type: ") + e.what()).c_str());
        }
    });
    defineContainers(m);
    defineItemClass(m);
    defineProjectClass(m);
    defineAtlas(m);
    defineDensity(m);
    m.def(
        "open",
        [](const py::object &path) {
            const QString file = pathArg(path, "open()");
            auto handle = std::make_shared<ProjectHandle>();
            QString why;
            bool ok = false;
            {
                py::gil_scoped_release release;
                ok = handle->project->open(file, &why);
            }
            if (!ok)
                throw Error(why);
            return handle;
        },
        py::arg("path"),
        "open(path) -> Project\n\nOpens a project file (.awb), or a PNG or SVG figure the "
        "application or attractor-cli wrote (it carries its project). Raises Error with the "
        "file, item and field of the first problem.");
    m.attr("__version__") = PROJECT_VERSION;
}

} // namespace awb::python
