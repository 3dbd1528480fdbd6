#include "springlab/methods.hpp"

#include <cmath>
#include <limits>

#include "methods/steps.hpp"

namespace springlab {

namespace {

constexpr double kNever = 0.0;
constexpr double kAlways = std::numeric_limits<double>::infinity();
constexpr double kControlled = std::numeric_limits<double>::quiet_NaN();

// The one table. Stability limits are on the undamped oscillator (docs/numerics.md, "The undamped oscillator"); with damping the
// limit is computed by stability.cpp from each method's own step.
const MethodInfo kMethods[] = {
    {Method::Euler, "euler", "Explicit Euler", 1, "1", kNever,
     "explicit Euler gains energy at any step without damping (growth sqrt(1 + (h w)^2) a step)",
     false, false, steps::euler},
    {Method::SymplecticEuler, "symplectic-euler", "Symplectic Euler", 1, "1", 2.0,
     "symplectic Euler is stable for h w < 2; its energy oscillates but does not drift", false,
     false, steps::symplectic_euler},
    {Method::Midpoint, "midpoint", "Midpoint", 2, "2", kNever,
     "midpoint gains energy at any step without damping, slowly: sqrt(1 + (h w)^4 / 4) a step",
     false, false, steps::midpoint},
    {Method::ModifiedEuler, "modified-euler", "Modified Euler", 1, "1", kNever,
     "modified Euler gains energy at any step without damping (growth sqrt(1 + (h w)^2 / 2))",
     false, false, steps::modified_euler},
    {Method::RK4, "rk4", "RK4", 4, "4", 2.0 * std::sqrt(2.0),
     "RK4 is stable for h w <= 2 sqrt(2) = 2.83, slightly dissipative below it", false, false,
     steps::rk4},
    {Method::AdaptiveEuler, "adaptive-euler", "Adaptive Euler", 1,
     "2 per accepted step (a rejected try needs none)", kControlled,
     "adaptive Euler controls each step's error, not its energy: undamped, it still gains energy",
     true, false, steps::adaptive_euler},
    {Method::RK45, "rk45", "RK45 (Dormand-Prince)", 5, "6 per accepted step (first same as last)",
     kControlled, "RK45 chooses its own steps to meet the tolerance; stiff scenes make them tiny",
     true, false, steps::rk45},
    {Method::ImplicitEuler, "implicit-euler", "Implicit Euler", 1, "1 + a linear solve", kAlways,
     "implicit Euler is stable at any step; it damps: amplification 1 / sqrt(1 + (h w)^2)", false,
     true, steps::implicit_euler},
    {Method::Verlet, "verlet", "Verlet", 2, "1", 2.0,
     "Verlet is stable for h w < 2; its energy oscillates but does not drift", false, false,
     steps::verlet},
};

}  // namespace

std::span<const MethodInfo> methods() { return kMethods; }

const MethodInfo& method_info(Method method) { return kMethods[static_cast<int>(method)]; }

std::optional<Method> find_method(std::string_view name) {
  for (const MethodInfo& m : kMethods)
    if (name == m.name) return m.id;
  return std::nullopt;
}

std::string method_names() {
  std::string names;
  for (const MethodInfo& m : kMethods) names += (names.empty() ? "" : ", ") + std::string(m.name);
  return names;
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
  info.step(model, in, out, h, settings, ws);
  if (!info.adaptive) ++ws.counters.accepted;
}

}  // namespace springlab
