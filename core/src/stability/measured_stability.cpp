// Stability measured on the methods' own steps (stability.hpp): the amplification of one step
// of the oscillator, and a scene's largest stable step found by running it.
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <vector>

#include "springlab/energy.hpp"
#include "springlab/simulation.hpp"
#include "springlab/stability.hpp"
#include "stability/cancel.hpp"
#include "stability/dense_spectrum.hpp"

namespace springlab {

namespace {

// The oscillator: an anchor pinned at the origin, a unit mass at distance 1 along x, a spring of
// rest length 1, k_s = w^2, k_d = c. Motion along x is exactly linear.
Model oscillator(double w, double c, const MethodParameters& parameters) {
  Model m;
  add_particle(m, 1.0, true);
  add_particle(m, 1.0, false);
  add_spring(m, 0, 1, 1.0, add_material(m, {w * w, c}));
  m.verlet_damping = parameters.verlet_damping;
  finalize(m);
  return m;
}

// The parts of a scene joined by springs, whether every part with a free particle is pinned
// somewhere: then gravity has a balance, else it is left out of the runs (a free part would
// fall and gain energy that is no instability).
bool every_part_held(const Model& model) {
  const int n = model.particle_count();
  std::vector<int> part(n);
  for (int i = 0; i < n; ++i) part[i] = i;
  const auto find = [&](int i) {
    while (part[i] != i) i = part[i] = part[part[i]];
    return i;
  };
  for (int s = 0; s < model.spring_count(); ++s)
    part[find(model.spring_a[s])] = find(model.spring_b[s]);
  std::vector<char> held(n, 0);
  for (int i = 0; i < n; ++i)
    if (model.pinned(i)) held[find(i)] = 1;
  for (int i = 0; i < n; ++i)
    if (!model.pinned(i) && !held[find(i)]) return false;
  return true;
}

// One step of the method on the oscillator x'' = -w^2 x - c x' as a matrix: on (x, v) for the
// one-step methods; Verlet runs a recurrence on (x, x_prev, a), its restart from (x, v) only
// once, so it is measured with that history. `size` is 2 or 3.
struct OscillatorStep {
  Eigen::Matrix3d matrix = Eigen::Matrix3d::Zero();
  int size = 2;
};

OscillatorStep oscillator_step(Method method, double w, double c, double h,
                               const MethodParameters& parameters) {
  const Model model = oscillator(w, c, parameters);
  const StepSettings settings;
  // Motion along the spring is exactly linear whatever the offset, so the offset only has to be
  // large enough for (x - 1) / delta to keep its digits (1e-13 relative), and small enough that
  // no stage crosses the anchor near the limits (amplitudes grow like (h w)^4 per step).
  const double delta = 1e-3;
  const bool verlet = method_info(method).history;  // (Verlet's history: x_prev and a_now)
  OscillatorStep out;
  out.size = verlet ? 3 : 2;
  State rest;
  rest.resize(2);
  rest.x.setZero();
  rest.v.setZero();
  rest.x(1, 0) = 1.0;
  Workspace history;
  if (verlet) {
    State next = rest;
    step(method, model, rest, next, h, settings, history);  // at rest: x_prev = x, a = 0
  }
  for (int column = 0; column < out.size; ++column) {
    State in = rest, next = rest;
    Workspace ws;
    if (verlet) {
      ws.x_prev = history.x_prev;
      ws.a_now = history.a_now;
      ws.verlet_ready = true;
      ws.verlet_h = h;
    }
    if (column == 0) in.x(1, 0) += delta;
    if (column == 1) (verlet ? ws.x_prev(1, 0) : in.v(1, 0)) += delta;
    if (column == 2) ws.a_now(1, 0) += delta;
    step(method, model, in, next, h, settings, ws);
    out.matrix(0, column) = (next.x(1, 0) - 1.0) / delta;
    out.matrix(1, column) = (verlet ? ws.x_prev(1, 0) - 1.0 : next.v(1, 0)) / delta;
    if (verlet) out.matrix(2, column) = ws.a_now(1, 0) / delta;
  }
  return out;
}

}  // namespace

double amplification(Method method, double w, double c, double h,
                     const MethodParameters& parameters) {
  const OscillatorStep s = oscillator_step(method, w, c, h, parameters);
  double rho = 0.0;
  const Eigen::VectorXcd mu = eigenvalues(s.matrix.topLeftCorner(s.size, s.size));
  for (const auto& z : mu) rho = std::max(rho, std::abs(z));
  return rho;
}

// In the energy norm, |(x, v)|^2 = kappa x^2 + v^2 (twice the mode's energy), the step is
// T = D S D^-1 with D = diag(sqrt(kappa), 1), and the growth is sup over n of |T^n|^2 (the
// spectral norm). With T = V diag(mu) V^-1, |T^n| <= cond(V) rho^n: once that falls to the
// largest |T^n| seen, no later power can exceed it.
double transient_growth(Method method, double gamma, double kappa, double h,
                        const MethodParameters& parameters) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  if (!(kappa > 0.0)) return 1.0;  // a first-order decay (drag alone): its speed only falls
  if (method_info(method).history)
    return kInf;  // its state holds a history: no energy norm of its own
  const OscillatorStep s =
      oscillator_step(method, std::sqrt(kappa), std::max(gamma, 0.0), h, parameters);
  const Eigen::Matrix2d D = Eigen::Vector2d(std::sqrt(kappa), 1.0).asDiagonal();
  const Eigen::Matrix2d T = D * s.matrix.topLeftCorner<2, 2>() * D.inverse();
  Eigen::VectorXcd mu;
  Eigen::MatrixXcd V;
  eigen_decomposition(T, mu, V);
  double rho = 0.0;
  for (int k = 0; k < 2; ++k) rho = std::max(rho, std::abs(mu[k]));
  if (!(rho <= 1.0 + 1e-12)) return kInf;
  // cond(V) = s1 / s2 from the singular values of a 2 x 2 matrix: s1^2 + s2^2 = |V|_F^2 and
  // s1 s2 = |det V|.
  const double f = V.squaredNorm(), d = std::abs(V(0, 0) * V(1, 1) - V(0, 1) * V(1, 0));
  const double largest_sv = std::sqrt(0.5 * (f + std::sqrt(std::max(f * f - 4.0 * d * d, 0.0))));
  const double smallest = largest_sv > 0.0 ? d / largest_sv : 0.0;
  const double condition = smallest > 1e-12 * largest_sv ? largest_sv / smallest : kInf;
  // |P|^2 of a 2 x 2 matrix: the larger eigenvalue of P^T P, from its trace (the entries'
  // squares) and determinant (det(P)^2).
  const auto norm2 = [](const Eigen::Matrix2d& P) {
    const double f = P.squaredNorm(), d = P.determinant();
    return 0.5 * (f + std::sqrt(std::max(f * f - 4.0 * d * d, 0.0)));
  };
  constexpr int kPowers = 1000000;
  Eigen::Matrix2d power = Eigen::Matrix2d::Identity();
  double largest = 1.0, bound = condition * condition;  // squared: cond(V)^2 rho^2n
  for (int n = 1; n <= kPowers; ++n) {
    power = T * power;
    largest = std::max(largest, norm2(power));
    bound *= rho * rho;
    if (bound <= largest) return largest;
  }
  // Still not decided (rho within about 1e-6 of 1 and V ill-conditioned): cond(V)^2 bounds it.
  return std::isfinite(condition) ? std::max(largest, condition * condition) : kInf;
}

namespace {

// The runs a measured limit makes of a scene: without colliders and fields (and without gravity
// unless every part is held, so that a free body stays put), from its balance given a tiny random
// push, the same every run. holds(h, steps): whether `steps` steps of h stay bounded.
struct Probe {
  Method method;
  StepSettings settings;
  Model runs;
  State pushed;
  double e_rest = 0.0;   // the balance's energy
  double start = 0.0;    // the push's energy above it
  double size = 0.0;     // particles and springs: what a step costs, in the budget's units
  double ceiling = 0.0;  // the iterative rows' divergence: kDivergenceFactor times the energy scale
  bool own_balance = false;
  double spent = 0.0;  // particle- and spring-steps run so far

  bool holds(double h, long steps);
};

// The probe of `model` from `state`; none where nothing can move (no push gives kinetic energy).
std::optional<Probe> make_probe(Method method, const Model& model, const State& state,
                                const StepSettings& settings) {
  Probe p;
  p.method = method;
  p.settings = settings;
  p.runs = model;
  Model& runs = p.runs;
  runs.planes.clear();
  runs.spheres.clear();
  runs.attractors.clear();
  if (!every_part_held(runs)) runs.gravity.setZero();
  const State rest = equilibrium(runs, state);
  p.e_rest = energy(runs, rest).total();
  const double scale = energy_scale(runs, rest);

  // A tiny random push, the same every run.
  p.pushed = rest;
  std::uint64_t seed = 0x2545F4914F6CDD1Dull;
  for (int i = 0; i < runs.particle_count(); ++i)
    for (int c = 0; c < 3; ++c) {
      seed = seed * 6364136223846793005ull + 1442695040888963407ull;
      p.pushed.v(i, c) =
          runs.pinned(i) ? 0.0 : static_cast<double>(seed >> 11) / 9007199254740992.0 - 0.5;
    }
  const double kinetic = kinetic_energy(runs, p.pushed);
  if (!(kinetic > 0.0)) return std::nullopt;
  p.pushed.v *= std::sqrt(1e-12 * scale / kinetic);
  p.start = energy(runs, p.pushed).total() - p.e_rest;
  p.size = runs.particle_count() + runs.spring_count();
  // The iterative rows stop short of the implicit solve, so the scene's balance is not their
  // own: from it they sag to another (XPBD's soft springs, by far more than the push), so their
  // energy above the balance grows, and two runs pushed differently can part (a cloth buckles
  // one way or the other), without any instability. For them a probe asks what the app asks of
  // a run: does it diverge, its kinetic or total energy leaving kDivergenceFactor (1e6) times the
  // scene's energy scale? Their push is 1e-3 of the scale, so that an unstable mode still has to
  // grow 1e9-fold to be caught, as for the others.
  p.own_balance = method_info(method).family == MethodFamily::Iterative;
  if (p.own_balance) p.pushed.v *= std::sqrt(1e9);
  p.ceiling = kDivergenceFactor * scale;
  return p;
}

bool Probe::holds(double h, long steps) {
  State a = pushed, b = pushed;
  Workspace ws;
  spent += static_cast<double>(steps) * size;
  for (long k = 0; k < steps; ++k) {
    if ((k & 255) == 0) check_cancel();
    try {
      step(method, runs, a, b, h, settings, ws);
    } catch (const StepFailure&) {
      return false;  // a step that could not be completed (a stage's Newton iteration): not held
    }
    std::swap(a, b);
    if ((k & 15) != 15 && k + 1 < steps) continue;
    const double e = energy(runs, a).total() - e_rest;
    if (!std::isfinite(e)) return false;
    if (own_balance ? std::max(kinetic_energy(runs, a), std::abs(e)) > ceiling : e > 1e3 * start)
      return false;
  }
  return true;
}

// How long a probe at h runs (measured_limit). The mode the analysis expects to fail first
// (w, c; the method's parameters the scene gives, Verlet's damping d) sets it: long enough for
// that mode's energy to grow 1e9-fold, ln(1e9) / (2 ln rho), so that the whole energy grows a
// thousandfold even if the push gave the mode a millionth of it; at least 200 steps, at most
// max_steps.
struct ProbeLength {
  Method method;
  double w, c;
  MethodParameters parameters;
  long max_steps;
  double guess = 0.0;     // the expected limit, or 1 / w
  bool any_step = false;  // stable at any step, as the table or the analysis says

  // The steps for the expected mode's energy to grow 1e9-fold at h, in [200, max_steps].
  long to_see(double h) const {
    const double rho = amplification(method, w, c, h, parameters);
    if (!(rho > 1.0)) return max_steps;
    const double steps = std::ceil(std::log(1e9) / (2.0 * std::log(rho)));
    return std::clamp(static_cast<long>(std::min(steps, 1e12)), 200L, max_steps);
  }
  // A probe at h runs as long as a thousandfold growth takes for the expected mode at h, or at
  // 0.5 % past its limit if h is below that (the slowest growth a run still has to see). A method
  // stable at any step (implicit Euler, the iterative rows, a tableau the analysis proves
  // A-stable: its limit infinite) is probed from h w = 1 up to 1000 with runs of 2000 steps: were
  // it unstable there, a step that large would show it within them (a mode past a limit at
  // h w >= 1 grows by at least its own factor a step), and runs of max_steps would cost the
  // iterative rows minutes, and a diagonally implicit tableau's Newton-solved stages 14 s on the
  // one spring (SDIRK3, whose |R| <= 1 everywhere left runs of max_steps at every probe).
  long at(double h) const {
    const long n = to_see(std::max(h, 1.005 * guess));
    return any_step ? std::min(n, 2000L) : n;
  }
};

// The bracket [lo, hi] round the limit, from the guess: up (x1.25, then doubling) while runs
// hold, or down (/1.25, then halving) while they fail. Where that decides it, the verdict: stable
// past 1000 times the guess (an infinite limit), unstable below a thousandth of it (0), or the
// budget spent with every probe held (stable at least to lo).
std::optional<MeasuredLimit> bracket_limit(Probe& probe, const ProbeLength& run, double budget,
                                           double& lo, double& hi) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  const double guess = run.guess;
  MeasuredLimit out;
  lo = guess;
  hi = guess;
  if (probe.holds(guess, run.at(guess))) {
    for (hi = guess * 1.25;; hi *= 2.0) {
      // Every step probed held, and no more runs: stable at least to lo.
      if (probe.spent > budget) {
        out.h = lo;
        out.resolution = kInf;
        out.at_least = true;
        return out;
      }
      if (!probe.holds(hi, run.at(hi))) break;
      lo = hi;
      if (hi > 1e3 * guess) {
        out.h = kInf;
        return out;
      }
    }
  } else {
    for (lo = guess / 1.25; !probe.holds(lo, run.at(lo)); lo /= 2.0) {
      hi = lo;
      if (lo < 1e-3 * guess) {
        out.h = 0.0;
        return out;
      }
    }
  }
  return std::nullopt;
}

}  // namespace

MeasuredLimit measured_limit(Method method, const Model& model, const State& state,
                             const StabilityLimit& expected, double w_max,
                             const StepSettings& settings, double budget) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  MeasuredLimit out;
  if (method_info(method).adaptive()) {
    out.h = std::numeric_limits<double>::quiet_NaN();
    return out;
  }
  std::optional<Probe> probe = make_probe(method, model, state, settings);
  if (!probe) {
    out.h = kInf;
    return out;
  }
  // The work allowed, in particle- and spring-steps: a probe is at most 200,000 steps and a
  // twentieth of it; the bisection stops when it is spent.
  const long max_steps =
      std::clamp(static_cast<long>(budget / (20.0 * probe->size)), 200L, 200000L);
  const double& spent = probe->spent;

  // The mode the analysis expects to fail first sets how long a run must be (ProbeLength).
  const double w = expected.mode ? expected.mode->w : w_max;
  const double c = expected.mode ? expected.mode->c : 0.0;
  ProbeLength run{method, w, c, method_parameters(model), max_steps};
  const auto holds = [&](double h, long steps) { return probe->holds(h, steps); };

  // Unstable at any step, says the analysis: then runs from h w = 0.3 up grow, fast enough to
  // see (midpoint's (h w)^4 / 8 a step is the slowest), and 0 is what they measure.
  if (expected.h == 0.0 && w > 0.0) {
    if (!holds(0.3 / w, run.to_see(0.3 / w))) {
      out.h = 0.0;
      return out;
    }
  }
  run.guess = std::isfinite(expected.h) && expected.h > 0.0 ? expected.h : w > 0.0 ? 1.0 / w : 1.0;
  run.any_step = method_info(method).any_step() || std::isinf(expected.h);
  double lo, hi;
  if (std::optional<MeasuredLimit> decided = bracket_limit(*probe, run, budget, lo, hi))
    return *decided;
  // Bisection, to 0.1 %, while runs of at most max_steps can still see the growth at the
  // bracket's midpoint.
  while (hi > lo * 1.001) {
    const double mid = 0.5 * (lo + hi);
    const long n = run.at(mid);
    if (n >= max_steps || spent > budget)
      break;  // runs this long could no longer tell, or no more runs
    (holds(mid, n) ? lo : hi) = mid;
  }
  out.h = lo;
  // A run of max_steps steps cannot see the growth within `blind` past the expected limit: the
  // largest step that held may be that far above the true limit.
  double blind = 1e-3;
  while (blind < 1.0 && run.to_see(run.guess * (1.0 + blind)) >= max_steps) blind *= 1.25;
  out.resolution = std::max(hi / lo - 1.0, blind);
  return out;
}

}  // namespace springlab
