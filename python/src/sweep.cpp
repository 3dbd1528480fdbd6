// sweep(): accuracy against cost (springlab/sweep.hpp), set up as `springlab compare` sets it up
// (app::prepare_sweep: the same defaults, checks and messages), its results as numpy arrays: a
// column a field, a row a run, so that a work-precision chart is one plot call per method.
#include "springlab/sweep.hpp"

#include <cmath>

#include "bindings.hpp"
#include "options/sweep_options.hpp"

namespace springlab::python {

namespace {

template <typename T>
py::array_t<T> array_of(const std::vector<T>& values) {
  return py::array_t<T>(static_cast<py::ssize_t>(values.size()), values.data());
}
// (std::vector<bool> packs its bits: element by element.)
py::array_t<bool> array_of(const std::vector<bool>& values) {
  py::array_t<bool> a(static_cast<py::ssize_t>(values.size()));
  auto out = a.mutable_unchecked<1>();
  for (std::size_t i = 0; i < values.size(); ++i) out(static_cast<py::ssize_t>(i)) = values[i];
  return a;
}

// A column of the runs (or of the summaries): one value a row.
template <typename Row, typename F>
auto column(const std::vector<Row>& rows, F field) {
  std::vector<decltype(field(rows.front()))> values;
  values.reserve(rows.size());
  for (const Row& r : rows) values.push_back(field(r));
  return values;
}

using namespace pybind11::literals;

// Method names as a numpy array of strings (compared with == "rk4" to pick a method's rows).
py::array names(const std::vector<Method>& methods) {
  py::list list;
  for (Method m : methods) list.append(method_info(m).name);
  return py::module_::import("numpy").attr("array")(list, "dtype"_a = "U");
}

py::dict runs_table(const std::vector<SweepRun>& runs) {
  py::dict t;
  if (runs.empty()) return t;
  t["method"] = names(column(runs, [](const SweepRun& r) { return r.method; }));
  t["h"] = array_of(column(runs, [](const SweepRun& r) { return r.h; }));
  t["tolerance"] = array_of(column(runs, [](const SweepRun& r) { return r.tolerance; }));
  t["mean_step"] = array_of(column(runs, [](const SweepRun& r) { return r.mean_step; }));
  t["error"] = array_of(column(runs, [](const SweepRun& r) { return r.error; }));
  t["seconds"] = array_of(column(runs, [](const SweepRun& r) { return r.seconds; }));
  t["force_evals"] =
      array_of(column(runs, [](const SweepRun& r) { return r.counters.force_evals; }));
  t["linear_solves"] =
      array_of(column(runs, [](const SweepRun& r) { return r.counters.linear_solves; }));
  t["solver_iterations"] =
      array_of(column(runs, [](const SweepRun& r) { return r.counters.solver_iterations; }));
  t["accepted"] = array_of(column(runs, [](const SweepRun& r) { return r.counters.accepted; }));
  t["rejected"] = array_of(column(runs, [](const SweepRun& r) { return r.counters.rejected; }));
  // The work-precision chart's cost, the same on every machine (app/chart/compare_charts.cpp).
  t["work"] = array_of(column(runs, [](const SweepRun& r) {
    return r.counters.force_evals + r.counters.solver_iterations;
  }));
  t["diverged"] = array_of(column(runs, [](const SweepRun& r) { return r.diverged; }));
  t["diverged_at"] = array_of(column(runs, [](const SweepRun& r) { return r.diverged_at; }));
  t["rise"] = array_of(column(runs, [](const SweepRun& r) { return r.rise; }));
  t["unstable"] = array_of(column(runs, [](const SweepRun& r) { return r.unstable; }));
  return t;
}

py::dict summary_table(const std::vector<MethodSummary>& rows) {
  py::dict t;
  if (rows.empty()) return t;
  t["method"] = names(column(rows, [](const MethodSummary& r) { return r.method; }));
  t["order_table"] =
      array_of(column(rows, [](const MethodSummary& r) { return method_info(r.method).order; }));
  t["order"] = array_of(column(rows, [](const MethodSummary& r) { return r.order; }));
  t["fitted_points"] =
      array_of(column(rows, [](const MethodSummary& r) { return r.fitted_points; }));
  t["measured_stable_h"] =
      array_of(column(rows, [](const MethodSummary& r) { return r.measured_stable_h; }));
  t["measured_resolution"] =
      array_of(column(rows, [](const MethodSummary& r) { return r.measured_resolution; }));
  t["theoretical_stable_h"] =
      array_of(column(rows, [](const MethodSummary& r) { return r.theoretical_stable_h; }));
  t["theory_exact"] = array_of(column(rows, [](const MethodSummary& r) { return r.theory_exact; }));
  return t;
}

// What a sweep's result holds besides its tables: DriftTrace (a method's energy drift at the
// scene's step), SolverErrorCurve and SolverErrorStudy (the iterative methods' solver error).
void bind_sweep_parts(py::module_& m) {
  py::class_<DriftTrace>(m, "DriftTrace", "a method's energy drift at the scene's step")
      .def_property_readonly(
          "method", [](const DriftTrace& d) { return std::string(method_info(d.method).name); })
      .def_readonly("substeps", &DriftTrace::substeps)
      .def_property_readonly("t", [](const DriftTrace& d) { return array_of(d.t); })
      .def_property_readonly(
          "drift", [](const DriftTrace& d) { return array_of(d.drift); },
          "(E + dissipated - E0) / energy scale")
      .def_readonly("diverged", &DriftTrace::diverged);

  py::class_<SolverErrorCurve>(m, "SolverErrorCurve")
      .def_property_readonly(
          "method",
          [](const SolverErrorCurve& c) { return std::string(method_info(c.method).name); })
      .def_property_readonly("iterations",
                             [](const SolverErrorCurve& c) { return array_of(c.iterations); })
      .def_property_readonly("error", [](const SolverErrorCurve& c) { return array_of(c.error); });

  py::class_<SolverErrorStudy>(m, "SolverErrorStudy",
                               "the iterative methods' solver error at one step (solver_error.hpp)")
      .def_readonly("h", &SolverErrorStudy::h)
      .def_readonly("motion", &SolverErrorStudy::motion)
      .def_readonly("residual", &SolverErrorStudy::residual)
      .def_readonly("curves", &SolverErrorStudy::curves);
}

// SweepResult: the runs and the summary as tables of numpy arrays, the drift traces, the
// reference and what the sweep measured of the scene.
void bind_sweep_result(py::module_& m) {
  py::class_<SweepResult>(m, "SweepResult",
                          R"(Accuracy against cost, as `springlab compare` measures it.

runs: a dict of equal-length numpy arrays, a row a run (method, h, tolerance, mean_step, error
in m, seconds, force_evals, linear_solves, solver_iterations, accepted, rejected, work = force
evaluations + solver iterations, diverged, diverged_at, rise, unstable); grouped by method,
steps from coarse to fine. summary: the same a row a method (method, order_table, order fitted,
fitted_points, measured_stable_h, measured_resolution, theoretical_stable_h, theory_exact).)")
      .def_property_readonly("runs", [](const SweepResult& r) { return runs_table(r.runs); })
      .def_property_readonly("summary",
                             [](const SweepResult& r) { return summary_table(r.methods); })
      .def_readonly("drift", &SweepResult::drift)
      .def_readonly("reference", &SweepResult::reference, "'exact solution' or 'rk4 at h = ... s'")
      .def_readonly("reference_error", &SweepResult::reference_error, "m, estimated")
      .def_readonly("sample_interval", &SweepResult::sample_interval, "s, where errors are taken")
      .def_readonly("samples", &SweepResult::samples)
      .def_readonly("motion", &SweepResult::motion, "m: the reference's largest RMS displacement")
      .def_readonly("w_max", &SweepResult::w_max, "rad/s at the equilibrium")
      .def_readonly("solver", &SweepResult::solver);
}

}  // namespace

void bind_sweep(py::module_& m) {
  bind_sweep_parts(m);
  bind_sweep_result(m);

  m.def(
      "sweep",
      [](const py::object& scene, const py::kwargs& kw) {
        std::vector<std::string> known;
        app::SimOptions sim = sim_options(kw, known);
        app::SweepOptions o;
        auto given = [&](const char* name) -> py::object {
          known.emplace_back(name);
          return kw.contains(name) ? py::object(kw[name]) : py::object(py::none());
        };
        // A range as (lo, hi), or "LO:HI" as typed after --dt-range.
        auto range_text = [](const py::object& v) {
          if (py::isinstance<py::str>(v)) return v.cast<std::string>();
          const auto pair = v.cast<std::pair<double, double>>();
          return py::repr(py::float_(pair.first)).cast<std::string>() + ":" +
                 py::repr(py::float_(pair.second)).cast<std::string>();
        };
        if (auto v = given("methods"); !v.is_none())
          o.methods = py::isinstance<py::str>(v) ? v.cast<std::string>()
                                                 : py::str(",").attr("join")(v).cast<std::string>();
        if (auto v = given("dt_range"); !v.is_none()) o.dt_range = range_text(v);
        if (auto v = given("tol_range"); !v.is_none()) o.tol_range = range_text(v);
        if (auto v = given("drift_duration"); !v.is_none()) o.drift_duration = v.cast<double>();
        if (auto v = given("stability_budget"); !v.is_none()) o.stability_budget = v.cast<double>();
        if (auto v = given("points"); !v.is_none()) o.points = v.cast<int>();
        if (auto v = given("repeats"); !v.is_none()) o.repeats = v.cast<int>();
        refuse_unknown("sweep", kw, known);
        std::string source;
        if (py::isinstance<LoadedScene>(scene)) {
          const auto& loaded = scene.cast<const LoadedScene&>();
          source = loaded.path;
          sim.sets.insert(sim.sets.begin(), loaded.sets.begin(), loaded.sets.end());
        } else {
          source = scene.cast<std::string>();
        }
        app::PreparedSweep plan = app::prepare_sweep(source, sim, o);
        py::gil_scoped_release unlocked;
        return run_sweep(plan.prepared.scene.model, plan.prepared.scene.state, plan.settings);
      },
      py::arg("scene"),
      R"(Every method's error against its cost on a scene: `springlab compare` without the files.

Options as `compare`'s flags: methods=["euler", "rk4"] (default: all), dt_range=(lo, hi) (default
dt / 16 to 2 dt), points=8, tol_range=(lo, hi), repeats=1, duration= (default: the scene's, at
most 2 s), drift_duration= (default: the scene's duration; 0: none), stability_budget=2e8 (0: the
stable step is not measured by runs), and Simulation's options (dt=, ks=, set=, threads= ...).
Returns a SweepResult.)");
}

}  // namespace springlab::python
