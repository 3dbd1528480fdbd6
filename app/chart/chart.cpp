#include "chart/chart.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace springlab::chart {

std::string format_tick(double value, double step) {
  if (value == 0.0) return "0";
  char s[32];
  const double a = std::abs(value);
  if (a >= 1e-3 && a < 1e5) {
    // Decimals enough for the step's last significant digit (2.5e-4 needs 5), at least as many
    // significant digits as %.4g gives.
    if (step > 0.0) {
      const double lead = std::floor(std::log10(step) + 1e-9);
      const double mantissa = step / std::pow(10.0, lead);
      const int decimals = std::max(
          0, static_cast<int>(-lead) + (std::abs(mantissa - std::round(mantissa)) > 1e-6 ? 1 : 0));
      std::snprintf(s, sizeof s, "%.*f", std::min(decimals, 12), value);
      return s;
    }
    // %.5g, not %.4g: 10000 stays "10000" (%.4g writes "1e+04", beside "1e5" from the branch
    // below).
    std::snprintf(s, sizeof s, "%.5g", value);
  } else {  // 1e-6, 2.5e7: a short mantissa and a bare exponent
    int exponent = static_cast<int>(std::floor(std::log10(a)));
    double mantissa = value / std::pow(10.0, exponent);
    if (std::abs(mantissa) >= 9.9995) {
      mantissa /= 10.0;
      ++exponent;
    }
    // Digits enough for the step, relative to the exponent.
    int digits = 3;
    if (step > 0.0)
      digits =
          std::clamp(exponent - static_cast<int>(std::floor(std::log10(step) + 1e-9)) + 1, 1, 12);
    std::snprintf(s, sizeof s, "%.*ge%d", digits, mantissa, exponent);
  }
  return s;
}

std::vector<Tick> ticks(double lo, double hi, bool log, int target) {
  std::vector<Tick> out;
  if (!(hi > lo)) return out;
  if (log) {
    const int first = static_cast<int>(std::ceil(std::log10(lo) - 1e-9));
    const int last = static_cast<int>(std::floor(std::log10(hi) + 1e-9));
    const int decades = last - first + 1;
    const int every = std::max(1, decades / std::max(1, target + 2));
    for (int k = first; k <= last; ++k) {
      if ((k - first) % every) continue;
      out.push_back({std::pow(10.0, k), format_tick(std::pow(10.0, k)), true});
    }
    if (decades <= 3)  // minor ticks 2..9, labelled 2 and 5
      for (int k = first - 1; k <= last; ++k)
        for (int m = 2; m <= 9; ++m) {
          const double v = m * std::pow(10.0, k);
          if (v < lo || v > hi) continue;
          out.push_back({v, (m == 2 || m == 5) && decades <= 2 ? format_tick(v) : "", false});
        }
    return out;
  }
  const double raw = (hi - lo) / target;
  const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
  double step = magnitude;
  for (double m : {1.0, 2.0, 2.5, 5.0, 10.0})
    if (m * magnitude >= raw) {
      step = m * magnitude;
      break;
    }
  for (double v = std::ceil(lo / step - 1e-9) * step; v <= hi + 1e-9 * step; v += step) {
    const double at = std::abs(v) < 1e-12 * step ? 0.0 : v;
    out.push_back({at, format_tick(at, step), true});
  }
  return out;
}

std::vector<Tick> ticks_that_fit(double lo, double hi, bool log,
                                 const std::function<float(double)>& at,
                                 const std::function<float(const std::string&)>& width, float gap) {
  const auto apart = [&](const std::vector<Tick>& t) {
    std::vector<std::pair<float, float>> spans;  // each label's left and right, in pixels
    for (const Tick& k : t)
      if (!k.label.empty())
        spans.emplace_back(at(k.value) - 0.5f * width(k.label),
                           at(k.value) + 0.5f * width(k.label));
    std::sort(spans.begin(), spans.end());
    for (std::size_t i = 1; i < spans.size(); ++i)
      if (spans[i].first < spans[i - 1].second + gap) return false;
    return true;
  };
  std::vector<Tick> out;
  for (int target = 5; target >= 1; --target) {
    out = ticks(lo, hi, log, target);
    if (apart(out)) return out;
  }
  // Still too close (a log axis's 2 and 5, or a very narrow chart): the minor labels go, then every
  // other major one, until they stand apart.
  for (Tick& k : out)
    if (!k.major) k.label.clear();
  for (int every = 2; !apart(out) && every < 64; every *= 2) {
    int n = 0;
    for (Tick& k : out)
      if (k.major && !k.label.empty() && n++ % 2 == 1) k.label.clear();
  }
  return out;
}

void axis_range(const Chart& chart, bool x_axis, double& lo, double& hi) {
  const Axis& axis = x_axis ? chart.x : chart.y;
  lo = std::numeric_limits<double>::infinity();
  hi = -lo;
  // The range of a series' values on this axis (infinite when it has none).
  const auto extent = [&](const Series& s, double& a, double& b) {
    a = std::numeric_limits<double>::infinity();
    b = -a;
    for (double v : x_axis ? s.x : s.y) {
      if (!std::isfinite(v) || (axis.log && v <= 0)) continue;
      a = std::min(a, v);
      b = std::max(b, v);
    }
  };
  for (const Series& s : chart.series) {
    if (s.escapes && !x_axis) continue;
    double a, b;
    extent(s, a, b);
    lo = std::min(lo, a);
    hi = std::max(hi, b);
  }
  // A diverged lane sets the scale too where it stays within kEscapeReach times the others'
  // (explicit Euler's energy growing 25-fold before the audit stops it beside symplectic Euler's:
  // its growth is the point), or where every lane diverged (the single view after a divergence).
  if (!x_axis) {
    const bool none = !std::isfinite(lo);
    const double reach =
        none ? 0.0 : kEscapeReach * std::max({hi - lo, std::abs(lo), std::abs(hi)});
    for (const Series& s : chart.series) {
      if (!s.escapes) continue;
      double a, b;
      extent(s, a, b);
      if (!std::isfinite(a) || (!none && std::max(std::abs(a), std::abs(b)) > reach)) continue;
      lo = std::min(lo, a);
      hi = std::max(hi, b);
    }
  }
  if (axis.min) lo = *axis.min;
  if (axis.max) hi = *axis.max;
  if (!std::isfinite(lo) || !std::isfinite(hi)) {
    lo = axis.log ? 0.1 : 0.0;
    hi = axis.log ? 10.0 : 1.0;
  }
  if (axis.log) {
    if (!axis.min) lo = std::pow(10.0, std::floor(std::log10(lo) + 1e-9));
    if (!axis.max) hi = std::pow(10.0, std::ceil(std::log10(hi) - 1e-9));
    if (hi <= lo) hi = lo * 10.0;
    return;
  }
  if (hi - lo < 1e-12 * std::max(1.0, std::abs(hi))) {
    // No spread: around the value, or -1 to 1 around zero or round-off (a chart's first sample,
    // at t = 0, of a scene at rest: its energy 1e-27 J would make ticks of 1e-27). Along x from
    // a value not below 0 onwards: a clock's first sample, t = 0, with no time before it.
    const double pad = std::abs(hi) > 1e-6 ? 0.5 * std::abs(hi) : 1.0;
    if (!(x_axis && lo >= 0.0)) lo -= pad;
    hi += pad;
  }
  // A little room above and below the data.
  if (!axis.min) lo -= 0.05 * (hi - lo);
  if (!axis.max) hi += 0.05 * (hi - lo);
}

Corner legend_corner(const Chart& chart, double width, double height, std::optional<Corner> taken) {
  double xlo, xhi, ylo, yhi;
  axis_range(chart, true, xlo, xhi);
  axis_range(chart, false, ylo, yhi);
  // The plot's unit square, y up.
  const auto unit = [](double v, double lo, double hi, bool log) {
    return log ? (std::log10(v) - std::log10(lo)) / (std::log10(hi) - std::log10(lo))
               : (v - lo) / (hi - lo);
  };
  const double pad = 0.01;  // the box's own margin
  const double w = std::min(width + pad, 1.0), h = std::min(height + pad, 1.0);
  const Corner corners[] = {Corner::TopRight, Corner::TopLeft, Corner::BottomRight,
                            Corner::BottomLeft};
  int covered[4] = {0, 0, 0, 0};
  const auto count = [&](double u, double v) {
    if (!(u >= 0.0 && u <= 1.0 && v >= 0.0 && v <= 1.0)) return;
    const bool right = u >= 1.0 - w, left = u <= w, up = v >= 1.0 - h, down = v <= h;
    covered[0] += right && up;
    covered[1] += left && up;
    covered[2] += right && down;
    covered[3] += left && down;
  };
  constexpr int kSamples = 24;  // along each segment
  for (const Series& s : chart.series) {
    if (s.color.a < 0.5f) continue;  // a faint fill (a stability region's inside) may be covered
    bool have = false;
    double pu = 0.0, pv = 0.0;
    for (std::size_t k = 0; k < s.x.size() && k < s.y.size(); ++k) {
      const double x = s.x[k], y = s.y[k];
      if (!std::isfinite(x) || !std::isfinite(y) || (chart.x.log && x <= 0) ||
          (chart.y.log && y <= 0)) {
        have = false;
        continue;
      }
      const double u = unit(x, xlo, xhi, chart.x.log), v = unit(y, ylo, yhi, chart.y.log);
      if (have)
        for (int j = 1; j < kSamples; ++j) {
          const double f = static_cast<double>(j) / kSamples;
          count(pu + f * (u - pu), pv + f * (v - pv));
        }
      count(u, v);
      pu = u, pv = v, have = true;
    }
  }
  int best = -1;
  for (int c = 0; c < 4; ++c)
    if (corners[c] != taken && (best < 0 || covered[c] < covered[best])) best = c;
  return corners[best];
}

std::vector<Pixel> marks_along(const std::vector<std::vector<Pixel>>& lines, double spacing,
                               double phase) {
  std::vector<Pixel> out;
  double next = phase;  // the length along the lines at which the next mark goes
  double walked = 0.0;
  for (const std::vector<Pixel>& line : lines)
    for (std::size_t k = 0; k + 1 < line.size(); ++k) {
      const double dx = line[k + 1][0] - line[k][0], dy = line[k + 1][1] - line[k][1];
      const double length = std::hypot(dx, dy);
      while (length > 0.0 && next <= walked + length) {
        const double f = (next - walked) / length;
        out.push_back({line[k][0] + f * dx, line[k][1] + f * dy});
        next += spacing;
      }
      walked += length;
    }
  return out;
}

std::vector<double> spread_labels(const std::vector<double>& wanted, double gap, double lo,
                                  double hi) {
  const std::size_t n = wanted.size();
  std::vector<std::size_t> order(n);
  for (std::size_t k = 0; k < n; ++k) order[k] = k;
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return wanted[a] < wanted[b]; });
  // Down from the top, each at least `gap` below the one above; then, where the last ran past
  // `hi`, back up from the bottom; a plot too short for them all keeps the top's.
  std::vector<double> y(n);
  double floor = lo;
  for (std::size_t k = 0; k < n; ++k) {
    y[order[k]] = std::max(wanted[order[k]], floor);
    floor = y[order[k]] + gap;
  }
  double ceiling = hi;
  for (std::size_t k = n; k-- > 0;) {
    y[order[k]] = std::max(lo, std::min(y[order[k]], ceiling));
    ceiling = y[order[k]] - gap;
  }
  return y;
}

void equal_scale(double& xlo, double& xhi, double& ylo, double& yhi, double width, double height) {
  if (!(width > 0.0 && height > 0.0)) return;
  const double per_pixel = std::max((xhi - xlo) / width, (yhi - ylo) / height);
  const double xc = 0.5 * (xlo + xhi), yc = 0.5 * (ylo + yhi);
  xlo = xc - 0.5 * per_pixel * width, xhi = xc + 0.5 * per_pixel * width;
  ylo = yc - 0.5 * per_pixel * height, yhi = yc + 0.5 * per_pixel * height;
}

}  // namespace springlab::chart
