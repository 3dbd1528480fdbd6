#include "chart/imgui_chart.hpp"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "chart/text_wrap.hpp"
#include "draw/palette.hpp"

namespace springlab::chart {

namespace {

ImU32 color(const draw::Rgba& c, float alpha = 1.0f) {
  return ImGui::ColorConvertFloat4ToU32(ImVec4(c.r, c.g, c.b, c.a * alpha));
}

struct Mapping {
  double lo, hi;
  bool log;
  float a, b;  // pixel at lo, at hi
  float operator()(double v) const {
    const double t = log ? (std::log10(v) - std::log10(lo)) / (std::log10(hi) - std::log10(lo))
                         : (v - lo) / (hi - lo);
    return a + static_cast<float>(t) * (b - a);
  }
};

// The text (a title, an axis label), or as many of its words as fit `width` followed by an
// ellipsis.
std::string fitted(const std::string& text, float width) {
  const auto fits = [&](const std::string& t) { return ImGui::CalcTextSize(t.c_str()).x <= width; };
  if (fits(text)) return text;
  std::string cut = text;
  for (std::size_t space = cut.rfind(' '); space != std::string::npos && space > 0;
       space = cut.rfind(' ')) {
    cut.resize(space);
    while (!cut.empty() && (cut.back() == ',' || cut.back() == ':' || cut.back() == '('))
      cut.pop_back();
    if (fits(cut + "\u2026")) return cut + "\u2026";
  }
  return cut;
}

// Where a chart is drawn: its box, its plot's edges, its text's line height (pixels), its ranges.
struct Plot {
  ImVec2 origin, size;
  float line_h = 0.0f, heading = 0.0f, top = 0.0f, left = 0.0f, right = 0.0f, bottom = 0.0f;
  double xlo = 0.0, xhi = 1.0, ylo = 0.0, yhi = 1.0;
};

// The title, wrapped at spaces to the chart's width: on as many lines as it takes, never cut.
std::string title_lines(const Chart& chart, float width) {
  return ui::wrap_text(chart.title, ImGui::GetFont(), ImGui::GetFontSize(), width);
}

// The legend: its labels (at most the plot's width, a longer one wrapped onto a second line at
// spaces, never inside a number such as "x1.33") stacked in a box in the plot's corner where it
// hides the least. Where that box would be taller than the plot (a phone's short chart, with
// five series: it covered the plot's right half and ran off its foot) it goes outside the
// plot: stacked beside it on the right, the plot made narrower, where the column fits the
// chart's height and leaves the plot 40 % of its width; else in rows over the plot, the plot made
// shorter, where it keeps two lines' height; else the box after all.
enum class Legend { Box, Column, Rows };
struct LegendLayout {
  Legend place = Legend::Box;
  std::vector<std::string> labels;
  float w = 0.0f, h = 0.0f;
  std::vector<int> row_of;  // in rows: each entry's row
};

// Places the legend; beside the plot or over it, it takes the plot's room (p.right, p.top).
LegendLayout place_legend(const Chart& chart, Plot& p) {
  const ImVec2 origin = p.origin, size = p.size;
  const float line_h = p.line_h, heading = p.heading, left = p.left, bottom = p.bottom;
  float& top = p.top;
  float& right = p.right;
  Legend place = Legend::Box;
  std::vector<std::string> labels;
  float legend_w = 0.0f, legend_h = 0.0f;
  std::vector<int> row_of;  // in rows: each entry's row
  const auto stack = [&](float most) {
    labels.clear();
    legend_w = legend_h = 0.0f;
    for (const Series& s : chart.series) {
      labels.push_back(ui::wrap_text(s.label, ImGui::GetFont(), ImGui::GetFontSize(), most));
      if (s.label.empty()) continue;
      const ImVec2 size = ImGui::CalcTextSize(labels.back().c_str());
      legend_w = std::max(legend_w, size.x);
      legend_h += size.y;
    }
  };
  if (chart.legend && !chart.end_labels) {  // (end labels name the lines in its place)
    stack(std::max(60.0f, right - left - 40.0f));
    // (The complex plane, whose regions fill the middle, and a chart told to: off the plot.)
    if (chart.equal_scale || chart.legend_off_plot || legend_h + 8.0f > bottom - top) {
      const std::vector<std::string> boxed = labels;
      const float box_w = legend_w, box_h = legend_h;
      stack(std::max(60.0f, 0.45f * size.x - 34.0f));
      const float column = legend_w + 34.0f + 8.0f;  // swatch, margins, the gap to the plot
      if (heading + legend_h <= origin.y + size.y &&
          right - column - left >= 0.4f * (right - left)) {
        place = Legend::Column;
        right -= column;
      } else {
        labels = boxed;
        legend_w = box_w;
        legend_h = box_h;
        // Entries side by side (a swatch, the label on one line, a gap), a new row where the
        // next would pass the chart's right edge.
        float x = 0.0f;
        int rows = 1;
        for (const Series& s : chart.series) {
          const float w = 26.0f + ImGui::CalcTextSize(s.label.c_str()).x + 14.0f;
          if (x > 0.0f && x + w > size.x) {
            ++rows;
            x = 0.0f;
          }
          row_of.push_back(rows - 1);
          if (!s.label.empty()) x += w;
        }
        if (bottom - (top + rows * line_h) >= std::max(20.0f, 2.0f * line_h)) {
          place = Legend::Rows;
          top += rows * line_h;
        }
      }
    }
  }
  return {place, labels, legend_w, legend_h, row_of};
}

// The title, the axes' labels, the ticks and their grid, the plot's frame.
void draw_axes(ImDrawList* list, const Chart& chart, const Plot& p, const std::vector<Tick>& yt,
               Legend place) {
  const ImVec2 origin = p.origin, size = p.size;
  const float line_h = p.line_h, top = p.top, left = p.left, right = p.right, bottom = p.bottom;
  const double xlo = p.xlo, xhi = p.xhi, ylo = p.ylo, yhi = p.yhi;
  const ImU32 text = ImGui::GetColorU32(ImGuiCol_Text);
  const ImU32 faint = ImGui::GetColorU32(ImGuiCol_Border);
  const ImU32 grid = ImGui::GetColorU32(ImGuiCol_Border, 0.45f);
  const Mapping mx{xlo, xhi, chart.x.log, left, right}, my{ylo, yhi, chart.y.log, bottom, top};
  // The x ticks: as many as the labels leave room for, never two labels running together (a
  // narrow chart takes 5 ticks' "0 0.25 0.5 0.75 1" as "00.250.50.751").
  const std::vector<Tick> xt = ticks_that_fit(
      xlo, xhi, chart.x.log, [&](double v) { return mx(v); },
      [](const std::string& label) { return ImGui::CalcTextSize(label.c_str()).x; },
      0.25f * line_h);

  if (!chart.title.empty())
    list->AddText(ImVec2(origin.x, origin.y), text, title_lines(chart, size.x).c_str());
  // (Beside a legend column, only as far as the plot's right edge.)
  list->AddText(ImVec2(origin.x, top - line_h * 1.1f), text,
                place == Legend::Column ? fitted(chart.y.label, right - origin.x).c_str()
                                        : chart.y.label.c_str());
  const std::string x_label = fitted(chart.x.label, size.x);
  const ImVec2 xl = ImGui::CalcTextSize(x_label.c_str());
  // Centred under the plot, but kept inside the chart (the plot is off centre by the y ticks).
  list->AddText(ImVec2(std::max(origin.x, std::min(0.5f * (left + right) - 0.5f * xl.x,
                                                   origin.x + size.x - xl.x)),
                       bottom + line_h * 1.15f),
                text, x_label.c_str());

  list->PushClipRect(ImVec2(origin.x, origin.y), ImVec2(origin.x + size.x, origin.y + size.y),
                     true);  // (the tick labels kept within the chart)
  for (const Tick& t : xt) {
    const float x = mx(t.value);
    list->AddLine(ImVec2(x, top), ImVec2(x, bottom),
                  t.major ? grid : ImGui::GetColorU32(ImGuiCol_Border, 0.2f));
    if (!t.label.empty()) {
      // Centred under its tick, but kept inside the chart (the last one sits on the right edge).
      const ImVec2 s = ImGui::CalcTextSize(t.label.c_str());
      const float at = std::clamp(x - 0.5f * s.x, origin.x, origin.x + size.x - s.x - 2.0f);
      list->AddText(ImVec2(at, bottom + 0.15f * line_h), text, t.label.c_str());
    }
  }
  const ImVec2 yl = ImGui::CalcTextSize(chart.y.label.c_str());
  for (const Tick& t : yt) {
    const float y = my(t.value);
    list->AddLine(ImVec2(left, y), ImVec2(right, y),
                  t.major ? grid : ImGui::GetColorU32(ImGuiCol_Border, 0.2f));
    if (!t.label.empty()) {
      const ImVec2 s = ImGui::CalcTextSize(t.label.c_str());
      // A tick at the very top would write over the axis' label above it: that one goes unlabelled.
      const bool under_label =
          y - 0.5f * s.y < top - 0.1f * line_h && left - s.x - 6.0f < origin.x + yl.x;
      if (!under_label)
        list->AddText(ImVec2(left - s.x - 6.0f, y - 0.5f * s.y), text, t.label.c_str());
    }
  }
  list->AddRect(ImVec2(left, top), ImVec2(right, bottom), faint);
  list->PopClipRect();
}

// A line's end label: where its line ends, its colour, its text (set in the margin by
// draw_chart_end_labels).
struct ChartEndLabel {
  ImVec2 at;
  ImU32 colour;
  const std::string* text;
};

// One series within the plot: its line (broken where a point is not finite or not on a log
// axis), marks on its points or along it, crosses on its crossed points, and where it escapes the
// plot the line to the edge and a marker there. Returns the last point of its line drawn, or
// (-1, -1) where none was.
ImVec2 draw_chart_series(ImDrawList* list, const Chart& chart, const Plot& plot,
                         std::size_t index) {
  const double ylo = plot.ylo, yhi = plot.yhi;
  const Mapping mx{plot.xlo, plot.xhi, chart.x.log, plot.left, plot.right},
      my{ylo, yhi, chart.y.log, plot.bottom, plot.top};
  const Series& s = chart.series[index];
  const ImU32 c = color(s.color);
  std::vector<ImVec2> points;
  std::vector<std::vector<Pixel>> drawn;  // (for the marks along it)
  const auto flush = [&] {
    if (!s.markers && s.mark != draw::Mark::None && points.size() >= 2) {
      drawn.emplace_back();
      for (const ImVec2& q : points) drawn.back().push_back({q.x, q.y});
    }
    if (points.size() >= 2) {
      if (s.dashed) {
        for (std::size_t k = 0; k + 1 < points.size(); k += 2)
          list->AddLine(points[k], points[k + 1], c, s.width);
      } else {
        list->AddPolyline(points.data(), static_cast<int>(points.size()), c, ImDrawFlags_None,
                          s.width);
      }
    }
    points.clear();
  };
  for (std::size_t k = 0; k < s.x.size(); ++k) {
    const double x = s.x[k], y = s.y[k];
    const bool ok =
        std::isfinite(x) && std::isfinite(y) && (!chart.x.log || x > 0) && (!chart.y.log || y > 0);
    if (s.escapes && (!ok || y > yhi || y < ylo)) {
      // Leaving the plot: the line to its edge, a marker there, and nothing after.
      if (!points.empty() && ok) {
        const double edge = y > yhi ? yhi : ylo;
        const double f = (edge - s.y[k - 1]) / (y - s.y[k - 1]);
        const ImVec2 at(mx(s.x[k - 1] + f * (x - s.x[k - 1])), my(edge));
        points.push_back(at);
        const float r = 5.0f + s.width, d = y > yhi ? 1.0f : -1.0f;
        list->AddTriangleFilled(ImVec2(at.x - r, at.y + d * 1.7f * r),
                                ImVec2(at.x + r, at.y + d * 1.7f * r), at, c);
      }
      break;
    }
    if (!ok) {
      flush();
      continue;
    }
    const ImVec2 p(mx(x), my(y));
    const bool crossed = k < s.crossed.size() && s.crossed[k];
    if (crossed) {
      flush();
      const float r = 4.0f + s.width;
      list->AddLine(ImVec2(p.x - r, p.y - r), ImVec2(p.x + r, p.y + r), c, 2.0f);
      list->AddLine(ImVec2(p.x - r, p.y + r), ImVec2(p.x + r, p.y - r), c, 2.0f);
      continue;
    }
    points.push_back(p);
    if (s.markers) {
      if (s.mark == draw::Mark::None)
        list->AddCircleFilled(p, 2.0f + s.width, c);
      else
        draw_mark(list, s.mark, p, 3.0f + s.width, c);
    }
  }
  const ImVec2 last = points.empty() ? ImVec2(-1, -1) : points.back();
  flush();
  const float mark_r = 2.5f + s.width;
  for (const Pixel& m : marks_along(
           drawn, kMarkSpacing, 0.5 * kMarkSpacing * (1.0 + 0.37 * static_cast<double>(index % 5))))
    draw_mark(list, s.mark, ImVec2(static_cast<float>(m[0]), static_cast<float>(m[1])), mark_r, c);
  return last;
}

// The notes: each ending at its point, just above it (those off the plot not drawn).
void draw_chart_notes(ImDrawList* list, const Chart& chart, const Plot& p) {
  const Mapping mx{p.xlo, p.xhi, chart.x.log, p.left, p.right},
      my{p.ylo, p.yhi, chart.y.log, p.bottom, p.top};
  for (const Note& n : chart.notes) {
    const bool ok = std::isfinite(n.x) && std::isfinite(n.y) && (!chart.x.log || n.x > 0) &&
                    (!chart.y.log || n.y > 0);
    if (!ok || n.y < p.ylo || n.y > p.yhi) continue;
    const ImVec2 size = ImGui::CalcTextSize(n.text.c_str());
    const ImVec2 at(std::max(p.left + 2.0f, mx(n.x) - size.x - 4.0f),
                    std::max(p.top, my(n.y) - size.y - 2.0f));
    list->AddText(at, color(n.color), n.text.c_str());
  }
}

// The end labels: in the margin right of the plot (draw_imgui keeps it), each at the height of
// its line's last point, moved apart, with a short lead from that point where it was moved.
void draw_chart_end_labels(ImDrawList* list, const std::vector<ChartEndLabel>& ends,
                           const Plot& p) {
  if (ends.empty()) return;
  const float line_h = p.line_h, right = p.right;
  std::vector<double> wanted;
  wanted.reserve(ends.size());
  for (const ChartEndLabel& e : ends) wanted.push_back(e.at.y - 0.5f * line_h);
  const std::vector<double> y = spread_labels(wanted, line_h, p.top, p.bottom - line_h);
  for (std::size_t k = 0; k < ends.size(); ++k) {
    const ImVec2 at(right + 8.0f, static_cast<float>(y[k]));
    list->AddLine(ImVec2(right + 1.0f, ends[k].at.y), ImVec2(at.x - 2.0f, at.y + 0.5f * line_h),
                  ends[k].colour, 1.0f);
    list->AddText(at, ends[k].colour, ends[k].text->c_str());
  }
}

// The series within the plot (draw_chart_series), the notes; then the end labels.
void draw_lines(ImDrawList* list, const Chart& chart, const Plot& p) {
  list->PushClipRect(ImVec2(p.left, p.top), ImVec2(p.right, p.bottom), true);
  std::vector<ChartEndLabel> ends;
  for (std::size_t index = 0; index < chart.series.size(); ++index) {
    const ImVec2 last = draw_chart_series(list, chart, p, index);
    const Series& s = chart.series[index];
    if (chart.end_labels && !s.label.empty() && last.x >= 0.0f)
      ends.push_back({last, color(s.color), &s.label});
  }
  draw_chart_notes(list, chart, p);
  list->PopClipRect();
  draw_chart_end_labels(list, ends, p);
}

// The legend as placed: in rows over the plot, in a column beside it, or in a box in the corner
// where it hides the least. Returns that corner (the inset takes another).
std::optional<Corner> draw_legend(ImDrawList* list, const Chart& chart, const Plot& p,
                                  const LegendLayout& legend) {
  const ImVec2 origin = p.origin;
  const float line_h = p.line_h, heading = p.heading, top = p.top, left = p.left, right = p.right,
              bottom = p.bottom;
  const ImU32 text = ImGui::GetColorU32(ImGuiCol_Text);
  const Legend place = legend.place;
  const std::vector<std::string>& labels = legend.labels;
  const float legend_w = legend.w, legend_h = legend.h;
  const std::vector<int>& row_of = legend.row_of;
  std::optional<Corner> legend_at;
  const auto entry = [&](std::size_t k, float x, float y,
                         const std::string& label) {  // a swatch, its label
    const Series& s = chart.series[k];
    const float mid = y + 0.5f * line_h;
    list->AddLine(ImVec2(x, mid), ImVec2(x + 20, mid), color(s.color), 3.0f);
    draw_mark(list, s.mark, ImVec2(x + 10, mid), 0.22f * line_h, color(s.color));
    list->AddText(ImVec2(x + 26, y), s.escapes ? color(draw::kDiverged) : text, label.c_str());
  };
  if (place == Legend::Rows) {
    float x = origin.x;
    int row = 0;
    for (std::size_t k = 0; k < chart.series.size(); ++k) {
      if (chart.series[k].label.empty()) continue;
      if (row_of[k] != row) {
        row = row_of[k];
        x = origin.x;
      }
      entry(k, x, heading + static_cast<float>(row) * line_h, chart.series[k].label);
      x += 26.0f + ImGui::CalcTextSize(chart.series[k].label.c_str()).x + 14.0f;
    }
  } else if (legend_h > 0.0f) {
    // Beside the plot, from the y label's line down; or the box: the labels and their swatches
    // (26 px) with 6 px round them, 4 px in from the plot's edge, in the corner where it hides
    // the least.
    float x = right + 8.0f + 6.0f, y = heading;
    if (place == Legend::Box) {
      const Corner corner = legend_corner(chart, (legend_w + 40.0f) / (right - left),
                                          (legend_h + 8.0f) / (bottom - top));
      legend_at = corner;
      const bool on_left = corner == Corner::TopLeft || corner == Corner::BottomLeft;
      const bool below = corner == Corner::BottomRight || corner == Corner::BottomLeft;
      x = on_left ? left + 10.0f : right - legend_w - 34.0f;
      y = below ? bottom - legend_h - 4.0f : top + 4.0f;
      list->AddRectFilled(ImVec2(x - 6, y - 2), ImVec2(x + legend_w + 30, y + legend_h + 2),
                          ImGui::GetColorU32(ImGuiCol_WindowBg, 0.85f), 3.0f);
    }
    for (std::size_t k = 0; k < chart.series.size(); ++k) {
      if (chart.series[k].label.empty()) continue;
      entry(k, x, y, labels[k]);
      y += ImGui::CalcTextSize(labels[k].c_str()).y;
    }
  }
  return legend_at;
}

// One scale on both axes (a chart with equal_scale and neither axis logarithmic): the ranges
// widened to the plot's shape as the legend left it, the plot's left edge moved where the new y
// ticks' labels are wider than `label_w` (at most 3 passes). Returns the y ticks to draw (`yt`
// where the scale is not equal).
std::vector<Tick> equal_scale_ticks(const Chart& chart, Plot& p, const std::vector<Tick>& yt,
                                    float label_w) {
  std::vector<Tick> y_ticks = yt;
  if (chart.equal_scale && !chart.x.log && !chart.y.log)
    for (int pass = 0; pass < 3; ++pass) {
      axis_range(chart, true, p.xlo, p.xhi);
      axis_range(chart, false, p.ylo, p.yhi);
      equal_scale(p.xlo, p.xhi, p.ylo, p.yhi, p.right - p.left, p.bottom - p.top);
      y_ticks = ticks(p.ylo, p.yhi, false, 4);
      float widest = 0.0f;
      for (const Tick& t : y_ticks)
        widest = std::max(widest, ImGui::CalcTextSize(t.label.c_str()).x);
      if (widest <= label_w) break;
      p.left += widest - label_w;
      label_w = widest;
    }
  return y_ticks;
}

// The chart's inset (kInsetWidth x kInsetHeight of the plot): over the corner that hides the least
// apart from the legend's, on its own backdrop; in a small chart there is no room for one worth
// reading, and the dots stay in the main view.
void draw_chart_inset(ImDrawList* list, const Chart& chart, const Plot& p,
                      std::optional<Corner> legend_at) {
  const float line_h = p.line_h;
  const ImU32 faint = ImGui::GetColorU32(ImGuiCol_Border);
  const float inset_w = static_cast<float>(kInsetWidth) * (p.right - p.left),
              inset_h = static_cast<float>(kInsetHeight) * (p.bottom - p.top);
  if (!(chart.inset && inset_w >= 12.0f * line_h && inset_h >= 7.0f * line_h)) return;
  const Corner at = legend_corner(chart, kInsetWidth, kInsetHeight, legend_at);
  const float w = inset_w, h = inset_h;
  const bool on_left = at == Corner::TopLeft || at == Corner::BottomLeft;
  const bool below = at == Corner::BottomRight || at == Corner::BottomLeft;
  const ImVec2 o(on_left ? p.left + 4.0f : p.right - w - 4.0f,
                 below ? p.bottom - h - 4.0f : p.top + 4.0f);
  list->AddRectFilled(o, ImVec2(o.x + w, o.y + h), ImGui::GetColorU32(ImGuiCol_WindowBg, 0.97f),
                      3.0f);
  list->AddRect(o, ImVec2(o.x + w, o.y + h), faint, 3.0f);
  draw_imgui(list, ImVec2(o.x + 4.0f, o.y + 2.0f), ImVec2(w - 8.0f, h - 4.0f), *chart.inset);
}

}  // namespace

// A mark (draw/marks.hpp) of radius r at c: filled, hollow (a 2 px outline) or two strokes.
void draw_mark(ImDrawList* list, draw::Mark mark, ImVec2 c, float r, ImU32 colour) {
  if (mark == draw::Mark::None) return;
  std::vector<ImVec2> p;
  for (const auto& [x, y] : draw::mark_outline(mark)) p.emplace_back(c.x + r * x, c.y + r * y);
  if (draw::strokes(mark)) {
    list->AddLine(p[0], p[1], colour, 2.0f);
    list->AddLine(p[2], p[3], colour, 2.0f);
  } else if (draw::hollow(mark)) {
    list->AddPolyline(p.data(), static_cast<int>(p.size()), colour, ImDrawFlags_Closed, 2.0f);
  } else {
    list->AddConvexPolyFilled(p.data(), static_cast<int>(p.size()), colour);
  }
}

void draw_imgui(ImDrawList* list, ImVec2 origin, ImVec2 size, const Chart& chart) {
  const ImGuiStyle& style = ImGui::GetStyle();
  const float line_h = ImGui::GetTextLineHeight();

  double xlo, xhi, ylo, yhi;
  axis_range(chart, true, xlo, xhi);
  axis_range(chart, false, ylo, yhi);
  const auto yt = ticks(ylo, yhi, chart.y.log, 4);
  float label_w = 0.0f;
  for (const Tick& t : yt) label_w = std::max(label_w, ImGui::CalcTextSize(t.label.c_str()).x);

  // Plot area: room for the title, the y label (rotated text is not available, so it goes above
  // the axis), tick labels and the x label.
  const float heading =
      origin.y + (chart.title.empty()
                      ? 0.0f
                      : ImGui::CalcTextSize(title_lines(chart, size.x).c_str()).y + 0.2f * line_h);
  const float top = heading + line_h * 1.1f;
  const float left = origin.x + label_w + style.ItemSpacing.x + 4.0f;
  const float right = origin.x + size.x - 8.0f;
  const float bottom = origin.y + size.y - line_h * (chart.x.label.empty() ? 1.3f : 2.4f);
  if (right - left < 20 || bottom - top < 20) return;
  // End labels in a margin right of the plot, clear of the lines, where the plot is tall enough
  // to stack them one a line and keeps 55 % of its width beside them; else the legend names the
  // lines (a phone's short chart: four labels written over one another).
  std::size_t labelled = 0;
  float labels_w = 0.0f;
  for (const Series& s : chart.series)
    if (!s.label.empty())
      ++labelled, labels_w = std::max(labels_w, ImGui::CalcTextSize(s.label.c_str()).x);
  float plot_right = right;
  if (chart.end_labels) {
    const float margin = labels_w + 12.0f;
    if (labelled * line_h > bottom - top - 4.0f || right - margin - left < 0.55f * (right - left)) {
      Chart named = chart;
      named.end_labels = false;
      named.legend = true;
      named.legend_off_plot = true;
      return draw_imgui(list, origin, size, named);
    }
    plot_right = right - margin;
  }
  Plot p{origin, size, line_h, heading, top, left, plot_right, bottom, xlo, xhi, ylo, yhi};
  const LegendLayout legend = place_legend(chart, p);
  const std::vector<Tick> y_ticks = equal_scale_ticks(chart, p, yt, label_w);
  draw_axes(list, chart, p, y_ticks, legend.place);
  list->PushClipRect(ImVec2(origin.x, origin.y), ImVec2(origin.x + size.x, origin.y + size.y),
                     true);
  draw_lines(list, chart, p);
  const std::optional<Corner> legend_at = draw_legend(list, chart, p, legend);
  draw_chart_inset(list, chart, p, legend_at);
  list->PopClipRect();
}

void chart_widget(const char* id, const Chart& chart, ImVec2 size) {
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  ImGui::InvisibleButton(id, size);
  draw_imgui(ImGui::GetWindowDrawList(), origin, size, chart);
}

}  // namespace springlab::chart
