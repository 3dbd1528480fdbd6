// A scene's stability analysis (stability.hpp has the mathematics). Sections:
//   the joint numerical range W   its boundary traced by Lanczos, searched per method
//   the partitioned methods       symplectic Euler and Verlet by Newton on a definiteness test
//   the dense spectrum            every eigenvalue of a small scene, for the Runge-Kutta methods
//   the analysis                  all of it, for every method
#include "springlab/stability.hpp"

#include <Eigen/Dense>
#include <Eigen/LU>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <numbers>
#include <sstream>
#include <stdexcept>

#include "dynamics/threads.hpp"
#include "springlab/iterative_cost.hpp"
#include "springlab/text.hpp"
#include "stability/analysis_rows.hpp"
#include "stability/cancel.hpp"
#include "stability/dense_spectrum.hpp"
#include "stability/lanczos.hpp"
#include "stability/linearised.hpp"
#include "stability/sqrt_of_real.hpp"

namespace springlab {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
using Complex = std::complex<double>;

// Independent pieces of the analysis on worker threads (threads::each), each under the
// analysis's cancel flag (the flag is the calling thread's): results are the same whichever
// thread runs which piece.
template <typename Task>
void each_task(int count, const Task& task) {
  const std::atomic<bool>* flag = cancel_detail::g_flag;
  threads::each(count, threads::max_team(), [&](int i) {
    const CancelScope scope(flag);
    task(i);
  });
}

// Lanczos steps for one eigenpair: enough to converge on the crowded top of a long chain's
// spectrum (about its length), and about 1e8 spring products at most.
int lanczos_cap(const Linearised& lin) {
  return std::clamp(lin.dofs() + 16, 32, 4000);
}

// A vector's damping rate and stiffness, gamma = x^T C^ x and kappa = x^T K^ x (|x| = 1).
struct Sample {
  double phi = 0.0;
  double gamma = 0.0, kappa = 0.0;
  Points x;
};

// The largest-eigenvalue residual |lambda^2 x + lambda D x + K^ x| relative to the terms' size,
// for the damping D = C^ + extra K^ (modified Euler: extra = h / 2): 0 for an eigenvector of the
// quadratic eigenproblem with that eigenvalue.
double residual(const Linearised& lin, const Points& x, Complex lambda, double extra) {
  Points kx, cx;
  lin.apply(1.0, 0.0, x, kx);
  lin.apply(0.0, 1.0, x, cx);
  const Points dx = cx + extra * kx;
  double r2 = 0.0;
  for (int c = 0; c < 3; ++c)
    for (int i = 0; i < x.rows(); ++i) {
      const Complex r = lambda * lambda * x(i, c) + lambda * dx(i, c) + kx(i, c);
      r2 += std::norm(r);
    }
  const double size = std::norm(lambda) +
                      std::abs(lambda) * (lin.damping_bound() + extra * lin.stiffness_bound()) +
                      lin.stiffness_bound();
  return std::sqrt(r2) / size;
}

// An eigenvector counts as found when its residual is below this.
constexpr double kEigenvectorResidual = 1e-6;

LimitingMode mode_of(const Linearised& lin, const Points& x, double gamma, double kappa) {
  LimitingMode mode;
  mode.w = std::sqrt(std::max(kappa, 0.0));
  mode.c = std::max(gamma, 0.0);
  mode.shape = lin.displacement(x);
  const double largest = mode.shape.rowwise().norm().maxCoeff();
  if (largest > 0.0) mode.shape /= largest;
  return mode;
}

// ---- The joint numerical range W ---------------------------------------------------------------

// Traces W's boundary: the top eigenvector of F(phi) = cos(phi) K^ / |K^| + sin(phi) C^ / |C^|
// (each scaled by its Gershgorin bound) for phi in (-pi/2, pi/2) is the point of W furthest
// along (cos phi, sin phi): phi = 0 is the stiffest mode, phi -> -pi/2 the least damped, phi ->
// pi/2 the most damped. Every mode limit falls as kappa grows, so only this right-hand half of
// W's boundary can hold the least.
class RangeTrace {
 public:
  explicit RangeTrace(const Linearised& lin)
      : lin_(lin),
        k_(lin.stiffness_bound()),
        c_(lin.damping_bound()),
        random_(lin.random_vector(0x9E3779B97F4A7C15ull)) {}

  // A neighbour's vector starts it (they are close), with `mix` of a fixed random vector so
  // that no direction is missing from the start: the top may have moved to another mode.
  Sample at(double phi, const Points& near, double mix = 0.1) const {
    check_cancel();
    const double a = std::cos(phi) / k_, b = c_ > 0.0 ? std::sin(phi) / c_ : 0.0;
    const Points start = near + mix * random_;
    // To a residual of 1e-7 of the operator's size. The sample is then on W's boundary to the
    // residual squared over the gap (its support value cos(phi) kappa + sin(phi) gamma is the
    // Rayleigh quotient); along the boundary it may slide to first order, which Brent's search
    // over phi takes up. Measured: 1e-10 cost a fifth more Lanczos steps on a 64 x 64 cloth (a
    // third on a 1000-node rope) for the same limits to ten digits and the same eigenvector
    // verdicts (kEigenvectorResidual, 1e-6) on eight shipped scenes.
    const Linearised::Combined op = lin_.combined(a, b);
    const TopEigenpair top = top_eigenpair([&](const Points& x, Points& y) { op.apply(x, y); },
                                           start, lanczos_cap(lin_), 1e-7);
    Sample s;
    s.phi = phi;
    s.x = top.vector;
    s.gamma = lin_.damping(s.x);
    s.kappa = lin_.stiffness(s.x);
    // A direction with no stiffness (a spring at rest turning about its anchor) has kappa of
    // rounding's size, not of a slow mode's: zero.
    if (s.kappa <= 1e-12 * k_) s.kappa = 0.0;
    if (s.gamma <= 1e-12 * c_) s.gamma = 0.0;
    return s;
  }

  // The stiffest mode (phi = 0), from a fixed pseudo-random start, then a grid over the half
  // circle, each point started from its neighbour's vector (they are close). The two sides are
  // independent chains, a job each; beside(j, top) for j < count are further jobs that need only
  // the stiffest mode `top`, run on the cores beside them (on a cloth the side towards the most
  // damped modes takes half as long again as the other: they fill the difference).
  template <typename Beside>
  void grid(int points, int count, const Beside& beside) {
    const Sample top = at(0.0, random_);
    samples_.push_back(top);
    // No damping: W is a segment of the kappa axis, its end is all.
    const int sides_count = c_ > 0.0 ? 2 : 0;
    std::vector<Sample> sides[2];
    each_task(sides_count + count, [&](int t) {
      if (t >= sides_count) return beside(t - sides_count, top);
      const int side = t == 0 ? -1 : 1;
      Points start = top.x;
      const int half = points / 2;
      for (int j = 1; j <= half; ++j) {
        const double phi = side * 0.5 * std::numbers::pi * j / (half + 0.5);
        sides[t].push_back(at(phi, start));
        start = sides[t].back().x;
      }
    });
    for (auto& side : sides)
      for (Sample& sample : side) samples_.push_back(std::move(sample));
    std::sort(samples_.begin(), samples_.end(),
              [](const Sample& p, const Sample& q) { return p.phi < q.phi; });
  }

  const std::vector<Sample>& samples() const { return samples_; }
  const Sample& stiffest() const {
    return *std::min_element(
        samples_.begin(), samples_.end(),
        [](const Sample& p, const Sample& q) { return std::abs(p.phi) < std::abs(q.phi); });
  }

  // The least of `limit` over the boundary: the best point sampled, then Brent's search between
  // its neighbours.
  template <typename Limit>
  Sample least(const Limit& limit) const {
    std::size_t best = 0;
    for (std::size_t j = 1; j < samples_.size(); ++j)
      if (limit(samples_[j]) < limit(samples_[best])) best = j;
    if (samples_.size() < 3) return samples_[best];
    // A corner of W (one mode supports a range of directions): its neighbours are the same
    // point, and no direction between them does better.
    const auto same = [&](std::size_t j) {
      return j < samples_.size() &&
             std::abs(samples_[j].kappa - samples_[best].kappa) <= 1e-9 * samples_[best].kappa &&
             std::abs(samples_[j].gamma - samples_[best].gamma) <=
                 1e-9 * std::max(samples_[best].gamma, 1e-300);
    };
    if (best > 0 && same(best - 1) && same(best + 1)) return samples_[best];
    const double edge = 0.5 * std::numbers::pi * (1.0 - 1e-9);
    double lo = best > 0 ? samples_[best - 1].phi : -edge;
    double hi = best + 1 < samples_.size() ? samples_[best + 1].phi : edge;
    return brent(limit, lo, hi, samples_[best]);
  }

  // A point found by a search, kept with the grid's (the modes the audit weighs).
  void add(Sample s) {
    const auto after = std::upper_bound(samples_.begin(), samples_.end(), s.phi,
                                        [](double phi, const Sample& q) { return phi < q.phi; });
    samples_.insert(after, std::move(s));
  }

 private:
  // Brent's minimisation of limit(at(phi)) over [lo, hi] from the bracketing point `x` (R. P.
  // Brent, Algorithms for Minimization without Derivatives, 1973, ch. 5): a parabola through the
  // three best points where it falls inside and shrinks the bracket fast enough, a golden-section
  // step where not. The limit is smooth in phi near its least (quadratic), so the parabolas
  // converge superlinearly: about 6 points instead of golden section's 16 for the same phi.
  template <typename Limit>
  Sample brent(const Limit& limit, double lo, double hi, Sample x) const {
    constexpr double kGolden = 0.3819660112501051;  // (3 - sqrt 5) / 2
    constexpr double kTolerance =
        3e-5;  // in phi (radians): the limit is quadratic there, to ~1e-12
    Sample w = x, v = x;
    double fx = limit(x), fw = fx, fv = fx;
    double d = 0.0, e = 0.0;
    for (int k = 0; k < 40; ++k) {
      const double mid = 0.5 * (lo + hi), tol1 = kTolerance, tol2 = 2.0 * tol1;
      if (std::abs(x.phi - mid) <= tol2 - 0.5 * (hi - lo)) break;
      bool parabola = false;
      if (std::abs(e) > tol1) {
        const double r = (x.phi - w.phi) * (fx - fv);
        double q = (x.phi - v.phi) * (fx - fw);
        double p = (x.phi - v.phi) * q - (x.phi - w.phi) * r;
        q = 2.0 * (q - r);
        if (q > 0.0) p = -p;
        q = std::abs(q);
        const double before = e;
        if (std::abs(p) < std::abs(0.5 * q * before) && p > q * (lo - x.phi) &&
            p < q * (hi - x.phi)) {
          e = d;
          d = p / q;
          const double u = x.phi + d;
          if (u - lo < tol2 || hi - u < tol2) d = mid >= x.phi ? tol1 : -tol1;
          parabola = true;
        }
      }
      if (!parabola) {
        e = x.phi >= mid ? lo - x.phi : hi - x.phi;
        d = kGolden * e;
      }
      const double u = std::abs(d) >= tol1 ? x.phi + d : x.phi + (d >= 0.0 ? tol1 : -tol1);
      // A point inside the bracket, from x's vector with a hundredth of the random one: between
      // two grid points the top has less room to change mode, and the start is closer to it.
      Sample su = at(u, x.x, 0.01);
      const double fu = limit(su);
      if (fu <= fx) {
        (u >= x.phi ? lo : hi) = x.phi;
        v = std::move(w);
        fv = fw;
        w = std::move(x);
        fw = fx;
        x = std::move(su);
        fx = fu;
      } else {
        (u < x.phi ? lo : hi) = u;
        if (fu <= fw || w.phi == x.phi) {
          v = std::move(w);
          fv = fw;
          w = std::move(su);
          fw = fu;
        } else if (fu <= fv || v.phi == x.phi || v.phi == w.phi) {
          v = std::move(su);
          fv = fu;
        }
      }
    }
    return x;
  }

  const Linearised& lin_;
  double k_, c_;
  Points random_;
  std::vector<Sample> samples_;
};

// A limit from W: the least over its boundary, exact when the vector attaining it is an
// eigenvector of the system with the eigenvalue that sets the limit.
// The point attaining it is `found`.
StabilityLimit range_limit(Method method, const Linearised& lin, const RangeTrace& trace,
                           Sample& found) {
  StabilityLimit out;
  out.method = method;
  const auto limit = [&](const Sample& s) { return mode_limit(method, s.gamma, s.kappa); };
  found = trace.least(limit);
  const Sample& s = found;
  out.h = limit(s);
  // A method stable as explicit Euler on the damping C^ + shift h K^ (modified Euler: shift 1/2).
  const double shift = analysis_row(method).damping_shift;
  const double extra = shift > 0.0 && std::isfinite(out.h) ? shift * out.h : 0.0;
  const double gamma = s.gamma + extra * s.kappa;
  // The root that sets the limit: either of a complex pair (conjugates), the larger of a real
  // pair (every method here is limited by |lambda| on the negative real axis).
  const Complex root = sqrt_of_real(0.25 * gamma * gamma - s.kappa);
  out.residual = residual(lin, s.x, -0.5 * gamma - root, extra);
  out.exact = out.residual <= kEigenvectorResidual;
  out.mode = mode_of(lin, s.x, s.gamma, s.kappa);
  return out;
}

// ---- The partitioned methods -------------------------------------------------------------------

// The largest h with a h^2 K^ + b h C^ <= c I: Newton's method on the largest eigenvalue
// g(h) = lambda_max(a h^2 K^ + b h C^), convex and increasing in h, from a step where it is
// above c (the stiffest mode's own limit), so that every iterate stays above the root.
StabilityLimit definite_limit(Method method, double a, double b, double c, const Linearised& lin,
                              const Sample& stiffest) {
  StabilityLimit out;
  out.method = method;
  const auto mode_h = [&](double gamma, double kappa) {
    // The root of a h^2 kappa + b h gamma = c (a = 1 for both methods).
    return 2.0 * c / (b * gamma + std::sqrt(b * b * gamma * gamma + 4.0 * a * kappa * c));
  };
  double h = mode_h(stiffest.gamma, stiffest.kappa);
  Points x = stiffest.x;
  double gamma = stiffest.gamma, kappa = stiffest.kappa;
  for (int iteration = 0; iteration < 40; ++iteration) {
    const double ka = a * h * h / c, cb = b * h / c;
    const Linearised::Combined op = lin.combined(ka, cb);
    const TopEigenpair top = top_eigenpair([&](const Points& v, Points& y) { op.apply(v, y); }, x,
                                           lanczos_cap(lin), 1e-13);
    x = top.vector;
    gamma = lin.damping(x);
    kappa = lin.stiffness(x);
    const double g = top.value;  // lambda_max / c
    if (std::abs(g - 1.0) <= 1e-11) break;
    const double slope = (2.0 * a * h * kappa + b * gamma) / c;
    const double next = h - (g - 1.0) / slope;
    if (!(next > 0.0) || std::abs(next - h) <= 1e-13 * h) break;
    h = next;
  }
  out.h = h;
  out.exact = true;
  out.mode = mode_of(lin, x, gamma, kappa);
  return out;
}

// ---- The dense spectrum ------------------------------------------------------------------------

// The eigenvector of the quadratic eigenproblem (lambda^2 I + lambda C^ + K^) y = 0 for a known
// eigenvalue, by inverse iteration with a shift a hair away from it; the real part of y turned
// so that its largest component is real.
Eigen::VectorXd dense_eigenvector(const Eigen::MatrixXd& K, const Eigen::MatrixXd& C,
                                  Complex lambda) {
  const Eigen::Index n = K.rows();
  const Complex shift = lambda * (1.0 + 1e-9) + 1e-12;
  const Eigen::MatrixXcd Q = shift * shift * Eigen::MatrixXcd::Identity(n, n) +
                             shift * C.cast<Complex>() + K.cast<Complex>();
  const Eigen::PartialPivLU<Eigen::MatrixXcd> lu(Q);
  Eigen::VectorXcd y = Eigen::VectorXcd::Ones(n);
  for (int k = 0; k < 3; ++k) {
    y = lu.solve(y);
    y /= y.norm();
  }
  Eigen::Index top = 0;
  y.cwiseAbs().maxCoeff(&top);
  y *= std::conj(y[top]) / std::abs(y[top]);
  Eigen::VectorXd real = y.real();
  return real / real.norm();
}

}  // namespace

double LimitingMode::damping_ratio() const {
  return w > 0.0 ? c / (2.0 * w) : kInf;
}

std::string describe(const StabilityLimit& limit) {
  if (std::isnan(limit.h)) return tr("the method chooses its own step sizes");
  if (std::isinf(limit.h)) return tr("stable at any step");
  if (limit.h == 0.0)
    return tr(method_info(limit.method).damping_helps()
                  ? "unstable at any step (not enough damping)"
                  : "unstable at any step");
  return format_text(
      limit.exact ? tr("stable up to h = %.4g s") : tr("stable at least up to h = %.4g s"),
      limit.h);
}

StabilityAnalysis::StabilityAnalysis(const Model& model, const State& state, int dense_dofs,
                                     const std::atomic<bool>* cancel) {
  const CancelScope scope(cancel);
  const struct Release {
    ~Release() { release_lanczos_memory(); }
  } release;
  try {
    analyse(model, state, dense_dofs);
  } catch (const Cancelled&) {
    cancelled_ = true;
  }
}

namespace {

// The dense spectrum, where the free coordinates are few: every eigenvalue of [0 I; -K -C], the
// modes from them (an overdamped pair from its eigenvector), and each Runge-Kutta row's limit
// from the eigenvalue that sets it, with its mode.
struct DenseSpectrum {
  std::vector<Complex> eigenvalues;
  std::vector<StabilityAnalysis::ModePoint> modes, growth_modes;
  std::vector<StabilityLimit> limits;
};

DenseSpectrum dense_spectrum(const Linearised& lin) {
  DenseSpectrum out;
  const Eigen::MatrixXd K = lin.dense_stiffness(), C = lin.dense_damping();
  const Eigen::Index n = K.rows();
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(2 * n, 2 * n);
  A.topRightCorner(n, n).setIdentity();
  A.bottomLeftCorner(n, n) = -K;
  A.bottomRightCorner(n, n) = -C;
  const Eigen::VectorXcd lambdas = springlab::eigenvalues(A);
  // K^ and C^ are positive semidefinite: a positive real part is rounding. A direction with
  // no stiffness and no damping (a spring at rest turning about its anchor) is a double
  // eigenvalue 0 that rounding splits by about sqrt(eps) |A|: left out.
  const double size = std::sqrt(lin.stiffness_bound()) + lin.damping_bound();
  for (Complex lambda : lambdas) {
    if (std::abs(lambda) <= 1e-6 * size) continue;
    if (lambda.real() > 0.0) lambda.real(0.0);
    if (std::abs(lambda.real()) <= 1e-13 * size) lambda.real(0.0);
    if (std::abs(lambda.imag()) <= 1e-13 * size) lambda.imag(0.0);
    out.eigenvalues.push_back(lambda);
    if (lambda.imag() > 0.0) {
      out.modes.push_back({-2.0 * lambda.real(), std::norm(lambda)});
      out.growth_modes.push_back(out.modes.back());
    } else if (lambda.imag() == 0.0 && lambda.real() < 0.0) {
      out.modes.push_back({-lambda.real(), 0.0});
      // A real eigenvalue is one root of its eigenvector's lambda^2 + gamma lambda + kappa: the
      // pair (an overdamped mode) comes from the vector (rare: none in the shipped scenes).
      const Points y = lin.points(dense_eigenvector(K, C, lambda));
      out.growth_modes.push_back({lin.damping(y), lin.stiffness(y)});
    }
  }
  for (const MethodInfo& info : methods()) {
    if (info.family != MethodFamily::RungeKutta) continue;
    const Method m = info.id;
    StabilityLimit limit;
    limit.method = m;
    limit.h = kInf;
    Complex worst = 0.0;
    for (Complex lambda : out.eigenvalues) {
      const double h = runge_kutta_limit(m, lambda);
      if (h < limit.h) {
        limit.h = h;
        worst = lambda;
      }
    }
    if (std::abs(worst) > 0.0) {
      const Points y = lin.points(dense_eigenvector(K, C, worst));
      limit.mode = mode_of(lin, y, lin.damping(y), lin.stiffness(y));
    }
    out.limits.push_back(std::move(limit));
  }
  return out;
}

}  // namespace

void StabilityAnalysis::analyse(const Model& model, const State& state, int dense_dofs) {
  const auto started = std::chrono::steady_clock::now();
  for (const MethodInfo& m : methods()) {
    StabilityLimit limit;
    limit.method = m.id;
    limit.h = m.adaptive() ? kNaN : m.any_step() ? kInf : 0.0;
    limits_.push_back(limit);
  }
  const State rest = equilibrium(model, state);
  lowest_energy_ = springlab::lowest_energy(model, rest);
  rest_stretch_ = rms_stretch(model, rest);
  const Linearised lin(model, rest);
  dofs_ = lin.dofs();
  w_bound_ = std::sqrt(lin.stiffness_bound());
  const auto finish = [&] {
    seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  };

  // No oscillating modes: only the drag's first-order decays, lambda = -k_drag / m.
  if (dofs_ == 0 || !(lin.stiffness_bound() > 0.0)) {
    // (English: the app shows them through tr().)
    no_modes_ = model.spring_count() == 0 ? N_("no springs")
                : dofs_ == 0              ? N_("every particle is pinned")
                                          : N_("no spring with stiffness holds a free particle");
    const double decay = lin.damping_bound();
    for (StabilityLimit& limit : limits_)
      if (!method_info(limit.method).adaptive() && !method_info(limit.method).any_step())
        limit.h = mode_limit(limit.method, decay, 0.0, method_parameters(model));
    if (decay > 0.0) modes_.push_back({decay, 0.0});
    growth_modes_ = modes_;
    finish();
    return;
  }
  oscillates_ = true;
  dense_ = dofs_ <= dense_dofs;

  const auto set = [&](StabilityLimit limit) {
    limits_[static_cast<int>(limit.method)] = std::move(limit);
  };
  // One search per method, independent of each other, so that they run on worker threads in any
  // order with the same results. A definiteness test (the partitioned methods) needs only the
  // stiffest mode: it runs beside the grid's two sides. The searches along W's boundary (the
  // Runge-Kutta methods, where the spectrum is not dense) need the whole grid.
  std::vector<const MethodInfo*> definite, searched;
  for (const MethodFamily family : {MethodFamily::RungeKutta, MethodFamily::Partitioned})
    for (const MethodInfo& m : methods())
      if (m.family == family && (family != MethodFamily::RungeKutta || !dense_))
        (m.definite ? definite : searched).push_back(&m);
  std::vector<StabilityLimit> definite_limits(definite.size());
  RangeTrace trace(lin);
  trace.grid(16, static_cast<int>(definite.size()), [&](int j, const Sample& stiffest) {
    const DefiniteForm f = definite[j]->definite(method_parameters(model));
    definite_limits[j] = definite_limit(definite[j]->id, f.a, f.b, f.c, lin, stiffest);
  });
  for (StabilityLimit& limit : definite_limits) set(std::move(limit));
  w_max_ = std::sqrt(std::max(trace.stiffest().kappa, 0.0));

  std::vector<StabilityLimit> found_limits(searched.size());
  std::vector<Sample> found_points(searched.size());
  each_task(static_cast<int>(searched.size()), [&](int t) {
    found_limits[t] = range_limit(searched[t]->id, lin, trace, found_points[t]);
  });
  for (std::size_t t = 0; t < searched.size(); ++t) {
    set(std::move(found_limits[t]));
    trace.add(std::move(found_points[t]));
  }

  if (dense_) {
    DenseSpectrum spectrum = dense_spectrum(lin);
    eigenvalues_ = std::move(spectrum.eigenvalues);
    modes_ = std::move(spectrum.modes);
    growth_modes_ = std::move(spectrum.growth_modes);
    for (StabilityLimit& limit : spectrum.limits) set(std::move(limit));
  } else {
    for (const Sample& s : trace.samples()) modes_.push_back({s.gamma, s.kappa});
    growth_modes_ = modes_;
  }
  finish();
}

const StabilityLimit& StabilityAnalysis::limit(Method method) const {
  const auto row = static_cast<std::size_t>(method);
  if (row < limits_.size()) return limits_[row];
  // A row made from a tableau after this analysis (a Runge-Kutta row): the least over the modes
  // found of its limit, from its R(z) as for the rows analysed (every eigenvalue on a dense scene,
  // exact; the traced boundary of the numerical range on a large one).
  const std::lock_guard lock(late_->mutex);
  for (const StabilityLimit& l : late_->limits)
    if (l.method == method) return l;
  StabilityLimit limit;
  limit.method = method;
  const MethodInfo& info = method_info(method);
  limit.h = info.adaptive() ? kNaN : kInf;
  if (!info.adaptive() && !info.any_step() && !cancelled_) {
    if (dense_ && !eigenvalues_.empty())
      for (Complex lambda : eigenvalues_)
        limit.h = std::min(limit.h, runge_kutta_limit(method, lambda));
    else
      for (const ModePoint& p : modes_)
        limit.h = std::min(limit.h, mode_limit(method, p.gamma, p.kappa));
    limit.exact = dense_;
  }
  late_->limits.push_back(limit);
  return late_->limits.back();
}

StabilityAnalysis::Growth StabilityAnalysis::transient_growth(
    Method method, double h, const MethodParameters& parameters) const {
  Growth g;
  for (const ModePoint& p : growth_modes_) {
    const double factor = springlab::transient_growth(method, p.gamma, p.kappa, h, parameters);
    if (std::isinf(factor))
      ++g.growing;
    else
      g.factor = std::max(g.factor, factor);
  }
  return g;
}

SubstepChoice choose_substeps(const StabilityLimit& limit, double dt, double fraction, int cap) {
  SubstepChoice choice;
  if (std::isnan(limit.h) || std::isinf(limit.h)) return choice;
  if (limit.h == 0.0) {  // unstable at any step: no number of sub-steps helps
    choice.capped = true;
    return choice;
  }
  const double wanted = std::ceil(dt / (fraction * limit.h) * (1.0 - 1e-12));
  choice.capped = !(wanted <= cap);
  choice.substeps = choice.capped ? cap : std::max(1, static_cast<int>(wanted));
  return choice;
}

StabilityLimit quick_limit(Method method, const Model& model, const State& state) {
  StabilityLimit limit;
  limit.method = method;
  limit.exact = false;
  const MethodInfo& info = method_info(method);
  if (info.adaptive() || info.any_step()) {
    limit.h = info.adaptive() ? kNaN : kInf;
    return limit;
  }
  const Linearised lin(model, state);
  const double kappa = lin.stiffness_bound(), gamma_hi = lin.damping_bound();
  double heaviest = 0.0;
  for (int i : lin.free_particles()) heaviest = std::max(heaviest, model.mass[i]);
  const double gamma_lo = heaviest > 0.0 ? std::min(model.drag / heaviest, gamma_hi) : 0.0;
  const MethodParameters parameters = method_parameters(model);
  limit.h = kInf;
  const auto at = [&](double gamma, double k) {
    limit.h = std::min(limit.h, mode_limit(method, gamma, k, parameters));
  };
  if (analysis_row(method).corner_bound) {
    for (double g : {gamma_lo, gamma_hi})
      for (double k : {0.0, kappa}) at(g, k);
  } else {
    constexpr int kGrid = 48;
    for (int i = 0; i <= kGrid; ++i)
      for (int j = 0; j <= kGrid; ++j)
        at(gamma_lo + (gamma_hi - gamma_lo) * i / kGrid,
           kappa * std::pow(static_cast<double>(j) / kGrid, 2.0));
    limit.h *= 0.9;
  }
  return limit;
}

}  // namespace springlab
