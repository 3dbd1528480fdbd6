#include "lesson/lesson_checks.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "chart/compare_charts.hpp"
#include "draw/camera.hpp"
#include "lesson/lesson_library.hpp"
#include "session/ik_kind.hpp"
#include "springlab/energy.hpp"
#include "springlab/iterative_cost.hpp"
#include "springlab/momentum.hpp"
#include "springlab/solver_error.hpp"
#include "springlab/sweep.hpp"
#include "ui/compare_panel.hpp"

namespace springlab::app {

namespace {

using K = LessonClaim::Kind;

std::string fmt(const char* format, double x) {
  char s[64];
  std::snprintf(s, sizeof s, format, x);
  return s;
}

// What a lane did, frame by frame (index k: after k frames).
struct Record {
  std::vector<double> energy, steps, adaptive_step, rejected, x_error;
  std::vector<Momentum> momentum;  // of the free particles (momentum.hpp), with its scales
  std::vector<std::int64_t> born;  // particles born so far (emitters)
  std::vector<double> internal;    // kinetic energy besides the rigid motion's
  std::vector<double> time;        // simulated
  int diverged_at = -1;            // the frame that first showed it diverged (stopped)
  int troubled_at = -1;            // the frame that first showed it diverged or went unstable
  double scale = 1.0;
};

void record(const Lane& lane, int frame, Record& r) {
  const Simulation& sim = lane.sim;
  const Model& m = sim.model();
  const State& s = sim.state();
  const Energy e = sim.energy();
  r.energy.push_back(e.total());
  r.steps.push_back(static_cast<double>(sim.steps_taken()) * sim.settings().substeps);
  r.adaptive_step.push_back(sim.adaptive_step());
  r.rejected.push_back(static_cast<double>(sim.counters().rejected));
  r.time.push_back(s.t);
  r.x_error.push_back(lane.history.exact_x.size() > 0
                          ? std::abs(lane.history.x.back() - lane.history.exact_x.back())
                          : 0.0);
  // Momentum and angular momentum (about the origin) of the free particles; the kinetic energy
  // of their rigid motion: the centre of mass's, and the spin's, L_c^T I^-1 L_c / 2 with L_c and
  // I about the centre of mass (a pseudo-inverse: a straight rope has no inertia about its axis).
  r.momentum.push_back(springlab::momentum(m, s));
  const Vec3 p = r.momentum.back().linear;
  Vec3 xc = Vec3::Zero();
  double mass = 0.0;
  for (int i = 0; i < s.particle_count(); ++i)
    if (!m.pinned(i)) {
      xc += m.mass[i] * s.x.row(i).transpose();
      mass += m.mass[i];
    }
  double rigid = 0.0;
  if (mass > 0.0) {
    xc /= mass;
    const Vec3 vc = p / mass;
    Vec3 lc = Vec3::Zero();
    Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();
    for (int i = 0; i < s.particle_count(); ++i)
      if (!m.pinned(i)) {
        const Vec3 d = s.x.row(i).transpose() - xc;
        lc += m.mass[i] * d.cross(s.v.row(i).transpose() - vc);
        inertia += m.mass[i] * (d.squaredNorm() * Eigen::Matrix3d::Identity() - d * d.transpose());
      }
    // I is symmetric and positive semidefinite: L I^+ L from its eigenvectors, leaving out the
    // directions with no inertia to rounding (as a rank-revealing factorisation would; Eigen's
    // complete orthogonal decomposition did, and GCC 12 warned of its dynamic blocks).
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(inertia);
    const Vec3 along = eig.eigenvectors().transpose() * lc;
    const double floor =
        3.0 * std::numeric_limits<double>::epsilon() * eig.eigenvalues().maxCoeff();
    double spin = 0.0;
    for (int k = 0; k < 3; ++k)
      if (eig.eigenvalues()[k] > floor) spin += along[k] * along[k] / eig.eigenvalues()[k];
    rigid = 0.5 * p.squaredNorm() / mass + 0.5 * spin;
  }
  r.born.push_back(sim.emission().born());
  r.internal.push_back(mass > 0.0 ? std::max(0.0, e.kinetic - rigid) : 0.0);
  if (r.diverged_at < 0 && sim.diverged()) r.diverged_at = frame;
  if (r.troubled_at < 0 && sim.trouble()) r.troubled_at = frame;
  r.scale = sim.energy_scale();
}

// The lane a claim names (a method's or a solver's name), or the first.
const Lane& lane_of(const Session& session, const std::string& name) {
  for (const Lane& lane : session.lanes()) {
    if (lane_row(lane).name == name) return lane;
  }
  return session.lanes().front();
}

// Slope of ln E against the step count over frames [i0, i1]: ln of the growth a step.
double growth_per_step(const Record& r, int i0, int i1) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  int n = 0;
  for (int k = i0; k <= i1; ++k) {
    if (!(r.energy[k] > 0.0)) continue;
    const double x = r.steps[k] - r.steps[i0], y = std::log(r.energy[k]);
    sx += x, sy += y, sxx += x * x, sxy += x * y, ++n;
  }
  const double d = n * sxx - sx * sx;
  return n >= 3 && d > 0 ? (n * sxy - sx * sy) / d : std::numeric_limits<double>::quiet_NaN();
}

ClaimResult orders(const LessonClaim& claim, const Session& session) {
  ClaimResult out{claim, true, ""};
  ui::ComparePanel panel;
  for (const auto& [name, order] : claim.orders) panel.methods.set(*find_method(name), true);
  SweepSettings settings = panel.settings(session);
  settings.workers = 1;  // the same result whatever the machine (only the seconds differ)
  settings.stability = false;
  const SweepResult result =
      run_sweep(session.primary().sim.model(), session.scene().state, settings);
  for (const MethodSummary& m : result.methods) {
    const std::string name = method_info(m.method).name;
    const double expected = claim.orders.at(name);
    out.measured += name + fmt(" %.2f ", m.order);
    if (!(std::abs(m.order - expected) <= claim.within)) out.passed = false;
  }
  if (claim.best.empty()) return out;
  // Each method's error at the largest cost every method reaches, on its log-log line.
  double cost = std::numeric_limits<double>::infinity(), floor = 0.0;
  for (const MethodSummary& m : result.methods) {
    double most = 0.0, least = std::numeric_limits<double>::infinity();
    for (const SweepRun& run : result.runs)
      if (run.method == m.method && !run.diverged) {
        most = std::max(most, chart::work(run.counters));
        least = std::min(least, chart::work(run.counters));
      }
    cost = std::min(cost, most);
    floor = std::max(floor, least);
  }
  cost = std::max(cost, floor);
  std::string best;
  double best_error = std::numeric_limits<double>::infinity();
  for (const MethodSummary& m : result.methods) {
    std::vector<std::pair<double, double>> line;  // (ln cost, ln error)
    for (const SweepRun& run : result.runs)
      if (run.method == m.method && !run.diverged && run.error > 0.0)
        line.emplace_back(std::log(chart::work(run.counters)), std::log(run.error));
    std::sort(line.begin(), line.end());
    if (line.empty()) continue;
    const double c = std::clamp(std::log(cost), line.front().first, line.back().first);
    double error = line.back().second;
    for (std::size_t k = 1; k < line.size(); ++k)
      if (c <= line[k].first) {
        const double s =
            (c - line[k - 1].first) / std::max(1e-300, line[k].first - line[k - 1].first);
        error = line[k - 1].second + s * (line[k].second - line[k - 1].second);
        break;
      }
    if (error < best_error) best_error = error, best = method_info(m.method).name;
  }
  out.measured += "; least error at the work of " + fmt("%.3g", cost) +
                  " force evaluations: " + best + fmt(" (%.2g m)", std::exp(best_error));
  if (best != claim.best) out.passed = false;
  return out;
}

// (Each judge below takes from the window the names its cases read, so that the cases read as
// they did in one function; a kind not its own falls through to `default`.)
// A claim's window over a lane's record: its frames from i0 to i1, and to sane_end while the lane
// was sane (the frame before it diverged); the lane's energy scale.
struct Window {
  const LessonClaim& c;
  const Session& session;
  const Lane& lane;
  const Record& r;
  double fps;
  int i0, i1, sane_end;
  double scale;
};

// Energy and motion: grows, decays, bounded, diverges, holds, follows the exact solution, the
// stated limit, the adaptive step.
void judge_energy_and_motion(const Window& w, ClaimResult& out) {
  const LessonClaim& c = w.c;
  const Lane& lane = w.lane;
  const Record& r = w.r;
  const int i0 = w.i0, i1 = w.i1, sane_end = w.sane_end;
  const double scale = w.scale, fps = w.fps;
  switch (c.kind) {
    case K::EnergyGrows:
    case K::EnergyDecays: {
      const bool grows = c.kind == K::EnergyGrows;
      if (c.per_step) {
        const double g = std::exp(growth_per_step(r, i0, sane_end));
        out.measured = fmt("x%.6f a step", g) + fmt(" (expected x%.6f)", *c.per_step);
        out.passed = std::abs(g - *c.per_step) <= c.within * std::abs(*c.per_step - 1);
      } else {
        const double change = (r.energy[sane_end] - r.energy[i0]) / scale;
        out.measured = fmt("changed by %.3g of the energy scale", change);
        out.passed = grows ? change > 0.05 : change < -0.05;
      }
      break;
    }
    case K::EnergyBounded: {
      double worst = 0.0;
      for (int k = i0; k <= sane_end; ++k)
        worst = std::max(worst, std::abs(r.energy[k] - r.energy[i0]) / scale);
      out.measured = fmt("within %.3g of the energy scale", worst);
      out.passed = worst <= c.within && r.troubled_at < 0;
      break;
    }
    case K::Diverges:
      out.measured = r.troubled_at < 0
                         ? "did not diverge"
                         : fmt(lane.sim.trouble()->unstable ? "went unstable at t = %.3g s"
                                                            : "diverged at t = %.3g s",
                               lane.sim.trouble()->t) +
                               fmt(" (seen in frame %.0f)", r.troubled_at);
      out.passed = r.troubled_at >= 0 && r.troubled_at <= std::lround(*c.by * fps);
      break;
    case K::Holds:
      out.measured = r.troubled_at < 0
                         ? fmt("held to t = %.3g s", r.time.back())
                         : fmt(lane.sim.trouble()->unstable ? "went unstable at t = %.3g s"
                                                            : "diverged at t = %.3g s",
                               lane.sim.trouble()->t);
      out.passed = r.troubled_at < 0;
      break;
    case K::FollowsExact: {
      double worst = 0.0;
      for (int k = i0; k <= i1; ++k) worst = std::max(worst, r.x_error[k]);
      out.measured = fmt("max |x - x_exact| = %.3g m", worst);
      out.passed = worst <= c.within && r.troubled_at < 0;
      break;
    }
    case K::Limit: {
      const double h = const_cast<Simulation&>(lane.sim).stable_step();
      out.measured = fmt("stated limit h = %.5g s", h);
      out.passed = std::abs(h / c.h - 1.0) <= c.within;
      break;
    }
    case K::StepsAdapt: {
      double lo = std::numeric_limits<double>::infinity(), hi = 0.0;
      for (int k = std::max(i0, 1); k <= sane_end; ++k)
        if (r.adaptive_step[k] > 0.0)
          lo = std::min(lo, r.adaptive_step[k]), hi = std::max(hi, r.adaptive_step[k]);
      const double rejected = r.rejected[sane_end] - r.rejected[i0];
      out.measured = fmt("%.0f tries rejected", rejected) + fmt(", step from %.3g", lo) +
                     fmt(" to %.3g s", hi);
      out.passed = rejected > 0 && hi >= c.ratio * lo;
      break;
    }
    default:
      break;
  }
}

// Momentum and drag: kept, changed, slowed by drag, the wiggles decaying.
void judge_momentum_and_drag(const Window& w, ClaimResult& out) {
  const LessonClaim& c = w.c;
  const Lane& lane = w.lane;
  const Record& r = w.r;
  const int i0 = w.i0, sane_end = w.sane_end;
  const double fps = w.fps;
  switch (c.kind) {
    case K::MomentumKept: {
      const Momentum &from = r.momentum[i0], &to = r.momentum[sane_end];
      const double p0 = from.linear.norm(), l0 = from.angular.norm();
      const double dp = (to.linear - from.linear).norm() / std::max(p0, 1e-300);
      const double dl = (to.angular - from.angular).norm() / std::max(l0, 1e-300);
      out.measured = fmt("|P| = %.4g kg m/s", p0) + fmt(" changed by %.2g of it", dp) +
                     fmt(", |L| = %.4g kg m^2/s", l0) + fmt(" by %.2g", dl);
      out.passed = p0 > 0.0 && dp <= c.within && l0 > 0.0 && dl <= c.within;
      break;
    }
    case K::LinearMomentumKept:
    case K::LinearMomentumChanges: {
      // Over the window, the largest change from its start: a break need not last to its end.
      double most = 0.0;
      for (int k = i0; k <= sane_end; ++k)
        most = std::max(most, momentum_change(r.momentum[i0], r.momentum[k]).linear);
      out.measured =
          fmt("P changed by %.2g of sum m|v|", most) +
          fmt(" (%.4g kg m/s)", r.momentum[i0].linear_scale) +
          (free_body(lane.sim.model()) ? "" : "; not a free body: an outside force acts");
      out.passed = free_body(lane.sim.model()) && r.momentum[i0].linear_scale > 0.0 &&
                   (c.kind == K::LinearMomentumKept ? most <= c.within : most > c.above);
      break;
    }
    case K::DragSlows: {
      const Model& m = lane.sim.model();
      double mass = 0.0;
      int n = 0;
      for (int i = 0; i < m.particle_count(); ++i)
        if (!m.pinned(i)) mass += m.mass[i], ++n;
      const double expected = std::exp(-m.drag * n * (r.time[sane_end] - r.time[i0]) / mass);
      const double measured =
          r.momentum[sane_end].linear.norm() / std::max(r.momentum[i0].linear.norm(), 1e-300);
      out.measured =
          fmt("speed ratio %.4f", measured) + fmt(" (exp(-k_drag n t / M) = %.4f)", expected);
      out.passed = std::abs(measured / expected - 1.0) <= c.within;
      break;
    }
    case K::InternalDecays: {
      // Peaks, not moments: the wiggles trade their energy with the springs' twice a period.
      const int second = static_cast<int>(std::lround(fps));
      const auto peak = [&](int a, int b) {
        double most = 0.0;
        for (int k = std::max(a, i0); k <= std::min(b, sane_end); ++k)
          most = std::max(most, r.internal[k]);
        return most;
      };
      const double first = peak(i0, i0 + second), last = peak(sane_end - second, sane_end);
      const double ratio = last / std::max(first, 1e-300);
      out.measured = fmt("the wiggles' kinetic energy peaks at %.4g J", first) +
                     fmt(" in the first second, %.3g J", last) +
                     fmt(" in the last (%.3g of it)", ratio);
      out.passed = first > 0.0 && ratio <= c.below;
      break;
    }
    default:
      break;
  }
}

// ActsAs: the stiffness a row acts as at rest under load, the stretch's RMS against the spring
// model's under the same load (their ratio: k_s x ratio), within [c.above, c.below].
void judge_acts_as(const Lane& lane, const LessonClaim& c, ClaimResult& out) {
  const Model& model = lane.sim.model();
  if (!loaded_balance(model)) {  // (iterative_cost.hpp: no load, no stiffness to act as)
    out.measured =
        "no load carried to pins (free, or resting on a collider): no effective stiffness";
    return;
  }
  if (!at_rest(model, lane.sim.state(), lane.sim.energy_scale())) {
    out.measured = fmt("not at rest at the end (kinetic energy %.3g J)",
                       kinetic_energy(model, lane.sim.state()));
    return;
  }
  const Softness s = softness(model, lane.sim.state());
  out.measured = fmt("stretch %.3g m RMS", s.stretch) +
                 fmt(" against the spring model's %.3g m", s.model_stretch) +
                 fmt(": k_s x%.3g", s.ratio());
  out.passed = (c.below == 0.0 || s.ratio() <= c.below) && s.ratio() >= c.above;
}

// PosesDiffer: every inverse kinematics lane reached the target, and the closest two poses (the
// largest distance between their joints) are at least c.min apart.
void judge_poses_differ(const Session& session, const LessonClaim& c, ClaimResult& out) {
  double closest = std::numeric_limits<double>::infinity();
  bool converged = true;
  const auto lanes = session.lanes();
  for (std::size_t a = 0; a < lanes.size(); ++a) {
    converged = converged && ik_lane(lanes[a]).status.converged;
    for (std::size_t b = a + 1; b < lanes.size(); ++b) {
      const auto pa = ik_lane(lanes[a]).chain.positions(), pb = ik_lane(lanes[b]).chain.positions();
      double apart = 0.0;
      for (std::size_t j = 0; j < pa.size(); ++j) apart = std::max(apart, (pa[j] - pb[j]).norm());
      closest = std::min(closest, apart);
    }
  }
  out.measured = std::string(converged ? "all reached the target" : "not all reached the target") +
                 fmt(", the closest two poses %.3g m apart", closest);
  out.passed = converged && closest >= c.min;
}

// The iterative rows, inverse kinematics and emitters: the stiffness a row acts as, its solver
// converging, an arm out of reach, the solvers' poses apart, bursts.
void judge_solvers_and_scenes(const Window& w, ClaimResult& out) {
  const LessonClaim& c = w.c;
  const Lane& lane = w.lane;
  const Record& r = w.r;
  const int i0 = w.i0, i1 = w.i1;
  const Session& session = w.session;
  switch (c.kind) {
    case K::ActsAs:
      judge_acts_as(lane, c, out);
      break;
    case K::SolverConverges: {
      // From where the lane is at the claim's end: one step at its h, 8 and 64 iterations.
      const SolverErrorStudy study = solver_error(lane.sim.model(), lane.sim.state(), lane.sim.h(),
                                                  64, lane.sim.settings().step);
      for (const SolverErrorCurve& curve : study.curves) {
        if (curve.method != lane.sim.settings().method) continue;
        const double e8 = curve.error[3], e64 = curve.error[6];
        const double rate = std::pow(e64 / std::max(e8, 1e-300), 1.0 / 56.0);
        out.measured = fmt("%.3g of the step from 8 to 64 iterations", e8) + fmt(" to %.3g", e64) +
                       fmt(": x%.4f an iteration", rate);
        out.passed = e8 > 0.0 && rate <= c.below;
      }
      break;
    }
    case K::OutOfReach: {
      const IkLane& ik = ik_lane(lane);
      const Eigen::Vector2d base = ik.chain.base, to = ik.target - base;
      const double reach = ik.chain.reach();
      const Eigen::Vector2d along = base + to.normalized() * reach;
      const double off = (ik.chain.effector() - along).norm();
      out.measured = fmt("target %.3g m from the base", to.norm()) + fmt(", reach %.3g m", reach) +
                     fmt(", end %.3g m off the straight line", off);
      out.passed = !ik.status.reachable && to.norm() > reach && off <= 0.01 * reach;
      break;
    }
    case K::PosesDiffer:
      judge_poses_differ(session, c, out);
      break;
    case K::Bursts: {
      // Every frame with more than half a burst's births: whole bursts of `count`, and at most a
      // shell born beside them.
      int bursts = 0, odd = 0;
      for (int k = std::max(i0, 1); k <= i1; ++k) {
        const std::int64_t births = r.born[k] - r.born[k - 1];
        if (births <= c.count / 2) continue;
        bursts += static_cast<int>(births / c.count);
        if (births % c.count > 1) ++odd;
      }
      out.measured =
          std::to_string(bursts) + " bursts" +
          (odd ? ", " + std::to_string(odd) + " frames with births not a whole number of bursts"
               : "");
      out.passed = bursts > 0 && odd == 0;
      break;
    }
    default:
      break;
  }
}

ClaimResult judge(const LessonClaim& c, const Session& session, const std::vector<Record>& records,
                  double fps, int frames) {
  ClaimResult out{c, false, ""};
  const Lane& lane = lane_of(session, c.lane);
  const Record& r = records[&lane - session.lanes().data()];
  const int i0 = std::clamp(static_cast<int>(std::lround(c.from * fps)), 0, frames);
  int i1 = std::clamp(static_cast<int>(std::lround(c.to.value_or(frames / fps) * fps)), i0, frames);
  // Energy and motion claims look at the lane while it is sane: up to the frame before it diverged.
  const int sane_end = r.diverged_at < 0 ? i1 : std::clamp(r.diverged_at - 1, i0, i1);
  const double scale = std::max(r.scale, 1e-300);
  if (c.kind == K::Orders) return orders(c, session);
  const Window w{c, session, lane, r, fps, i0, i1, sane_end, scale};
  judge_energy_and_motion(w, out);
  judge_momentum_and_drag(w, out);
  judge_solvers_and_scenes(w, out);  // (Particles: measured while playing, check_step)
  return out;
}

// The share of a lane's free particles (those alive, where the scene emits them) that land in the
// scene camera's 16:9 frame: every lane's view shows at least that frame (draw/lane_views.hpp).
double share_in_frame(const Lane& lane, const draw::ViewCamera& frame) {
  const State& s = lane.shown();
  const Model& m = lane.sim.model();
  const bool emits = !m.emitters.empty();
  int in = 0, counted = 0;
  for (int i = 0; i < s.particle_count(); ++i) {
    if (m.pinned(i) || (emits && !lane.sim.emission().alive(i))) continue;
    const Eigen::Vector3d p = draw::project(frame, s.x.row(i).transpose(), 1600, 900);
    ++counted;
    in += p.x() >= 0 && p.x() <= 1600 && p.y() >= 0 && p.y() <= 900 && p.z() >= 0 && p.z() <= 1;
  }
  return counted == 0 ? 1.0 : static_cast<double>(in) / counted;
}

// InSight: over every frame, each lane that holds to the step's end (never diverges nor goes
// unstable) keeps at least half of its free particles in the frame. A lane that diverges leaving
// the frame is the lesson (its claim says so), and is drawn as its last sane state once caught.
struct Sight {
  std::vector<double> least;  // a lane's least share, and the frame that showed it
  std::vector<int> at;
  void take(const Session& session, const draw::ViewCamera& frame_camera, int frame) {
    least.resize(session.lanes().size(), 1.0);
    at.resize(session.lanes().size(), 0);
    for (std::size_t n = 0; n < session.lanes().size(); ++n) {
      const double share = share_in_frame(session.lanes()[n], frame_camera);
      if (share < least[n]) least[n] = share, at[n] = frame;
    }
  }
  ClaimResult result(const Session& session, double fps) const {
    LessonClaim claim;
    claim.kind = K::InSight;
    int worst = -1;
    for (std::size_t n = 0; n < least.size(); ++n) {
      const Lane& lane = session.lanes()[n];
      if (lane.wild() || lane.sim.trouble()) continue;
      if (worst < 0 || least[n] < least[worst]) worst = static_cast<int>(n);
    }
    if (worst < 0 || least[worst] >= 1.0)
      return {claim, true, "all of every holding lane's, in every frame"};
    const std::string who(lane_row(session.lanes()[worst]).name);
    return {claim, least[worst] >= 0.5,
            who + fmt(": %.1f %% at least", 100.0 * least[worst]) +
                fmt(", at t = %.3g s", at[worst] / fps)};
  }
};

}  // namespace

std::vector<ClaimResult> check_step(const LessonStep& step, double fps) {
  std::unique_ptr<Session> session = step_session(step, fps, false);
  const int frames = static_cast<int>(std::lround(step.duration * fps));
  std::vector<Record> records(session->lanes().size());
  std::vector<ClaimResult> results(step.claims.size());
  const draw::ViewCamera frame_camera = draw::view_camera(session->scene().camera, 1600, 900);
  Sight sight;
  const auto take = [&](int frame) {
    for (std::size_t k = 0; k < records.size(); ++k) record(session->lanes()[k], frame, records[k]);
    sight.take(*session, frame_camera, frame);
    for (std::size_t k = 0; k < step.claims.size(); ++k) {
      const LessonClaim& c = step.claims[k];
      if (c.kind != K::Particles || std::lround(*c.at * fps) != frame) continue;
      const int n = session->primary().sim.emission().alive_count();
      results[k] = {c, std::abs(n / c.about - 1.0) <= c.within, std::to_string(n) + " alive"};
    }
  };
  take(0);
  for (int k = 1; k <= frames; ++k) {
    session->advance_frame();
    take(k);
  }
  for (std::size_t k = 0; k < step.claims.size(); ++k)
    if (step.claims[k].kind != K::Particles)
      results[k] = judge(step.claims[k], *session, records, fps, frames);
  results.push_back(sight.result(*session, fps));
  return results;
}

}  // namespace springlab::app
