#include "chart/stability_region.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <map>
#include <mutex>

#include "draw/palette.hpp"
#include "springlab/text.hpp"

namespace springlab::chart {

namespace {

using Complex = std::complex<double>;

// |R(z)| - 1 at z = h lambda (the complex plane's methods), by the row's stability function:
// the region is where it is <= 0.
double margin_at(Method method, Complex z) {
  const Tableau* tableau = method_info(method).tableau;
  return tableau ? std::abs(tableau->stability_function(z)) - 1.0 : 1.0;
}
bool stable_at(Method method, Complex z) {
  return margin_at(method, z) <= 0.0;
}

// For a mode at (X, Y) = (h w, h c) (the oscillator plane's methods): 1 - mode_limit() of the
// mode (c, w^2) over h (with h = 1, w = X and c = Y), <= 0 where the mode is stable.
double margin_at(Method method, double X, double Y) {
  return 1.0 - std::min(mode_limit(method, Y, X * X), 1e3);
}
bool stable_at(Method method, double X, double Y) {
  return mode_limit(method, Y, X * X) >= 1.0 * (1.0 - 1e-12);
}

// The region where `margin` <= 0, from its values on a grid: the boundary as the contour
// margin = 0 (marching squares, each crossing placed on its cell side by linear interpolation, so
// the edge is a smooth curve, not a staircase), and the inside as faint horizontal strokes whose
// ends are interpolated the same way; both appended to series.
template <typename Margin>
void region(const Margin& margin, double x0, double x1, double y0, double y1,
            const draw::Rgba& color, const std::string& label, std::vector<Series>& out) {
  constexpr int kN = 160;
  Series edge, fill;
  edge.label = label;
  edge.color = color;
  edge.width = 2.0f;
  fill.color = color;
  fill.color.a = 0.16f;
  fill.width = 2.5f;
  const auto x = [&](int i) { return x0 + (x1 - x0) * i / kN; };
  const auto y = [&](int j) { return y0 + (y1 - y0) * j / kN; };
  std::vector<double> m((kN + 1) * (kN + 1));
  for (int j = 0; j <= kN; ++j)
    for (int i = 0; i <= kN; ++i) {
      const double v = margin(x(i), y(j));
      m[j * (kN + 1) + i] = std::isfinite(v) ? v : 1.0;  // (a pole of R: outside)
    }
  const auto at = [&](int i, int j) { return m[j * (kN + 1) + i]; };
  const auto inside = [&](int i, int j) { return at(i, j) <= 0.0; };
  // Where margin = 0 between two grid points a and b (one inside, one not), as a fraction of a to
  // b.
  const auto zero = [](double a, double b) { return std::clamp(a / (a - b), 0.0, 1.0); };
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const auto cut = [&](Series& s) {
    s.x.push_back(nan);
    s.y.push_back(nan);
  };
  // The inside: a stroke per row from where it enters to where it leaves.
  for (int j = 0; j <= kN; ++j)
    for (int i = 0; i <= kN; ++i) {
      if (!inside(i, j)) continue;
      int k = i;
      while (k + 1 <= kN && inside(k + 1, j)) ++k;
      const double from =
          i > 0 ? x(i - 1) + zero(at(i - 1, j), at(i, j)) * (x(i) - x(i - 1)) : x(i);
      const double to = k < kN ? x(k) + zero(at(k, j), at(k + 1, j)) * (x(k + 1) - x(k)) : x(k);
      fill.x.insert(fill.x.end(), {from, to});
      fill.y.insert(fill.y.end(), {y(j), y(j)});
      cut(fill);
      i = k;
    }
  // The edge: in each cell, segments between the interpolated crossings of its sides.
  for (int j = 0; j < kN; ++j)
    for (int i = 0; i < kN; ++i) {
      const int ci[4] = {i, i + 1, i + 1, i},
                cj[4] = {j, j, j + 1, j + 1};  // corners, anticlockwise
      double px[4], py[4];
      std::vector<int> crossings;
      for (int e = 0; e < 4; ++e) {
        const int a = e, b = (e + 1) % 4;
        if (inside(ci[a], cj[a]) == inside(ci[b], cj[b])) continue;
        const double f = zero(at(ci[a], cj[a]), at(ci[b], cj[b]));
        px[e] = x(ci[a]) + f * (x(ci[b]) - x(ci[a]));
        py[e] = y(cj[a]) + f * (y(cj[b]) - y(cj[a]));
        crossings.push_back(e);
      }
      for (std::size_t k = 0; k + 1 < crossings.size(); k += 2) {
        edge.x.insert(edge.x.end(), {px[crossings[k]], px[crossings[k + 1]]});
        edge.y.insert(edge.y.end(), {py[crossings[k]], py[crossings[k + 1]]});
        cut(edge);
      }
    }
  out.push_back(std::move(fill));
  out.push_back(std::move(edge));
}

// The scene's eigenvalues (the complex plane): every one on a small scene; on a large one, the
// traced bounds of its modes, each (gamma, kappa) as the roots of lambda^2 + gamma lambda + kappa.
std::vector<Complex> spectrum(const StabilityAnalysis& analysis) {
  if (analysis.dense()) return analysis.eigenvalues();
  std::vector<Complex> out;
  for (const auto& m : analysis.modes()) {
    const Complex root = std::sqrt(Complex(0.25 * m.gamma * m.gamma - m.kappa, 0.0));
    out.push_back(-0.5 * m.gamma + root);
    out.push_back(-0.5 * m.gamma - root);
  }
  return out;
}

// How far a method's region reaches, in the view's terms: a bounded region (an explicit
// tableau's) by the box of its stable points; an unbounded one (implicit) by the box of its
// unstable points (implicit Euler's disc |z - 1| < 1), to the left at least to -3. Sampled once
// for each method on a coarse grid, then kept: a region depends on its method alone. The grid
// starts at |Re|, |Im| <= 8 (16 for an unbounded one) and doubles while the set it bounds reaches
// its edge: a long-interval explicit method (Ketcheson's ten-stage SSPRK(10,4) to -13.9, a
// Chebyshev method to -2 s^2) is held whole, as the view promises.
struct Extent {
  double left = 1.0, right = 0.25, up = 1.0;
};
Extent region_extent(Method method) {
  static std::mutex mutex;
  static std::map<int, Extent> known;
  const std::lock_guard lock(mutex);
  if (const auto it = known.find(static_cast<int>(method)); it != known.end()) return it->second;
  const Tableau* tableau = method_info(method).tableau;
  Extent e;
  if (tableau) {
    const bool bounded = tableau->is_explicit();
    constexpr int kN = 96;
    constexpr double kLargest = 4096.0;  // (a 45-stage Chebyshev method's interval)
    double kL = bounded ? 8.0 : 16.0;    // (an SDIRK's unstable disc reaches past 10)
    double left = 0.0, right = 0.0, up = 0.0, step = kL / kN;
    for (;; kL *= 2.0) {
      left = right = up = 0.0;
      step = kL / kN;  // (a sample's width, for the edge between samples)
      for (int j = 0; j <= kN; ++j)
        for (int i = 0; i <= 2 * kN; ++i) {
          const Complex z(-kL + kL * i / kN, kL * j / kN);
          if (stable_at(method, z) != bounded) continue;
          left = std::max(left, -z.real());
          right = std::max(right, z.real());
          up = std::max(up, z.imag());
        }
      const bool at_edge = left >= kL - 2.0 * step || up >= kL - 2.0 * step;
      if (!bounded || !at_edge || 2.0 * kL > kLargest) break;
    }
    e.left = std::max(bounded ? left + step : 3.0, 1.0);
    e.right = std::max(right + step, 0.25);
    e.up = std::max(up + step, 1.0);
    // Unstable out to the grid's edge (the trapezoidal rule: the whole right half plane): no set
    // to show whole; a little of the right half plane, as for the explicit ones.
    if (!bounded && (right >= kL - 2.0 * step || up >= kL - 2.0 * step)) e.right = 2.0, e.up = 3.0;
  }
  known[static_cast<int>(method)] = e;
  return e;
}

// The largest factor h may be multiplied by with every mode stable (inf: any; 0: none).
double room(const StabilityAnalysis& analysis, const RegionLane& lane) {
  const double limit = analysis.limit(lane.method).h;
  if (std::isnan(limit) || !(lane.h > 0.0)) return std::numeric_limits<double>::quiet_NaN();
  return limit / lane.h;
}

}  // namespace

RegionPlane region_plane(Method method) {
  return method_info(method).family == MethodFamily::Partitioned ? RegionPlane::Oscillator
                                                                 : RegionPlane::Complex;
}

std::string region_verdict(const StabilityAnalysis& analysis, const RegionLane& lane) {
  char s[160];
  const MethodInfo& m = method_info(lane.method);
  if (m.adaptive()) return format_text(tr("%s chooses its own steps: no region"), m.name);
  const double factor = room(analysis, lane);
  if (std::isinf(factor)) return format_text(tr("%s: stable at any step"), m.name);
  if (factor == 0.0)
    return format_text(tr("%s: unstable at any step (a mode sits outside for every h)"), m.name);
  const bool exact = analysis.limit(lane.method).exact;
  if (factor >= 1.0)
    std::snprintf(s, sizeof s, tr("%s: every mode inside; h may grow x%.3g%s"), m.name, factor,
                  exact ? "" : tr(" at least"));
  else
    std::snprintf(s, sizeof s, tr("%s: modes outside; h must shrink x%.3g (to %.3g s)"), m.name,
                  factor, analysis.limit(lane.method).h);
  return s;
}

namespace {

// The lanes' dots: `points(lane, put)` puts each of a lane's dots, (x, y) and whether the lane's
// region holds it; stable ones in the lane's colour and mark, the others in red, added after
// every lane's stable ones (a red dot is never hidden under another lane's).
template <typename Points>
void lane_dots(std::vector<Series>& series, const std::vector<RegionLane>& shown,
               const Points& points) {
  std::vector<Series> outsides;
  for (const RegionLane& l : shown) {
    Series inside, outside;
    inside.color = draw::method_color(l.method);
    inside.mark = draw::method_mark(l.method);
    inside.markers = true;
    inside.width = 1.5f;
    outside = inside;
    outside.color = draw::kDiverged;
    const double nan = std::numeric_limits<double>::quiet_NaN();
    points(l, [&](double x, double y, bool stable) {
      Series& s = stable ? inside : outside;
      s.x.insert(s.x.end(), {x, nan});
      s.y.insert(s.y.end(), {y, nan});
    });
    series.push_back(std::move(inside));
    outsides.push_back(std::move(outside));
  }
  for (Series& o : outsides) series.push_back(std::move(o));
}

// The dots h lambda, each lane's inside its region in its colour, outside in red (drawn last: a
// red dot is never hidden under another lane's); never a NaN dot.
void complex_plane_dots(Chart& chart, const std::vector<RegionLane>& shown,
                        const std::vector<Complex>& lambdas) {
  lane_dots(chart.series, shown, [&](const RegionLane& l, const auto& put) {
    for (Complex lambda : lambdas) {
      const Complex z = l.h * lambda;
      if (!std::isfinite(z.real()) || !std::isfinite(z.imag())) continue;  // never a NaN dot
      put(z.real(), z.imag(), stable_at(l.method, z));
    }
  });
}

// Dots near 0 at a small step (the farthest, `reach` = max |h lambda|, under 0.08 of the view's
// reach `dots`), where the regions' edges decide: an inset zooming on them, with the edges there
// (x in [-1.6, 0.6] reach, y in [-1.3, 1.3] reach). Null where the dots do not gather there.
std::shared_ptr<Chart> near_zero_inset(const std::vector<RegionLane>& shown,
                                       const std::vector<Complex>& lambdas, const Extent& dots) {
  double reach = 0.0;
  for (const RegionLane& l : shown)
    for (Complex lambda : lambdas)
      if (std::isfinite(std::abs(l.h * lambda))) reach = std::max(reach, std::abs(l.h * lambda));
  if (!(reach > 0.0 && reach < 0.08 * std::max(dots.left, dots.up))) return nullptr;
  auto zoom = std::make_shared<Chart>();
  zoom->title = tr("near 0");
  zoom->legend = false;
  zoom->equal_scale = true;
  zoom->x.min = -1.6 * reach;
  zoom->x.max = 0.6 * reach;
  zoom->y.min = -1.3 * reach;
  zoom->y.max = 1.3 * reach;
  for (const RegionLane& l : shown)
    region([&](double x, double y) { return margin_at(l.method, Complex(x, y)); }, *zoom->x.min,
           *zoom->x.max, *zoom->y.min, *zoom->y.max, draw::method_color(l.method), "",
           zoom->series);
  complex_plane_dots(*zoom, shown, lambdas);
  return zoom;
}

// The regions of h lambda in the complex plane (the Runge-Kutta rows and tableaux), with the
// scene's eigenvalues times h as dots; an inset on the dots near 0 when they gather there.
Chart complex_plane(const StabilityAnalysis& analysis, const std::vector<RegionLane>& shown,
                    Chart c) {
  c.title =
      tr("Stability region, h lambda in the complex plane (dots: the scene's eigenvalues times h)");
  c.x.label = tr("Re(h lambda)");
  c.y.label = tr("Im(h lambda)");
  c.equal_scale = true;
  const std::vector<Complex> lambdas = spectrum(analysis);
  // The view, as Hairer and Wanner draw regions: every charted region whole (a bounded one's
  // stable set, an unbounded one's unstable set), whatever its size, and the dots, each with some
  // room, at most 40 across or the regions' size (a stiff scene's dots far out at a large step
  // are drawn at the view's edge).
  Extent regions;
  for (const RegionLane& l : shown) {
    const Extent e = region_extent(l.method);
    regions.left = std::max(regions.left, e.left);
    regions.right = std::max(regions.right, e.right);
    regions.up = std::max(regions.up, e.up);
  }
  Extent dots = regions;
  for (const RegionLane& l : shown)
    for (Complex lambda : lambdas) {
      const Complex z = l.h * lambda;
      if (!std::isfinite(z.real()) || !std::isfinite(z.imag())) continue;
      dots.left = std::max(dots.left, -1.1 * z.real());
      dots.right = std::max(dots.right, 1.1 * z.real());
      dots.up = std::max(dots.up, 1.1 * std::abs(z.imag()));
    }
  const auto shown_to = [](double region, double dot) {
    return std::max(region, std::min(dot, std::max(region, 40.0)));
  };
  const double x0 = -shown_to(regions.left, dots.left), x1 = shown_to(regions.right, dots.right);
  const double y0 = -shown_to(regions.up, dots.up), y1 = -y0;
  c.x.min = x0;
  c.x.max = x1;
  c.y.min = y0;
  c.y.max = y1;
  // A bounded region is sampled over its own box (its edge stays smooth however far the view
  // reaches); an unbounded one over the view.
  for (const RegionLane& l : shown) {
    const Tableau* tableau = method_info(l.method).tableau;
    const bool bounded = tableau && tableau->is_explicit();
    const Extent e = region_extent(l.method);
    region([&](double x, double y) { return margin_at(l.method, Complex(x, y)); },
           bounded ? std::max(x0, -e.left) : x0, bounded ? std::min(x1, e.right) : x1,
           bounded ? std::max(y0, -e.up) : y0, bounded ? std::min(y1, e.up) : y1,
           draw::method_color(l.method), region_verdict(analysis, l), c.series);
  }
  complex_plane_dots(c, shown, lambdas);
  if (std::shared_ptr<Chart> zoom = near_zero_inset(shown, lambdas, dots)) c.inset = zoom;
  return c;
}

// The regions in the damped oscillator's plane (h w, h c), for the rows that have none in the
// complex plane, with the scene's modes as dots.
Chart oscillator_plane(const StabilityAnalysis& analysis, const std::vector<RegionLane>& shown,
                       Chart c) {
  c.title =
      tr("Stability region in the damped oscillator's plane (h w, h c): these methods have none in "
         "the "
         "complex plane; dots: the scene's modes");
  c.x.label = "h w";
  c.y.label = "h c";
  double xmax = 2.5, ymax = 2.5;
  for (const RegionLane& l : shown)
    for (const auto& m : analysis.modes()) {
      xmax = std::max(xmax, 1.1 * l.h * std::sqrt(m.kappa));
      ymax = std::max(ymax, 1.1 * l.h * m.gamma);
    }
  xmax = std::min(xmax, 40.0);
  ymax = std::min(ymax, 40.0);
  c.x.min = 0.0;
  c.x.max = xmax;
  c.y.min = 0.0;
  c.y.max = ymax;
  // Every region here lies within h w <= 2, h c <= 2 (the closed forms of docs/numerics.md, "One
  // damped mode"): sampled there, its edge stays smooth when the modes stretch the view.
  for (const RegionLane& l : shown)
    region([&](double x, double y) { return margin_at(l.method, x, y); }, 0.0, std::min(xmax, 2.2),
           0.0, std::min(ymax, 2.2), draw::method_color(l.method), region_verdict(analysis, l),
           c.series);
  lane_dots(c.series, shown, [&](const RegionLane& l, const auto& put) {
    for (const auto& m : analysis.modes()) {
      const double X = l.h * std::sqrt(std::max(m.kappa, 0.0)), Y = l.h * m.gamma;
      if (!std::isfinite(X) || !std::isfinite(Y)) continue;
      put(X, Y, stable_at(l.method, X, Y));
    }
  });
  return c;
}

}  // namespace

Chart stability_region(const StabilityAnalysis& analysis, const std::vector<RegionLane>& lanes) {
  Chart c;
  c.legend = true;
  if (lanes.empty()) return c;
  const RegionPlane plane = region_plane(lanes.front().method);
  std::vector<RegionLane> shown;
  for (const RegionLane& l : lanes)
    if (region_plane(l.method) == plane && !method_info(l.method).adaptive()) shown.push_back(l);
  return plane == RegionPlane::Complex ? complex_plane(analysis, shown, std::move(c))
                                       : oscillator_plane(analysis, shown, std::move(c));
}

}  // namespace springlab::chart
