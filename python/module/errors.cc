// The library's error types as Python exceptions, with the same one-line
// messages that the command-line tools print after their name.
#include <pybind11/pybind11.h>

#include "common/error.h"
#include "python/module/bindings.h"

namespace areagraph::python {
namespace {

namespace py = pybind11;

// Held for the life of the process: released at exit, after the interpreter,
// they would touch it.
struct ErrorTypes {
  py::exception<Error>* error;
  py::exception<InputError>* input;
  py::exception<OptionsError>* options;
  py::exception<StoreError>* store;
  py::exception<MapStepError>* map_step;
};
ErrorTypes types;

template <typename Type>
py::exception<Type>* NewType(py::module_& module, const char* name, py::handle base,
                             const char* doc) {
  auto* type = new py::exception<Type>(module, name, base);
  type->attr("__doc__") = doc;
  return type;
}

}  // namespace

void AddErrors(py::module_& module) {
  types.error = NewType<Error>(
      module, "Error", PyExc_RuntimeError,
      "Base of every areagraph error; str() is the one line that the command-line tools print.");
  types.input = NewType<InputError>(module, "InputError", *types.error,
                                    "A bad file, image, YAML, grid or map content.");
  types.options = NewType<OptionsError>(module, "OptionsError", *types.error,
                                        "A bad option key, value or combination.");
  types.store = NewType<StoreError>(module, "StoreError", *types.error,
                                    "The store cannot be opened or read.");
  types.map_step =
      NewType<MapStepError>(module, "MapStepError", *types.error,
                            "A stage failed on one map; str() reads \"map 'M', STAGE: cause\".");
  py::register_local_exception_translator([](std::exception_ptr pointer) {
    try {
      if (pointer) std::rethrow_exception(pointer);
    } catch (const MapStepError& caught) {
      (*types.map_step)(caught.what());
    } catch (const InputError& caught) {
      (*types.input)(caught.what());
    } catch (const OptionsError& caught) {
      (*types.options)(caught.what());
    } catch (const StoreError& caught) {
      (*types.store)(caught.what());
    } catch (const Error& caught) {
      (*types.error)(caught.what());
    }
  });
}

}  // namespace areagraph::python
