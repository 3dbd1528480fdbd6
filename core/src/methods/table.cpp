#include <algorithm>
#include <atomic>
#include <cmath>
#include <deque>
#include <iomanip>
#include <limits>
#include <mutex>
#include <sstream>

#include "methods/steps.hpp"
#include "springlab/error.hpp"
#include "springlab/methods.hpp"
#include "springlab/text.hpp"
#include "stability/mode_limits.hpp"

namespace springlab {

namespace {

constexpr double kNever = 0.0;
constexpr double kAlways = std::numeric_limits<double>::infinity();
constexpr double kControlled = std::numeric_limits<double>::quiet_NaN();

// The Runge-Kutta rows' tableaux (defined before the table that points at them).
const Tableau kEulerTableau({{0.0}}, {1.0});
const Tableau kMidpointTableau({{0.0}, {0.5}}, {0.0, 1.0});
const Tableau kRK4Tableau({{0.0}, {0.5}, {0.0, 0.5}, {0.0, 0.0, 1.0}},
                          {1.0 / 6.0, 1.0 / 3.0, 1.0 / 3.0, 1.0 / 6.0});
const Tableau kImplicitEulerTableau({{1.0}}, {1.0});

DefiniteForm symplectic_euler_form(const MethodParameters&) {
  return {1.0, 2.0, 4.0};
}
DefiniteForm verlet_form(const MethodParameters& parameters) {
  const double d = parameters.verlet_damping;
  return {1.0, 4.0 - d, 4.0 - 2.0 * d};
}

using F = MethodFamily;

// The one table. Stability limits are on the undamped oscillator (docs/numerics.md, "The
// undamped oscillator"); with damping the limit is computed by the stability analysis from what
// each row gives: its tableau's R(z), its closed form, its definite form.
// (How each row is shown, its colour and mark, is the app's: app/draw/row_styles.cpp.)
// constexpr: constant-initialised, so that the table (below) can copy it during other files'
// static initialisation (a test's list of methods) whatever the order the linker gives them.
constexpr MethodInfo kMethods[] = {
    {.id = Method::Euler,
     .name = "euler",
     .label = N_("Explicit Euler"),
     .order = 1,
     .evaluations = "1",
     .undamped_limit = kNever,
     .stability = N_("explicit Euler gains energy at any step without damping (growth sqrt(1 + (h "
                     "w)^2) a step)"),
     .family = F::RungeKutta,
     .step = steps::euler,
     .tableau = &kEulerTableau,
     .mode_limit = modes::euler,
     .audited = true,
     .compared_first = true},
    {.id = Method::SymplecticEuler,
     .name = "symplectic-euler",
     .label = N_("Symplectic Euler"),
     .order = 1,
     .evaluations = "1",
     .undamped_limit = 2.0,
     .stability =
         N_("symplectic Euler is stable for h w < 2; its energy oscillates but does not drift"),
     .family = F::Partitioned,
     .step = steps::symplectic_euler,
     .mode_limit = modes::symplectic_euler,
     .definite = symplectic_euler_form,
     .angular_momentum = Kept::Exactly,
     .compared_first = true},
    {.id = Method::Midpoint,
     .name = "midpoint",
     .label = N_("Midpoint"),
     .order = 2,
     .evaluations = "2",
     .undamped_limit = kNever,
     .stability = N_(
         "midpoint gains energy at any step without damping, slowly: sqrt(1 + (h w)^4 / 4) a step"),
     .family = F::RungeKutta,
     .tableau = &kMidpointTableau,
     .tableau_step = steps::explicit_tableau,
     .audited = true},
    {.id = Method::ModifiedEuler,
     .name = "modified-euler",
     .label = N_("Modified Euler"),
     .order = 1,
     .evaluations = "1",
     .undamped_limit = kNever,
     .stability = N_(
         "modified Euler gains energy at any step without damping (growth sqrt(1 + (h w)^2 / 2))"),
     .family = F::Partitioned,
     .step = steps::modified_euler,
     .mode_limit = modes::modified_euler,
     .audited = true},
    {.id = Method::RK4,
     .name = "rk4",
     .label = N_("RK4"),
     .order = 4,
     .evaluations = "4",
     .undamped_limit =
         2.8284271247461903,  // 2 sqrt(2) (a literal: std::sqrt is not constexpr in clang)
     .stability = N_("RK4 is stable for h w <= 2 sqrt(2) = 2.83, slightly dissipative below it"),
     .family = F::RungeKutta,
     .tableau = &kRK4Tableau,
     .tableau_step = steps::explicit_tableau,
     .audited = true,
     .compared_first = true},
    {.id = Method::AdaptiveEuler,
     .name = "adaptive-euler",
     .label = N_("Adaptive Euler"),
     .order = 1,
     .evaluations = "2 per accepted step (a rejected try needs none)",
     .undamped_limit = kControlled,
     .stability = N_("adaptive Euler controls each step's error, not its energy: undamped, it "
                     "still gains energy"),
     .family = F::Adaptive,
     .step = steps::adaptive_euler},
    {.id = Method::RK45,
     .name = "rk45",
     .label = N_("RK45 (Dormand-Prince)"),
     .order = 5,
     .evaluations = "6 per accepted step (first same as last)",
     .undamped_limit = kControlled,
     .stability =
         N_("RK45 chooses its own steps to meet the tolerance; stiff scenes make them tiny"),
     .family = F::Adaptive,
     .step = steps::rk45},
    {.id = Method::ImplicitEuler,
     .name = "implicit-euler",
     .label = N_("Implicit Euler"),
     .order = 1,
     .evaluations = "1 + a linear solve",
     .undamped_limit = kAlways,
     .stability =
         N_("implicit Euler is stable at any step; it damps: amplification 1 / sqrt(1 + (h w)^2)"),
     .family = F::Implicit,
     .step = steps::implicit_euler,
     .tableau = &kImplicitEulerTableau,
     .audited = true,
     .momentum = Kept::ToSolverTolerance,
     .compared_first = true},
    {.id = Method::Verlet,
     .name = "verlet",
     .label = N_("Verlet"),
     .order = 2,
     .evaluations = "1",
     .undamped_limit = 2.0,
     .stability = N_("Verlet is stable for h w < 2; its energy oscillates but does not drift"),
     .family = F::Partitioned,
     .step = steps::verlet,
     .mode_limit = modes::verlet,
     .definite = verlet_form,
     .angular_momentum = Kept::Exactly,
     .history = true},
    // The iterative rows solve implicit Euler's step approximately (methods/iterative.hpp): no
    // limit; their cost at a large step is damping and stretch, which the gauge shows instead.
    // Not audited: each step only lowers the step's objective, so they cannot create energy.
    {.id = Method::XPBD,
     .name = "xpbd",
     .label = N_("XPBD (small steps)"),
     .order = 1,
     .evaluations = "none: 1 pass over the springs as constraints, colour by colour (--iterations)",
     .undamped_limit = kAlways,
     .stability = N_("XPBD is bounded at any step; with few passes its springs act softer than "
                     "k_s, and their stretch can hold energy the physics never had"),
     .family = F::Iterative,
     .step = steps::xpbd,
     .default_iterations = 1,
     .iteration_unit = "passes over the springs"},
    {.id = Method::LocalGlobal,
     .name = "local-global",
     .label = N_("Local-global (projective)"),
     .order = 1,
     .evaluations =
         "none: 10 iterations (--iterations), each a pass over the springs and a prefactored solve",
     .undamped_limit = kAlways,
     .stability = N_("local-global is bounded at any step; each iteration moves it closer to the "
                     "converged backward-Euler step"),
     .family = F::Iterative,
     .step = steps::local_global,
     .default_iterations = 10,
     .iteration_unit = "local steps and global solves",
     .reads_rho = true},
    {.id = Method::VBD,
     .name = "vbd",
     .label = N_("Vertex block descent"),
     .order = 1,
     .evaluations = "none: 10 iterations (--iterations), each a 3x3 Newton step a vertex",
     .undamped_limit = kAlways,
     .stability = N_("vertex block descent is bounded at any step; converged it damps like "
                     "implicit Euler, while few iterations leave its springs soft, their stretch "
                     "holding energy the physics never had"),
     .family = F::Iterative,
     .step = steps::vbd,
     .momentum = Kept::No,
     .default_iterations = 10,
     .iteration_unit = "sweeps over the vertices"},
};

// Rows in the enum's order: a method's row is found by its id.
constexpr bool in_enum_order() {
  for (std::size_t i = 0; i < std::size(kMethods); ++i)
    if (static_cast<std::size_t>(kMethods[i].id) != i) return false;
  return true;
}
static_assert(in_enum_order(), "kMethods' rows must be in the order of enum Method");

// The table: the built-in rows, then the rows made from tableaux (add_tableau_method), in fixed
// storage so that a row, once counted, never moves while other threads (an analysis, a sweep)
// read it; `count` is published after the row is written.
constexpr std::size_t kMaxAdded = 32;
struct AddedRow {
  std::string name, label, evaluations, stability, iteration_unit;
  ButcherTableau source;
  Tableau tableau;
};
struct Table {
  std::array<MethodInfo, std::size(kMethods) + kMaxAdded> rows{};
  std::atomic<std::size_t> count{0};
  std::mutex adding;
  std::deque<AddedRow> added;  // (a deque: its elements stay put as it grows)
  Table() {
    std::copy(std::begin(kMethods), std::end(kMethods), rows.begin());
    count.store(std::size(kMethods), std::memory_order_release);
  }
};
Table& table() {
  static Table t;
  return t;
}

bool same_entries(const ButcherTableau& a, const ButcherTableau& b) {
  const auto texts = [](const std::vector<TableauEntry>& v) {
    std::vector<std::string> out;
    out.reserve(v.size());
    for (const TableauEntry& e : v) out.push_back(e.text);
    return out;
  };
  if (a.stages != b.stages || texts(a.b) != texts(b.b)) return false;
  for (int i = 0; i < a.stages; ++i)
    if (texts(a.a[static_cast<std::size_t>(i)]) != texts(b.a[static_cast<std::size_t>(i)]))
      return false;
  return true;
}

std::string limit_text(double limit, const char* unit) {
  std::ostringstream s;
  if (std::isinf(limit))
    s << "the whole " << unit << " axis";
  else
    s << std::setprecision(4) << limit;
  return s.str();
}

}  // namespace

std::span<const MethodInfo> methods() {
  const Table& t = table();
  return {t.rows.data(), t.count.load(std::memory_order_acquire)};
}

std::span<const MethodInfo> built_in_methods() {
  return methods().first(std::size(kMethods));
}

std::span<const MethodInfo> added_methods() {
  return methods().subspan(std::size(kMethods));
}

const MethodInfo& method_info(Method method) {
  return table().rows[static_cast<std::size_t>(method)];
}

std::optional<Method> find_method(std::string_view name) {
  for (const MethodInfo& m : methods())
    if (name == m.name) return m.id;
  return std::nullopt;
}

std::string method_names() {
  std::string names;
  for (const MethodInfo& m : built_in_methods())
    names += (names.empty() ? "" : ", ") + std::string(m.name);
  return names;
}

Method add_method(const MethodInfo& given) {
  Table& t = table();
  const std::lock_guard lock(t.adding);
  const std::string name = given.name ? given.name : "";
  if (name.empty() || !given.step || given.tableau_step)
    throw InputError("method '" + name +
                     "': an added row needs a name and a step function of its own");
  if (find_method(name))
    throw InputError("method '" + name + "': a row of the method table already has this name");
  const std::size_t index = t.count.load(std::memory_order_relaxed);
  if (index >= t.rows.size())
    throw InputError("method '" + name + "': at most " + std::to_string(kMaxAdded) +
                     " added methods in one run");
  AddedRow& row = t.added.emplace_back();
  const auto text = [](const char* s) { return std::string(s ? s : ""); };
  row.name = name;
  row.label = given.label ? given.label : name;
  row.evaluations = text(given.evaluations);
  row.stability = text(given.stability);
  row.iteration_unit = text(given.iteration_unit);
  MethodInfo info = given;
  info.id = static_cast<Method>(index);
  info.name = row.name.c_str();
  info.label = row.label.c_str();
  info.evaluations = row.evaluations.c_str();
  info.stability = row.stability.c_str();
  info.iteration_unit = given.iteration_unit ? row.iteration_unit.c_str() : nullptr;
  t.rows[index] = info;
  t.count.store(index + 1, std::memory_order_release);
  return info.id;
}

Method add_tableau_method(const ButcherTableau& tableau, const std::string& name) {
  Table& t = table();
  const std::lock_guard lock(t.adding);
  for (const AddedRow& row : t.added)
    if (row.name == name && row.source.stages > 0) {
      if (!same_entries(row.source, tableau))
        throw InputError(
            "method '" + name +
            "': another tableau already has this name; give this one another file name");
      return *find_method(name);
    }
  if (const std::optional<Method> taken = find_method(name))
    throw InputError("method '" + name + "': " +
                     (static_cast<std::size_t>(*taken) < std::size(kMethods)
                          ? "a built-in method"
                          : "a row added by the program") +
                     " has this name; give the tableau's file another name");
  const std::size_t index = t.count.load(std::memory_order_relaxed);
  if (index >= t.rows.size())
    throw InputError("method '" + name + "': at most " + std::to_string(kMaxAdded) +
                     " methods from tableaux in one run");
  const TableauAnalysis a = analyse_tableau(tableau);
  AddedRow& row = t.added.emplace_back();
  row.name = name;
  row.label = tableau.name.empty() ? name : tableau.name;
  row.source = tableau;
  row.tableau = tableau.numeric();
  row.tableau.set_stability_function(a.numerator_value, a.denominator_value);
  const bool explicit_stages = tableau.is_explicit();
  // An explicit pair is adaptive: it steps under its error estimate (a diagonally implicit one's
  // b_hat is checked but not used: its stages are not solved for a controller).
  const bool pair = explicit_stages && tableau.b_hat && a.embedded_order;
  if (pair) {
    for (int i = 0; i < tableau.stages; ++i)
      row.tableau.error_weights.push_back(tableau.b[static_cast<std::size_t>(i)].value -
                                          (*tableau.b_hat)[static_cast<std::size_t>(i)].value);
    row.tableau.error_exponent = 1.0 / (std::min(a.order_to_rounding, *a.embedded_order) + 1);
  }
  row.evaluations = pair ? std::to_string(tableau.stages) + " per try (" +
                               std::to_string(tableau.stages - row.tableau.first_same_as_last()) +
                               " once running, first same as last)"
                    : explicit_stages ? std::to_string(tableau.stages)
                                      : std::to_string(tableau.stages) +
                                            " stages, each solved as an implicit Euler step";
  row.stability = "from its tableau's R(z): |R| <= 1 on the real axis to " +
                  limit_text(a.real_limit, "real") + ", on the imaginary axis to " +
                  limit_text(a.imaginary_limit, "imaginary");
  MethodInfo info{};
  info.id = static_cast<Method>(index);
  info.name = row.name.c_str();
  info.label = row.label.c_str();
  info.order = a.order_to_rounding;
  info.evaluations = row.evaluations.c_str();
  info.undamped_limit = pair ? kControlled : a.imaginary_limit;
  info.stability = pair ? "chooses its own steps from its embedded error estimate (--tol)"
                        : row.stability.c_str();
  info.family = pair ? MethodFamily::Adaptive : MethodFamily::RungeKutta;
  info.tableau = &row.tableau;
  info.tableau_step = pair              ? steps::embedded_pair
                      : explicit_stages ? steps::explicit_tableau
                                        : steps::diagonally_implicit;
  info.audited = !pair;  // (as rk45: the adaptive rows are not audited)
  // An explicit tableau adds forces linearly: P to rounding; a diagonally implicit one's stages
  // are solved by Newton's method to a tolerance. L only where the tableau is symplectic.
  info.momentum = explicit_stages ? Kept::Exactly : Kept::ToSolverTolerance;
  info.angular_momentum = !a.symplectic     ? Kept::No
                          : explicit_stages ? Kept::Exactly
                                            : Kept::ToSolverTolerance;
  t.rows[index] = info;
  t.count.store(index + 1, std::memory_order_release);
  return info.id;
}

const char* kept_text(Kept kept) {
  switch (kept) {
    case Kept::Exactly:
      return N_("kept");
    case Kept::ToSolverTolerance:
      return N_("kept to the solver's tolerance");
    case Kept::No:
      return N_("not kept");
  }
  return "";
}

std::string kept_summary(const MethodInfo& m) {
  std::string out;
  for (const auto& [kept, name] :
       {std::pair{m.momentum, "P"}, std::pair{m.angular_momentum, "L"}}) {
    if (kept == Kept::No) continue;
    if (!out.empty()) out += ", ";
    out += name;
    if (kept == Kept::ToSolverTolerance) out += " to the solver's tolerance";
  }
  return out.empty() ? "neither" : out;
}

const ButcherTableau* tableau_source(Method method) {
  Table& t = table();
  const std::lock_guard lock(t.adding);
  const auto row = static_cast<std::size_t>(method);
  const std::size_t built_in = std::size(kMethods);
  if (row < built_in || row - built_in >= t.added.size()) return nullptr;
  const ButcherTableau& source = t.added[row - built_in].source;
  return source.stages > 0 ? &source : nullptr;  // (a row added with a step of its own has none)
}

void accelerations(const Model& model, const Points& x, const Points& v, Points& a, Workspace& ws) {
  evaluate_forces(model, x, v, a, ws.spring_forces, ForceOutput::Acceleration);
  ++ws.counters.force_evals;
}

void step(Method method, const Model& model, const State& in, State& out, double h,
          const StepSettings& settings, Workspace& ws) {
  const MethodInfo& info = method_info(method);
  ws.step_probe.reset();
  ws.input_power.reset();
  if (info.step)
    info.step(model, in, out, h, settings, ws);
  else
    info.tableau_step(*info.tableau, model, in, out, h, settings, ws);
  if (!info.adaptive()) ++ws.counters.accepted;
}

}  // namespace springlab
