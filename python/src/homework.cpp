// Homework 8 in Python: a step of one's own, fn(x, v, force, h) -> (x, v), as a Simulation's
// method (simulation.cpp) and checked by the core's homework checker (springlab/homework.hpp):
// springlab.homework.check(fn) (python/springlab/homework.py) says which of springlab's rows it
// is, and measures its order, stability and energy on a spring against that row's.
#include <memory>
#include <stdexcept>

#include "own_step.hpp"
#include "springlab/error.hpp"
#include "springlab/text.hpp"
#include "util/language.hpp"

namespace springlab::python {

namespace {

using Rows = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>;

Rows as_rows(const Points& p) {
  return Rows(p);
}

Rows result_array(const py::handle& value, const char* what, int n, const std::string& name) {
  Rows a;
  try {
    a = value.cast<Rows>();
  } catch (const py::cast_error&) {
    throw py::value_error(name + " must return (x, v): its " + what +
                          " is not an array of numbers of shape (" + std::to_string(n) + ", 3)");
  }
  if (a.rows() != n)
    throw py::value_error(name + " must return (x, v) of shape (" + std::to_string(n) +
                          ", 3): its " + what + " has " + std::to_string(a.rows()) + " rows");
  return a;
}

}  // namespace

std::string step_name(const py::object& fn) {
  return py::hasattr(fn, "__name__") ? fn.attr("__name__").cast<std::string>() : std::string("fn");
}

namespace {

// Whether a result is a NumPy array of float32 (or narrower), whose numbers are float's.
bool single(const py::handle& value) {
  if (!py::isinstance<py::array>(value)) return false;
  const py::dtype type = py::reinterpret_borrow<py::array>(value).dtype();
  return type.kind() == 'f' && type.itemsize() <= 4;
}

}  // namespace

homework::OwnStep python_step(const py::object& fn, const std::string& name,
                              const std::shared_ptr<bool>& single_precision) {
  // The function lives as long as any copy of the step; it is let go of with the interpreter's
  // lock held, whichever thread drops the last copy.
  std::shared_ptr<py::object> held(new py::object(fn), [](py::object* o) {
    py::gil_scoped_acquire gil;
    delete o;
  });
  return [held, name, single_precision](const Model& model, const State& in, State& out, double h,
                                        Workspace& ws) {
    py::gil_scoped_acquire gil;
    const int n = in.particle_count();
    // force() reads this step's model and workspace: called after the step, it says so.
    auto live = std::make_shared<bool>(true);
    py::cpp_function force(
        [&model, &ws, live, n](const Rows& x, const Rows& v) {
          if (!*live)
            throw std::runtime_error("force(x, v) works only within the step it was given to");
          if (x.rows() != n || v.rows() != n)
            throw py::value_error("force(x, v) takes arrays of shape (" + std::to_string(n) +
                                  ", 3)");
          Points px(x), pv(v), a;
          accelerations(model, px, pv, a, ws);
          return as_rows(a);
        },
        py::arg("x"), py::arg("v"));
    struct Expire {
      std::shared_ptr<bool> live;
      ~Expire() { *live = false; }
    } expire{live};
    const py::object result = (*held)(as_rows(in.x), as_rows(in.v), force, h);
    if (!py::isinstance<py::tuple>(result) && !py::isinstance<py::list>(result))
      throw py::value_error(name + " must return (x, v), a pair of arrays of shape (" +
                            std::to_string(n) + ", 3)");
    const py::sequence pair = result.cast<py::sequence>();
    if (pair.size() != 2)
      throw py::value_error(name + " must return (x, v): it returned " +
                            std::to_string(pair.size()) + " values");
    out.x = result_array(pair[0], "x", n, name);
    out.v = result_array(pair[1], "v", n, name);
    if (single_precision) *single_precision = single(pair[0]) || single(pair[1]);
    out.t = in.t + h;
  };
}

namespace {

// The language springlab writes its words in (the homework report): set_language, language,
// languages; at import the environment's, as the app takes it.
void bind_languages(py::module_& m) {
  m.def(
      "set_language",
      [](const std::string& tag) {
        return app::use_language(app::check_language(tag, "set_language"), false);
      },
      py::arg("tag"),
      "the language of what springlab writes in words (the homework report): \"en\", \"zh-CN\", or "
      "any form the "
      "environment uses (\"zh_CN.UTF-8\"); returns the one used. At import it is the environment's "
      "(LANGUAGE, LC_ALL, "
      "LC_MESSAGES, LANG), as the app's.");
  m.def("language", &current_language, "the language springlab writes in: \"en\", \"zh-CN\"");
  m.def(
      "languages",
      [] {
        std::vector<std::string> tags;
        for (const app::Language& l : app::languages()) tags.push_back(l.tag);
        return tags;
      },
      "the languages springlab speaks");
  // The environment's, as the app takes it; a catalog that cannot be read leaves English.
  try {
    app::use_language(app::environment_language(), false);
  } catch (const InputError&) {
  }
}

// HomeworkReport: what springlab.homework.check found, as text and line by line, its counts and
// the row of the table the step is.
void bind_homework_report(py::module_& m) {
  py::class_<homework::Report>(m, "HomeworkReport",
                               "what springlab.homework.check found, line by line")
      .def_property_readonly(
          "text", [](const homework::Report& r) { return homework::format_report(r); },
          "the report as `springlab homework check` prints one")
      .def_property_readonly("passed", &homework::Report::passed, "checks passed")
      .def_property_readonly("failed", &homework::Report::failed, "checks failed")
      .def_property_readonly(
          "method",
          [](const homework::Report& r) -> py::object {
            if (r.euler.method.empty()) return py::none();
            return py::str(r.euler.method);
          },
          "the row of springlab's table the step is (\"euler\", \"rk4\", ...), or None")
      .def_property_readonly(
          "failed_keys", &homework::Report::failed_keys,
          "what each failed line is about, the same in every language (\"forces-kept\", ...)")
      .def_property_readonly(
          "lines",
          [](const homework::Report& r) {
            py::list lines;
            for (const homework::CheckSection& s : r.sections)
              for (const homework::CheckLine& l : s.lines)
                lines.append(py::make_tuple(l.kind == homework::CheckLine::Pass   ? "ok"
                                            : l.kind == homework::CheckLine::Fail ? "fail"
                                                                                  : "note",
                                            l.text));
            return lines;
          },
          "(\"ok\" | \"fail\" | \"note\", text) for each line")
      .def("__str__", [](const homework::Report& r) { return homework::format_report(r); })
      .def("__repr__", [](const homework::Report& r) {
        return "<springlab.HomeworkReport " + std::to_string(r.passed()) + " passed, " +
               std::to_string(r.failed()) + " failed>";
      });
}

}  // namespace

void bind_homework(py::module_& m) {
  bind_languages(m);
  bind_homework_report(m);

  m.def(
      "_homework_check",
      [](const py::object& fn, const std::string& name) {
        if (!PyCallable_Check(fn.ptr()))
          throw py::type_error("check(fn): fn must be a function fn(x, v, force, h) -> (x, v)");
        auto in_float = std::make_shared<bool>(false);
        const homework::OwnStep step = python_step(fn, name, in_float);
        int calls = 0;
        // An exception in fn ends the check's lines where it happened, said as the checker says
        // a crash in C++ code; Ctrl-C still stops it.
        const homework::OwnStep checked = [&](const Model& model, const State& in, State& out,
                                              double h, Workspace& ws) {
          ++calls;
          try {
            step(model, in, out, h, ws);
          } catch (py::error_already_set& e) {
            if (e.matches(PyExc_KeyboardInterrupt)) throw;
            // The exception's type and message, without the traceback what() appends.
            const std::string type = py::str(e.type().attr("__name__")),
                              message = py::str(e.value());
            throw homework::CodeFailure(
                name + " raised " + type + (message.empty() ? "" : ": " + message) +
                " on its call " + std::to_string(calls) + " (h = " + homework::step_text(h) + ")");
          } catch (const py::builtin_exception& e) {
            throw homework::CodeFailure(std::string(e.what()) + " (its call " +
                                        std::to_string(calls) + ")");
          }
        };
        return homework::check_step(checked, name, in_float.get());
      },
      py::arg("fn"), py::arg("name"));
}

}  // namespace springlab::python
