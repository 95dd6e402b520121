// areagraph._core: the C++ side of the Python package (python/areagraph).
// It hands plain Python values to the package, which builds the shapely,
// networkx and protobuf objects.
#include "python/module/bindings.h"

PYBIND11_MODULE(_core, module) {
  module.doc() = "The C++ side of areagraph; use the package areagraph, not this module.";
  areagraph::python::AddErrors(module);
  areagraph::python::AddGraph(module);
  areagraph::python::AddSegment(module);
  areagraph::python::AddStore(module);
}
