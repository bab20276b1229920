#pragma once
// attractor_workbench, the Python module (layer 3, beside cli and gui): the project documents of
// the model and the computations of the core and the CLI's figure code, with nothing computed a
// second way. The standalone module (Module.cpp, build/python/) and the application's Python
// console (gui: PythonConsole) both define it through defineModule(), so a script behaves the
// same in both places; only pybind11's files include pybind11.

namespace pybind11 {
class module_;
class object;
} // namespace pybind11

namespace awb {
class Item;
class Project;
} // namespace awb

namespace awb::python {

// Fills `m` with the module's classes and functions (docs/python.md lists them).
void defineModule(pybind11::module_ &m);
// A Project object of the module for a document the caller owns (the application's open
// document); it never deletes it. The module must have been imported.
pybind11::object borrowProject(Project *project);
// The Item object for `item` of that project (None for nullptr).
pybind11::object itemObject(const pybind11::object &project, Item *item);

} // namespace awb::python
