// springlab compare SCENE --out DIR: every method's error against its cost, its order and its
// largest stable step (springlab/sweep.hpp), written as DIR/results.csv and DIR/summary.csv,
// printed as a table, and charted as PNG (rendered headlessly by springlab) and SVG.
#include <imgui.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <sstream>

#include "chart/compare_charts.hpp"
#include "chart/imgui_chart.hpp"
#include "chart/stability_region.hpp"
#include "chart/svg.hpp"
#include "cli/commands.hpp"
#include "cli/options.hpp"
#include "gfx/offscreen.hpp"
#include "options/sweep_options.hpp"
#include "springlab/error.hpp"
#include "springlab/forces.hpp"
#include "util/atomic_file.hpp"
#include "util/language.hpp"
#include "util/progress.hpp"

namespace springlab::app {

namespace {

struct CompareOptions {
  std::string scene, out;
  SimOptions sim;
  SweepOptions sweep;  // (options/sweep_options.hpp: shared with the Python module)
  bool software = false, no_charts = false;
  std::string lang = "en";  // the charts' titles, axes and legends
};

std::string number(double x) {
  char s[32];
  std::snprintf(s, sizeof s, "%.10g", x);
  return s;
}

// A limit or step in words: NaN is "adaptive" for a method that chooses its steps (or a step
// not fixed), "not measured" for the limits of any other method.
std::string step_text(double h, bool adaptive = true) {
  if (std::isnan(h)) return adaptive ? "adaptive" : "not measured";
  if (std::isinf(h)) return "always";
  if (h == 0.0) return "never";
  char s[32];
  std::snprintf(s, sizeof s, "%.4g s", h);
  return s;
}

void write_csvs(const std::filesystem::path& dir, const SweepResult& r) {
  AtomicFile results(dir / "results.csv", "results");
  std::fprintf(
      results.file(),
      "method,step,tolerance,mean_step,error,seconds,force_evals,linear_solves,solver_iterations,"
      "accepted,rejected,diverged,diverged_at,energy_rise,unstable\n");
  for (const SweepRun& run : r.runs)
    std::fprintf(results.file(), "%s,%s,%s,%s,%s,%s,%lld,%lld,%lld,%lld,%lld,%d,%s,%s,%d\n",
                 method_info(run.method).name, number(run.h).c_str(),
                 std::isnan(run.tolerance) ? "" : number(run.tolerance).c_str(),
                 number(run.mean_step).c_str(), run.diverged ? "inf" : number(run.error).c_str(),
                 number(run.seconds).c_str(), static_cast<long long>(run.counters.force_evals),
                 static_cast<long long>(run.counters.linear_solves),
                 static_cast<long long>(run.counters.solver_iterations),
                 static_cast<long long>(run.counters.accepted),
                 static_cast<long long>(run.counters.rejected), run.diverged ? 1 : 0,
                 run.diverged ? number(run.diverged_at).c_str() : "", number(run.rise).c_str(),
                 run.unstable ? 1 : 0);
  results.commit();
  AtomicFile summary(dir / "summary.csv", "summary");
  std::fprintf(summary.file(),
               "method,order_table,order_measured,fitted_points,stable_step_measured,"
               "measured_resolution,stable_step_theoretical,theory_exact,ratio,error_floor,floor_"
               "from_step\n");
  for (const MethodSummary& m : r.methods) {
    // (measured_resolution inf: the budget ran out with every probe held, a lower bound)
    const bool finite = !m.measured_at_least && std::isfinite(m.measured_stable_h) &&
                        std::isfinite(m.theoretical_stable_h) && m.theoretical_stable_h > 0;
    std::fprintf(summary.file(), "%s,%d,%s,%d,%s,%s,%s,%d,%s,%s,%s\n", method_info(m.method).name,
                 method_info(m.method).order, std::isnan(m.order) ? "" : number(m.order).c_str(),
                 m.fitted_points, number(m.measured_stable_h).c_str(),
                 number(m.measured_resolution).c_str(), number(m.theoretical_stable_h).c_str(),
                 m.theory_exact ? 1 : 0,
                 finite ? number(m.measured_stable_h / m.theoretical_stable_h).c_str() : "",
                 std::isnan(m.floor_error) ? "" : number(m.floor_error).c_str(),
                 std::isnan(m.floor_h) ? "" : number(m.floor_h).c_str());
  }
  summary.commit();
}

// The stability-region charts (stability_region.hpp) of the sweep's fixed-step methods, each at
// the step `run` takes with the scene's dt (its sub-steps as the drift runs chose them): one
// chart per plane, none for a scene without oscillating modes.
std::vector<chart::NamedChart> region_charts(const Prepared& p, const SweepResult& r) {
  std::vector<chart::NamedChart> out;
  const StabilityAnalysis analysis(p.scene.model, p.scene.state);
  if (!analysis.oscillates()) return out;
  std::vector<chart::RegionLane> complex, oscillator;
  for (const MethodSummary& m : r.methods) {
    if (method_info(m.method).adaptive()) continue;
    int substeps = p.settings.substeps;
    for (const DriftTrace& d : r.drift)
      if (d.method == m.method) substeps = d.substeps;
    const chart::RegionLane lane{m.method, p.settings.dt / substeps};
    (chart::region_plane(m.method) == chart::RegionPlane::Complex ? complex : oscillator)
        .push_back(lane);
  }
  if (!complex.empty())
    out.push_back({"stability-region", chart::stability_region(analysis, complex)});
  if (!oscillator.empty())
    out.push_back({"stability-region-oscillator", chart::stability_region(analysis, oscillator)});
  return out;
}

void write_charts(const std::filesystem::path& dir, const std::vector<chart::NamedChart>& charts,
                  bool software) {
  constexpr int kWidth = 1200, kHeight = 760;
  for (const auto& named : charts) {
    AtomicFile svg(dir / (named.name + ".svg"), "chart");
    const std::string text = chart::to_svg(named.chart, kWidth, kHeight);
    std::fwrite(text.data(), 1, text.size(), svg.file());
    svg.commit();
  }
  gfx::Offscreen offscreen(software, kWidth, kHeight, 1.15f);
  draw::Frame blank;
  blank.background = {0.086f, 0.094f, 0.11f, 1.0f};
  Image image;
  for (const auto& named : charts) {
    offscreen.render(
        blank,
        [&] {
          ImGui::SetNextWindowPos(ImVec2(0, 0));
          ImGui::SetNextWindowSize(ImVec2(kWidth, kHeight));
          ImGui::Begin("chart", nullptr,
                       ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoBackground |
                           ImGuiWindowFlags_NoSavedSettings);
          chart::chart_widget("##chart", named.chart, ImGui::GetContentRegionAvail());
          ImGui::End();
        },
        image);
    write_png(dir / (named.name + ".png"), image, 6);
  }
}

// One method's line of the printed table: its order fitted (the table's in brackets), its stable
// step by runs and by the analysis and their ratio; then, where it has no order, why (its stable
// runs' errors against the fitted band), and where its errors reach a floor, that floor.
void compare_print_method_row(const MethodSummary& m, const SweepResult& r) {
  char order[32];
  if (std::isnan(m.order))
    std::snprintf(order, sizeof order, "n/a (%d)", method_info(m.method).order);
  else
    std::snprintf(order, sizeof order, "%.2f (%d)", m.order, method_info(m.method).order);
  const bool finite = !m.measured_at_least && std::isfinite(m.measured_stable_h) &&
                      std::isfinite(m.theoretical_stable_h) && m.theoretical_stable_h > 0;
  char ratio[16] = "";
  if (finite)
    std::snprintf(ratio, sizeof ratio, "%.3f", m.measured_stable_h / m.theoretical_stable_h);
  const bool adaptive = method_info(m.method).adaptive();
  std::string measured = step_text(m.measured_stable_h, adaptive),
              theory = step_text(m.theoretical_stable_h, adaptive);
  if (m.measured_at_least)
    measured = ">= " + measured + " (budget)";
  else if (finite && m.measured_resolution > 0.0) {
    char within[32];
    std::snprintf(within, sizeof within, " (+%.1f %%)", 100.0 * m.measured_resolution);
    measured += within;
  }
  if (!m.theory_exact && finite) theory = ">= " + theory;
  std::printf("%-18s %-16s %-22s %-16s %s\n", method_info(m.method).name, order, measured.c_str(),
              theory.c_str(), ratio);
  // Too few runs to fit: why, with their errors.
  if (std::isnan(m.order)) {
    double least = INFINITY, most = 0.0;
    int stable = 0;
    for (const SweepRun& run : r.runs)
      if (run.method == m.method &&
          std::isnan(run.tolerance) == !method_info(m.method).adaptive() && !run.diverged) {
        ++stable;
        least = std::min(least, run.error);
        most = std::max(most, run.error);
      }
    std::printf(
        "%-18s no order: %d of its %d stable runs fall between the reference's floor (%.2g m) "
        "and a tenth of "
        "the motion (%.2g m), and 3 are needed; its errors go from %.2g to %.2g m\n",
        "", m.fitted_points, stable, r.fit_floor, r.fit_ceiling, most, least);
  }
  // Below the floor the error is the solvers' tolerance and rounding: the order is fitted above
  // it.
  if (std::isfinite(m.floor_h))
    std::printf(
        "%-18s order fitted above the floor its errors reach: %.2g m from h = %s down (rounding "
        "and the "
        "solvers' tolerances, which a smaller step does not reduce)\n",
        "", m.floor_error, step_text(m.floor_h).c_str());
}

int compare(const CompareOptions& o) {
  PreparedSweep plan = prepare_sweep(o.scene, o.sim, o.sweep);
  const Prepared& p = plan.prepared;
  const SweepSettings& s = plan.settings;
  const double dt = p.settings.dt;
  use_language(check_language(o.lang, "--lang"));

  // The output folder first: it must be writable before the work starts.
  std::error_code ec;
  std::filesystem::create_directories(o.out, ec);
  if (ec || !std::filesystem::is_directory(o.out))
    throw InputError("--out: cannot create the folder '" + o.out + "' (" + ec.message() + ")");
  { TemporaryPath probe(std::filesystem::path(o.out) / "results.csv", "results"); }

  Progress progress("compare " + p.scene.name, 1);
  const SweepResult r =
      run_sweep(p.scene.model, p.scene.state, s, [&](const SweepRun&, int done, int total) {
        progress = Progress("compare " + p.scene.name, total);
        progress.update(done);
      });
  progress.finish();
  write_csvs(o.out, r);
  std::vector<chart::NamedChart> charts;
  if (!o.no_charts) {
    charts = chart::compare_charts(r, p.scene.name);
    for (chart::NamedChart& region : region_charts(p, r)) charts.push_back(std::move(region));
    write_charts(o.out, charts, o.software);
  }

  std::printf("scene      %s: %d particles, %d springs; w_max = %.4g rad/s\n", p.scene.name.c_str(),
              p.scene.model.particle_count(), p.scene.model.spring_count(), r.w_max);
  std::printf("steps      %zu from %.4g s to %.4g s; %d samples over %.4g s; reference: %s\n",
              step_divisors(s.h_min, s.h_max, s.points).size(),
              s.h_max / step_divisors(s.h_min, s.h_max, s.points).back(), s.h_max, r.samples,
              r.samples * r.sample_interval, r.reference.c_str());
  std::printf("\n%-18s %-16s %-22s %-16s %s\n", "method", "order (table)", "stable step, by runs",
              "analysis", "runs/analysis");
  for (const MethodSummary& m : r.methods) compare_print_method_row(m, r);
  // The sweep's runs take each step as given (the step is what it varies); the drift runs, at
  // the scene's step, take the sub-steps `run` would.
  if (!r.drift.empty()) {
    std::string list;
    for (const DriftTrace& d : r.drift)
      list += (list.empty() ? "" : ", ") + std::string(method_info(d.method).name) + " " +
              std::to_string(d.substeps);
    std::printf("\ndrift      at dt = %s, sub-steps (%s): %s\n", step_text(dt).c_str(),
                p.settings.auto_substeps ? "auto" : "fixed", list.c_str());
  }
  std::string names;
  for (const chart::NamedChart& c : charts) names += ", " + c.name;
  std::printf("\nwritten    %s/results.csv, summary.csv%s%s\n", o.out.c_str(), names.c_str(),
              charts.empty() ? "" : " (.png, .svg)");
  return kOk;
}

}  // namespace

Command add_compare_command(CLI::App& app) {
  auto o = std::make_shared<CompareOptions>();
  CLI::App* c =
      app.add_subcommand("compare", "accuracy against cost for the methods: CSV and charts");
  c->add_option("scene", o->scene, "scene name or JSON file")->required();
  c->add_option("--out", o->out, "folder for results.csv, summary.csv and the charts")->required();
  add_sim_options(*c, o->sim);
  c->add_option("--methods", o->sweep.methods, "methods to compare, e.g. euler,rk4 (default: all)");
  c->add_option("--dt-range", o->sweep.dt_range,
                "LO:HI steps to sweep, log-spaced (default: dt/16 to 2 dt)");
  c->add_option(
      "--lang", o->lang,
      "language of the charts' titles, axes and legends: " + language_list() + " (default en)");
  c->add_option("--points", o->sweep.points, "steps (and tolerances) per method (default 8)");
  c->add_option("--tol-range", o->sweep.tol_range,
                "LO:HI tolerances for the adaptive methods (default 1e-10:1e-4)");
  c->add_option("--repeats", o->sweep.repeats,
                "time each run this many times and keep the fastest (default 1)");
  c->add_option("--drift-duration", o->sweep.drift_duration,
                "length of the energy-drift runs (default: the scene's duration; 0: none)");
  c->add_flag("--software", o->software, "render the PNG charts with the software rasteriser");
  c->add_flag("--no-charts", o->no_charts, "write only the CSV files");
  c->add_option("--stability-budget", o->sweep.stability_budget,
                "work allowed for each method's measured stable step, in particle- and "
                "spring-steps (default 2e8, "
                "about a second; 0: not measured)");
  return [o] { return compare(*o); };
}

}  // namespace springlab::app
