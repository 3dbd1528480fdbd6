// A chart described as data: axes (linear or log), series of points with a colour and a label,
// reference lines. Drawn live with Dear ImGui (imgui_chart.cpp) and written as SVG (svg.cpp),
// so the app, the PNG charts and the SVG charts show the same thing.
#pragma once

#include <array>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "draw/frame.hpp"
#include "draw/marks.hpp"

namespace springlab::chart {

struct Series {
  std::string label;
  draw::Rgba color;
  std::vector<double> x, y;
  bool dashed = false;
  bool markers = false;  // its mark (a dot if none) on each point
  // Its shape (draw/marks.hpp): on each point with `markers`, else along its line every
  // kMarkSpacing pixels, and on its legend's swatch: lines told apart by more than colour.
  draw::Mark mark = draw::Mark::None;
  std::vector<bool> crossed;  // per point: drawn as a cross (a diverged run)
  float width = 2.0f;         // pixels
  // A series that left the sane range (a diverged lane): it does not set the axes' range (unless
  // it stays within kEscapeReach times the others' values, or every series escapes), and is drawn
  // up to where it leaves the plot, with a marker on the edge there; its legend entry is red.
  bool escapes = false;
};

inline constexpr double kEscapeReach = 100.0;
// Marks along a line: one every this many pixels of its length, the first a little further for
// each series after the first (so that lines on top of each other show each one's marks).
inline constexpr double kMarkSpacing = 90.0;

struct Axis {
  std::string label;  // with units: "step h (s)"
  bool log = false;
  std::optional<double> min, max;  // else from the data
};

// A few words at a point of the plot, in the axes' units, written ending there and just above it:
// a reference slope named at its end ("order 4").
struct Note {
  double x = 0, y = 0;
  std::string text;
  draw::Rgba color;
};

struct Chart {
  std::string title;
  Axis x, y;
  std::vector<Series> series;
  bool legend = true;
  // Each labelled line's label written at its last point (inside the plot, kept from running into
  // another) in place of the legend, so that a line is named where the eye ends up, by its
  // colour's text and not by a swatch to match: the live charts' lines.
  bool end_labels = false;
  // One unit as long on both axes (both linear): the complex plane, where a region's shape is
  // the lesson (explicit Euler's disc drawn round, never a wide ellipse). The axis with room to
  // spare shows more, about its centre.
  bool equal_scale = false;
  // Keep the legend off the plot (beside it, else in rows over it) even where a box in a corner
  // would fit: where the data fill the plot (the complex plane's regions; live charts whose end
  // labels found no room).
  bool legend_off_plot = false;
  std::vector<Note> notes;
  // A smaller chart drawn over a corner of the plot (the region chart's zoom on the dots near 0),
  // in the corner that hides the least data apart from the legend's.
  std::shared_ptr<const Chart> inset;
};

// The inset's size, as fractions of the plot's width and height.
inline constexpr double kInsetWidth = 0.42, kInsetHeight = 0.46;

// Ticks for an axis over [lo, hi]: "nice" numbers (1, 2, 5 x 10^k) for a linear axis, decades
// for a log one (and 2, 5 between them when there are few decades).
struct Tick {
  double value;
  std::string label;
  bool major = true;
};
std::vector<Tick> ticks(double lo, double hi, bool log, int target_count = 5);

// An x axis's ticks as many as their labels leave room for (at most 5): `at` puts a value on the
// axis (pixels), `width` measures a label; no two labels, centred on their ticks, come closer
// than `gap` (a narrow chart would otherwise read 5 ticks' labels as "00.250.50.751").
std::vector<Tick> ticks_that_fit(double lo, double hi, bool log,
                                 const std::function<float(double)>& at,
                                 const std::function<float(const std::string&)>& width, float gap);

// The range the axis shows: the data's, widened to whole ticks, or the one set.
void axis_range(const Chart& chart, bool x_axis, double& lo, double& hi);

// For an equal_scale chart: the ranges widened, each about its centre, so that a unit is as many
// pixels on both axes of a plot `width` x `height` pixels.
void equal_scale(double& xlo, double& xhi, double& ylo, double& yhi, double width, double height);

// Where a legend of the given size (fractions of the plot's width and height) covers the least
// of the data: the corner whose box holds the fewest of the series' points, each line sampled
// along its segments in the plot's own (log or linear) coordinates; faint series (alpha below
// 0.5: a region's fill) do not count. Ties keep the earlier corner
// in this order, so that a legend stays top right unless it would hide something there.
enum class Corner { TopRight, TopLeft, BottomRight, BottomLeft };
Corner legend_corner(const Chart& chart, double width, double height,
                     std::optional<Corner> taken = std::nullopt);

// Where a line's marks go (kMarkSpacing): along the polylines a series is drawn as (pixels), one
// every `spacing` of their length from `phase` on, the length carried from one polyline to the
// next (a line broken where it left the plot keeps its rhythm).
using Pixel = std::array<double, 2>;
std::vector<Pixel> marks_along(const std::vector<std::vector<Pixel>>& lines, double spacing,
                               double phase);

// The end labels' heights: each wanted height (its line's end), moved apart as little as it
// takes for no two to come closer than `gap`, kept within [lo, hi]; in the order given.
std::vector<double> spread_labels(const std::vector<double>& wanted, double gap, double lo,
                                  double hi);

// "0.5", "1e-06", "120": short tick labels; with the ticks' spacing, as many digits as the labels
// need to differ ("1.9990", "1.9995").
std::string format_tick(double value, double step = 0.0);

}  // namespace springlab::chart
