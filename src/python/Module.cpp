// The compiled part of the package attractor_workbench (build/python/attractor_workbench/, or
// the Debian package's dist-packages): _native, re-exported by the package's __init__.py. The
// application defines the same module in its console.

#include "python/Bindings.h"

#include <pybind11/pybind11.h>

PYBIND11_MODULE(_native, m)
{
    // The classes are the package's: attractor_workbench.Item, not ..._native.Item (their
    // __module__ is the module's __name__ while they are defined).
    m.attr("__name__") = "attractor_workbench";
    awb::python::defineModule(m);
    m.attr("__name__") = "attractor_workbench._native";
}
