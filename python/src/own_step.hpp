// A Python function as a step of springlab's: fn(x, v, force, h) -> (x, v), x and v the state's
// (N, 3) positions and velocities (copies), force(x, v) the core's accelerations f / m at any
// (x, v) (a pinned particle's: 0), counted as the table's rows count theirs. Used by
// Simulation(method=fn) and springlab.homework.check(fn) (homework.cpp).
#pragma once

#include <memory>
#include <string>

#include "bindings.hpp"
#include "springlab/homework.hpp"

namespace springlab::python {

/// The step. A Python exception in fn propagates as itself; a result of the wrong shape raises
/// ValueError saying what was expected. `single_precision`, where given, is set after each call to
/// whether fn returned its arrays in single precision (NumPy's float32).
homework::OwnStep python_step(const py::object& fn, const std::string& name,
                              const std::shared_ptr<bool>& single_precision = nullptr);

/// fn's name for messages: its __name__, else "fn".
std::string step_name(const py::object& fn);

}  // namespace springlab::python
