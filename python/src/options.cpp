// Keyword options -> the command line's SimOptions. The values are checked where the command line
// checks them (app::prepare, options/scene_options.cpp), so Python and the command line refuse
// the same values with the same message; the whole-number options are read as CLI11 reads them
// (cli/options.cpp, whole_number) and refused with the message it gives.
#include <algorithm>
#include <cmath>

#include "bindings.hpp"
#include "options/option_ranges.hpp"
#include "springlab/error.hpp"
#include "util/data_dir.hpp"

namespace springlab::python {

namespace {

// A number as typed: Python's repr reads back to the same double ("0.1", "1e-05").
std::string text_of(const py::handle& value) {
  if (py::isinstance<py::str>(value)) return value.cast<std::string>();
  if (py::isinstance<py::bool_>(value)) throw py::type_error("expected a number, got a bool");
  return py::repr(value).cast<std::string>();
}

// --steps, --iterations, --threads: a whole number written any way, within the range.
std::int64_t whole(const char* flag, const py::handle& value, app::WholeRange range) {
  std::string text = text_of(value);
  const std::string error = app::parse_whole_number(text, range.lo, range.hi);
  if (!error.empty()) throw InputError(std::string(flag) + ": " + error);
  return std::stoll(text);
}

}  // namespace

std::vector<std::string> set_overrides(const py::handle& set) {
  std::vector<std::string> out;
  if (set.is_none()) return out;
  if (py::isinstance<py::str>(set)) return {set.cast<std::string>()};
  if (py::isinstance<py::dict>(set)) {
    const py::object dumps = py::module_::import("json").attr("dumps");
    for (const auto& [key, value] : set.cast<py::dict>()) {
      const std::string text = py::isinstance<py::str>(value) ? value.cast<std::string>()
                                                              : dumps(value).cast<std::string>();
      out.push_back(py::str(key).cast<std::string>() + "=" + text);
    }
    return out;
  }
  for (const py::handle item : set) out.push_back(item.cast<std::string>());
  return out;
}

app::SimOptions sim_options(const py::kwargs& kw, std::vector<std::string>& known) {
  app::SimOptions o;
  // Each option: its keyword, read when given and not None.
  auto given = [&](const char* name) -> py::object {
    known.emplace_back(name);
    if (!kw.contains(name)) return py::none();
    return kw[name];
  };
  if (auto v = given("method"); !v.is_none()) o.method = v.cast<std::string>();
  if (auto v = given("dt"); !v.is_none()) o.dt = v.cast<double>();
  if (auto v = given("substeps"); !v.is_none()) o.substeps = text_of(v);
  if (auto v = given("steps"); !v.is_none()) o.steps = whole("--steps", v, app::kSteps);
  if (auto v = given("duration"); !v.is_none()) o.duration = v.cast<double>();
  if (auto v = given("ks"); !v.is_none()) o.ks = v.cast<double>();
  if (auto v = given("kd"); !v.is_none()) o.kd = v.cast<double>();
  if (auto v = given("tol"); !v.is_none()) o.tol = v.cast<double>();
  if (auto v = given("iterations"); !v.is_none())
    o.iterations = static_cast<int>(whole("--iterations", v, app::kIterations));
  if (auto v = given("rho"); !v.is_none()) o.rho = v.cast<double>();
  if (auto v = given("set"); !v.is_none()) o.sets = set_overrides(v);
  if (auto v = given("threads"); !v.is_none())
    o.threads = static_cast<int>(whole("--threads", v, app::kThreads));
  return o;
}

void refuse_unknown(const char* function, const py::kwargs& kw,
                    const std::vector<std::string>& known) {
  for (const auto& [key, value] : kw) {
    const std::string name = py::str(key).cast<std::string>();
    if (std::find(known.begin(), known.end(), name) == known.end())
      throw py::type_error(std::string(function) + "() got an unexpected keyword argument '" +
                           name + "'");
  }
}

Method method_named(const std::string& name) {
  return app::resolve_method(name);
}

}  // namespace springlab::python
