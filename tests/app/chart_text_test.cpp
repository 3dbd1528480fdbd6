// The live charts in words (chart/chart_text.hpp), for whoever cannot see them: on the spring,
// explicit Euler's energy is said to rise and symplectic Euler's to hold (the growth per step
// 1 + (h w)^2 and the bounded energy of a symplectic step); a diverged lane is said to leave the
// chart; the CSV holds every point of every line.
#include "chart/chart_text.hpp"

#include <gtest/gtest.h>

#include <memory>
#include <regex>
#include <sstream>

#include "chart/compare_charts.hpp"
#include "session/session.hpp"
#include "springlab/momentum.hpp"
#include "springlab/sweep.hpp"
#include "support.hpp"
#include "ui/live_charts.hpp"

namespace springlab::test {
namespace {

std::unique_ptr<app::Session> compared(double dt, double seconds) {
  Scene scene = shipped("spring");
  SimulationSettings settings = settings_for(scene);
  settings.dt = dt;
  settings.substeps = 1;
  settings.auto_substeps = false;
  auto session = std::make_unique<app::Session>(std::move(scene), settings, 60.0);
  session->set_compare_rows(test::method_rows({Method::Euler, Method::SymplecticEuler}));
  for (int frame = 0; frame < static_cast<int>(seconds * 60.0); ++frame) session->advance_frame();
  return session;
}

bool has(const std::string& text, const std::string& words) {
  return text.find(words) != std::string::npos;
}

TEST(ChartText, ExplicitEulersEnergyRisesAndSymplecticEulersHolds) {
  // h w = 0.1 on the spring (w = 10 rad/s): explicit Euler's energy x1.01 a step, 4 s of steps.
  auto session = compared(0.01, 4.0);
  const std::string said = chart::describe_chart(ui::energy_chart(*session));
  EXPECT_TRUE(has(said, "Energy (J) against t (s), from 0")) << said;
  EXPECT_TRUE(has(said, "euler rises from 12.5 to ")) << said;
  // (its energy is bounded, not constant: it swings by O(h w) about the true 12.5 J)
  EXPECT_TRUE(has(said, "symplectic-euler holds at about 1")) << said;
  EXPECT_TRUE(has(said, "(11.9 to 13.2)")) << said;
  EXPECT_FALSE(has(said, "symplectic-euler rises")) << said;
  // Past its limit (h w = 2.5 > 2), symplectic Euler too leaves the chart; explicit Euler first.
  auto past = compared(0.25, 20.0);
  const std::string beyond = chart::describe_chart(ui::energy_chart(*past));
  // Each line's own sentence, between its "; " (or ": ") and the next.
  const auto sentence = [&](const std::string& text, const std::string& name) {
    for (const std::string& before : {std::string(": "), std::string("; ")}) {
      const std::size_t at = text.find(before + name + " ");
      if (at != std::string::npos) return text.substr(at + 2, text.find(';', at + 2) - (at + 2));
    }
    return std::string();
  };
  EXPECT_TRUE(has(sentence(beyond, "euler"), "leaves the chart (diverged)")) << beyond;
  EXPECT_TRUE(has(sentence(beyond, "symplectic-euler"), "leaves the chart (diverged)")) << beyond;
  EXPECT_FALSE(has(sentence(said, "euler"), "leaves the chart")) << said;
  EXPECT_FALSE(has(said, "leaves the chart")) << said;
}

TEST(ChartText, TheCsvHoldsEveryPointOfEveryLine) {
  auto session = compared(0.01, 1.0);
  const chart::Chart energy = ui::energy_chart(*session);
  std::istringstream csv(chart::chart_csv(energy));
  std::string header, row;
  std::getline(csv, header);
  EXPECT_EQ(std::count(header.begin(), header.end(), ','),
            2 * static_cast<long>(energy.series.size()) - 1)
      << header;
  EXPECT_TRUE(has(header, "euler t (s),euler J")) << header;
  // Every row holds every line's point of its index (to the CSV's 9 digits), or nothing past its
  // end.
  std::size_t rows = 0, longest = 0;
  for (const chart::Series& s : energy.series) longest = std::max(longest, s.x.size());
  for (; std::getline(csv, row); ++rows) {
    std::vector<std::string> cells;
    std::istringstream fields(row);
    for (std::string cell; std::getline(fields, cell, ',');) cells.push_back(cell);
    cells.resize(2 * energy.series.size());
    for (std::size_t k = 0; k < energy.series.size(); ++k) {
      const chart::Series& s = energy.series[k];
      if (rows >= s.x.size()) {
        EXPECT_TRUE(cells[2 * k].empty()) << "row " << rows << ", line " << k;
        continue;
      }
      EXPECT_NEAR(std::stod(cells[2 * k]), s.x[rows], 1e-8 * std::max(1.0, std::abs(s.x[rows])))
          << "row " << rows << ", line " << k;
      EXPECT_NEAR(std::stod(cells[2 * k + 1]), s.y[rows], 1e-8 * std::max(1.0, std::abs(s.y[rows])))
          << "row " << rows << ", line " << k;
    }
  }
  EXPECT_EQ(rows, longest);
}

// The accuracy panel's work-precision chart in words: on the spring, error against work falls
// with slopes minus the orders (explicit Euler 1, midpoint 2, RK4 4: work grows as 1 / h), and
// RK4 is said to be the lowest where every line has points.
TEST(ChartText, WorkPrecisionIsSaidByItsSlopesAndItsLowestLine) {
  const Scene scene = shipped("spring");
  SweepSettings s;
  s.methods = {Method::Euler, Method::Midpoint, Method::RK4};
  s.h_min = 1e-3;
  s.h_max = 1e-2;
  s.points = 5;
  s.duration = 1.0;
  s.stability = false;
  const SweepResult r = run_sweep(scene.model, scene.state, s);
  std::string said;
  for (const chart::NamedChart& c : chart::compare_charts(r, "spring"))
    if (c.name == "work-precision-work") said = chart::describe_chart(c.chart);
  ASSERT_FALSE(said.empty());
  const auto slope = [&](const std::string& name) {
    std::smatch m;
    const std::regex re(name + R"( has slope ([-0-9.e+]+) on these log-log axes)");
    return std::regex_search(said, m, re) ? std::stod(m[1]) : NAN;
  };
  EXPECT_NEAR(slope("euler"), -1.0, 0.25) << said;
  EXPECT_NEAR(slope("midpoint"), -2.0, 0.3) << said;
  EXPECT_NEAR(slope("rk4"), -4.0, 0.4) << said;
  EXPECT_TRUE(has(said, "where every line has points")) << said;
  EXPECT_TRUE(has(said, "), rk4 is lowest (")) << said;
}

// The momentum chart (a chart added by CONTRIBUTING's checklist, for lesson 11): a stiff cloth
// thrown in empty space, as lesson 11 throws it. Springs act in equal and opposite pairs, so XPBD
// (each projection moves a pair's ends by equal and opposite momenta) keeps P to rounding, and
// VBD's ten vertex sweeps (a vertex moved alone) do not: its line rises past a thousandth. While
// the cloth is held it is not free and the lines wait; a pinned cloth says it is not a free body.
TEST(ChartText, TheMomentumChartShowsWhatEachLaneKeeps) {
  Scene scene = shipped("cloth", {"cloth.pinned=[]", "gravity=[0,0,0]", "drag=0"});
  SimulationSettings settings = settings_for(scene);
  settings.dt = 1.0 / 60.0;
  settings.substeps = 1;
  settings.auto_substeps = false;
  app::Session session(std::move(scene), settings, 60.0);
  session.set_compare_rows(test::method_rows({Method::XPBD, Method::VBD}));
  session.set_stiffness(20000.0);
  session.advance_frame();  // free, at rest: nothing to keep yet, and said so
  EXPECT_TRUE(has(ui::momentum_chart(session).title, "a free body at rest"))
      << ui::momentum_chart(session).title;
  session.grab(0);
  const Eigen::Vector3d start = session.primary().sim.state().x.row(0).transpose();
  for (int frame = 1; frame <= 15; ++frame) {
    session.drag_to(start + frame / 15.0 * Eigen::Vector3d(-1.0, 1.0, 0.4));
    session.advance_frame();
  }
  session.release();
  for (int frame = 0; frame < 60; ++frame) session.advance_frame();
  const chart::Chart chart = ui::momentum_chart(session);
  ASSERT_EQ(chart.series.size(), 5u);  // P and L for each lane, and the "visible" line
  const auto largest = [](const chart::Series& s) {
    double most = 0.0;
    for (double y : s.y) most = std::isnan(y) ? most : std::max(most, y);
    return most;
  };
  const std::vector<double>& xpbd = chart.series[0].y;
  EXPECT_TRUE(std::any_of(xpbd.begin(), xpbd.end(), [](double y) { return std::isnan(y); }))
      << "held: not free";
  EXPECT_LE(largest(chart.series[0]), kMomentumKept) << "xpbd's P";
  EXPECT_GT(largest(chart.series[2]), kMomentumVisible) << "vbd's P";
  EXPECT_TRUE(has(chart::describe_chart(chart), "vbd rises")) << chart::describe_chart(chart);

  Scene pinned = shipped("cloth");
  app::Session hanging(std::move(pinned), settings_for(shipped("cloth")), 60.0);
  hanging.advance_frame();
  const chart::Chart none = ui::momentum_chart(hanging);
  EXPECT_TRUE(none.series.empty());
  EXPECT_TRUE(has(none.title, "not a free body")) << none.title;
}

}  // namespace
}  // namespace springlab::test
