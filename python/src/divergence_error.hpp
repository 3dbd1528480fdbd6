// A run that diverged or went numerically unstable (Simulation.run()): "rope: diverged during
// step ...", the line the command line's `run` prints before exiting with status 3.
#pragma once

#include <stdexcept>

namespace springlab::python {

struct DivergenceError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace springlab::python
