// Errors: bad input (an unknown scene, a bad --set, an unknown method, an option out of range)
// raises springlab.InputError, a ValueError whose message is the one line the command line prints
// after "springlab: " before exiting with status 2. A run that diverges raises
// springlab.DivergenceError with the line `run` prints before exiting with status 3.
#include "bindings.hpp"
#include "divergence_error.hpp"
#include "springlab/error.hpp"

namespace springlab::python {

void bind_errors(py::module_& m) {
  py::register_exception<InputError>(m, "InputError", PyExc_ValueError);
  py::register_exception<DivergenceError>(m, "DivergenceError", PyExc_RuntimeError);
}

}  // namespace springlab::python
