#pragma once

#include <pybind11/pybind11.h>

namespace areagraph::python {

// Each adds its part of the module `areagraph._core`.
void AddErrors(pybind11::module_& module);
void AddGraph(pybind11::module_& module);
void AddSegment(pybind11::module_& module);
void AddStore(pybind11::module_& module);

}  // namespace areagraph::python
