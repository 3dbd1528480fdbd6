// springlab run SCENE: simulates without graphics, prints a summary, optionally writes a CSV
// trace (docs/command-line.md): a header, then one row per step (every K-th with --every), columns
// t,kinetic,potential,total, then x0,y0,z0,vx0,vy0,vz0 for particle 0, and so on.
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>

#include "cli/commands.hpp"
#include "cli/options.hpp"
#include "springlab/cells.hpp"
#include "springlab/error.hpp"
#include "springlab/iterative_cost.hpp"
#include "springlab/momentum.hpp"
#include "util/atomic_file.hpp"
#include "util/progress.hpp"

namespace springlab::app {

namespace {

struct RunOptions {
  std::string scene;
  SimOptions sim;
  std::optional<std::string> csv;
  std::int64_t every = 1;
};

// Shortest text that reads back as the same double.
void put_number(std::FILE* f, double x, char separator) {
  char buffer[32];
  auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, x);
  *end++ = separator;
  std::fwrite(buffer, 1, static_cast<std::size_t>(end - buffer), f);
}

void write_header(std::FILE* f, int particles) {
  std::fputs("t,kinetic,potential,total", f);
  for (int i = 0; i < particles; ++i)
    std::fprintf(f, ",x%d,y%d,z%d,vx%d,vy%d,vz%d", i, i, i, i, i, i);
  std::fputc('\n', f);
}

void write_row(std::FILE* f, const Simulation& sim) {
  const State& s = sim.state();
  const Energy e = sim.energy();
  put_number(f, s.t, ',');
  put_number(f, e.kinetic, ',');
  put_number(f, e.potential(), ',');
  put_number(f, e.total(), s.particle_count() > 0 ? ',' : '\n');
  for (int i = 0; i < s.particle_count(); ++i) {
    const bool last = i + 1 == s.particle_count();
    for (int c = 0; c < 3; ++c) put_number(f, s.x(i, c), ',');
    for (int c = 0; c < 3; ++c) put_number(f, s.v(i, c), c == 2 && last ? '\n' : ',');
  }
}

std::string format(double x) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.6g", x);
  return buffer;
}

// An inverse-kinematics scene: each solver from the starting pose to the target, as far as it
// gets, one line each.
int run_ik(const Scene& scene, bool csv) {
  if (csv)
    throw InputError("--csv: '" + scene.name +
                     "' is an inverse-kinematics scene, which has no trace over time");
  const IkScene& ik = *scene.ik;
  const Eigen::Vector2d target = scene.state.x.row(ik.target).head<2>().transpose();
  const double distance = (target - ik.chain.base).norm();
  std::printf("scene      %s (inverse kinematics: %d links, reach %.4g m)\n", scene.name.c_str(),
              ik.chain.size(), ik.chain.reach());
  const IkStatus start = ik_status(ik.chain, target, ik.settings);
  std::printf(
      "target     (%.4g, %.4g), %.4g m from the base: %s\n", target.x(), target.y(), distance,
      start.reachable ? "within reach" : "out of reach (the chain can only stretch towards it)");
  for (IkSolver solver : ik.solvers) {
    IkChain chain = ik.chain;
    const IkStatus s = ik_solve(solver, chain, target, ik.settings);
    std::printf("%-10s %s after %d iterations, error %.3g m (tolerance %.3g m)\n",
                ik_solver_info(solver).name,
                s.converged ? "reached"
                : s.stalled ? "stuck"
                            : "not reached",
                s.iterations, s.error, ik.settings.tolerance);
  }
  return kOk;
}

// An iterative row's account at the end of a run: the energy it took out (or put in) beyond the
// physics' damping, and how far its springs stretch against the spring model's own.
void print_iterative_account(const Simulation& sim) {
  // What it pays instead of a limit (springlab/iterative_cost.hpp).
  // Taken out in all: E0 + W - E = -net; by the physics' damping: dissipated; the rest, the
  // method's own. Negative, it put energy in: its springs' stretch, counted with k_s, grew.
  const double artificial = -(sim.net_energy() + sim.dissipated());
  if (!energy_account_closed(sim.model()))
    std::printf(
        "damping    not stated: the colliders' contacts and friction take energy the account does "
        "not "
        "count apart\n");
  else if (artificial >= 0.0)
    std::printf(
        "damping    %s J taken out beyond the physics' damping (%s W on average; the physics' "
        "damping took %s J)\n",
        format(artificial).c_str(), format(artificial / sim.state().t).c_str(),
        format(sim.dissipated()).c_str());
  else
    std::printf(
        "energy in  %s J put in beyond the physics (%s W on average): its springs ended stretched "
        "or compressed further than k_s "
        "would hold them, and that counts with k_s (the physics' damping took %s J)\n",
        format(-artificial).c_str(), format(-artificial / sim.state().t).c_str(),
        format(sim.dissipated()).c_str());
  const double lengths = length_ratio(sim.model(), sim.state());
  if (!at_rest(sim.model(), sim.state(), sim.energy_scale())) {
    std::printf("stretch    in motion: springs at %sx their rest length in all\n",
                format(lengths).c_str());
  } else if (loaded_balance(sim.model())) {
    const Softness s = softness(sim.model(), sim.state());
    std::printf(
        "stretch    at rest, springs at %sx their rest length in all; %s m RMS against the spring "
        "model's %s m "
        "under the same load: its springs act as k_s x %s\n",
        format(lengths).c_str(), format(s.stretch).c_str(), format(s.model_stretch).c_str(),
        format(s.ratio()).c_str());
  } else {
    std::printf(
        "stretch    at rest, springs at %sx their rest length in all; no load carried to pins "
        "(free, or resting "
        "on a collider), so no effective stiffness to state\n",
        format(lengths).c_str());
  }
}

// The stability line: the stiffest mode, h w_max, the method's limit and the mode that sets it.
void print_stability(const Simulation& sim, const StabilityAnalysis& stability,
                     const StabilityLimit& limit, const MethodInfo& m) {
  if (stability.oscillates()) {
    std::printf("stability  w_max = %s rad/s (Gershgorin bound %s), h w_max = %s; %s: %s",
                format(stability.w_max()).c_str(), format(stability.w_bound()).c_str(),
                format(sim.h() * stability.w_max()).c_str(), m.name, describe(limit).c_str());
    if (limit.mode && std::isfinite(limit.h))
      std::printf(", set by a mode of %s rad/s with damping ratio %s",
                  format(limit.mode->w).c_str(), format(limit.mode->damping_ratio()).c_str());
    std::printf(" (at the scene's equilibrium, %s, %s s)\n",
                stability.dense() ? "every eigenvalue" : "Lanczos",
                format(stability.seconds()).c_str());
  } else {
    std::printf("stability  no oscillating modes (%s); %s: %s\n",
                stability.no_modes_reason().c_str(), m.name, describe(limit).c_str());
  }
}

// The cost line: force evaluations, and a solver's iterations, solves, corrections, halvings, or
// an adaptive method's accepted and rejected steps.
void print_cost(const Counters& c, const MethodInfo& m) {
  std::printf("cost       %lld force evaluations", static_cast<long long>(c.force_evals));
  if (m.family == MethodFamily::Iterative)
    std::printf(", %lld solver iterations (%s)", static_cast<long long>(c.solver_iterations),
                m.iteration_unit ? m.iteration_unit : "iterations");
  else if (c.linear_solves)
    std::printf(", %lld linear solves (%lld CG iterations)",
                static_cast<long long>(c.linear_solves),
                static_cast<long long>(c.solver_iterations));
  if (c.newton_corrections)
    std::printf(", %lld Newton corrections (%.3g a step)",
                static_cast<long long>(c.newton_corrections),
                static_cast<double>(c.newton_corrections) /
                    static_cast<double>(std::max<std::int64_t>(1, c.accepted)));
  if (c.halved_steps)
    std::printf(", %lld steps halved (their stages not solved at the whole step)",
                static_cast<long long>(c.halved_steps));
  if (m.adaptive())
    std::printf(", %lld accepted and %lld rejected internal steps",
                static_cast<long long>(c.accepted), static_cast<long long>(c.rejected));
  std::printf("\n");
}

// The method line: its name, dt, the sub-steps and how they were chosen (fixed, or auto: within
// the safety factor of the limit, or capped), and the step h they make.
void run_print_method(Simulation& sim, double dt, const MethodInfo& m) {
  const int substeps = sim.settings().substeps;
  std::string chosen = "fixed";
  if (sim.auto_substeps())
    chosen = !sim.substeps_capped()
                 ? "auto: h within " + format(sim.settings().safety) + " of the limit"
             : sim.stable_step() == 0.0
                 ? "auto: unstable at any step, sub-steps cannot help"
                 : "auto, capped at " + std::to_string(kMaxAutoSubsteps) + ": still past the limit";
  std::printf("method     %s, dt = %s s, %d substep%s (%s; h = %s s)\n", m.name, format(dt).c_str(),
              substeps, substeps == 1 ? "" : "s", chosen.c_str(), format(sim.h()).c_str());
}

// The momentum line, for a free body (no outside force: P and L are constants of the motion, and
// any change is the method's): each kept or changed, by how much of its scale (sum m|v|,
// sum m|x||v|), and what the method is said to keep.
void run_print_momentum(const Simulation& sim, const Momentum& initial_momentum,
                        const MethodInfo& m) {
  const Momentum now = momentum(sim.model(), sim.state());
  const MomentumChange d = momentum_change(initial_momentum, now);
  const auto said = [](double change) {
    return std::string(change <= kMomentumKept ? "kept (" : "changed (") + "by " + format(change) +
           " of ";
  };
  std::printf(
      "momentum   a free body (no pins, gravity, drag, fields or colliders): P %ssum m|v| = %s "
      "kg m/s), "
      "L %ssum m|x||v| = %s kg m^2/s); %s: P %s, L %s\n",
      said(d.linear).c_str(), format(now.linear_scale).c_str(), said(d.angular).c_str(),
      format(now.angular_scale).c_str(), m.name, kept_text(m.momentum),
      kept_text(m.angular_momentum));
}

int run(const RunOptions& o) {
  Prepared p = prepare(o.scene, o.sim);
  if (p.scene.ik) return run_ik(p.scene, o.csv.has_value());
  if (o.every < 1) throw InputError("--every: must be at least 1, got " + std::to_string(o.every));
  std::unique_ptr<AtomicFile> csv;
  if (o.csv) csv = std::make_unique<AtomicFile>(*o.csv, "CSV trace");

  // The scene's model and state move into the simulation: a big scene is not held twice.
  const bool iterative = method_info(p.settings.method).family == MethodFamily::Iterative;
  if (iterative) p.settings.track_dissipation = true;  // for its artificial damping, below
  Simulation sim(std::move(p.scene.model), std::move(p.scene.state), p.settings);
  const Energy initial = sim.energy();
  const Momentum initial_momentum = momentum(sim.model(), sim.state());
  const StabilityAnalysis& stability = sim.stability();  // (before the timed steps)
  const StabilityLimit limit = sim.stability_limit();
  warn_if_unstable(sim, p.scene.name);

  if (csv) {
    write_header(csv->file(), sim.model().particle_count());
    write_row(csv->file(), sim);
  }
  Progress progress("run " + p.scene.name, p.steps);
  const auto start = std::chrono::steady_clock::now();
  std::int64_t taken = 0;
  while (taken < p.steps && sim.step()) {
    ++taken;
    if (csv && (taken % o.every == 0 || taken == p.steps)) write_row(csv->file(), sim);
    if ((taken & 255) == 0) progress.update(taken);
  }
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  progress.finish();
  if (csv) csv->commit();

  const Energy e = sim.energy();
  const Counters& c = sim.counters();
  const MethodInfo& m = method_info(p.settings.method);
  std::printf("scene      %s (%s): %d particles, %d springs\n", p.scene.name.c_str(),
              p.scene.file.c_str(), sim.model().particle_count(), sim.model().spring_count());
  run_print_method(sim, p.settings.dt, m);
  std::printf("steps      %lld of %lld, simulated %s s in %s s of wall time (%s steps/s)\n",
              static_cast<long long>(taken), static_cast<long long>(p.steps),
              format(sim.state().t).c_str(), format(wall).c_str(),
              format(wall > 0 ? taken / wall : 0.0).c_str());
  std::printf("energy     kinetic %s J, potential %s J, total %s J (initially %s J)\n",
              format(e.kinetic).c_str(), format(e.potential()).c_str(), format(e.total()).c_str(),
              format(initial.total()).c_str());
  print_stability(sim, stability, limit, m);
  print_cost(c, m);
  if (iterative && !sim.diverged() && sim.state().t > 0.0) print_iterative_account(sim);
  if (!p.scene.cells.empty()) {
    // Springs cannot undo an inverted cell (cells.hpp): counted for every method.
    const int inverted = inverted_cells(p.scene.cells, sim.state().x);
    std::printf("cells      %d of %zu inverted%s\n", inverted, p.scene.cells.size(),
                inverted > 0 ? " (turned inside out: springs alone cannot turn them back)" : "");
  }
  if (free_body(sim.model()) && !sim.diverged()) run_print_momentum(sim, initial_momentum, m);
  if (o.csv) std::printf("trace      %s\n", o.csv->c_str());

  if (sim.diverged()) {
    std::fflush(stdout);
    std::fprintf(stderr, "springlab: %s: %s\n", p.scene.name.c_str(),
                 sim.explain_divergence()->message().c_str());
    return kDiverged;
  }
  return kOk;
}

}  // namespace

Command add_run_command(CLI::App& app) {
  auto options = std::make_shared<RunOptions>();
  CLI::App* c =
      app.add_subcommand("run", "simulate without graphics; print a summary, write a CSV trace");
  c->add_option("scene", options->scene, "scene name or JSON file")->required();
  add_sim_options(*c, options->sim);
  c->add_option("--csv", options->csv, "write a trace: one row per step");
  c->add_option("--every", options->every, "write every K-th step to the CSV")
      ->transform(whole_number(1, 1e12));
  return [options] { return run(*options); };
}

}  // namespace springlab::app
