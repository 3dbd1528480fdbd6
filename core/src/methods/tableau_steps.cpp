// The steps of the rows made from tableaux (add_tableau_method, springlab/butcher.hpp), on
// y = (x, v), y' = F(y) = (v, a(x, v)):
//
//   stage i:  Y_i = y + h sum_{j < i} a_ij K_j + h a_ii K_i,   K_i = F(Y_i)
//   result:   y1 = y + h sum_i b_i K_i
//
// Explicit (a_ii = 0 for all i): as RK4, stage after stage (runge_kutta.hpp). With an embedded
// b_hat: adaptive, under the controller rk45 uses (adaptive.hpp, embedded_pair_step), its error
// estimate h sum (b_i - b_hat_i) K_i and its exponent 1 / (q + 1), q the lower order of the two.
//
// Diagonally implicit: with (x~, v~) = y + h sum_{j < i} a_ij K_j and g = a_ii h, the stage
// (X, V) = Y_i solves
//   X = x~ + g V,   V = v~ + g a(X, V),
// which is exactly one backward-Euler step of size g from (x~, v~), solved to convergence
// (stage_newton.hpp: Baraff and Witkin's linearised step, conjugate gradients to 1e-10, as the
// first guess, then Newton's corrections with the true Jacobian, factorised, until M (V - v~) =
// g f(X, V) to 1e-12 of g times the forces). Then
// K_i = (V, (V - v~) / g), the acceleration the solve satisfied, with no further force
// evaluation. On a linear system (a spring along its own axis, or rest length zero) the
// linearised step is already converged; on a nonlinear one (a swinging rope) a stage linearised
// once would be a Rosenbrock-type method, not the tableau's (the trapezoidal rule put 0.3 J into
// the damped spring over 80 s at h w = 100): the corrections make it the tableau's. A stage
// whose Newton iteration does not converge fails the step as unsolved (SolveFailure), naming the
// stage. A stage with a_ii = 0 is explicit.
// Pinned particles move with their velocity in every stage, so x1 = x + h v for them.
#include "tableau_steps.hpp"

#include <algorithm>
#include <string>

#include "adaptive.hpp"
#include "runge_kutta.hpp"
#include "stage_newton.hpp"
#include "steps.hpp"

namespace springlab::steps {

void explicit_tableau(const Tableau& tableau, const Model& model, const State& in, State& out,
                      double h, const StepSettings&, Workspace& ws) {
  rk::stages(model, in.x, in.v, h, tableau, ws);
  rk::combine(in.x, in.v, h, tableau.b, scratch(ws), out.x, out.v);
  out.t = in.t + h;
}

void embedded_pair(const Tableau& tableau, const Model& model, const State& in, State& out,
                   double h, const StepSettings& settings, Workspace& ws) {
  adaptive::embedded_pair_step(tableau, tableau.error_weights.data(), tableau.error_exponent,
                               "the embedded pair", model, in, out, h, settings, ws);
}

namespace {

// One step of the tableau, its stages each solved to convergence; throws SolveFailure naming the
// stage whose Newton iteration did not converge.
void dirk_stages(const Tableau& tableau, const Model& model, const State& in, State& out, double h,
                 const StepSettings& settings, Workspace& ws) {
  // The stages' solves to kStageTolerance at most: at implicit Euler's 1e-5 their error put a
  // floor of about 1e-5 under the spring's error, which a third-order method reaches within
  // `compare`'s steps (dt / 16 to 2 dt): SDIRK3's error stopped falling there (it rose from 8e-6
  // to 1.2e-5 as h went from 1.4e-3 to 5.2e-4), its order measured 1.71, and 2.99 at 1e-10.
  constexpr double kStageTolerance = 1e-10;
  StepSettings stage_settings = settings;
  stage_settings.solver_tolerance = std::min(settings.solver_tolerance, kStageTolerance);
  const int s = tableau.stages;
  if (!ws.stages) ws.stages = std::make_unique<StageSolvers>();
  StageSolvers& S = *ws.stages;
  if (S.solvers.size() < static_cast<std::size_t>(s)) S.solvers.resize(static_cast<std::size_t>(s));
  StepScratch& k = scratch(ws);  // K_i = (k.stage_dx[i], k.stage_dv[i])
  if (k.stage_dx.size() < static_cast<std::size_t>(s)) {
    k.stage_dx.resize(static_cast<std::size_t>(s));
    k.stage_dv.resize(static_cast<std::size_t>(s));
  }
  for (int i = 0; i < s; ++i) {
    S.in.x = in.x;
    S.in.v = in.v;
    S.in.t = in.t;
    for (int j = 0; j < i; ++j) {
      const double w = h * tableau.A(i, j);
      if (w == 0.0) continue;
      S.in.x += w * k.stage_dx[static_cast<std::size_t>(j)];
      S.in.v += w * k.stage_dv[static_cast<std::size_t>(j)];
    }
    const double g = h * tableau.A(i, i);
    if (g == 0.0) {
      k.stage_dx[static_cast<std::size_t>(i)] = S.in.v;
      accelerations(model, S.in.x, S.in.v, k.stage_dv[static_cast<std::size_t>(i)], ws);
      continue;
    }
    Workspace& solver = S.solvers[static_cast<std::size_t>(i)];
    try {
      backward_euler_converged(model, S.in, S.out, g, stage_settings, solver, S.newton);
    } catch (const StepFailure& e) {
      throw SolveFailure("stage " + std::to_string(i + 1) + " of the tableau: " + e.what());
    }
    k.stage_dx[static_cast<std::size_t>(i)] = S.out.v;
    k.stage_dv[static_cast<std::size_t>(i)] = (S.out.v - S.in.v) / g;
    // The stage's work counts as the step's.
    Counters& c = solver.counters;
    ws.counters.force_evals += c.force_evals;
    ws.counters.linear_solves += c.linear_solves;
    ws.counters.solver_iterations += c.solver_iterations;
    ws.counters.unconverged_solves += c.unconverged_solves;
    ws.counters.newton_corrections += c.newton_corrections;
    c = Counters{};
  }
  rk::combine(in.x, in.v, h, tableau.b, k, out.x, out.v);
  out.t = in.t + h;
}

// A step whose stages were not solved at h is taken as two of h / 2, and so on down to h / 16:
// the same method over the same interval, as implicit integrators reject a step whose Newton
// iteration fails (counted: Counters::halved_steps). Where even h / 16 is not solved, it fails.
constexpr int kMaxStepHalvings = 4;

void dirk_halving(const Tableau& tableau, const Model& model, const State& in, State& out, double h,
                  const StepSettings& settings, Workspace& ws, int depth) {
  try {
    dirk_stages(tableau, model, in, out, h, settings, ws);
  } catch (const SolveFailure&) {
    if (depth == kMaxStepHalvings) throw;
    ++ws.counters.halved_steps;
    State mid;
    dirk_halving(tableau, model, in, mid, 0.5 * h, settings, ws, depth + 1);
    dirk_halving(tableau, model, mid, out, 0.5 * h, settings, ws, depth + 1);
    out.t = in.t + h;
  }
}

}  // namespace

void diagonally_implicit(const Tableau& tableau, const Model& model, const State& in, State& out,
                         double h, const StepSettings& settings, Workspace& ws) {
  dirk_halving(tableau, model, in, out, h, settings, ws, 0);
}

}  // namespace springlab::steps
