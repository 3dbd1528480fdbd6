// springlab tableau [NAME|FILE...]: a Butcher tableau checked exactly (springlab/butcher.hpp):
// its order from the order conditions, the first that fails, R(z) and its limits on the axes.
// With no argument, the shipped tableaux (assets/tableaux) in one table.
#include <cmath>
#include <cstdio>
#include <memory>

#include "cli/commands.hpp"
#include "springlab/butcher.hpp"
#include "util/data_dir.hpp"
#include "util/text_table.hpp"

namespace springlab::app {

namespace {

std::string kind(const ButcherTableau& t) {
  return (t.is_explicit() ? "explicit, " : "diagonally implicit, ") + std::to_string(t.stages) +
         (t.stages == 1 ? " stage" : " stages");
}

std::string order_text(const TableauAnalysis& a) {
  std::string s = std::to_string(a.order);
  if (a.order == TableauAnalysis::kMaxOrder) s = "at least " + s;
  return s;
}

void report(const std::string& name, const ButcherTableau& t, const TableauAnalysis& a) {
  std::printf("tableau     %s (%s): %s\n", t.name.empty() ? name.c_str() : t.name.c_str(),
              name.c_str(), kind(t).c_str());
  std::printf(
      "order       %s, exactly: every condition up to it holds (%d conditions, orders 1 to %d)\n",
      order_text(a).c_str(), a.conditions, TableauAnalysis::kMaxOrder);
  if (a.first_failure) {
    const OrderCondition& f = *a.first_failure;
    std::printf("fails       order %d, tree %s: %s = %s, but the tableau gives %s\n", f.order,
                f.tree.c_str(), f.formula.c_str(), f.rhs.c_str(), f.lhs.c_str());
  }
  if (a.order_to_rounding > a.order)
    std::printf(
        "rounding    order %d when each condition need only hold to 1e-10 (entries rounded from "
        "irrational values)\n",
        a.order_to_rounding);
  if (a.embedded_order)
    std::printf(
        "embedded    b_hat: order %d%s\n", *a.embedded_order,
        t.is_explicit() ? "; as a method it chooses its own steps (--tol), as rk45 does" : "");
  std::printf("R(z)        %s\n", stability_function_text(a).c_str());
  if (std::isinf(a.real_limit))
    std::printf("real axis   |R| <= 1 on the whole negative real axis\n");
  else if (a.real_limit == 0.0)
    std::printf("real axis   |R| > 1 just left of 0: a decaying mode grows at any step\n");
  else
    std::printf("real axis   |R| <= 1 on [-%s, 0]\n", axis_limit_text(a.real_limit).c_str());
  if (std::isinf(a.imaginary_limit))
    std::printf("imag axis   |R| <= 1 on the whole imaginary axis\n");
  else if (a.imaginary_limit == 0.0)
    std::printf(
        "imag axis   |R| > 1 everywhere on it but 0: an undamped oscillation grows at any step\n");
  else
    std::printf("imag axis   |R| <= 1 on [-%s i, %s i]\n",
                axis_limit_text(a.imaginary_limit).c_str(),
                axis_limit_text(a.imaginary_limit).c_str());
  if (a.rounded_limits)
    std::printf(
        "limits      exact roots of |R|^2 - 1 for the tableau the entries round (coefficients that "
        "cancel to\n"
        "            1e-12 of their terms, and on the imaginary axis those up to y^%d, which order "
        "%d makes 0, taken as 0)\n",
        a.order_to_rounding, a.order_to_rounding);
  if (std::isinf(a.r_at_infinity))
    std::printf(
        "infinity    |R| grows without bound (explicit: a stiff mode needs a small step)\n");
  else
    std::printf(
        "infinity    |R| -> %.6g%s\n", a.r_at_infinity,
        a.r_at_infinity == 0.0 ? " (L-stable if A-stable: stiff modes are damped out)" : "");
  for (const std::string& w : a.warnings) std::printf("warning     %s\n", w.c_str());
}

int table() {
  std::vector<std::vector<std::string>> rows = {
      {"name", "tableau", "kind", "order", "embedded", "real axis", "imaginary axis"}};
  for (const std::string& name : shipped_tableaux()) {
    const ButcherTableau t = load_tableau_file(resolve_tableau(name));
    const TableauAnalysis a = analyse_tableau(t);
    std::string order = std::to_string(a.order);
    if (a.order_to_rounding > a.order) order += " (" + std::to_string(a.order_to_rounding) + ")";
    rows.push_back({name, t.name, kind(t), order,
                    a.embedded_order ? std::to_string(*a.embedded_order) : "-",
                    axis_limit_text(a.real_limit), axis_limit_text(a.imaginary_limit)});
  }
  std::fputs(text_table(rows).c_str(), stdout);
  std::printf(
      "(order in brackets: to rounding, for entries written as decimals of irrational values)\n");
  return kOk;
}

}  // namespace

Command add_tableau_command(CLI::App& app) {
  auto names = std::make_shared<std::vector<std::string>>();
  CLI::App* c = app.add_subcommand(
      "tableau", "a Butcher tableau checked exactly: its order, R(z) and its limits");
  c->add_option("tableaux", *names,
                "shipped tableau names or JSON files (default: a table of the shipped ones)");
  return [names] {
    if (names->empty()) return table();
    for (std::size_t k = 0; k < names->size(); ++k) {
      const std::string& name = (*names)[k];
      const ButcherTableau t = load_tableau_file(resolve_tableau(name));
      if (k) std::printf("\n");
      report(name, t, analyse_tableau(t));
    }
    return static_cast<int>(kOk);
  };
}

}  // namespace springlab::app
