// The step on a spring, against what its row promises: a mass m = 1 kg hanging from a pin by a
// spring k = 64 N/m (w = 8 rad/s) under g = 8 m/s^2, let go from the spring's rest length, a
// swing of A = m g / k = 0.125 m about y_eq = -1.125 m. The code's own 2-mass rope, its own steps.
//   order:     the error at t = 1 s against the exact (damped) oscillation, h = 1/128 ... 1/1024;
//   stability: runs at 0.9 and 1.1 of the limit springlab states for the row (mode_limit);
//   energy:    its rate a step over 16 s against the determinant of the row's amplification
//              matrix on the mode, which is |lambda|^2, the energy's factor a step on average:
//                explicit Euler  [1, h; -k h, 1 - g h]                  1 - g h + k h^2
//                symplectic      [1 - k h^2, h (1 - g h); -k h, 1 - g h]   1 - g h
//                Verlet (y, y_last)  [2 - d - k h^2, -(1 - d); 1, 0]        1 - d
//              (k: kappa = w^2, g: gamma = c / m).
#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>
#include <numeric>

#include "parts.hpp"
#include "springlab/stability.hpp"

namespace springlab::homework {

namespace {

constexpr double kMass = kSpringMass, kG = kSpringG, kRest = kSpringRest;
constexpr double kKappa = kSpringK / kSpringMass;
const double kW = std::sqrt(kKappa);
constexpr double kYeq = -kRest - kG / kKappa;
constexpr double kA = kG / kKappa;  // y(0) - y_eq
const double kTwoPi = 2.0 * std::acos(-1.0);

struct Mode {
  double gamma = 0.0, d = 0.0;
  // Euler's drag, apart from gamma's other forms: its rate (1/s), or a factor a step (a rate of
  // per_step / h), taken with the forces or, `after`, from the velocity once the position moved.
  double drag = 0.0, per_step = 0.0;
  DragAt drag_at = DragAt::Forces;
  bool verlet_whole = false;  // d on the whole displacement, x + (1 - d)((x - x_last) + a h^2)
  Method row = Method::SymplecticEuler;
  bool velocity_verlet = false;
  bool damps = false;  // the step damps by design (any damping fitted)
};

// The exact y(t) of y'' = -kappa (y - y_eq) - gamma y', let go at rest from y_eq + A.
double exact_y(const Mode& m, double t) {
  const double gamma = m.gamma + m.drag;  // (a factor a step has no limit: not measured then)
  const double wd = std::sqrt(kKappa - 0.25 * gamma * gamma);
  return kYeq +
         kA * std::exp(-0.5 * gamma * t) * (std::cos(wd * t) + 0.5 * gamma / wd * std::sin(wd * t));
}

std::complex<double> largest_root(double trace, double det) {
  const std::complex<double> disc = std::sqrt(std::complex<double>(0.25 * trace * trace - det));
  const std::complex<double> a = 0.5 * trace + disc, b = 0.5 * trace - disc;
  return std::abs(a) > std::abs(b) ? a : b;
}

// The drag's share of the rate at step h.
double drag_rate(const Mode& m, double h) {
  return m.drag + m.per_step / h;
}

// The row's amplification matrix on the mode at step h. The three rows of the rope exercise in
// closed form: on (y, v) explicit Euler [1, h; -k h, 1 - g h], symplectic Euler
// [1 - k h^2, h (1 - g h); -k h, 1 - g h], on (y, y_last) Verlet [2 - d - k h^2, -(1 - d); 1, 0];
// any other from springlab's own row, stepped from (y, v) = (e, 0) and (0, e) on the spring
// without gravity (linear along its axis). A drag taken after the position moved scales the
// velocity's row of the undragged matrix by 1 - c h.
Eigen::Matrix2d amplification(const Mode& m, double h) {
  const double kh2 = kKappa * h * h;
  const bool later = m.drag_at != DragAt::Forces;
  const double gh = (m.gamma + (later ? 0.0 : drag_rate(m, h))) * h;
  Eigen::Matrix2d a;
  if (m.row == Method::Euler) {
    a << 1.0, h, -kKappa * h, 1.0 - gh;
  } else if (m.row == Method::SymplecticEuler) {
    a << 1.0 - kh2, h * (1.0 - gh), -kKappa * h, 1.0 - gh;
  } else if (m.row == Method::Verlet && !m.velocity_verlet) {
    a << 2.0 - m.d - (m.verlet_whole ? 1.0 - m.d : 1.0) * kh2, -(1.0 - m.d), 1.0, 0.0;
  } else {
    const Model model = rope_model(hanging_spring(), Vec2::Zero(), Damping{gh / h * kMass});
    const double e = 1e-3 * kRest;
    for (int column = 0; column < 2; ++column) {
      State s;
      s.resize(2);
      s.x.setZero();
      s.v.setZero();
      s.x(1, 1) = -kRest + (column == 0 ? e : 0.0);
      s.v(1, 1) = column == 1 ? e : 0.0;
      const State next = reference_step(m.row, model, s, h);
      a(0, column) = (next.x(1, 1) + kRest) / e;
      a(1, column) = next.v(1, 1) / e;
    }
  }
  if (later) {
    a.row(1) *= 1.0 - drag_rate(m, h) * h;
    // Symplectic Euler's position moves by the damped velocity: y1 = y + h v1.
    if (m.drag_at == DragAt::NewVelocity && m.row == Method::SymplecticEuler)
      a.row(0) = Eigen::RowVector2d(1.0, 0.0) + h * a.row(1);
  }
  return a;
}

void amplification(const Mode& m, double h, double& trace, double& det) {
  const Eigen::Matrix2d a = amplification(m, h);
  trace = a.trace(), det = a.determinant();
}

// The largest step at which the mode's amplification has no root beyond 1, by bisection: for a
// drag that depends on h (a factor a step) or is taken after the position moved, where springlab's
// limit (mode_limit: a fixed rate, with the forces) does not say it.
double limit_by_roots(const Mode& m) {
  const auto grows = [&](double h) {
    double trace, det;
    amplification(m, h, trace, det);
    return std::abs(largest_root(trace, det)) > 1.0 + 1e-12;
  };
  double lo = 1e-9, hi = 1.0;
  while (!grows(hi) && hi < 1e3) hi *= 2.0;
  if (!grows(hi)) return 0.0;  // (never: the spring's k h^2 outgrows every damping)
  for (int k = 0; k < 80; ++k) {
    const double mid = 0.5 * (lo + hi);
    (grows(mid) ? hi : lo) = mid;
  }
  return lo;
}

std::string precise(double factor) {
  char text[32];
  std::snprintf(text, sizeof text, "%.9f", factor);
  return text;
}

}  // namespace

Swing rope_swing(const Bench& bench, Step step, double h, int steps, double y_before) {
  bench.build(hanging_spring());
  RopeState s(2);
  s[1].x = s[1].x_last = Vec2(0.0, -kRest);
  // Verlet from the exact last position, so that the start costs no order (the exercise's own
  // start, last_position = position, makes the first velocity h a instead of h a / 2).
  if (step == Step::Verlet) s[1].x_last.y() = y_before;
  Swing out;
  out.has_velocity = step == Step::Euler;
  out.y.push_back(s[1].x.y());
  out.v.push_back(0.0);
  for (const RopeState& state : bench.run(s, step, h, Vec2(0.0, -kG), steps)) {
    out.y.push_back(state[1].x.y());
    out.v.push_back(state[1].v.y());
  }
  return out;
}

namespace {

void check_order(const SwingRunner& swing, const Mode& mode, CheckSection& section) {
  const int expected = method_info(mode.row).order;
  if ((mode.row == Method::Verlet && mode.d != 0.0) || mode.per_step != 0.0) {
    note(section, "order",
         tr("order: not measured: a damping factor d a step has no limit as h -> 0 (at a fixed d, "
            "halving h doubles the "
            "damping a second)"));
    return;
  }
  std::vector<double> errors;
  std::string list;
  for (int k = 7; k <= 10; ++k) {
    const double h = std::ldexp(1.0, -k);
    const Swing s = swing(h, 1 << k, exact_y(mode, -h));
    errors.push_back(std::abs(s.y.back() - exact_y(mode, 1.0)));
    list += (list.empty() ? "" : ", ") + num(errors.back());
  }
  const double slope = std::log2(errors[errors.size() - 2] / errors.back());
  const std::string text = format_text(
      tr("order %s measured (%s: %d): errors at t = 1 s against the exact swing %s m at "
         "h = 1/128 ... 1/1024 s"),
      num(slope).c_str(), tr(method_info(mode.row).label), expected, list.c_str());
  if (std::isfinite(slope) && std::abs(slope - expected) <= 0.15)
    pass(section, "order", text);
  else
    fail(section, "order", text);
}

void check_stability(const SwingRunner& swing, const Mode& mode, CheckSection& section) {
  // Verlet's factor on the whole displacement scales a h^2 by (1 - d): its limit is 1 / sqrt(1 - d)
  // wider.
  const bool by_roots =
      mode.per_step != 0.0 || (mode.drag_at != DragAt::Forces && mode.drag != 0.0);
  const double limit =
      by_roots ? limit_by_roots(mode)
               : mode_limit(mode.row, mode.gamma + mode.drag, kKappa, {.verlet_damping = mode.d}) /
                     (mode.verlet_whole ? std::sqrt(1.0 - mode.d) : 1.0);
  const char* label = tr(method_info(mode.row).label);
  if (limit == 0.0) {
    note(section, "stability",
         format_text(tr("stability: %s is stable at no step on an undamped spring (its limit is "
                        "0): the energy below grows "
                        "at every step"),
                     label));
    return;
  }
  double trace, det;
  const double over = as_float(1.1 * limit), under = as_float(0.9 * limit);
  amplification(mode, over, trace, det);
  const double growth = std::abs(largest_root(trace, det));
  const double needed = std::log(1e3) / std::log(growth);  // steps for the swing to grow 1000 times
  const std::string stated =
      by_roots
          ? format_text(tr("the limit of %s with this damping here, where its step's "
                           "amplification first has a root beyond 1: h = %s s"),
                        label, num(limit).c_str())
          : format_text(tr("springlab's limit for %s here: h = %s s"), label, num(limit).c_str());
  if (!(needed <= 20000)) {
    note(section, "stability",
         format_text(tr("stability: %s; at 1.1 of it the swing grows only x%s a step, too slowly "
                        "to see in 20000 steps (the "
                        "energy's rate below measures it)"),
                     stated.c_str(), precise(growth).c_str()));
    return;
  }
  const int steps = std::max(400, static_cast<int>(std::ceil(needed)));
  auto widest = [&](double h) {
    double w = 0.0;
    for (double y : swing(h, steps, exact_y(mode, -h)).y)
      w = std::isfinite(y) ? std::max(w, std::abs(y - kYeq)) : INFINITY;
    return w;
  };
  const double calm = widest(under), wild = widest(over);
  const std::string text =
      format_text(tr("stability: %s; over %d steps the swing of %s m reaches %s m at h = %s (0.9 "
                     "of it) and %s m at h = %s "
                     "(1.1 of it)"),
                  stated.c_str(), steps, num(kA).c_str(), num(calm).c_str(),
                  step_text(under).c_str(), num(wild).c_str(), step_text(over).c_str());
  if (calm <= 10.0 * kA && wild >= 100.0 * kA)
    pass(section, "stability", text);
  else
    fail(section, "stability",
         text + (calm > 10.0 * kA ? tr(" (unstable below the limit)")
                                  : tr(" (stable past the limit)")));
}

void check_energy(const SwingRunner& swing, const Mode& mode, CheckSection& section) {
  const double h = 1.0 / 256;
  const int steps = 4096;
  const Swing s = swing(h, steps, exact_y(mode, -h));
  std::vector<double> energy;
  for (int n = 1; n < steps; ++n) {
    const double v = s.has_velocity ? s.v[n] : (s.y[n + 1] - s.y[n - 1]) / (2.0 * h);
    energy.push_back(0.5 * kMass * v * v +
                     0.5 * kKappa * kMass * (s.y[n] - kYeq) * (s.y[n] - kYeq));
  }
  // Means over a swing at each end, so that the energy's swing within a period cancels.
  const int period = static_cast<int>(std::lround(kTwoPi / (kW * h)));
  const int n = static_cast<int>(energy.size());
  const double first = std::accumulate(energy.begin(), energy.begin() + period, 0.0);
  const double last = std::accumulate(energy.end() - period, energy.end(), 0.0);
  const double measured = std::pow(last / first, 1.0 / (n - period));
  double trace, det;
  amplification(mode, h, trace, det);
  const double log_gap = std::abs(std::log(measured) - std::log(det));
  const char* says = mode.row == Method::Euler                             ? "1 + (w h)^2 - (c/m) h"
                     : mode.row == Method::Verlet && !mode.velocity_verlet ? "1 - d"
                     : mode.row == Method::SymplecticEuler                 ? "1 - (c/m) h"
                                                           : tr("|lambda|^2 of its step here");
  // (A determinant within rounding of 1, as a symplectic row's measured from its step, holds.)
  const bool holds = std::abs(det - 1.0) <= 1e-9, grows = !holds && det > 1.0;
  const char* verdict =
      holds   ? N_("energy holds: x%s a step at h = 1/256 s (%s predicts %s = %s), x%s over 16 s")
      : grows ? N_("energy grows: x%s a step at h = 1/256 s (%s predicts %s = %s), x%s over 16 s")
              : N_("energy falls: x%s a step at h = 1/256 s (%s predicts %s = %s), x%s over 16 s");
  std::string text =
      format_text(tr(verdict), precise(measured).c_str(), tr(method_info(mode.row).label), says,
                  precise(det).c_str(), num(last / first).c_str());
  const double loss = mode.row == Method::Verlet ? mode.d : mode.per_step;
  if (loss != 0.0 && (mode.row == Method::Verlet || mode.per_step != 0.0))
    text += format_text(tr("; d is a step's loss, so it takes %s %% of the energy a second at this "
                           "h and about twice that at h/2"),
                        num(100.0 * (1.0 - std::pow(1.0 - loss, 1.0 / h))).c_str());
  const bool as_predicted =
      std::isfinite(log_gap) && log_gap <= 2e-6 + 0.02 * std::abs(std::log(det));
  if (!as_predicted)
    fail(section, "energy", text);
  else if (grows && mode.damps)
    // The measurement agrees with the method, but a step the exercise asks to damp must not gain:
    // here the method's own gain outruns the damping (explicit Euler), which is said, not passed.
    note(section, "energy",
         text + tr(": the method gains energy faster than the damping takes it at this step "
                   "(explicit Euler's own "
                   "instability, as predicted; not a mistake in the code)"));
  else
    pass(section, "energy", text);
}

}  // namespace

void check_on_a_spring(const SwingRunner& run, const Identified& found, CheckSection& section) {
  if (found.method.empty()) {
    note(section, "not-measured",
         tr("order, stability and energy: not measured, since the step is none of the textbook "
            "methods"));
    return;
  }
  if (found.damping.drag < 0.0 || found.damping.drag_step < 0.0 || found.damping.along < 0.0 ||
      found.damping.relative < 0.0 || found.damping.verlet < 0.0) {
    note(section, "not-measured",
         tr("order, stability and energy: not measured while the damping has the wrong sign "
            "(above): it feeds the "
            "oscillation instead of taking energy out"));
    return;
  }
  Mode mode;
  mode.row = *find_method(found.method);
  // On the hanging spring every damping form acts along the spring: one rate (c + k_d) / m, the
  // drag's share apart (drag, per_step), as it may depend on h or come after the position moved.
  mode.gamma = (found.damping.along + found.damping.relative) / kMass;
  mode.drag = found.damping.drag_on(kMass) / kMass;
  mode.per_step = found.damping.drag_step;
  mode.drag_at = found.damping.drag_at;
  mode.d = found.damping.verlet;
  mode.verlet_whole = found.damping.verlet_whole;
  mode.velocity_verlet = found.velocity_verlet;
  mode.damps = found.damping.any();
  check_order(run, mode, section);
  check_stability(run, mode, section);
  check_energy(run, mode, section);
}

}  // namespace springlab::homework
