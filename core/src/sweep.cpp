#include "springlab/sweep.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <mutex>
#include <sstream>
#include <thread>

#include "springlab/energy.hpp"
#include "springlab/exact.hpp"
#include "springlab/simulation.hpp"
#include "threads.hpp"

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
                 int samples, double tolerance, const StepSettings& base, const Trajectory& reference,
                 int repeats) {
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
    // The audit's bookkeeping without its stop: the error is measured over the whole run, and
    // the energy the method created says whether the run was numerically unstable.
    s.track_dissipation = true;
    s.audit_fraction = 0.0;
    // An adaptive method without a tolerance runs at fixed steps: every try accepted. (Not an
    // infinite one: times a zero coordinate in RK45's error norm it would make NaN.)
    if (method_info(method).adaptive) s.step.tolerance = std::isnan(tolerance) ? 1e300 : tolerance;
    Simulation sim(model, initial, s);
    double error = 0.0;
    const auto start = std::chrono::steady_clock::now();
    bool diverged = false;
    for (int k = 0; k < samples && !diverged; ++k) {
      if (sim.advance(every) < every) {
        diverged = true;
        break;
      }
      error = std::max(error, rms(take(sim.state(), reference.free), reference.samples[k]));
    }
    run.seconds = std::min(run.seconds, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    run.counters = sim.counters();
    run.diverged = diverged;
    run.error = diverged ? kInf : error;
    if (diverged) run.diverged_at = sim.divergence()->t;
    run.created = sim.created_energy();
    run.unstable = diverged || run.created > kAuditFraction * sim.energy_scale();
    const double internal = static_cast<double>(std::max<std::int64_t>(1, sim.counters().accepted));
    run.mean_step = method_info(method).adaptive ? sim.state().t / internal : h / s.substeps;
    if (diverged) break;  // a diverging run is not worth timing again
  }
  return run;
}

Trajectory rk4_trajectory(const Model& model, const State& initial, double h, int every, int samples) {
  Trajectory t;
  t.free = free_particles(model);
  SimulationSettings s;
  s.method = Method::RK4;
  s.dt = h;
  s.audit_fraction = 0.0;  // the reference is checked by its own convergence
  Simulation sim(model, initial, s);
  for (int k = 0; k < samples; ++k) {
    sim.advance(every);
    t.samples.push_back(take(sim.state(), t.free));
  }
  return t;
}

// Runs jobs on `workers` threads, each of which runs its force loops on one thread (the sweep
// is parallel across runs instead).
void parallel_for(int jobs, int workers, const std::function<void(int)>& job, const std::atomic<bool>* cancel) {
  std::atomic<int> next{0};
  const int caller_threads = threads::max_team();
  const auto work = [&] {
    threads::set_max_team(1);
    for (int j; (j = next++) < jobs;) {
      if (cancel && cancel->load()) return;
      job(j);
    }
  };
  std::vector<std::thread> threads;
  for (int w = 1; w < workers; ++w) threads.emplace_back(work);
  work();
  for (auto& t : threads) t.join();
  threads::set_max_team(caller_threads);
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

double fitted_order(const std::vector<SweepRun>& runs, Method method, double floor, double ceiling, int* points) {
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

SweepResult run_sweep(const Model& model, const State& initial, const SweepSettings& settings,
                      const std::function<void(const SweepRun&, int, int)>& on_run,
                      const std::atomic<bool>* cancel) {
  SweepResult result;
  std::vector<Method> list = settings.methods;
  if (list.empty())
    for (const MethodInfo& m : methods()) list.push_back(m.id);
  const double H = settings.h_max;
  const std::vector<int> divisors = step_divisors(settings.h_min, H, settings.points);
  result.sample_interval = H;
  result.samples = std::max(1, static_cast<int>(std::lround(settings.duration / H)));
  // Without threads (threads.hpp) every run is made on the caller's.
  const int workers = !threads::kAvailable ? 1 : settings.workers > 0 ? settings.workers : threads::hardware_workers();

  // The reference.
  Trajectory reference;
  reference.free = free_particles(model);
  if (const auto exact = ExactOscillator::detect(model, initial)) {
    for (int k = 1; k <= result.samples; ++k)
      reference.samples.push_back(take(exact->at(initial.t + k * H), reference.free));
    result.reference = "exact solution";
  } else {
    const int fine = divisors.back() * 16;
    const double h_ref = H / fine;
    std::vector<Trajectory> both(2);
    parallel_for(2, std::min(2, workers), [&](int j) {
      both[j] = rk4_trajectory(model, initial, j == 0 ? h_ref : 2 * h_ref, j == 0 ? fine : fine / 2, result.samples);
    }, nullptr);
    reference = std::move(both[0]);
    double difference = 0.0;
    for (int k = 0; k < result.samples; ++k)
      difference = std::max(difference, rms(reference.samples[k], both[1].samples[k]));
    result.reference_error = difference / 15.0;  // RK4: halving the step divides the error by 16
    result.reference = "rk4 at h = " + format(h_ref) + " s (estimated error " + format(result.reference_error) + " m)";
  }
  const Points start = take(initial, reference.free);
  for (const Points& p : reference.samples) result.motion = std::max(result.motion, rms(p, start));

  // The jobs: every method at every step (or tolerance), then stability, then drift.
  struct Job {
    Method method;
    int divisor;       // fixed step: h = H / divisor
    double tolerance;  // adaptive: NaN otherwise
  };
  std::vector<Job> jobs;
  for (Method m : list) {
    // Every method at fixed steps (the order), and the adaptive ones over their tolerances too
    // (what they cost for the accuracy they choose).
    for (int d : divisors) jobs.push_back({m, d, std::numeric_limits<double>::quiet_NaN()});
    if (!method_info(m).adaptive) continue;
    for (int k = 0; k < settings.points; ++k) {
      const double f = settings.points > 1 ? static_cast<double>(k) / (settings.points - 1) : 0.0;
      jobs.push_back({m, 1, settings.tol_max * std::pow(settings.tol_min / settings.tol_max, f)});
    }
  }
  const auto shared = std::make_shared<const StabilityAnalysis>(model, initial);
  const StabilityAnalysis& analysis = *shared;
  result.w_max = analysis.w_max();
  const bool drift = settings.drift_h > 0.0 && settings.drift_duration > 0.0;
  const int stability_jobs = settings.stability ? static_cast<int>(list.size()) : 0;
  const int drift_jobs = drift ? static_cast<int>(list.size()) : 0;
  const int total = static_cast<int>(jobs.size()) + stability_jobs + drift_jobs;

  result.runs.resize(jobs.size());
  result.methods.resize(list.size());
  result.drift.resize(drift_jobs);
  std::mutex mutex;
  int done = 0;
  const auto finished = [&](const SweepRun* run) {
    std::lock_guard lock(mutex);
    ++done;
    if (on_run) on_run(run ? *run : SweepRun{}, done, total);
  };

  parallel_for(total, workers, [&](int j) {
    if (j < static_cast<int>(jobs.size())) {
      const Job& job = jobs[j];
      result.runs[j] = run_one(model, initial, job.method, H / job.divisor, job.divisor, result.samples,
                               job.tolerance, settings.step, reference, settings.repeats);
      if (!std::isnan(job.tolerance)) result.runs[j].h = H;
      finished(&result.runs[j]);
      return;
    }
    j -= static_cast<int>(jobs.size());
    if (j < stability_jobs) {
      MethodSummary& s = result.methods[j];
      s.method = list[j];
      const StabilityLimit& limit = analysis.limit(list[j]);
      s.theoretical_stable_h = limit.h;
      s.theory_exact = limit.exact;
      const MeasuredLimit measured =
          measured_limit(list[j], model, initial, limit, analysis.w_max(), settings.step, settings.stability_budget);
      s.measured_stable_h = measured.h;
      s.measured_resolution = measured.resolution;
      finished(nullptr);
      return;
    }
    j -= stability_jobs;
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
    sim.set_stability(shared);  // the same scene: chooses the sub-steps
    trace.substeps = sim.settings().substeps;
    const double scale = sim.energy_scale(), e0 = sim.energy().total();
    const auto steps = static_cast<std::int64_t>(std::llround(settings.drift_duration / settings.drift_h));
    const std::int64_t every = std::max<std::int64_t>(1, steps / 400);
    trace.t.push_back(initial.t);
    trace.drift.push_back(0.0);
    for (std::int64_t k = 0; k < steps; k += every) {
      if (sim.advance(every) < every) {
        trace.diverged = true;
        break;
      }
      trace.t.push_back(sim.state().t);
      trace.drift.push_back((sim.energy().total() + sim.dissipated() - e0) / scale);
    }
    finished(nullptr);
  }, cancel);
  result.cancelled = cancel && cancel->load();

  // Orders, over the runs above the reference's error (and round-off) and below a tenth of the
  // motion.
  for (std::size_t k = 0; k < list.size(); ++k) {
    result.methods[k].method = list[k];
    const double floor = std::max(100.0 * result.reference_error, 1e-12 * std::max(1.0, result.motion));
    result.methods[k].order = fitted_order(result.runs, list[k], floor, 0.1 * result.motion, &result.methods[k].fitted_points);
  }
  return result;
}

}  // namespace springlab
