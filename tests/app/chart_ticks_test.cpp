// Axis ticks: where they fall and how they read. A log axis labels every decade the same way
// (plain from 0.001 to 10000, 1eN beyond); a linear axis gives each label the decimals its step
// needs.
#include <gtest/gtest.h>

#include <cmath>
#include <tuple>

#include "chart/chart.hpp"

namespace springlab::chart {
namespace {

float width_of_8(const std::string& label) {
  return 8.0f * static_cast<float>(label.size());
}

std::vector<std::string> major_labels(const std::vector<Tick>& ticks) {
  std::vector<std::string> out;
  for (const Tick& t : ticks)
    if (t.major) out.push_back(t.label);
  return out;
}

TEST(ChartTicks, LogDecadesReadAlike) {
  EXPECT_EQ(major_labels(ticks(1e-6, 1e9, true, 20)),
            (std::vector<std::string>{"1e-6", "1e-5", "1e-4", "0.001", "0.01", "0.1", "1", "10",
                                      "100", "1000", "10000", "1e5", "1e6", "1e7", "1e8", "1e9"}));
}

TEST(ChartTicks, LinearStepsGetTheirDecimals) {
  EXPECT_EQ(major_labels(ticks(0.0, 1.0, false, 4)),
            (std::vector<std::string>{"0", "0.25", "0.50", "0.75", "1.00"}));
  EXPECT_EQ(major_labels(ticks(0.0, 20000.0, false, 4)),
            (std::vector<std::string>{"0", "5000", "10000", "15000", "20000"}));
  EXPECT_EQ(major_labels(ticks(-2e-7, 2e-7, false, 4)),
            (std::vector<std::string>{"-2e-7", "-1e-7", "0", "1e-7", "2e-7"}));
}

TEST(ChartTicks, LogMinorTicksLabelTwoAndFiveOnShortAxes) {
  std::vector<std::string> labelled;
  for (const Tick& t : ticks(1.0, 50.0, true, 4))
    if (!t.major && !t.label.empty()) labelled.push_back(t.label);
  std::sort(labelled.begin(), labelled.end());
  EXPECT_EQ(labelled, (std::vector<std::string>{"2", "20", "5", "50"}));
}

// A chart's first sample, at t = 0: its time axis runs forward from 0 (it showed -1 to 1 s, a
// time before the scene began), and its value axis around the value either way.
TEST(ChartTicks, AFirstSampleAtTimeZeroHasNoTimeBeforeIt) {
  Chart chart;
  Series s;
  s.x = {0.0};
  s.y = {-30.0};
  chart.series.push_back(s);
  double lo = 0, hi = 0;
  axis_range(chart, true, lo, hi);
  EXPECT_GE(lo, -0.05 * (hi - lo) - 1e-12);  // (the room beside the data: 5 %)
  EXPECT_GE(hi, 1.0);
  axis_range(chart, false, lo, hi);
  EXPECT_LT(lo, -30.0);
  EXPECT_GT(hi, -30.0);
  chart.series[0].x = {-2.0};  // (a value axis below 0 keeps both sides)
  axis_range(chart, true, lo, hi);
  EXPECT_LT(lo, -2.0);
  EXPECT_GT(hi, -2.0);
}

// A narrow chart (a phone, a panel on the side) keeps its x labels apart: as many ticks as fit,
// never two labels running together, and all five where there is room.
TEST(ChartTicks, XLabelsNeverRunTogether) {
  const auto width = [](const std::string& label) {
    return 8.0f * static_cast<float>(label.size());
  };  // 8 px a character
  for (const auto& range : std::vector<std::tuple<double, double, bool>>{{0.0, 1.0, false},
                                                                         {-1.0, 1.0, false},
                                                                         {0.0, 1.5, false},
                                                                         {1e-4, 0.01, true},
                                                                         {-0.12, -0.08, false}}) {
    // Plain variables: clang before 16 cannot capture a structured binding in a lambda.
    const double lo = std::get<0>(range), hi = std::get<1>(range);
    const bool log = std::get<2>(range);
    int most = 0;
    for (float plot = 40.0f; plot <= 800.0f; plot += 20.0f) {
      const auto at = [&](double v) {
        const double f = log ? (std::log10(v) - std::log10(lo)) / (std::log10(hi) - std::log10(lo))
                             : (v - lo) / (hi - lo);
        return static_cast<float>(f) * plot;
      };
      const std::vector<Tick> t = ticks_that_fit(lo, hi, log, at, width, 4.0f);
      float last = -1e30f;
      int labels = 0;
      for (const Tick& k : t) {
        if (k.label.empty()) continue;
        ++labels;
        EXPECT_GE(at(k.value) - 0.5f * width(k.label), last + 4.0f)
            << lo << ".." << hi << " in " << plot << " px";
        last = at(k.value) + 0.5f * width(k.label);
      }
      EXPECT_GE(labels, 1) << plot;
      most = std::max(most, labels);
    }
    EXPECT_GE(most, 3) << lo << ".." << hi;  // a wide chart keeps several
  }
  // The case a phone showed: 5 ticks' labels in 100 px ran together as "00.250.50.751.00".
  const auto at = [](double v) { return static_cast<float>(v) * 100.0f; };
  EXPECT_LT(ticks_that_fit(0.0, 1.0, false, at, width_of_8, 4.0f).size(),
            ticks(0.0, 1.0, false, 5).size());
}

}  // namespace
}  // namespace springlab::chart
