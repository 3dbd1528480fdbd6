// Simulation: a scene made ready as `springlab run` makes it (app::prepare: the same options, the
// same checks, the same settings), stepped from Python. Its state is read through numpy views of
// the simulation's own arrays, without a copy.
#include "springlab/simulation.hpp"

#include <algorithm>
#include <cstdio>

#include "bindings.hpp"
#include "divergence_error.hpp"
#include "options/option_ranges.hpp"
#include "own_step.hpp"
#include "springlab/error.hpp"

namespace springlab::python {

namespace {

struct PySimulation {
  std::string scene;               // its name, for messages
  std::int64_t planned_steps = 0;  // steps=, or duration= (or the scene's) / dt, as `run` takes
  std::unique_ptr<Simulation> sim;
};

std::unique_ptr<PySimulation> make(const py::object& scene, const py::kwargs& given) {
  // method= a function: a step of one's own (own_step.hpp) in place of a row, which is then the
  // scene's own method, standing for its defaults (sub-steps: as given, or those it would take).
  py::kwargs kw;
  py::object own;
  for (const auto& [key, value] : given) {
    if (key.cast<std::string>() == "method" && PyCallable_Check(value.ptr()))
      own = py::reinterpret_borrow<py::object>(value);
    else
      kw[key] = value;
  }
  std::vector<std::string> known;
  app::SimOptions options = sim_options(kw, known);
  refuse_unknown("Simulation", kw, known);
  std::string source;
  if (py::isinstance<LoadedScene>(scene)) {
    const auto& loaded = scene.cast<const LoadedScene&>();
    source = loaded.path;
    options.sets.insert(options.sets.begin(), loaded.sets.begin(), loaded.sets.end());
  } else {
    source = scene.cast<std::string>();
  }
  app::Prepared p = app::prepare(source, options);
  // As `run` does: the iterative methods' artificial damping is measured against the physics'.
  if (method_info(p.settings.method).family == MethodFamily::Iterative)
    p.settings.track_dissipation = true;
  if (own) {
    p.settings.own_step_name = step_name(own);
    p.settings.own_step = python_step(own, p.settings.own_step_name);
    p.settings.track_dissipation = false;
  }
  auto out = std::make_unique<PySimulation>();
  out->scene = p.scene.name;
  out->planned_steps = p.steps;
  out->sim =
      std::make_unique<Simulation>(std::move(p.scene.model), std::move(p.scene.state), p.settings);
  return out;
}

// Steps with the interpreter free for other threads, a chunk at a time so that Ctrl-C is heard
// between chunks (a chunk is about 4 million particle- and spring-steps, a few ms).
std::int64_t advance(PySimulation& s, std::int64_t steps) {
  const std::int64_t size = s.sim->model().particle_count() + s.sim->model().spring_count() + 1;
  const std::int64_t chunk = std::clamp<std::int64_t>(4'000'000 / size, 1, 4096);
  std::int64_t taken = 0;
  while (taken < steps) {
    const std::int64_t want = std::min(chunk, steps - taken), done = [&] {
      py::gil_scoped_release unlocked;
      return s.sim->advance(want);
    }();
    taken += done;
    if (done < want) break;  // diverged
    if (PyErr_CheckSignals() != 0) throw py::error_already_set();
  }
  return taken;
}

// The line `run` prints after "springlab: " when a run diverges.
std::string divergence_line(PySimulation& s) {
  return s.scene + ": " + s.sim->explain_divergence()->message();
}

std::string format(double x) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.6g", x);
  return buffer;
}

}  // namespace

// The run's results as Python reads them: its energies, its cost, how it diverged.
void bind_results(py::module_& m) {
  py::class_<Energy>(m, "Energy", "a state's energies, J")
      .def_readonly("kinetic", &Energy::kinetic)
      .def_readonly("spring", &Energy::spring)
      .def_readonly("gravity", &Energy::gravity)
      .def_readonly("field", &Energy::field)
      .def_property_readonly("potential", &Energy::potential, "spring + gravity + field")
      .def_property_readonly("total", &Energy::total)
      .def("__repr__", [](const Energy& e) {
        return "<springlab.Energy kinetic " + format(e.kinetic) + " J, potential " +
               format(e.potential()) + " J, total " + format(e.total()) + " J>";
      });

  py::class_<Counters>(m, "Counters",
                       "work done, summed over steps: the machine-independent cost of a run")
      .def_readonly("force_evals", &Counters::force_evals)
      .def_readonly("linear_solves", &Counters::linear_solves)
      .def_readonly("solver_iterations", &Counters::solver_iterations)
      .def_readonly("unconverged_solves", &Counters::unconverged_solves)
      .def_readonly("accepted", &Counters::accepted)
      .def_readonly("rejected", &Counters::rejected);

  py::class_<Divergence>(m, "Divergence", "how a run diverged or went numerically unstable")
      .def_readonly("step", &Divergence::step, "the step during which it happened (1-based)")
      .def_readonly("t", &Divergence::t, "time of the last good state kept, s")
      .def_property_readonly("method",
                             [](const Divergence& d) {
                               return d.own_step.empty() ? std::string(method_info(d.method).name)
                                                         : d.own_step;
                             })
      .def_readonly("h", &Divergence::h)
      .def_readonly("stable_h", &Divergence::stable_h, "the method's stated limit")
      .def_readonly("unstable", &Divergence::unstable, "caught by the energy audit")
      .def_readonly("reason", &Divergence::reason)
      .def_property_readonly("message", &Divergence::message,
                             "one paragraph, as `springlab run` prints it");
}

// What a Simulation says of itself: its scene and settings, its state as numpy views, its
// energies, cost and divergence.
void bind_readouts(py::class_<PySimulation>& simulation) {
  simulation.def_property_readonly("scene", [](const PySimulation& s) { return s.scene; })
      .def_property_readonly("planned_steps", [](const PySimulation& s) { return s.planned_steps; })
      .def_property_readonly(
          "method",
          [](const PySimulation& s) {
            const SimulationSettings& settings = s.sim->settings();
            return settings.own_step ? settings.own_step_name
                                     : std::string(method_info(settings.method).name);
          },
          "the row's name, or the name of the function given as method=")
      .def_property_readonly(
          "t", [](const PySimulation& s) { return s.sim->state().t; }, "s")
      .def_property_readonly("steps_taken",
                             [](const PySimulation& s) { return s.sim->steps_taken(); })
      .def_property_readonly("dt", [](const PySimulation& s) { return s.sim->settings().dt; })
      .def_property_readonly("substeps",
                             [](const PySimulation& s) { return s.sim->settings().substeps; })
      .def_property_readonly("auto_substeps",
                             [](const PySimulation& s) { return s.sim->auto_substeps(); })
      .def_property_readonly("substeps_capped",
                             [](const PySimulation& s) { return s.sim->substeps_capped(); })
      .def_property_readonly(
          "h", [](const PySimulation& s) { return s.sim->h(); }, "dt / substeps")
      .def_property_readonly("particle_count",
                             [](const PySimulation& s) { return s.sim->model().particle_count(); })
      .def_property_readonly("spring_count",
                             [](const PySimulation& s) { return s.sim->model().spring_count(); })
      .def_property_readonly(
          "positions", [](const PySimulation& s) { return view(s.sim->state().x); },
          py::return_value_policy::reference_internal,
          "N x 3, m: a read-only view of the state now")
      .def_property_readonly(
          "velocities", [](const PySimulation& s) { return view(s.sim->state().v); },
          py::return_value_policy::reference_internal,
          "N x 3, m/s: a read-only view of the state now")
      .def(
          "state_hash", [](const PySimulation& s) { return state_hash(s.sim->state()); },
          "FNV-1a of the state's exact bits: equal hashes mean bit-identical states")
      .def("energy", [](const PySimulation& s) { return s.sim->energy(); })
      .def_property_readonly("energy_scale",
                             [](const PySimulation& s) { return s.sim->energy_scale(); })
      .def_property_readonly(
          "dissipated", [](const PySimulation& s) { return s.sim->dissipated(); },
          "J taken out by damping, drag and contacts (counted for the iterative methods, as by "
          "run)")
      .def_property_readonly("external_work",
                             [](const PySimulation& s) { return s.sim->external_work(); })
      .def_property_readonly("net_energy",
                             [](const PySimulation& s) { return s.sim->net_energy(); })
      .def_property_readonly("counters", [](const PySimulation& s) { return s.sim->counters(); })
      .def_property_readonly("diverged", [](const PySimulation& s) { return s.sim->diverged(); })
      .def_property_readonly(
          "divergence",
          [](PySimulation& s) -> std::optional<Divergence> {
            if (!s.sim->diverged()) return std::nullopt;
            return *s.sim->explain_divergence();
          },
          "how it diverged (with the stated limit), or None")
      .def_property_readonly(
          "instability", [](const PySimulation& s) { return s.sim->instability(); },
          "the energy audit's finding, or None");
}

// The stability analysis and limit, and the settings changed between steps as the app's panels
// change them (each checked as the command line checks it).
void bind_analysis_and_settings(py::class_<PySimulation>& simulation) {
  simulation
      .def(
          "stability",
          [](PySimulation& s) {
            {
              py::gil_scoped_release unlocked;
              s.sim->stability();
            }
            return std::const_pointer_cast<StabilityAnalysis>(s.sim->stability_if_any());
          },
          "the stability analysis of the scene as it is now (made when first asked after a change)")
      .def(
          "stability_limit",
          [](PySimulation& s) {
            if (s.sim->settings().own_step)
              throw InputError(
                  s.sim->settings().own_step_name +
                  " is a step of your own: springlab states no limit for it "
                  "(springlab.homework.check measures its stability against the row it is)");
            {
              py::gil_scoped_release unlocked;
              s.sim->stability();
            }
            return s.sim->stability_limit();
          },
          "the current method's stated limit (a copy); InputError for a step of your own")
      .def(
          "set_method",
          [](PySimulation& s, const std::string& name) { s.sim->set_method(method_named(name)); },
          py::arg("method"))
      .def(
          "set_dt",
          [](PySimulation& s, double dt) {
            app::check_option("--dt", dt, 0.0, 1.0, true, " s");
            s.sim->set_dt(dt);
          },
          py::arg("dt"))
      .def(
          "set_substeps",
          [](PySimulation& s, const py::object& substeps) {
            std::string text = py::isinstance<py::str>(substeps)
                                   ? substeps.cast<std::string>()
                                   : py::repr(substeps).cast<std::string>();
            if (text == "auto") return s.sim->set_auto_substeps(s.sim->settings().safety);
            const std::string error =
                app::parse_whole_number(text, app::kSubsteps.lo, app::kSubsteps.hi);
            if (!error.empty()) throw InputError("--substeps: " + error + " (or auto)");
            s.sim->set_substeps(std::stoi(text));
          },
          py::arg("substeps"), "a number, or 'auto'")
      .def(
          "set_stiffness",
          [](PySimulation& s, double ks) {
            app::check_option("--ks", ks, 0.0, 1e12, false, " N/m");
            s.sim->set_stiffness(ks);
          },
          py::arg("ks"), "k_s of the first material; the others keep their ratio to it")
      .def(
          "set_damping",
          [](PySimulation& s, double kd) {
            app::check_option("--kd", kd, 0.0, 1e12, false, " N s/m");
            s.sim->set_damping(kd);
          },
          py::arg("kd"))
      .def("__repr__", [](const PySimulation& s) {
        const SimulationSettings& settings = s.sim->settings();
        return "<springlab.Simulation '" + s.scene + "' " +
               (settings.own_step ? settings.own_step_name
                                  : std::string(method_info(settings.method).name)) +
               ", t = " + format(s.sim->state().t) + " s>";
      });
}

void bind_simulation(py::module_& m) {
  bind_results(m);
  py::class_<PySimulation> simulation(m, "Simulation",
                                      R"(A scene stepped as `springlab run` steps it.

Simulation(scene, **options): scene is a shipped scene's name, a JSON file or a Scene; options are
the command line's: method="rk4" (or a function of your own, fn(x, v, force, h) -> (x, v): see
springlab.homework), dt=1e-3, substeps=4 or "auto", steps=N or duration=T (what
run() takes), ks=, kd=, tol=, iterations=, rho=, set={"rope.nodes": 64} (or "KEY=VALUE" strings),
threads=. Bad input raises springlab.InputError with the command line's message.

positions and velocities are read-only numpy views of the state now, not copies: a step writes
the next state into the simulation's other buffer and swaps the two, so read them again after
stepping (or keep a .copy()).)");
  simulation.def(py::init(&make), py::arg("scene"))
      .def(
          "step", [](PySimulation& s) { return s.sim->step(); },
          "one step of dt; False (and nothing done) once the run has diverged")
      .def("advance", &advance, py::arg("steps"),
           "up to `steps` steps; returns how many were taken")
      .def(
          "run",
          [](PySimulation& s, std::optional<std::int64_t> steps) {
            // As `run`: the analysis first, from the state it starts from (a divergence's message
            // then states the limits `run` states; made at the divergence instead, from the state
            // there, its equilibrium and figures can differ in the last digits).
            {
              py::gil_scoped_release unlocked;
              s.sim->stability();
            }
            const std::int64_t taken = advance(s, steps.value_or(s.planned_steps));
            if (s.sim->diverged()) throw DivergenceError(divergence_line(s));
            return taken;
          },
          py::arg("steps") = py::none(),
          "the steps `springlab run` takes (planned_steps), or `steps`, after the stability "
          "analysis as `run` "
          "makes it; springlab.DivergenceError, with `run`'s message, if it diverges")
      .def(
          "reset", [](PySimulation& s) { s.sim->reset(); },
          "back to the initial state, keeping the settings");
  bind_readouts(simulation);
  bind_analysis_and_settings(simulation);
}

}  // namespace springlab::python
