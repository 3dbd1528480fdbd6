#include "chart/chart_text.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <sstream>
#include <utility>
#include <vector>

#include "springlab/text.hpp"

namespace springlab::chart {

namespace {

std::string num(double v) {
  return format_text("%.3g", v);
}

std::string name_of(const Series& s, std::size_t k) {
  return s.label.empty() ? format_text(tr("line %d"), static_cast<int>(k) + 1) : s.label;
}

// The finite values of a line.
struct Span {
  double first = NAN, last = NAN, lo = INFINITY, hi = -INFINITY;
  bool any = false;
};
Span span_of(const std::vector<double>& v) {
  Span s;
  for (double y : v) {
    if (!std::isfinite(y)) continue;
    if (!s.any) s.first = y;
    s.any = true;
    s.last = y;
    s.lo = std::min(s.lo, y);
    s.hi = std::max(s.hi, y);
  }
  return s;
}

std::string csv_cell(const std::string& text) {
  if (text.find_first_of(",\"\n") == std::string::npos) return text;
  std::string out = "\"";
  for (char c : text) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

// A line's points with both coordinates positive and finite, as logs, by x.
std::vector<std::pair<double, double>> logs_of(const Series& s) {
  std::vector<std::pair<double, double>> p;
  for (std::size_t i = 0; i < std::min(s.x.size(), s.y.size()); ++i)
    if (std::isfinite(s.x[i]) && std::isfinite(s.y[i]) && s.x[i] > 0 && s.y[i] > 0)
      p.emplace_back(std::log10(s.x[i]), std::log10(s.y[i]));
  std::sort(p.begin(), p.end());
  return p;
}

// log y at log x = u along the line (straight between its points), if u is within them.
std::optional<double> log_y_at(const std::vector<std::pair<double, double>>& p, double u) {
  for (std::size_t i = 0; i + 1 < p.size(); ++i)
    if (p[i].first <= u && u <= p[i + 1].first)
      return p[i].first == p[i + 1].first
                 ? p[i].second
                 : p[i].second + (u - p[i].first) / (p[i + 1].first - p[i].first) *
                                     (p[i + 1].second - p[i].second);
  return std::nullopt;
}

// On log-log axes (work-precision, convergence): each line by its slope, the power of x it
// follows (least squares on the logs: an order where x is the step, minus one where it is the
// work), and which line is lowest where they all have points, at the most x they share.
std::string describe_log_log(const Chart& chart) {
  std::string lines;
  double shared_lo = -INFINITY, shared_hi = INFINITY;
  std::vector<std::pair<std::string, std::vector<std::pair<double, double>>>> named;
  for (std::size_t k = 0; k < chart.series.size(); ++k) {
    const Series& s = chart.series[k];
    if (s.label.empty()) continue;  // (a guide: an order's slope, drawn dashed)
    auto p = logs_of(s);
    if (p.size() < 2) continue;
    double mx = 0, my = 0;
    for (const auto& [u, v] : p) mx += u, my += v;
    mx /= p.size(), my /= p.size();
    double sxy = 0, sxx = 0;
    for (const auto& [u, v] : p) sxy += (u - mx) * (v - my), sxx += (u - mx) * (u - mx);
    if (sxx <= 0) continue;
    lines +=
        (lines.empty() ? "" : "; ") +
        format_text(tr("%s has slope %.2g on these log-log axes, from %s to %s"),
                    name_of(s, k).c_str(), sxy / sxx, num(std::pow(10.0, p.front().second)).c_str(),
                    num(std::pow(10.0, p.back().second)).c_str());
    shared_lo = std::max(shared_lo, p.front().first);
    shared_hi = std::min(shared_hi, p.back().first);
    named.emplace_back(name_of(s, k), std::move(p));
  }
  std::string text = lines.empty() ? "." : ": " + lines + ".";
  if (named.size() >= 2 && shared_lo <= shared_hi) {
    const std::pair<std::string, std::vector<std::pair<double, double>>>* best = nullptr;
    double best_y = INFINITY;
    for (const auto& line : named)
      if (const auto y = log_y_at(line.second, shared_hi); y && *y < best_y)
        best_y = *y, best = &line;
    if (best)
      text += " " +
              format_text(tr("Furthest right where every line has points (%s), %s is lowest (%s)."),
                          num(std::pow(10.0, shared_hi)).c_str(), best->first.c_str(),
                          num(std::pow(10.0, best_y)).c_str());
  }
  return text;
}

}  // namespace

std::string describe_chart(const Chart& chart) {
  const std::string y = chart.y.label, x = chart.x.label;
  std::string text = chart.title + " (" + y + ") " + tr("against") + " " + x;
  double x_lo = INFINITY, x_hi = -INFINITY, y_lo = INFINITY, y_hi = -INFINITY;
  for (const Series& s : chart.series) {
    const Span sx = span_of(s.x), sy = span_of(s.y);
    if (sx.any) x_lo = std::min(x_lo, sx.lo), x_hi = std::max(x_hi, sx.hi);
    if (sy.any && !s.escapes) y_lo = std::min(y_lo, sy.lo), y_hi = std::max(y_hi, sy.hi);
  }
  if (!std::isfinite(x_lo)) return text + ": " + tr("no data yet") + ".";
  text += format_text(tr(", from %s to %s"), num(x_lo).c_str(), num(x_hi).c_str());
  if (chart.x.log && chart.y.log) return text + describe_log_log(chart);
  const double range = std::isfinite(y_lo) ? std::max(y_hi - y_lo, 1e-300) : 1.0;
  std::string lines;
  for (std::size_t k = 0; k < chart.series.size(); ++k) {
    const Series& s = chart.series[k];
    if (s.label.empty() && chart.legend)
      continue;  // (a companion line: "total + lost" beside a lane's)
    const Span sy = span_of(s.y);
    if (!sy.any) continue;
    std::string said;
    if (s.escapes)
      said = format_text(tr("%s leaves the chart (diverged), at %s"), name_of(s, k).c_str(),
                         num(sy.last).c_str());
    else if (std::abs(sy.last - sy.first) < 0.02 * range && sy.hi - sy.lo < 0.1 * range)
      said = format_text(tr("%s holds at about %s (%s to %s)"), name_of(s, k).c_str(),
                         num(sy.last).c_str(), num(sy.lo).c_str(), num(sy.hi).c_str());
    else if (std::abs(sy.last - sy.first) < 0.02 * range)
      said = format_text(tr("%s goes between %s and %s, ending where it began, at %s"),
                         name_of(s, k).c_str(), num(sy.lo).c_str(), num(sy.hi).c_str(),
                         num(sy.last).c_str());
    else
      said = format_text(
          sy.last > sy.first ? tr("%s rises from %s to %s") : tr("%s falls from %s to %s"),
          name_of(s, k).c_str(), num(sy.first).c_str(), num(sy.last).c_str());
    lines += (lines.empty() ? "" : "; ") + said;
  }
  return text + (lines.empty() ? "." : ": " + lines + ".");
}

std::string chart_csv(const Chart& chart) {
  std::ostringstream out;
  std::size_t rows = 0;
  for (std::size_t k = 0; k < chart.series.size(); ++k) {
    const Series& s = chart.series[k];
    out << (k ? "," : "") << csv_cell(name_of(s, k) + " " + chart.x.label) << ","
        << csv_cell(name_of(s, k) + " " + chart.y.label);
    rows = std::max(rows, std::min(s.x.size(), s.y.size()));
  }
  out << "\n";
  for (std::size_t r = 0; r < rows; ++r) {
    for (std::size_t k = 0; k < chart.series.size(); ++k) {
      const Series& s = chart.series[k];
      if (k) out << ",";
      if (r < std::min(s.x.size(), s.y.size()))
        out << format_text("%.9g,%.9g", s.x[r], s.y[r]);
      else
        out << ",";
    }
    out << "\n";
  }
  return out.str();
}

}  // namespace springlab::chart
