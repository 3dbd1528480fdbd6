#include "springlab/sweep.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <mutex>
#include <sstream>
#include <thread>

#include "dynamics/threads.hpp"
#include "springlab/energy.hpp"
#include "springlab/exact.hpp"
#include "springlab/simulation.hpp"
#include "stability/cancel.hpp"

namespace springlab {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Positions of the free particles at the sample times k H, k = 1..samples.
struct Trajectory {
  std::vector<int> free;
  std::vector<Points> samples;
};

std::vector<int> free_particles(const Model& model) {
  std::vector<int> out;
  for (int i = 0; i < model.particle_count(); ++i)
    if (!model.pinned(i)) out.push_back(i);
  return out;
}

Points take(const State& s, const std::vector<int>& free) {
  Points p(static_cast<int>(free.size()), 3);
  for (std::size_t k = 0; k < free.size(); ++k) p.row(static_cast<int>(k)) = s.x.row(free[k]);
  return p;
}

// RMS over free particles of |a - b|.
double rms(const Points& a, const Points& b) {
  return a.rows() == 0 ? 0.0 : std::sqrt((a - b).rowwise().squaredNorm().mean());
}

// A run of `method` with outer step h, sampled every `every` steps: the error against the
// reference, or infinity once it diverges.
SweepRun run_one(const Model& model, const State& initial, Method method, double h, int every,
                 int samples, double tolerance, const StepSettings& base,
                 const Trajectory& reference, int repeats,
                 const std::shared_ptr<const StabilityAnalysis>& analysis) {
  SweepRun run;
  run.method = method;
  run.h = h;
  run.tolerance = tolerance;
  run.seconds = kInf;
  for (int r = 0; r < std::max(1, repeats); ++r) {
    SimulationSettings s;
    s.method = method;
    s.dt = h;
    s.step = base;
    // The audit without its stop: the error is measured over the whole run, and the audit says
    // whether the run was numerically unstable (with the sweep's one analysis of the scene).
    s.audit_stops = false;
    // An adaptive method without a tolerance runs at fixed steps: every try accepted. (Not an
    // infinite one: times a zero coordinate in RK45's error norm it would make NaN.)
    if (method_info(method).adaptive())
      s.step.tolerance = std::isnan(tolerance) ? 1e300 : tolerance;
    Simulation sim(model, initial, s);
    if (analysis) sim.set_stability(analysis);
    double error = 0.0;
    const auto start = std::chrono::steady_clock::now();
    bool diverged = false;
    for (int k = 0; k < samples && !diverged; ++k) {
      check_cancel();
      if (sim.advance(every) < every) {
        diverged = true;
        break;
      }
      error = std::max(error, rms(take(sim.state(), reference.free), reference.samples[k]));
    }
    run.seconds =
        std::min(run.seconds,
                 std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    run.counters = sim.counters();
    run.diverged = diverged;
    run.error = diverged ? kInf : error;
    if (diverged) run.diverged_at = sim.divergence()->t;
    run.rise = sim.instability() ? sim.instability()->audit.rise : 0.0;
    run.unstable = diverged || sim.instability().has_value();
    const double internal = static_cast<double>(std::max<std::int64_t>(1, sim.counters().accepted));
    run.mean_step = method_info(method).adaptive() ? sim.state().t / internal : h / s.substeps;
    if (diverged) break;  // a diverging run is not worth timing again
  }
  return run;
}

Trajectory rk4_trajectory(const Model& model, const State& initial, double h, int every,
                          int samples) {
  Trajectory t;
  t.free = free_particles(model);
  SimulationSettings s;
  s.method = Method::RK4;
  s.dt = h;
  s.audit_fraction = 0.0;  // the reference is checked by its own convergence
  Simulation sim(model, initial, s);
  for (int k = 0; k < samples; ++k) {
    check_cancel();
    sim.advance(every);
    t.samples.push_back(take(sim.state(), t.free));
  }
  return t;
}

// Runs jobs on `workers` threads, each of which runs its force loops on one thread (the sweep
// is parallel across runs instead). Cancelled, each stops within a sample of the run it makes
// (its loops call check_cancel(): stability/cancel.hpp).
void parallel_for(int jobs, int workers, const std::function<void(int)>& job,
                  const std::atomic<bool>* cancel) {
  try {
    threads::each(jobs, workers, [&](int j) {
      const CancelScope scope(cancel);
      check_cancel();
      job(j);
    });
  } catch (const Cancelled&) {
  }
}

std::string format(double x) {
  std::ostringstream s;
  s.precision(4);
  s << x;
  return s.str();
}

}  // namespace

std::vector<int> step_divisors(double h_min, double h_max, int count) {
  const double ratio = std::max(1.0, h_max / h_min);
  std::vector<int> n;
  for (int k = 0; k < std::max(1, count); ++k) {
    const double f = count > 1 ? static_cast<double>(k) / (count - 1) : 0.0;
    const int d = static_cast<int>(std::lround(std::pow(ratio, f)));
    if (n.empty() || d > n.back()) n.push_back(d);
  }
  return n;
}

double fitted_order(const std::vector<SweepRun>& runs, Method method, double floor, double ceiling,
                    int* points) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  int n = 0;
  for (const SweepRun& r : runs) {
    if (r.method != method || !std::isnan(r.tolerance) || r.diverged) continue;
    if (!(r.error > floor) || !(r.error < ceiling)) continue;
    const double x = std::log(r.h), y = std::log(r.error);
    sx += x;
    sy += y;
    sxx += x * x;
    sxy += x * y;
    ++n;
  }
  if (points) *points = n;
  if (n < 3) return std::numeric_limits<double>::quiet_NaN();
  const double denom = n * sxx - sx * sx;
  return denom > 0 ? (n * sxy - sx * sy) / denom : std::numeric_limits<double>::quiet_NaN();
}

void fit_order_above_floor(const std::vector<SweepRun>& runs, Method method, double floor,
                           double ceiling, MethodSummary& summary) {
  // The fixed-step runs that count, coarse to fine.
  std::vector<const SweepRun*> kept;
  for (const SweepRun& r : runs)
    if (r.method == method && std::isnan(r.tolerance) && !r.diverged && r.error > floor &&
        r.error < ceiling)
      kept.push_back(&r);
  std::sort(kept.begin(), kept.end(),
            [](const SweepRun* a, const SweepRun* b) { return a->h > b->h; });
  // The floor: the longest tail (two runs at least, three left before it) whose every error is
  // at least half the least error before it.
  std::size_t fit = kept.size();
  for (std::size_t start = 3; start + 2 <= kept.size(); ++start) {
    double least = INFINITY;
    for (std::size_t i = 0; i < start; ++i) least = std::min(least, kept[i]->error);
    bool flat = true;
    for (std::size_t i = start; i < kept.size(); ++i) flat = flat && kept[i]->error >= 0.5 * least;
    if (flat) {
      fit = start;
      break;
    }
  }
  std::vector<SweepRun> above;
  for (std::size_t i = 0; i < fit; ++i) above.push_back(*kept[i]);
  summary.order = fitted_order(above, method, floor, ceiling, &summary.fitted_points);
  summary.floor_error = summary.floor_h = std::numeric_limits<double>::quiet_NaN();
  if (fit < kept.size()) {
    summary.floor_h = kept[fit]->h;
    summary.floor_error = 0.0;
    for (std::size_t i = fit; i < kept.size(); ++i)
      summary.floor_error = std::max(summary.floor_error, kept[i]->error);
  }
}

// --- The sweep's jobs: planned once, then run by run_sweep on worker threads or by SweepInSteps
// one at a time.

namespace {

struct SweepJob {
  Method method;
  int divisor;       // fixed step: h = H / divisor
  double tolerance;  // adaptive: NaN otherwise
};

// What every job of a sweep shares, and the result they fill in.
struct SweepPlan {
  const Model& model;
  const State& initial;
  SweepSettings settings;
  std::vector<Method> list;
  double H = 0.0;
  std::vector<int> divisors;
  Trajectory reference;
  std::vector<SweepJob> jobs;
  std::shared_ptr<const StabilityAnalysis> analysis;
  int stability_jobs = 0, drift_jobs = 0, total = 0;
  SweepResult result;

  SweepPlan(const Model& m, const State& s, const SweepSettings& settings_)
      : model(m), initial(s), settings(settings_) {
    list = settings.methods;
    if (list.empty())
      for (const MethodInfo& info : methods()) list.push_back(info.id);
    H = settings.h_max;
    divisors = step_divisors(settings.h_min, H, settings.points);
    result.sample_interval = H;
    result.samples = std::max(1, static_cast<int>(std::lround(settings.duration / H)));
    reference.free = free_particles(model);
  }

  // The reference: the exact solution where the scene has one (then no RK4 runs are needed).
  bool exact_reference() {
    const auto exact = ExactOscillator::detect(model, initial);
    if (!exact) return false;
    for (int k = 1; k <= result.samples; ++k)
      reference.samples.push_back(take(exact->at(initial.t + k * H), reference.free));
    result.reference = "exact solution";
    return true;
  }
  // Else RK4 at a step 16 times smaller than the finest charted (j = 0), checked against RK4 at
  // twice that step (j = 1).
  Trajectory rk4_reference(int j) const {
    const int fine = divisors.back() * 16;
    const double h_ref = H / fine;
    return rk4_trajectory(model, initial, j == 0 ? h_ref : 2 * h_ref, j == 0 ? fine : fine / 2,
                          result.samples);
  }
  void set_rk4_reference(Trajectory fine, const Trajectory& coarse) {
    reference = std::move(fine);
    double difference = 0.0;
    for (int k = 0; k < result.samples; ++k)
      difference = std::max(difference, rms(reference.samples[k], coarse.samples[k]));
    result.reference_error = difference / 15.0;  // RK4: halving the step divides the error by 16
    result.reference = "rk4 at h = " + format(H / (divisors.back() * 16)) + " s (estimated error " +
                       format(result.reference_error) + " m)";
  }

  // The jobs: every method at every step (or tolerance), then stability, then drift.
  void plan_jobs() {
    const Points start = take(initial, reference.free);
    for (const Points& p : reference.samples)
      result.motion = std::max(result.motion, rms(p, start));
    for (Method m : list) {
      // Every method at fixed steps (the order), and the adaptive ones over their tolerances too
      // (what they cost for the accuracy they choose).
      for (int d : divisors) jobs.push_back({m, d, std::numeric_limits<double>::quiet_NaN()});
      if (!method_info(m).adaptive()) continue;
      for (int k = 0; k < settings.points; ++k) {
        const double f = settings.points > 1 ? static_cast<double>(k) / (settings.points - 1) : 0.0;
        jobs.push_back({m, 1, settings.tol_max * std::pow(settings.tol_min / settings.tol_max, f)});
      }
    }
    analysis = std::make_shared<const StabilityAnalysis>(model, initial);
    result.w_max = analysis->w_max();
    const bool drift = settings.drift_h > 0.0 && settings.drift_duration > 0.0;
    stability_jobs = settings.stability ? static_cast<int>(list.size()) : 0;
    drift_jobs = drift ? static_cast<int>(list.size()) : 0;
    bool iterative = false;
    for (Method m : list) iterative = iterative || method_info(m).family == MethodFamily::Iterative;
    total = static_cast<int>(jobs.size()) + stability_jobs + drift_jobs + (iterative ? 1 : 0);
    result.runs.resize(jobs.size());
    result.methods.resize(list.size());
    result.drift.resize(drift_jobs);
  }

  // Runs job j (any thread; jobs write only their own part of the result). Returns its run, if
  // it is one.
  const SweepRun* run_job(int j) {
    if (j < static_cast<int>(jobs.size())) {
      const SweepJob& job = jobs[j];
      result.runs[j] =
          run_one(model, initial, job.method, H / job.divisor, job.divisor, result.samples,
                  job.tolerance, settings.step, reference, settings.repeats, analysis);
      if (!std::isnan(job.tolerance)) result.runs[j].h = H;
      return &result.runs[j];
    }
    j -= static_cast<int>(jobs.size());
    if (j < stability_jobs) {
      MethodSummary& s = result.methods[j];
      s.method = list[j];
      const StabilityLimit& limit = analysis->limit(list[j]);
      s.theoretical_stable_h = limit.h;
      s.theory_exact = limit.exact;
      const MeasuredLimit measured =
          measured_limit(list[j], model, initial, limit, analysis->w_max(), settings.step,
                         settings.stability_budget);
      s.measured_stable_h = measured.h;
      s.measured_resolution = measured.resolution;
      s.measured_at_least = measured.at_least;
      return nullptr;
    }
    j -= stability_jobs;
    if (j >= drift_jobs) {
      // The solver error of the iterative methods at one step a frame (h = 1/60 s, or the
      // coarsest step if larger), from the scene in motion: implicit Euler at that step for the
      // sweep's duration (from a scene at rest, one iteration solves a nearly uniform fall).
      const double h = std::max(H, 1.0 / 60.0);
      SimulationSettings s;
      s.method = Method::ImplicitEuler;
      s.dt = h;
      s.step = settings.step;
      Simulation sim(model, initial, s);
      sim.advance(std::max<std::int64_t>(1, std::llround(settings.duration / h)));
      result.solver =
          solver_error(model, sim.diverged() ? initial : sim.state(), h, 64, settings.step);
      return nullptr;
    }
    DriftTrace& trace = result.drift[j];
    trace.method = list[j];
    SimulationSettings s;
    s.method = list[j];
    s.dt = settings.drift_h;
    s.substeps = settings.drift_substeps;
    s.auto_substeps = settings.drift_auto_substeps;
    s.safety = settings.drift_safety;
    s.step = settings.step;
    s.track_dissipation = true;
    s.audit_fraction = 0.0;  // the drift is what the chart shows, however far it goes
    Simulation sim(model, initial, s);
    sim.set_stability(analysis);  // the same scene: chooses the sub-steps
    trace.substeps = sim.settings().substeps;
    const double scale = sim.energy_scale(), e0 = sim.energy().total();
    const auto steps =
        static_cast<std::int64_t>(std::llround(settings.drift_duration / settings.drift_h));
    const std::int64_t every = std::max<std::int64_t>(1, steps / 400);
    trace.t.push_back(initial.t);
    trace.drift.push_back(0.0);
    for (std::int64_t k = 0; k < steps; k += every) {
      check_cancel();
      if (sim.advance(every) < every) {
        trace.diverged = true;
        break;
      }
      trace.t.push_back(sim.state().t);
      trace.drift.push_back((sim.energy().total() + sim.dissipated() - e0) / scale);
    }
    return nullptr;
  }

  // Orders, over the runs above the reference's error (and round-off) and below a tenth of the
  // motion.
  void finish(bool cancelled) {
    result.cancelled = cancelled;
    for (std::size_t k = 0; k < list.size(); ++k) {
      result.methods[k].method = list[k];
      const double floor =
          std::max(100.0 * result.reference_error, 1e-12 * std::max(1.0, result.motion));
      result.fit_floor = floor;
      result.fit_ceiling = 0.1 * result.motion;
      fit_order_above_floor(result.runs, list[k], floor, 0.1 * result.motion, result.methods[k]);
    }
  }
};

}  // namespace

SweepResult run_sweep(const Model& model, const State& initial, const SweepSettings& settings,
                      const std::function<void(const SweepRun&, int, int)>& on_run,
                      const std::atomic<bool>* cancel) {
  SweepPlan plan(model, initial, settings);
  // Without threads (threads.hpp) every run is made on the caller's.
  const int workers = !threads::kAvailable   ? 1
                      : settings.workers > 0 ? settings.workers
                                             : threads::hardware_workers();
  if (!plan.exact_reference()) {
    std::vector<Trajectory> both(2);
    parallel_for(
        2, std::min(2, workers), [&](int j) { both[j] = plan.rk4_reference(j); }, cancel);
    if (cancel && cancel->load()) {
      plan.result.cancelled = true;
      return std::move(plan.result);
    }
    plan.set_rk4_reference(std::move(both[0]), both[1]);
  }
  {
    const CancelScope scope(cancel);
    try {
      plan.plan_jobs();
    } catch (const Cancelled&) {
      plan.result.cancelled = true;
      return std::move(plan.result);
    }
  }
  std::mutex mutex;
  int done = 0;
  parallel_for(
      plan.total, workers,
      [&](int j) {
        const SweepRun* run = plan.run_job(j);
        std::lock_guard lock(mutex);
        ++done;
        if (on_run) on_run(run ? *run : SweepRun{}, done, plan.total);
      },
      cancel);
  plan.finish(cancel && cancel->load());
  return std::move(plan.result);
}

struct SweepInSteps::Impl {
  Model model;
  State initial;
  SweepPlan plan;
  int phase = 0;  // 0: the reference, 1: its check, 2: the jobs' plan, then job (phase - 3)
  Trajectory fine;
  bool done = false;
  Impl(const Model& m, const State& s, const SweepSettings& settings)
      : model(m), initial(s), plan(model, initial, settings) {}
};

SweepInSteps::SweepInSteps(const Model& model, const State& initial, const SweepSettings& settings)
    : impl_(std::make_unique<Impl>(model, initial, settings)) {}
SweepInSteps::~SweepInSteps() = default;
SweepInSteps::SweepInSteps(SweepInSteps&&) noexcept = default;
SweepInSteps& SweepInSteps::operator=(SweepInSteps&&) noexcept = default;

bool SweepInSteps::step(const std::function<void(const SweepRun&, int done, int total)>& on_run) {
  Impl& s = *impl_;
  SweepPlan& plan = s.plan;
  if (s.done) return false;
  switch (s.phase) {
    case 0:
      if (plan.exact_reference())
        s.phase = 1;  // nothing to check: the jobs' plan next
      else
        s.fine = plan.rk4_reference(0);
      break;
    case 1:
      plan.set_rk4_reference(std::move(s.fine), plan.rk4_reference(1));
      break;
    case 2:
      plan.plan_jobs();
      break;
    default: {
      const int j = s.phase - 3;
      const SweepRun* run = plan.run_job(j);
      if (on_run) on_run(run ? *run : SweepRun{}, j + 1, plan.total);
      break;
    }
  }
  ++s.phase;
  if (s.phase >= 3 && s.phase - 3 == plan.total) {
    plan.finish(false);
    s.done = true;
  }
  return !s.done;
}

bool SweepInSteps::done() const {
  return impl_->done;
}
const SweepResult& SweepInSteps::result() const {
  return impl_->plan.result;
}
std::pair<int, int> SweepInSteps::progress() const {
  const int phase = impl_->phase;
  return {std::max(0, phase - 3), impl_->plan.total};
}

}  // namespace springlab
