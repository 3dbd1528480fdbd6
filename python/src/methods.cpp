// The method table (springlab/methods.hpp) as Python sees it: one MethodInfo a row, the built-in
// rows and those made from tableaux (a shipped tableau or a file, once used as a method), with
// each Runge-Kutta or implicit row's Butcher tableau and stability function.
#include "springlab/methods.hpp"

#include <pybind11/complex.h>

#include <cmath>

#include "bindings.hpp"
#include "springlab/butcher.hpp"
#include "springlab/stability.hpp"

namespace springlab::python {

namespace {

py::array_t<double> array_of(const std::vector<double>& values) {
  return py::array_t<double>(static_cast<py::ssize_t>(values.size()), values.data());
}

std::vector<std::vector<std::string>> texts(const std::vector<std::vector<TableauEntry>>& rows) {
  std::vector<std::vector<std::string>> out;
  for (const auto& row : rows) {
    out.emplace_back();
    for (const TableauEntry& e : row) out.back().push_back(e.text);
  }
  return out;
}
std::vector<std::string> texts(const std::vector<TableauEntry>& row) {
  std::vector<std::string> out;
  out.reserve(row.size());
  for (const TableauEntry& e : row) out.push_back(e.text);
  return out;
}

// The tableau classes: a row's Tableau (doubles) and a ButcherTableau as read (its entries' text).
void bind_tableaux(py::module_& m) {
  // Rows live for the whole process (the table is never shrunk): returned by reference.
  py::class_<Tableau>(m, "Tableau", "a Runge-Kutta method's Butcher tableau, in doubles")
      .def_readonly("stages", &Tableau::stages)
      .def_property_readonly(
          "a",
          [](const Tableau& t) {
            py::array_t<double> a({t.stages, t.stages});
            auto out = a.mutable_unchecked<2>();
            for (int i = 0; i < t.stages; ++i)
              for (int j = 0; j < t.stages; ++j) out(i, j) = t.A(i, j);
            return a;
          },
          "stages x stages")
      .def_property_readonly("b", [](const Tableau& t) { return array_of(t.b); })
      .def_property_readonly(
          "c",
          [](const Tableau& t) {
            std::vector<double> c(static_cast<std::size_t>(t.stages), 0.0);
            for (int i = 0; i < t.stages; ++i)
              for (int j = 0; j < t.stages; ++j) c[static_cast<std::size_t>(i)] += t.A(i, j);
            return array_of(c);
          },
          "the nodes, as the row sums of a")
      .def_property_readonly(
          "numerator", [](const Tableau& t) { return array_of(t.numerator); },
          "R(z) = P(z) / Q(z): P's coefficients from z^0 up")
      .def_property_readonly(
          "denominator", [](const Tableau& t) { return array_of(t.denominator); },
          "Q's coefficients from z^0 up")
      .def_property_readonly(
          "error_weights", [](const Tableau& t) { return array_of(t.error_weights); },
          "an embedded pair's b - b_hat (empty otherwise)")
      .def_property_readonly("explicit", &Tableau::is_explicit)
      .def_property_readonly("first_same_as_last", &Tableau::first_same_as_last)
      .def("stability_function", &Tableau::stability_function, py::arg("z"),
           "R(z), the factor a step multiplies y' = lambda y by, z = h lambda");

  py::class_<ButcherTableau>(m, "ButcherTableau",
                             "a tableau read as data (assets/tableaux), its entries as written")
      .def_readonly("name", &ButcherTableau::name)
      .def_readonly("description", &ButcherTableau::description)
      .def_readonly("stages", &ButcherTableau::stages)
      .def_property_readonly("a", [](const ButcherTableau& t) { return texts(t.a); })
      .def_property_readonly("b", [](const ButcherTableau& t) { return texts(t.b); })
      .def_property_readonly("c", [](const ButcherTableau& t) { return texts(t.c); })
      .def_readonly("stated_order", &ButcherTableau::stated_order);
}

// MethodInfo: a row of the method table, read-only.
void bind_method_info(py::module_& m) {
  py::class_<MethodInfo>(m, "MethodInfo", "a row of the method table (springlab/methods.hpp)")
      .def_property_readonly("id", [](const MethodInfo& r) { return static_cast<int>(r.id); })
      .def_readonly("name", &MethodInfo::name, "as typed on the command line")
      .def_readonly("label", &MethodInfo::label, "as shown to people")
      .def_readonly("order", &MethodInfo::order, "global order of accuracy in positions")
      .def_readonly("evaluations", &MethodInfo::evaluations, "force evaluations per step, in words")
      .def_readonly(
          "undamped_limit", &MethodInfo::undamped_limit,
          "largest stable h w on the undamped oscillator: 0 never, inf always, nan adaptive")
      .def_readonly("stability", &MethodInfo::stability, "why, in one line")
      .def_readonly("family", &MethodInfo::family)
      .def_property_readonly(
          "tableau", [](const MethodInfo& r) { return r.tableau; },
          py::return_value_policy::reference,
          "the Butcher tableau of a Runge-Kutta or implicit row, else None")
      .def_property_readonly(
          "source", [](const MethodInfo& r) { return tableau_source(r.id); },
          py::return_value_policy::reference,
          "the tableau file a row was made from, else None (a built-in row)")
      .def_property_readonly(
          "closed_form_limit", [](const MethodInfo& r) { return r.mode_limit != nullptr; },
          "whether one damped mode's limit has a closed form")
      .def(
          "definite_form",
          [](const MethodInfo& r, double verlet_damping) -> py::object {
            if (!r.definite) return py::none();
            const DefiniteForm f = r.definite({.verlet_damping = verlet_damping});
            return py::make_tuple(f.a, f.b, f.c);
          },
          py::arg("verlet_damping") = 0.0,
          "(a, b, c): stable exactly while a h^2 K + b h C <= c I, for the rows that have one, "
          "else None")
      .def_readonly("audited", &MethodInfo::audited, "whether the energy audit watches it")
      .def_property_readonly(
          "built_in",
          [](const MethodInfo& r) {
            return static_cast<std::size_t>(r.id) < built_in_methods().size();
          },
          "whether the row is compiled in; else made this run (a tableau, a step of one's own)")
      .def_property_readonly("adaptive", &MethodInfo::adaptive)
      .def_property_readonly("implicit", &MethodInfo::implicit)
      .def_property_readonly("any_step", &MethodInfo::any_step, "stable at any step")
      .def_property_readonly("damping_helps", &MethodInfo::damping_helps,
                             "never stable without damping")
      .def_property_readonly(
          "keeps", [](const MethodInfo& r) { return kept_summary(r); },
          "what it keeps on a free body: \"P\", \"P, L\", \"P to the solver's tolerance\", "
          "\"neither\" "
          "(P the momentum, L the angular momentum; springlab/momentum.hpp)")
      .def("__repr__", [](const MethodInfo& r) {
        return std::string("<springlab.MethodInfo '") + r.name + "'>";
      });
}

}  // namespace

void bind_methods(py::module_& m) {
  py::enum_<MethodFamily>(m, "MethodFamily",
                          "how a method steps, which decides how its stability is found")
      .value("RUNGE_KUTTA", MethodFamily::RungeKutta)
      .value("PARTITIONED", MethodFamily::Partitioned)
      .value("IMPLICIT", MethodFamily::Implicit)
      .value("ADAPTIVE", MethodFamily::Adaptive)
      .value("ITERATIVE", MethodFamily::Iterative);

  bind_tableaux(m);
  bind_method_info(m);

  m.def(
      "methods",
      [](bool built_in) {
        std::vector<const MethodInfo*> rows;
        for (const MethodInfo& r : built_in ? springlab::built_in_methods() : springlab::methods())
          rows.push_back(&r);
        return rows;
      },
      py::return_value_policy::reference, py::arg("built_in") = false,
      "the method table's rows: the built-in ones, then those made from tableaux so far "
      "(built_in=True: the built-in "
      "ones only; each row's .built_in says which it is)");
  m.def(
      "method", [](const std::string& name) { return &method_info(method_named(name)); },
      py::return_value_policy::reference, py::arg("name"),
      R"(A method's row by name, as --method takes it: a built-in method, a shipped tableau ("heun")
or a tableau's JSON file (which adds its row to the table). Unknown: springlab.InputError.)");
  m.def(
      "mode_limit",
      [](const std::string& method, double gamma, double kappa, double verlet_damping) {
        return mode_limit(method_named(method), gamma, kappa, {.verlet_damping = verlet_damping});
      },
      py::arg("method"), py::arg("gamma"), py::arg("kappa"), py::arg("verlet_damping") = 0.0,
      "the largest stable h on one damped mode x'' = -kappa x - gamma x' (0 never, inf always, nan "
      "adaptive)");
}

}  // namespace springlab::python
