// The module springlab._springlab: springlab's core for Python. python/springlab/__init__.py
// re-exports it; docs/python.md tells how to build, install and use it.
#include "bindings.hpp"
#include "springlab/version.hpp"

PYBIND11_MODULE(_springlab, m) {
  using namespace springlab::python;
  m.doc() =
      "springlab: mass-spring simulation for teaching (scenes, methods, stability, accuracy "
      "sweeps)";
  m.attr("__version__") = springlab::kVersion;
  bind_errors(m);
  bind_methods(m);
  bind_scenes(m);
  bind_stability(m);
  bind_simulation(m);
  bind_sweep(m);
  bind_homework(m);
}
