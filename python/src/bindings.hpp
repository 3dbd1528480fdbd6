// The Python module `springlab._springlab` (python/springlab/__init__.py re-exports it): what its
// files share. One file a topic:
//
//   module.cpp      the module: version, data folder, shipped scenes and tableaux
//   errors.cpp      springlab::InputError -> springlab.InputError, with the command line's message
//   options.cpp     keyword options -> the command line's SimOptions (the same checks, the same
//   words) scenes.cpp      Scene: a scene file loaded, with --set overrides methods.cpp     the
//   method table's rows, their tableaux simulation.cpp  Simulation: stepped; its state as numpy
//   views; energies; divergence stability.cpp   StabilityAnalysis: each method's limit and its
//   limiting mode sweep.cpp       sweep(): accuracy against cost, as numpy arrays homework.cpp    a
//   step of one's own (fn(x, v, force, h)) and springlab.homework.check
#pragma once

#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <memory>
#include <string>
#include <vector>

#include "options/scene_options.hpp"
#include "springlab/scene.hpp"
#include "springlab/state.hpp"

namespace springlab::python {

namespace py = pybind11;

void bind_errors(py::module_& m);
void bind_methods(py::module_& m);
void bind_scenes(py::module_& m);
void bind_stability(py::module_& m);
void bind_simulation(py::module_& m);
void bind_sweep(py::module_& m);
void bind_homework(py::module_& m);

// A scene as load_scene() gave it, and where it came from: a Simulation or a sweep made from it
// loads it again through the command line's own path (app::prepare), options and all.
struct LoadedScene {
  std::string path;               // resolved: a file
  std::vector<std::string> sets;  // "KEY=VALUE"
  Scene scene;
};

// Positions, velocities, a mode's shape: N x 3 doubles, column-major with the columns a padded
// stride apart (state.hpp). Returned to Python with reference_internal, this Map is a read-only
// numpy view of those doubles whose base keeps the owner alive: no copy.
using PointsView =
    Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, 3>, 0, Eigen::OuterStride<>>;
inline PointsView view(const Points& p) {
  return PointsView(p.data(), p.rows(), 3, Eigen::OuterStride<>(p.outerStride()));
}

// The keyword options shared by Simulation() and sweep(), as the command line's flags
// (--method, --dt, --set, ...). `known` collects the names read, so that callers can refuse the
// rest.
app::SimOptions sim_options(const py::kwargs& options, std::vector<std::string>& known);
// Refuses a keyword no option reads: TypeError, as Python does for a function's arguments.
void refuse_unknown(const char* function, const py::kwargs& options,
                    const std::vector<std::string>& known);
// --set as a string, a list of "KEY=VALUE" strings, or a dict {key: value} (a value not a string
// is written as JSON: 64, [0, -9.81, 0], true).
std::vector<std::string> set_overrides(const py::handle& set);

// A method by name as --method takes it (built-in, shipped tableau or tableau file), or
// springlab.InputError with the command line's message.
Method method_named(const std::string& name);

}  // namespace springlab::python
