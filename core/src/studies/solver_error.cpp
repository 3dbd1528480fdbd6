// The solver error of the iterative methods (solver_error.hpp).
#include "springlab/solver_error.hpp"

#include <algorithm>
#include <cmath>

#include "springlab/forces.hpp"
#include "springlab/text.hpp"

namespace springlab {

namespace {

// The RMS over the free particles of |a - b|.
double rms(const Model& model, const Points& a, const Points& b) {
  double sum = 0.0;
  int free = 0;
  for (int i = 0; i < model.particle_count(); ++i) {
    if (model.pinned(i)) continue;
    sum += (a.row(i) - b.row(i)).squaredNorm();
    ++free;
  }
  return free > 0 ? std::sqrt(sum / free) : 0.0;
}

State one_step(const Model& model, const State& state, double h, Method method,
               StepSettings settings) {
  Workspace ws;
  State out;
  step(method, model, state, out, h, settings, ws);
  return out;
}

// The largest |m (v1 - v) / h - f(x1, v1)| over the free particles, over the largest |f|.
double residual(const Model& model, const State& state, const State& out, double h) {
  Points f;
  SpringForces buffer;
  evaluate_forces(model, out.x, out.v, f, buffer, ForceOutput::Force);
  double worst = 0.0, scale = 0.0;
  for (int i = 0; i < model.particle_count(); ++i) {
    if (model.pinned(i)) continue;
    worst =
        std::max(worst, (model.mass[i] * (out.v.row(i) - state.v.row(i)) / h - f.row(i)).norm());
    scale = std::max(scale, f.row(i).norm());
  }
  return scale > 0.0 ? worst / scale : worst;
}

}  // namespace

SolverErrorStudy solver_error(const Model& model, const State& state, double h, int max_iterations,
                              const StepSettings& settings) {
  SolverErrorStudy study;
  study.h = h;
  // The converged step: VBD (which converges fastest of the three) until the residual stops
  // falling below 1e-10, at most 4096 iterations.
  StepSettings converged = settings;
  State reference;
  for (converged.iterations = 256; converged.iterations <= 4096; converged.iterations *= 2) {
    reference = one_step(model, state, h, Method::VBD, converged);
    study.residual = residual(model, state, reference, h);
    if (study.residual <= 1e-10) break;
  }
  study.motion = rms(model, reference.x, state.x);
  const double scale = study.motion > 0.0 ? study.motion : 1.0;
  // Every iterative row, then implicit Euler's conjugate gradients at the same iteration counts.
  std::vector<Method> rows;
  for (const MethodInfo& m : methods())
    if (m.family == MethodFamily::Iterative) rows.push_back(m.id);
  rows.push_back(Method::ImplicitEuler);
  for (Method m : rows) {
    SolverErrorCurve curve;
    curve.method = m;
    if (m == Method::ImplicitEuler) curve.note = N_(" (CG; linearised once: levels off)");
    for (int k = 1; k <= max_iterations; k *= 2) {
      StepSettings s = settings;
      if (m == Method::ImplicitEuler) {
        s.max_solver_iterations = k;
        s.solver_tolerance = 0.0;  // never stop early: exactly k iterations
      } else {
        s.iterations = k;
      }
      curve.iterations.push_back(k);
      curve.error.push_back(rms(model, one_step(model, state, h, m, s).x, reference.x) / scale);
    }
    study.curves.push_back(std::move(curve));
  }
  return study;
}

}  // namespace springlab
