// springlab bench, as the performance issue asks for it: one key=value a line, figures that agree
// with each other and with the scene, a divergence reported instead of figures, bad options
// refused with one message.
#include <gtest/gtest.h>

#include <map>
#include <sstream>

#include "cli/cli_support.hpp"

namespace springlab::test {
namespace {

std::map<std::string, std::string> keys(const std::string& text) {
  std::map<std::string, std::string> out;
  std::istringstream s(text);
  for (std::string line; std::getline(s, line);) {
    const auto eq = line.find('=');
    if (eq != std::string::npos) out[line.substr(0, eq)] = line.substr(eq + 1);
  }
  return out;
}

double number(const std::map<std::string, std::string>& k, const std::string& key) {
  return k.count(key) ? std::stod(k.at(key)) : -1.0;
}

TEST(Bench, PrintsItsFiguresOneKeyALine) {
  const Result r = springlab("bench cloth --set cloth.width=10 --set cloth.height=10 --method symplectic-euler "
                             "--steps 300 --threads 1");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto k = keys(r.out);
  for (const char* key : {"particles", "springs", "steps", "seconds", "steps_per_s", "ns_per_spring_step", "peak_rss_mb"})
    ASSERT_EQ(k.count(key), 1u) << key << "\n" << r.out;
  EXPECT_EQ(k.at("method"), "symplectic-euler");
  EXPECT_EQ(k.at("threads"), "1");
  EXPECT_EQ(k.at("particles"), "100");
  // Structural 9 x 10 + 10 x 9, shear 2 x 9 x 9, bending 8 x 10 + 10 x 8.
  EXPECT_EQ(k.at("springs"), "502");
  EXPECT_EQ(k.at("steps"), "300");
  // The figures are one measurement, printed to 6 and 4 significant digits.
  const double seconds = number(k, "seconds");
  ASSERT_GT(seconds, 0.0);
  EXPECT_NEAR(number(k, "steps_per_s"), 300 / seconds, 1e-5 * 300 / seconds);
  EXPECT_NEAR(number(k, "ns_per_spring_step"), 1e9 * seconds / (300 * 502), 1e-3 * 1e9 * seconds / (300 * 502));
  EXPECT_GT(number(k, "peak_rss_mb"), 1.0);
  EXPECT_EQ(k.count("repeats"), 0u);
}

TEST(Bench, RepeatedRunsPrintTheirCountAndMedian) {
  const Result r = springlab("bench spring --steps 2000 --repeat 5");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto k = keys(r.out);
  ASSERT_EQ(k.count("repeats"), 1u) << r.out;
  EXPECT_EQ(k.at("repeats"), "5");
  EXPECT_EQ(k.at("steps"), "2000");  // a run's steps, not all runs'
  EXPECT_GT(number(k, "ns_per_spring_step_median"), 0.0) << r.out;
  EXPECT_GT(number(k, "ns_per_spring_step"), 0.0) << r.out;
}

TEST(Bench, ReportsADivergenceInsteadOfFigures) {
  // Explicit Euler on the undamped spring grows every step; at h w = 10 it overflows quickly.
  const Result r = springlab("bench spring --method euler --dt 1 --steps 1000");
  EXPECT_EQ(r.status, 3) << r.out << r.err;
  EXPECT_EQ(r.out.find("seconds="), std::string::npos) << r.out;
  EXPECT_NE(r.err.find("springlab: spring: "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("euler"), std::string::npos) << r.err;
}

TEST(Bench, RefusesBadOptionsWithOneMessage) {
  for (const char* args : {"bench spring --repeat 0", "bench spring --repeat 2.5", "bench spring --steps 0",
                           "bench no-such-scene"}) {
    const Result r = springlab(args);
    EXPECT_EQ(r.status, 2) << args << "\n" << r.err;
    EXPECT_TRUE(r.out.empty()) << args << "\n" << r.out;
    EXPECT_NE(r.err.find("springlab"), std::string::npos) << args << "\n" << r.err;
  }
}

}  // namespace
}  // namespace springlab::test
