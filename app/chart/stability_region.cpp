#include "chart/stability_region.hpp"

#include <algorithm>
#include <cmath>
#include <complex>

#include "draw/palette.hpp"

namespace springlab::chart {

namespace {

using Complex = std::complex<double>;

// Stable at z = h lambda (the complex plane's methods), by the row's stability function.
bool stable_at(Method method, Complex z) {
  const Tableau* tableau = method_info(method).tableau;
  return tableau && std::abs(tableau->stability_function(z)) <= 1.0;
}

// Stable for a mode at (X, Y) = (h w, h c) (the oscillator plane's methods): mode_limit() of the
// mode (c, w^2) is at least h. With h = 1, w = X and c = Y.
bool stable_at(Method method, double X, double Y) { return mode_limit(method, Y, X * X) >= 1.0 * (1.0 - 1e-12); }

// The region's boundary as line segments (marching squares on a grid of the plane), and its
// inside as faint horizontal strokes, both appended to series.
template <typename Stable>
void region(const Stable& stable, double x0, double x1, double y0, double y1, const draw::Rgba& color,
            const std::string& label, std::vector<Series>& out) {
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
  std::vector<char> in((kN + 1) * (kN + 1));
  for (int j = 0; j <= kN; ++j)
    for (int i = 0; i <= kN; ++i) in[j * (kN + 1) + i] = stable(x(i), y(j));
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const auto cut = [&](Series& s) {
    s.x.push_back(nan);
    s.y.push_back(nan);
  };
  // The inside: one stroke per row where it is stable.
  for (int j = 0; j <= kN; ++j)
    for (int i = 0; i <= kN; ++i) {
      if (!in[j * (kN + 1) + i]) continue;
      int k = i;
      while (k + 1 <= kN && in[j * (kN + 1) + k + 1]) ++k;
      fill.x.insert(fill.x.end(), {x(i), x(k)});
      fill.y.insert(fill.y.end(), {y(j), y(j)});
      cut(fill);
      i = k;
    }
  // The edge: in each cell, a segment between the midpoints of the sides where stability changes.
  for (int j = 0; j < kN; ++j)
    for (int i = 0; i < kN; ++i) {
      const bool c[4] = {static_cast<bool>(in[j * (kN + 1) + i]), static_cast<bool>(in[j * (kN + 1) + i + 1]),
                         static_cast<bool>(in[(j + 1) * (kN + 1) + i + 1]), static_cast<bool>(in[(j + 1) * (kN + 1) + i])};
      const double mx[4] = {0.5 * (x(i) + x(i + 1)), x(i + 1), 0.5 * (x(i) + x(i + 1)), x(i)};
      const double my[4] = {y(j), 0.5 * (y(j) + y(j + 1)), y(j + 1), 0.5 * (y(j) + y(j + 1))};
      std::vector<int> crossings;
      for (int s = 0; s < 4; ++s)
        if (c[s] != c[(s + 1) % 4]) crossings.push_back(s);
      for (std::size_t k = 0; k + 1 < crossings.size(); k += 2) {
        edge.x.insert(edge.x.end(), {mx[crossings[k]], mx[crossings[k + 1]]});
        edge.y.insert(edge.y.end(), {my[crossings[k]], my[crossings[k + 1]]});
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

// The largest factor h may be multiplied by with every mode stable (inf: any; 0: none).
double room(const StabilityAnalysis& analysis, const RegionLane& lane) {
  const double limit = analysis.limit(lane.method).h;
  if (std::isnan(limit) || !(lane.h > 0.0)) return std::numeric_limits<double>::quiet_NaN();
  return limit / lane.h;
}

}  // namespace

RegionPlane region_plane(Method method) {
  return method_info(method).family == MethodFamily::Partitioned ? RegionPlane::Oscillator : RegionPlane::Complex;
}

std::string region_verdict(const StabilityAnalysis& analysis, const RegionLane& lane) {
  char s[160];
  const MethodInfo& m = method_info(lane.method);
  if (m.adaptive()) return std::string(m.name) + " chooses its own steps: no region";
  const double factor = room(analysis, lane);
  if (std::isinf(factor)) return std::string(m.name) + ": stable at any step";
  if (factor == 0.0) return std::string(m.name) + ": unstable at any step (a mode sits outside for every h)";
  const bool exact = analysis.limit(lane.method).exact;
  if (factor >= 1.0)
    std::snprintf(s, sizeof s, "%s: every mode inside; h may grow x%.3g%s", m.name, factor, exact ? "" : " at least");
  else
    std::snprintf(s, sizeof s, "%s: modes outside; h must shrink x%.3g (to %.3g s)", m.name, factor,
                  analysis.limit(lane.method).h);
  return s;
}

Chart stability_region(const StabilityAnalysis& analysis, const std::vector<RegionLane>& lanes) {
  Chart c;
  c.legend = true;
  if (lanes.empty()) return c;
  const RegionPlane plane = region_plane(lanes.front().method);
  std::vector<RegionLane> shown;
  for (const RegionLane& l : lanes)
    if (region_plane(l.method) == plane && !method_info(l.method).adaptive()) shown.push_back(l);
  const draw::Rgba red = draw::kDiverged;

  if (plane == RegionPlane::Complex) {
    c.title = "Stability region, h lambda in the complex plane (dots: the scene's eigenvalues times h)";
    c.x.label = "Re(h lambda)";
    c.y.label = "Im(h lambda)";
    const std::vector<Complex> lambdas = spectrum(analysis);
    // The view: the dots with room around them (at small h they sit near 0, where the regions'
    // edges decide), at least 1 across (where the regions differ) and at most 40.
    double reach = 1.0;
    for (const RegionLane& l : shown)
      for (Complex z : lambdas) reach = std::max(reach, 1.5 * std::abs(l.h * z));
    reach = std::min(reach, 40.0);
    const double x0 = -reach, x1 = 0.25 * reach, y0 = -reach, y1 = reach;
    c.x.min = x0;
    c.x.max = x1;
    c.y.min = y0;
    c.y.max = y1;
    // An explicit method's region lies within |z| <= 3 (RK4's reaches 2.83): sampled there, its
    // edge is smooth however far the view reaches. Implicit Euler's is everything but a disc.
    for (const RegionLane& l : shown) {
      const bool bounded = !method_info(l.method).implicit();
      region([&](double x, double y) { return stable_at(l.method, Complex(x, y)); },
             bounded ? std::max(x0, -3.0) : x0, bounded ? std::min(x1, 0.5) : x1, bounded ? std::max(y0, -3.0) : y0,
             bounded ? std::min(y1, 3.0) : y1, draw::method_color(l.method), region_verdict(analysis, l), c.series);
    }
    std::vector<Series> outsides;  // drawn last: a red dot is never hidden under another lane's
    for (const RegionLane& l : shown) {
      Series inside, outside;
      inside.color = draw::method_color(l.method);
      inside.markers = true;
      inside.width = 1.5f;
      outside = inside;
      outside.color = red;
      const double nan = std::numeric_limits<double>::quiet_NaN();
      for (Complex lambda : lambdas) {
        const Complex z = l.h * lambda;
        if (!std::isfinite(z.real()) || !std::isfinite(z.imag())) continue;  // never a NaN dot
        Series& s = stable_at(l.method, z) ? inside : outside;
        s.x.insert(s.x.end(), {z.real(), nan});
        s.y.insert(s.y.end(), {z.imag(), nan});
      }
      c.series.push_back(std::move(inside));
      outsides.push_back(std::move(outside));
    }
    for (Series& o : outsides) c.series.push_back(std::move(o));
    return c;
  }

  c.title = "Stability region in the damped oscillator's plane (h w, h c): these methods have none in the "
            "complex plane; dots: the scene's modes";
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
  // Every region here lies within h w <= 2, h c <= 2 (the closed forms of docs/numerics.md, "One damped mode"): sampled
  // there, its edge stays smooth when the modes stretch the view.
  for (const RegionLane& l : shown)
    region([&](double x, double y) { return stable_at(l.method, x, y); }, 0.0, std::min(xmax, 2.2), 0.0,
           std::min(ymax, 2.2), draw::method_color(l.method), region_verdict(analysis, l), c.series);
  std::vector<Series> outsides;
  for (const RegionLane& l : shown) {
    Series inside, outside;
    inside.color = draw::method_color(l.method);
    inside.markers = true;
    inside.width = 1.5f;
    outside = inside;
    outside.color = red;
    const double nan = std::numeric_limits<double>::quiet_NaN();
    for (const auto& m : analysis.modes()) {
      const double X = l.h * std::sqrt(std::max(m.kappa, 0.0)), Y = l.h * m.gamma;
      if (!std::isfinite(X) || !std::isfinite(Y)) continue;
      Series& s = stable_at(l.method, X, Y) ? inside : outside;
      s.x.insert(s.x.end(), {X, nan});
      s.y.insert(s.y.end(), {Y, nan});
    }
    c.series.push_back(std::move(inside));
    outsides.push_back(std::move(outside));
  }
  for (Series& o : outsides) c.series.push_back(std::move(o));
  return c;
}

}  // namespace springlab::chart
