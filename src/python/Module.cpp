// The standalone module: `import attractor_workbench` from build/python/ or from the Debian
// package's dist-packages. The application defines the same module in its console.

#include "python/Bindings.h"

#include <pybind11/pybind11.h>

PYBIND11_MODULE(attractor_workbench, m)
{
    awb::python::defineModule(m);
}
