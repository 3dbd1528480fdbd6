// XPBD in its small-steps form (Macklin, Mueller, Chentanez 2016, "XPBD: position-based
// simulation of compliant constrained dynamics"; Macklin et al. 2019, "Small steps in physics
// simulation"): each step is one sub-step that predicts, then makes `iterations` Gauss-Seidel
// passes (default 1) over the springs as distance constraints, colour by colour (below), then
// takes v from the positions.
//
//   x = y (iterative.hpp),  lambda_s = 0
//   each pass, each spring s, colour by colour:  C = |x_b - x_a| - L,  u = (x_b - x_a) / |x_b -
//   x_a|
//     dlambda = (-C - a~ lambda_s - gamma u . (dx_b - dx_a)) / ((1 + gamma)(w_a + w_b) + a~)
//     lambda_s += dlambda,  x_a -= w_a dlambda u,  x_b += w_b dlambda u
//   v1 = (x1 - x) / h
//
// with w = 1 / m~ (0 for pinned ends), dx = x - x_start over the step so far, and
//   a~ = 1 / (k_s h^2)       the compliance alpha = 1 / k_s over h^2 (the paper's Eq. 4): as
//                            h -> 0 a pass moves x by h^2 k_s C / m, the spring's own
//                            acceleration, so XPBD tends to the spring model;
//   gamma = a~ b~ / h = k_d / (k_s h)   the constraint damping of Eq. 26 with beta = k_d, the
//                            notes' damping along the spring (b~ = h^2 beta).
// So k_s is a stiffness (N/m) as everywhere, exactly so only as h -> 0 or as the passes grow:
// with one pass a step XPBD's springs are softer than k_s (the "stretchy" cloth), which the
// effective stiffness measures. A spring with k_s = 0 has no constraint (infinite compliance);
// its damping alone is not modelled here.
//
// Each pass is Gauss-Seidel colour by colour: the springs are coloured so that no two of a colour
// share a particle (colour_springs, iterative.hpp), the colours taken in turn, each colour's
// springs at once, on the threads there are (a spring moves only its own ends and its own
// lambda, so the colour's result is the same whichever thread projects which spring: the same
// bits for any thread count). The order of projection is part of the result (a pass in the
// springs' own order moves the cloth otherwise); colour by colour is how multi-core and GPU
// Gauss-Seidel solvers order it (Fratarcangeli et al. 2016, "Vivace").
#include <algorithm>
#include <cmath>

#include "dynamics/threads.hpp"
#include "iterative.hpp"
#include "springlab/spring_kernel.hpp"
#include "steps.hpp"

namespace springlab {

namespace {

// The step's start: the first iterate x = y, each particle's 1 / m~ (0 if pinned) and each
// material's compliance and damping, once a step rather than once a spring (a spring with k_s = 0
// is not projected).
void begin_step(const Model& model, const State& in, double h, IterativeSolvers& S, State& out) {
  iterative::predict(model, in, h, S.y, S.mass);
  const int n = in.particle_count();
  out.resize(n);
  S.w.resize(n);
  iterative::each_particle_piece(n, [&](int begin, int end) {
    for (int c = 0; c < 3; ++c)
      out.x.col(c).segment(begin, end - begin) = S.y.col(c).segment(begin, end - begin);
    for (int i = begin; i < end; ++i) S.w[i] = model.pinned(i) ? 0.0 : 1.0 / S.mass[i];
  });
  S.compliance.assign(model.materials.size(), 0.0);
  S.gamma.assign(model.materials.size(), 0.0);
  for (std::size_t m = 0; m < model.materials.size(); ++m)
    if (const SpringMaterial& material = model.materials[m]; material.ks > 0.0) {
      S.compliance[m] = 1.0 / (material.ks * h * h);
      S.gamma[m] = material.kd / (material.ks * h);
    }
}

}  // namespace

namespace steps {

void xpbd(const Model& model, const State& in, State& out, double h, const StepSettings& settings,
          Workspace& ws) {
  if (!ws.iterative) ws.iterative = std::make_unique<IterativeSolvers>();
  IterativeSolvers& S = *ws.iterative;
  begin_step(model, in, h, S, out);
  const int springs = model.spring_count();
  // lambda_s = 0 at the step's start: read as 0 in the first pass rather than cleared first (a
  // serial pass over every spring's lambda: 1.3 % of the 128 x 128 cloth's step at 2 threads, and
  // a larger share the more threads share the rest).
  S.lambda.resize(springs);
  bool first_pass = true;

  double* X[3] = {out.x.col(0).data(), out.x.col(1).data(), out.x.col(2).data()};
  const double* X0[3] = {in.x.col(0).data(), in.x.col(1).data(), in.x.col(2).data()};
  const double* w = S.w.data();
  SpringColouring& C = S.xpbd_colours;
  if (C.spans != model.spans.data() || C.particles != in.particle_count() || C.springs != springs)
    colour_springs(model, C);
  // One spring's projection (the file's header): the spring at place k of the colouring, its
  // lambda at the same place.
  const auto project = [&](int k) {
    const SpringColouring::Spring& spring = C.springs_in_order[k];
    const int m = spring.material;
    if (model.materials[m].ks <= 0.0) return;
    const int a = spring.a, b = spring.b;
    const double wa = w[a], wb = w[b];
    if (wa + wb == 0.0) return;
    double d[3], l2 = 0.0;
    for (int c = 0; c < 3; ++c) d[c] = X[c][b] - X[c][a], l2 += d[c] * d[c];
    const double l = std::sqrt(l2);
    const double rest = spring.rest;
    if (coincident(l, rest)) {  // not moved: its lambda stays as it was, 0 in the first pass
      if (first_pass) S.lambda[k] = 0.0;
      return;
    }
    double u[3], rate = 0.0;
    for (int c = 0; c < 3; ++c) {
      u[c] = d[c] / l;
      rate += u[c] * ((X[c][b] - X0[c][b]) - (X[c][a] - X0[c][a]));
    }
    const double compliance = S.compliance[m], gamma = S.gamma[m];
    const double lambda = first_pass ? 0.0 : S.lambda[k];
    const double dlambda = (-(l - rest) - compliance * lambda - gamma * rate) /
                           ((1.0 + gamma) * (wa + wb) + compliance);
    S.lambda[k] = lambda + dlambda;
    for (int c = 0; c < 3; ++c) {
      X[c][a] -= wa * dlambda * u[c];
      X[c][b] += wb * dlambda * u[c];
    }
  };
  const int passes = iterations_for(Method::XPBD, settings);
  // A colour's springs in pieces of kPiece: a thread another program has parked holds up only the
  // piece it has begun, the rest of its run taken by the others (threads::for_each_piece). Measured
  // on the 128 x 128 cloth on 2 cores: one piece a thread ran 1.35 times as fast on two threads as
  // on one, quiet, but 1.3 to 1.5 times slower than one thread beside two busy programs; 512 keeps
  // the default as fast as one thread there (0.9 to 1.1 times), and gains little when quiet.
  constexpr int kPiece = 512;
  // A projection's work in the force pass's units (threads::worth_threads): its square root and
  // four divisions cost about as much as five force-pass spring visits (the 64 x 64 cloth on one
  // thread: an XPBD step 547 us, a symplectic Euler step 97 us, the same springs).
  constexpr double kProjectionWork = 5.0;
  for (int pass = 0; pass < passes; ++pass) {
    first_pass = pass == 0;
    for (std::size_t c = 0; c + 1 < C.colour_first.size(); ++c) {
      const int first = C.colour_first[c], count = C.colour_first[c + 1] - first;
      threads::for_each_piece((count + kPiece - 1) / kPiece, kProjectionWork * count, [&](int p) {
        const int to = std::min(count, (p + 1) * kPiece);
        for (int k = p * kPiece; k < to; ++k) project(first + k);
      });
    }
  }
  ws.counters.solver_iterations += passes;
  iterative::finish(model, in, out, h);
}

}  // namespace steps
}  // namespace springlab
