#include "chart/svg.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>
#include <vector>

#include "draw/palette.hpp"
#include "springlab/text.hpp"

namespace springlab::chart {

namespace {

std::string escape(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '&')
      out += "&amp;";
    else if (c == '<')
      out += "&lt;";
    else if (c == '>')
      out += "&gt;";
    else
      out += c;
  }
  return out;
}

struct Map {
  double lo, hi;
  bool log;
  double a, b;
  double operator()(double v) const {
    const double t = log ? (std::log10(v) - std::log10(lo)) / (std::log10(hi) - std::log10(lo))
                         : (v - lo) / (hi - lo);
    return a + t * (b - a);
  }
};

// A mark (draw/marks.hpp) of radius r at (x, y).
void write_mark(std::ostringstream& s, draw::Mark mark, double x, double y, double r,
                const std::string& colour) {
  if (mark == draw::Mark::None) return;
  const auto p = draw::mark_outline(mark);
  if (draw::strokes(mark)) {
    s << "<path d=\"M" << x + r * p[0][0] << " " << y + r * p[0][1] << "L" << x + r * p[1][0] << " "
      << y + r * p[1][1] << "M" << x + r * p[2][0] << " " << y + r * p[2][1] << "L"
      << x + r * p[3][0] << " " << y + r * p[3][1] << "\" stroke=\"" << colour
      << "\" stroke-width=\"2\"/>\n";
    return;
  }
  s << "<polygon points=\"";
  for (const auto& [px, py] : p) s << x + r * px << "," << y + r * py << " ";
  s << "\""
    << (draw::hollow(mark) ? " fill=\"none\" stroke=\"" + colour + "\" stroke-width=\"2\""
                           : " fill=\"" + colour + "\"")
    << "/>\n";
}

// A series' label at the end of its line (chart.hpp).
struct EndLabel {
  double x, y;
  std::string colour, text;
};

// The notes: each ending at its point, just above it.
void write_notes(std::ostringstream& s, const Chart& chart, const Map& mx, const Map& my) {
  for (const Note& n : chart.notes) {
    const bool ok = std::isfinite(n.x) && std::isfinite(n.y) && (!chart.x.log || n.x > 0) &&
                    (!chart.y.log || n.y > 0);
    if (!ok) continue;
    s << "<text x=\"" << mx(n.x) - 4.0 << "\" y=\"" << my(n.y) - 4.0 << "\" fill=\""
      << draw::hex(n.color) << "\" text-anchor=\"end\">" << escape(n.text) << "</text>\n";
  }
}

// The end labels, spread apart so that none covers another.
void write_end_labels(std::ostringstream& s, const std::vector<EndLabel>& ends, double kFont,
                      double line, double top, double bottom, double left) {
  std::vector<double> wanted;
  wanted.reserve(ends.size());
  for (const EndLabel& e : ends) wanted.push_back(e.y);
  const std::vector<double> y = spread_labels(wanted, line, top + line, bottom - 4.0);
  for (std::size_t k = 0; k < ends.size(); ++k)
    s << "<text x=\"" << std::max(left + 4.0, ends[k].x - 10.0) << "\" y=\"" << y[k] + kFont * 0.35
      << "\" fill=\"" << ends[k].colour
      << "\" text-anchor=\"end\" paint-order=\"stroke\" stroke=\"#16181c\" stroke-width=\"4\">"
      << escape(ends[k].text) << "</text>\n";
}

// The series, clipped to the plot: lines, marks on their points or along them, crosses; then
// the notes and the end labels (chart.hpp).
void write_series(std::ostringstream& s, const Chart& chart, const Map& mx, const Map& my,
                  double kFont, double line, double top, double bottom, double left) {
  std::vector<EndLabel> ends;
  for (std::size_t index = 0; index < chart.series.size(); ++index) {
    const Series& series = chart.series[index];
    const std::string colour = draw::hex(series.color);
    const std::string opacity = series.color.a < 1.0f
                                    ? " stroke-opacity=\"" + std::to_string(series.color.a) + "\""
                                    : std::string();
    std::ostringstream points;
    points.precision(6);
    std::vector<std::vector<Pixel>> drawn{{}};  // (for the marks along it)
    const auto flush = [&] {
      if (!series.markers && series.mark != draw::Mark::None && drawn.back().size() >= 2)
        drawn.emplace_back();
      else
        drawn.back().clear();
      const std::string p = points.str();
      if (!p.empty() && p.find(' ') != p.rfind(' '))
        s << "<polyline fill=\"none\" stroke=\"" << colour << "\" stroke-width=\"" << series.width
          << "\" stroke-linejoin=\"round\"" << (series.dashed ? " stroke-dasharray=\"7 5\"" : "")
          << opacity << " points=\"" << p << "\"/>\n";
      points.str("");
    };
    for (std::size_t k = 0; k < series.x.size(); ++k) {
      const double xv = series.x[k], yv = series.y[k];
      const bool ok = std::isfinite(xv) && std::isfinite(yv) && (!chart.x.log || xv > 0) &&
                      (!chart.y.log || yv > 0);
      if (!ok) {
        flush();
        continue;
      }
      const double x = mx(xv), y = my(yv);
      if (k < series.crossed.size() && series.crossed[k]) {
        flush();
        const double r = 4.0 + series.width;
        s << "<path d=\"M" << x - r << " " << y - r << "L" << x + r << " " << y + r << "M" << x - r
          << " " << y + r << "L" << x + r << " " << y - r << "\" stroke=\"" << colour
          << "\" stroke-width=\"2\"/>\n";
        continue;
      }
      points << x << "," << y << " ";
      drawn.back().push_back({x, y});
      if (series.markers && series.mark == draw::Mark::None)
        s << "<circle cx=\"" << x << "\" cy=\"" << y << "\" r=\"" << 2.0 + series.width
          << "\" fill=\"" << colour << "\"/>\n";
      else if (series.markers)
        write_mark(s, series.mark, x, y, 3.0 + series.width, colour);
    }
    const std::optional<Pixel> last =
        drawn.back().empty() ? std::nullopt : std::optional<Pixel>(drawn.back().back());
    flush();
    for (const Pixel& m :
         marks_along(drawn, kMarkSpacing,
                     0.5 * kMarkSpacing * (1.0 + 0.37 * static_cast<double>(index % 5))))
      write_mark(s, series.mark, m[0], m[1], 2.5 + series.width, colour);
    if (chart.end_labels && !series.label.empty() && last)
      ends.push_back({(*last)[0], (*last)[1], colour, series.label});
  }
  write_notes(s, chart, mx, my);
  write_end_labels(s, ends, kFont, line, top, bottom, left);
}

// The chart's drawing, in a picture of width x height: the root document's or a nested <svg>'s
// (an inset). `id` keeps its clip path's name apart from another chart's in the same document.
// The legend, in the corner of the plot where it hides the least (chart.hpp); that corner, or none
// (no labelled series).
std::optional<Corner> write_legend(std::ostringstream& s, const Chart& chart, double left,
                                   double right, double top, double bottom, double font,
                                   double line, const char* text) {
  const double kFont = font, kChar = 0.56 * font;
  std::size_t chars = 0;
  int rows = 0;
  for (const Series& series : chart.series)
    if (!series.label.empty()) {
      chars = std::max(chars, series.label.size());
      ++rows;
    }
  if (rows == 0) return std::nullopt;
  const double w = chars * kChar + 44;
  const Corner corner =
      legend_corner(chart, (w + 14) / (right - left), (rows * line + 12) / (bottom - top));
  const bool on_left = corner == Corner::TopLeft || corner == Corner::BottomLeft;
  const bool below = corner == Corner::BottomRight || corner == Corner::BottomLeft;
  const double x = on_left ? left + 10 : right - w - 6,
               y0 = below ? bottom - rows * line - 6 : top + 6;
  s << "<rect x=\"" << x - 6 << "\" y=\"" << y0 - 4 << "\" width=\"" << w + 8 << "\" height=\""
    << rows * line + 8 << "\" rx=\"3\" fill=\"#0d0f12\" fill-opacity=\"0.85\"/>\n";
  int row = 0;
  for (const Series& series : chart.series) {
    if (series.label.empty()) continue;
    const double y = y0 + row++ * line + 0.5 * line;
    s << "<line x1=\"" << x << "\" y1=\"" << y << "\" x2=\"" << x + 22 << "\" y2=\"" << y
      << "\" stroke=\"" << draw::hex(series.color) << "\" stroke-width=\"3\""
      << (series.dashed ? " stroke-dasharray=\"5 3\"" : "") << "/>\n<text x=\"" << x + 30
      << "\" y=\"" << y + kFont * 0.35 << "\" fill=\""
      << (series.escapes ? draw::hex(draw::kDiverged) : std::string(text)) << "\">"
      << escape(series.label) << "</text>\n";
    write_mark(s, series.mark, x + 11, y, 0.3 * kFont, draw::hex(series.color));
  }
  return corner;
}

void write_chart(std::ostringstream& s, const Chart& chart, double width, double height,
                 const std::string& id) {
  constexpr double kFont = 15.0, kChar = 0.56 * kFont;  // DejaVu Sans's mean advance, roughly
  double xlo, xhi, ylo, yhi;
  axis_range(chart, true, xlo, xhi);
  axis_range(chart, false, ylo, yhi);
  auto xt = ticks(xlo, xhi, chart.x.log), yt = ticks(ylo, yhi, chart.y.log, 4);
  std::size_t label_chars = 0;
  for (const Tick& t : yt) label_chars = std::max(label_chars, t.label.size());
  const double line = kFont * 1.35;
  const double top = (chart.title.empty() ? 8.0 : line * 1.4) + line;
  const double left = 14.0 + label_chars * kChar + 8.0;
  const double right = width - 16.0, bottom = height - line * 2.6;
  if (chart.equal_scale && !chart.x.log && !chart.y.log) {
    equal_scale(xlo, xhi, ylo, yhi, right - left, bottom - top);
    xt = ticks(xlo, xhi, false), yt = ticks(ylo, yhi, false, 4);
  }
  const Map mx{xlo, xhi, chart.x.log, left, right}, my{ylo, yhi, chart.y.log, bottom, top};

  s << "<rect width=\"100%\" height=\"100%\" fill=\"#16181c\"/>\n";
  const char* text = "#f3f4f6";
  const char* grid = "#3a3f47";
  if (!chart.title.empty())
    s << "<text x=\"12\" y=\"" << line << "\" fill=\"" << text << "\" font-size=\"" << kFont * 1.15
      << "\" font-weight=\"bold\">" << escape(chart.title) << "</text>\n";
  s << "<text x=\"12\" y=\"" << top - line * 0.35 << "\" fill=\"" << text << "\">"
    << escape(chart.y.label) << "</text>\n";
  s << "<text x=\"" << 0.5 * (left + right) << "\" y=\"" << height - line * 0.55 << "\" fill=\""
    << text << "\" text-anchor=\"middle\">" << escape(chart.x.label) << "</text>\n";
  for (const Tick& t : xt) {
    const double x = mx(t.value);
    s << "<line x1=\"" << x << "\" y1=\"" << top << "\" x2=\"" << x << "\" y2=\"" << bottom
      << "\" stroke=\"" << grid << "\" stroke-opacity=\"" << (t.major ? 1.0 : 0.45) << "\"/>\n";
    if (!t.label.empty()) {
      // Centred under its tick, but kept inside the picture (the last one sits on the right edge).
      const double half = 0.5 * t.label.size() * kChar;
      const double at = std::clamp(x, half + 2.0, width - half - 4.0);
      s << "<text x=\"" << at << "\" y=\"" << bottom + line << "\" fill=\"" << text
        << "\" text-anchor=\"middle\">" << escape(t.label) << "</text>\n";
    }
  }
  for (const Tick& t : yt) {
    const double y = my(t.value);
    s << "<line x1=\"" << left << "\" y1=\"" << y << "\" x2=\"" << right << "\" y2=\"" << y
      << "\" stroke=\"" << grid << "\" stroke-opacity=\"" << (t.major ? 1.0 : 0.45) << "\"/>\n";
    // A tick at the very top would write over the axis' label above it: that one goes unlabelled.
    const bool under_label = y - kFont * 0.45 < top - line * 0.35 + kFont * 0.2 &&
                             left - 8 - t.label.size() * kChar < 12 + chart.y.label.size() * kChar;
    if (!t.label.empty() && !under_label)
      s << "<text x=\"" << left - 8 << "\" y=\"" << y + kFont * 0.35 << "\" fill=\"" << text
        << "\" text-anchor=\"end\">" << escape(t.label) << "</text>\n";
  }
  s << "<rect x=\"" << left << "\" y=\"" << top << "\" width=\"" << right - left << "\" height=\""
    << bottom - top << "\" fill=\"none\" stroke=\"#6b7280\"/>\n";
  s << "<clipPath id=\"" << id << "\"><rect x=\"" << left << "\" y=\"" << top << "\" width=\""
    << right - left << "\" height=\"" << bottom - top << "\"/></clipPath>\n<g clip-path=\"url(#"
    << id << ")\">\n";
  write_series(s, chart, mx, my, kFont, line, top, bottom, left);
  s << "</g>\n";
  std::optional<Corner> legend_at;
  if (chart.legend && !chart.end_labels)  // (end labels name the lines in its place)
    legend_at = write_legend(s, chart, left, right, top, bottom, kFont, line, text);
  if (chart.inset) {
    // Over the corner that hides the least apart from the legend's (chart.hpp), on its backdrop.
    const Corner at = legend_corner(chart, kInsetWidth, kInsetHeight, legend_at);
    const double w = kInsetWidth * (right - left), h = kInsetHeight * (bottom - top);
    const bool on_left = at == Corner::TopLeft || at == Corner::BottomLeft;
    const bool below = at == Corner::BottomRight || at == Corner::BottomLeft;
    const double x = on_left ? left + 4 : right - w - 4, y = below ? bottom - h - 4 : top + 4;
    s << "<svg x=\"" << x << "\" y=\"" << y << "\" width=\"" << w << "\" height=\"" << h
      << "\" viewBox=\"0 0 " << w << " " << h << "\">\n";
    write_chart(s, *chart.inset, w, h, id + "-inset");
    s << "<rect width=\"100%\" height=\"100%\" fill=\"none\" stroke=\"#6b7280\"/>\n</svg>\n";
  }
}

}  // namespace

std::string to_svg(const Chart& chart, int width, int height) {
  std::ostringstream s;
  s.precision(6);
  s << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << height
    << "\" viewBox=\"0 0 " << width << " " << height << "\" font-family=\"DejaVu Sans, "
    << (current_language() == "en" ? "" : "Noto Sans CJK SC, ")
    << "Verdana, sans-serif\" font-size=\"" << 15.0 << "\">\n";
  write_chart(s, chart, width, height, "plot");
  s << "</svg>\n";
  return s.str();
}

}  // namespace springlab::chart
