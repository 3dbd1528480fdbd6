// The stability analysis (springlab/stability.hpp): a scene linearised at its equilibrium, each
// method's largest stable step on it, whether that step is exact or a lower bound, and the
// limiting mode (its frequency, damping ratio and shape). Computed once a scene; immutable.
#include "springlab/stability.hpp"

#include <pybind11/complex.h>

#include <cmath>

#include "bindings.hpp"

namespace springlab::python {

namespace {

using AnalysisPtr = std::shared_ptr<StabilityAnalysis>;

std::string repr(const StabilityLimit& l) {
  return std::string("<springlab.StabilityLimit ") + method_info(l.method).name + ": " +
         describe(l) + ">";
}

// LimitingMode and StabilityLimit: a method's largest stable step on a scene, and the mode that
// sets it.
void bind_stability_limit(py::module_& m) {
  py::class_<LimitingMode>(m, "LimitingMode", "the mode that sets a method's limit")
      .def_readonly("w", &LimitingMode::w, "its frequency, rad/s")
      .def_readonly("c", &LimitingMode::c, "its damping rate, 1/s: it decays as exp(-c t / 2)")
      .def_property_readonly("damping_ratio", &LimitingMode::damping_ratio, "c / (2 w)")
      .def_property_readonly(
          "shape", [](const LimitingMode& mode) { return view(mode.shape); },
          py::return_value_policy::reference_internal,
          "N x 3: each particle's displacement in the mode, the largest of length 1 (read-only "
          "view)");

  py::class_<StabilityLimit>(m, "StabilityLimit", "a method's largest stable step on a scene")
      .def_property_readonly(
          "method", [](const StabilityLimit& l) { return std::string(method_info(l.method).name); })
      .def_readonly("h", &StabilityLimit::h,
                    "s: 0 unstable at any step, inf stable at any step, nan adaptive")
      .def_readonly("exact", &StabilityLimit::exact,
                    "False: h is a lower bound (stable at least up to h)")
      .def_property_readonly(
          "mode", [](const StabilityLimit& l) { return l.mode ? &*l.mode : nullptr; },
          py::return_value_policy::reference_internal, "the limiting mode, or None")
      .def_readonly("residual", &StabilityLimit::residual, "of the limiting mode as an eigenvector")
      .def_property_readonly(
          "description", [](const StabilityLimit& l) { return describe(l); },
          "as `springlab run` says it: 'stable up to h = ...'")
      .def("__repr__", &repr);
}

// StabilityAnalysis: a scene linearised at its equilibrium, each method's limit on it, its
// frequencies, eigenvalues and modes, and a stable step's transient growth.
void bind_stability_analysis(py::module_& m) {
  py::class_<StabilityAnalysis, AnalysisPtr>(m, "StabilityAnalysis",
                                             R"(A scene's stability, for every method.

StabilityAnalysis(scene) analyses a loaded Scene as it starts; Simulation.stability() returns the
analysis of the simulation as it runs (after ks=, kd= ...). limit(method) is what `springlab run`
states, the limiting mode included.)")
      .def(py::init([](const LoadedScene& scene, int dense_dofs) {
             py::gil_scoped_release unlocked;
             return std::make_shared<StabilityAnalysis>(scene.scene.model, scene.scene.state,
                                                        dense_dofs);
           }),
           py::arg("scene"), py::arg("dense_dofs") = kDenseDofs,
           "dense_dofs: up to how many free coordinates every eigenvalue is computed")
      .def(
          "limit",
          [](const StabilityAnalysis& a, const std::string& method) -> const StabilityLimit& {
            return a.limit(method_named(method));
          },
          py::return_value_policy::reference_internal, py::arg("method"))
      .def_property_readonly("oscillates", &StabilityAnalysis::oscillates)
      .def_property_readonly("no_modes_reason", &StabilityAnalysis::no_modes_reason)
      .def_property_readonly("w_max", &StabilityAnalysis::w_max, "the highest frequency, rad/s")
      .def_property_readonly("w_bound", &StabilityAnalysis::w_bound, "Gershgorin's bound on it")
      .def_property_readonly("dense", &StabilityAnalysis::dense, "every eigenvalue computed")
      .def_property_readonly("dofs", &StabilityAnalysis::dofs, "free coordinates")
      .def_property_readonly("seconds", &StabilityAnalysis::seconds,
                             "what the analysis took, wall time")
      .def_property_readonly("lowest_energy", &StabilityAnalysis::lowest_energy)
      .def_property_readonly("rest_stretch", &StabilityAnalysis::rest_stretch)
      .def_property_readonly(
          "eigenvalues",
          [](const StabilityAnalysis& a) {
            const auto& e = a.eigenvalues();
            return py::array_t<std::complex<double>>(static_cast<py::ssize_t>(e.size()), e.data());
          },
          "of the first-order system (dense scenes: all of them; large ones: none)")
      .def_property_readonly(
          "modes",
          [](const StabilityAnalysis& a) {
            std::vector<double> gamma, kappa;
            for (const auto& p : a.modes()) {
              gamma.push_back(p.gamma);
              kappa.push_back(p.kappa);
            }
            return py::make_tuple(
                py::array_t<double>(static_cast<py::ssize_t>(gamma.size()), gamma.data()),
                py::array_t<double>(static_cast<py::ssize_t>(kappa.size()), kappa.data()));
          },
          "(gamma, kappa): each mode's damping and stiffness (large scenes: the boundary of their "
          "range)")
      .def(
          "transient_growth",
          [](const StabilityAnalysis& a, const std::string& method, double h,
             double verlet_damping) {
            const StabilityAnalysis::Growth g =
                a.transient_growth(method_named(method), h, {.verlet_damping = verlet_damping});
            return py::make_tuple(g.factor, g.growing);
          },
          py::arg("method"), py::arg("h"), py::arg("verlet_damping") = 0.0,
          "(factor, growing): the most a stable step raises a mode's energy, and how many modes "
          "grow");
}

}  // namespace

void bind_stability(py::module_& m) {
  bind_stability_limit(m);
  bind_stability_analysis(m);

  m.def(
      "equilibrium",
      [](const LoadedScene& scene) {
        py::gil_scoped_release unlocked;
        const State rest = equilibrium(scene.scene.model, scene.scene.state);
        return Eigen::Matrix<double, Eigen::Dynamic, 3>(rest.x);
      },
      py::arg("scene"),
      "N x 3, m: the static balance the analysis linearises about (a hanging rope in tension); a "
      "copy");
}

}  // namespace springlab::python
