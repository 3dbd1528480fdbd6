#include "chart/compare_charts.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <set>

#include "draw/palette.hpp"
#include "springlab/text.hpp"

namespace springlab::chart {

namespace {

constexpr draw::Rgba kGuide{0.62f, 0.65f, 0.70f, 1.0f};

std::string order_text(double order) {
  if (std::isnan(order)) return "";
  char s[32];
  std::snprintf(s, sizeof s, tr(" (order %.2f)"), order);
  return s;
}

// The order, and where the errors level off (fitted above that floor).
std::string order_text(const MethodSummary& m) {
  if (std::isnan(m.order) || std::isnan(m.floor_error)) return order_text(m.order);
  return format_text(tr(" (order %.2f above a floor of %.2g m)"), m.order, m.floor_error);
}

// A method's limit in words: NaN is "adaptive" for a method that chooses its steps, "not measured"
// for any other (a sweep with --stability-budget 0 measures none).
std::string step_text(double h, Method method) {
  if (std::isnan(h)) return method_info(method).adaptive() ? tr("adaptive") : tr("not measured");
  if (std::isinf(h)) return tr("always stable");
  if (h == 0.0) return tr("never stable");
  char s[32];
  std::snprintf(s, sizeof s, "%.3g s", h);
  return s;
}

// The highest finite error, where diverged runs are drawn (as crosses) on a log chart.
double ceiling_of(const SweepResult& r) {
  double top = 0.0;
  for (const SweepRun& run : r.runs)
    if (std::isfinite(run.error)) top = std::max(top, run.error);
  return top > 0 ? 3.0 * top : 1.0;
}

}  // namespace

double work(const Counters& c) {
  return static_cast<double>(c.force_evals + c.solver_iterations);
}

Chart work_precision(const SweepResult& r, const std::string& scene, Cost cost) {
  Chart c;
  c.title = format_text(tr("Work-precision on %s: error against cost (lower left is better)"),
                        scene.c_str());
  c.x.label = cost == Cost::Time ? tr("wall time of the run (s)")
                                 : tr("work: force evaluations + linear-solver iterations");
  c.x.log = true;
  c.y.label = tr("error: largest RMS position error over the samples (m)");
  c.y.log = true;
  const double ceiling = ceiling_of(r);
  for (const MethodSummary& m : r.methods) {
    const bool adaptive = method_info(m.method).adaptive();
    Series s;
    s.label = std::string(method_info(m.method).name) + (adaptive ? tr(" (over tolerances)") : "");
    s.color = draw::method_color(m.method);
    s.mark = draw::method_mark(m.method);
    s.markers = true;
    for (const SweepRun& run : r.runs) {
      // Adaptive methods at their tolerances: the accuracy they choose, at the price they pay.
      if (run.method != m.method || adaptive == std::isnan(run.tolerance)) continue;
      s.x.push_back(cost == Cost::Time ? std::max(run.seconds, 1e-6)
                                       : std::max(work(run.counters), 1.0));
      s.y.push_back(run.diverged ? ceiling : run.error);
      s.crossed.push_back(run.diverged);
    }
    c.series.push_back(std::move(s));
  }
  return c;
}

Chart convergence(const SweepResult& r, const std::string& scene) {
  Chart c;
  c.title = format_text(tr("Convergence on %s: error against step (x = diverged)"), scene.c_str());
  c.x.label = tr("step h (s)");
  c.x.log = true;
  c.y.label = tr("error (m)");
  c.y.log = true;
  const double ceiling = ceiling_of(r);
  double hmin = 1e300, hmax = 0, emin = 1e300, emax = 0;
  for (const MethodSummary& m : r.methods) {
    Series s;
    s.label = std::string(method_info(m.method).name) + order_text(m);
    s.color = draw::method_color(m.method);
    s.mark = draw::method_mark(m.method);
    s.markers = true;
    for (const SweepRun& run : r.runs) {
      if (run.method != m.method || !std::isnan(run.tolerance)) continue;
      s.x.push_back(run.h);
      s.y.push_back(run.diverged ? ceiling : run.error);
      s.crossed.push_back(run.diverged);
      hmin = std::min(hmin, run.h);
      hmax = std::max(hmax, run.h);
      if (std::isfinite(run.error) && run.error > 0) {
        emin = std::min(emin, run.error);
        emax = std::max(emax, run.error);
      }
    }
    c.series.push_back(std::move(s));
  }
  // Reference slopes through the middle of the data, one for each order the rows drawn against
  // the step are of (their table's), to read orders against: dashed, each named at its end.
  if (hmax > hmin && emax > emin) {
    const double hc = std::sqrt(hmin * hmax), ec = std::sqrt(emin * emax);
    std::set<int> orders;
    for (const MethodSummary& m : r.methods)
      for (const SweepRun& run : r.runs)
        if (run.method == m.method && std::isnan(run.tolerance) &&
            method_info(m.method).order > 0) {
          orders.insert(method_info(m.method).order);
          break;
        }
    for (int order : orders) {
      Series guide;  // (no label: not in the legend; its note names it)
      guide.color = kGuide;
      guide.color.a = 0.55f;
      guide.dashed = true;
      guide.width = 1.5f;
      for (int k = 0; k <= 40; ++k) {  // (points enough for its dashes)
        const double h = hmin * std::pow(hmax / hmin, k / 40.0);
        guide.x.push_back(h);
        guide.y.push_back(ec * std::pow(h / hc, order));
      }
      c.notes.push_back({hmax, guide.y.back(), format_text(tr("slope %d"), order), kGuide});
      c.series.push_back(std::move(guide));
    }
    c.y.min = emin / 3.0;
    c.y.max = ceiling * 1.5;
  }
  return c;
}

Chart stability(const SweepResult& r, const std::string& scene) {
  Chart c;
  char title[160];
  std::snprintf(
      title, sizeof title,
      tr("Largest stable step on %s: measured by runs against the analysis (w_max = %.4g rad/s)"),
      scene.c_str(), r.w_max);
  c.title = title;
  c.x.label = tr("from the analysis (s)");
  c.x.log = true;
  c.y.label = tr("measured on the scene (s)");
  c.y.log = true;
  double lo = 1e300, hi = 0;
  for (const MethodSummary& m : r.methods) {
    Series s;
    s.color = draw::method_color(m.method);
    s.mark = draw::method_mark(m.method);
    s.markers = true;
    s.width = 3.0f;
    const bool plotted = !m.measured_at_least && std::isfinite(m.theoretical_stable_h) &&
                         m.theoretical_stable_h > 0 && std::isfinite(m.measured_stable_h) &&
                         m.measured_stable_h > 0;
    char label[160];
    if (plotted) {
      std::snprintf(label, sizeof label, tr("%s: %.3g s measured, %s%.3g s analysis"),
                    method_info(m.method).name, m.measured_stable_h,
                    m.theory_exact ? "" : ">= ", m.theoretical_stable_h);
      s.x = {m.theoretical_stable_h};
      s.y = {m.measured_stable_h};
      lo = std::min({lo, m.theoretical_stable_h, m.measured_stable_h});
      hi = std::max({hi, m.theoretical_stable_h, m.measured_stable_h});
    } else {
      std::snprintf(
          label, sizeof label, tr("%s: %s (theory: %s)"), method_info(m.method).name,
          ((m.measured_at_least ? ">= " : "") + step_text(m.measured_stable_h, m.method)).c_str(),
          step_text(m.theoretical_stable_h, m.method).c_str());
    }
    s.label = label;
    c.series.push_back(std::move(s));
  }
  if (hi > 0) {
    Series diagonal;
    diagonal.label = tr("measured = theory");
    diagonal.color = kGuide;
    diagonal.dashed = true;
    diagonal.width = 1.5f;
    diagonal.x = {lo / 2, hi * 2};
    diagonal.y = {lo / 2, hi * 2};
    c.series.push_back(std::move(diagonal));
    c.x.min = c.y.min = lo / 2;
    c.x.max = c.y.max = hi * 2;
  }
  return c;
}

Chart energy_drift(const SweepResult& r, const std::string& scene) {
  Chart c;
  c.title = format_text(
      tr("Energy drift on %s: |E + dissipated - E0| / energy scale (x = diverged)"), scene.c_str());
  c.x.label = "t (s)";
  c.x.log = false;
  c.y.label = tr("relative drift");
  c.y.log = true;
  for (const DriftTrace& d : r.drift) {
    Series s;
    s.label = method_info(d.method).name;
    s.color = draw::method_color(d.method);
    s.mark = draw::method_mark(d.method);
    for (std::size_t k = 1; k < d.t.size(); ++k) {
      s.x.push_back(d.t[k]);
      s.y.push_back(std::max(std::abs(d.drift[k]), 1e-16));
      s.crossed.push_back(false);
    }
    if (d.diverged && !s.x.empty()) s.crossed.back() = true;
    c.series.push_back(std::move(s));
  }
  return c;
}

Chart solver_convergence(const SweepResult& r, const std::string& scene) {
  Chart c;
  char title[200];
  std::snprintf(
      title, sizeof title,
      tr("Solver error on %s: one step of h = %.3g s against the converged implicit-Euler step"),
      scene.c_str(), r.solver.h);
  c.title = title;
  c.x.label = tr("iterations a step (XPBD: passes; implicit Euler: conjugate-gradient iterations)");
  c.x.log = true;
  c.y.label = "|x_k - x*| / |x* - x_0|";
  c.y.log = true;
  for (const SolverErrorCurve& curve : r.solver.curves) {
    Series s;
    s.label = method_info(curve.method).name;
    if (!curve.note.empty()) s.label += tr(curve.note.c_str());
    s.color = draw::method_color(curve.method);
    s.mark = draw::method_mark(curve.method);
    s.markers = true;
    for (std::size_t k = 0; k < curve.iterations.size(); ++k) {
      s.x.push_back(curve.iterations[k]);
      s.y.push_back(std::max(curve.error[k], 1e-16));
    }
    c.series.push_back(std::move(s));
  }
  return c;
}

std::vector<NamedChart> compare_charts(const SweepResult& result, const std::string& scene) {
  std::vector<NamedChart> out{{"work-precision", work_precision(result, scene, Cost::Time)},
                              {"work-precision-work", work_precision(result, scene, Cost::Work)},
                              {"convergence", convergence(result, scene)}};
  // The limits' chart where a limit was found (none with --stability-budget 0, nor for methods
  // that all choose their own steps: an empty chart says nothing).
  const bool limits = std::any_of(result.methods.begin(), result.methods.end(), [](const auto& m) {
    return !std::isnan(m.theoretical_stable_h) || !std::isnan(m.measured_stable_h);
  });
  if (limits) out.push_back({"stability", stability(result, scene)});
  if (!result.drift.empty()) out.push_back({"energy-drift", energy_drift(result, scene)});
  if (!result.solver.curves.empty())
    out.push_back({"solver-convergence", solver_convergence(result, scene)});
  return out;
}

}  // namespace springlab::chart
