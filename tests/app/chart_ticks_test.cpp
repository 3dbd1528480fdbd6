// Axis ticks: where they fall and how they read. A log axis labels every decade the same way
// (plain from 0.001 to 10000, 1eN beyond); a linear axis gives each label the decimals its step needs.
#include <gtest/gtest.h>

#include "chart/chart.hpp"

namespace springlab::chart {
namespace {

std::vector<std::string> major_labels(const std::vector<Tick>& ticks) {
  std::vector<std::string> out;
  for (const Tick& t : ticks)
    if (t.major) out.push_back(t.label);
  return out;
}

TEST(ChartTicks, LogDecadesReadAlike) {
  EXPECT_EQ(major_labels(ticks(1e-6, 1e9, true, 20)),
            (std::vector<std::string>{"1e-6", "1e-5", "1e-4", "0.001", "0.01", "0.1", "1", "10", "100", "1000",
                                      "10000", "1e5", "1e6", "1e7", "1e8", "1e9"}));
}

TEST(ChartTicks, LinearStepsGetTheirDecimals) {
  EXPECT_EQ(major_labels(ticks(0.0, 1.0, false, 4)), (std::vector<std::string>{"0", "0.25", "0.50", "0.75", "1.00"}));
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

}  // namespace
}  // namespace springlab::chart
