// "Your method" (ui/tableau_panel.hpp) without a window: the cells checked as a student types them
// (the order, the first failing condition, a bad cell named by row and column), a shipped tableau
// loaded into them, and "Run beside" adding the tableau as a lane whose limit the gauge can show.
#include "ui/tableau_panel.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "chart/stability_region.hpp"
#include "support.hpp"
#include "util/data_dir.hpp"

namespace springlab::ui {
namespace {

void type(TableauPanel::Cell& cell, const char* text) {
  std::snprintf(cell.data(), cell.size(), "%s", text);
}

TEST(TableauPanel, ChecksTheCellsAsTheyAreTyped) {
  TableauPanel panel;  // Heun's, to start from
  panel.check();
  ASSERT_TRUE(panel.analysis) << panel.error;
  EXPECT_EQ(panel.analysis->order, 2);
  EXPECT_EQ(panel.analysis->real_limit, 2.0);
  type(panel.a[1][0], "1/2");  // one wrong entry
  panel.check();
  ASSERT_TRUE(panel.analysis);
  EXPECT_EQ(panel.analysis->order, 1);
  EXPECT_EQ(panel.analysis->first_failure->tree, "[t]");
  type(panel.a[1][0], "1/0");  // not a number: that cell, named
  panel.check();
  EXPECT_FALSE(panel.analysis);
  EXPECT_EQ(panel.error_row, 1);
  EXPECT_EQ(panel.error_col, 0);
  EXPECT_NE(panel.error.find("A row 2, column 1 \"1/0\" is not a number"), std::string::npos)
      << panel.error;
  type(panel.a[1][0], "1");
  type(panel.b[1], "half");  // a weight
  panel.check();
  EXPECT_EQ(panel.error_row, 1);
  EXPECT_EQ(panel.error_col, -1);
  EXPECT_NE(panel.error.find("b entry 2"), std::string::npos) << panel.error;
  // A diagonal entry makes the stage implicit: implicit midpoint in one cell.
  panel.stages = 1;
  type(panel.a[0][0], "1/2");
  type(panel.b[0], "1");
  panel.check();
  ASSERT_TRUE(panel.tableau) << panel.error;
  EXPECT_FALSE(panel.tableau->is_explicit());
  EXPECT_EQ(panel.analysis->order, 2);
  EXPECT_TRUE(std::isinf(panel.analysis->imaginary_limit));
}

TEST(TableauPanel, StartsFromAShippedTableau) {
  TableauPanel panel;
  panel.load(load_tableau_file(app::resolve_tableau("dormand-prince")));
  panel.check();
  ASSERT_TRUE(panel.analysis) << panel.error;
  EXPECT_EQ(panel.stages, 7);
  EXPECT_EQ(panel.analysis->order, 5);
  EXPECT_NEAR(panel.analysis->real_limit, 3.30657, 1e-5);
}

// Run beside: a lane of its own, stepping; its limit comes from the analysis the lanes already
// have (made before the row existed): Heun's on the damped spring is midpoint's, 0.105 s.
TEST(TableauPanel, RunBesideAddsALaneTheGaugeCanShow) {
  Scene scene = test::shipped("damped-spring");
  SimulationSettings s = settings_for(scene);
  s.method = Method::Midpoint;
  app::Session session(std::move(scene), s, 60.0);
  for (int k = 0; k < 5; ++k) session.advance_frame();
  const StabilityAnalysis before(session.primary().sim.model(), session.primary().sim.state());
  TableauPanel panel;
  panel.check();
  const std::string said = run_beside(*panel.tableau, session);
  EXPECT_NE(said.find("running as 'mine'"), std::string::npos) << said;
  ASSERT_EQ(session.lanes().size(), 2u);
  const Method mine = session.lanes()[1].sim.settings().method;
  EXPECT_STREQ(method_info(mine).name, "mine");
  for (int k = 0; k < 30; ++k) session.advance_frame();
  EXPECT_FALSE(session.lanes()[1].sim.diverged());
  EXPECT_NEAR(session.lanes()[1].sim.state().t, session.lanes()[0].sim.state().t, 1e-12);
  // An analysis made before the row existed gives its limit too (from the modes it found).
  EXPECT_NEAR(before.limit(mine).h, before.limit(Method::Midpoint).h,
              1e-9 * before.limit(Method::Midpoint).h);
  EXPECT_NEAR(before.limit(mine).h, 0.105, 1e-3);
  // Another tableau takes the next name; the same one again keeps its row.
  type(panel.a[1][0], "2/3");
  type(panel.b[0], "1/4");
  type(panel.b[1], "3/4");  // Ralston's
  panel.check();
  EXPECT_NE(run_beside(*panel.tableau, session).find("'mine-2'"), std::string::npos);
  EXPECT_EQ(session.lanes().size(), 3u);
}

// What the panel shows (the exact axis limits), `springlab tableau` prints (the same analysis),
// the run-time analysis finds on a scene and the region chart draws agree, on every shipped
// tableau and a published ten-stage one: on the undamped spring (lambda = +-10 i) the
// limit is the imaginary one over 10; on an overdamped one (lambda = -15 +- sqrt(125)) the real
// one over 15 + sqrt(125); the region chart holds the region's real interval whole.
TEST(TableauPanel, ThePanelTheRunTimeAnalysisAndTheRegionChartAgree) {
  // The reference spring balanced at its rest length (the analysis linearises at the balance):
  // one mode along it, none across.
  Scene undamped = test::shipped("damped-spring"), overdamped = test::shipped("damped-spring");
  set_damping(undamped.model, 0.0);
  set_damping(overdamped.model, 30.0);
  const StabilityAnalysis oscillating(undamped.model, undamped.state),
      decaying(overdamped.model, overdamped.state);
  const double fastest = 15.0 + std::sqrt(125.0);
  std::vector<std::string> files;
  for (const std::string& name : app::shipped_tableaux())
    files.push_back(app::resolve_tableau(name));
  files.push_back(std::string(SPRINGLAB_SOURCE_DIR) + "/tests/data/ssprk10-4.json");
  for (const std::string& file : files) {
    SCOPED_TRACE(file);
    const ButcherTableau t = load_tableau_file(file);
    TableauPanel panel;
    if (t.stages <= TableauPanel::kMaxStages) {
      panel.load(t);
      panel.check();
      ASSERT_TRUE(panel.analysis) << panel.error;
    } else {
      panel.analysis = analyse_tableau(t);  // (more stages than the panel's cells: the report's)
    }
    const TableauAnalysis& a = *panel.analysis;
    const Method row = add_tableau_method(t, "agree-" + std::to_string(&file - files.data()));
    if (method_info(row).adaptive()) continue;  // an embedded pair chooses its own steps
    const auto same = [](double run_time, double exact) {
      if (std::isinf(exact))
        EXPECT_TRUE(std::isinf(run_time)) << run_time;
      else
        EXPECT_NEAR(run_time, exact, 1e-9 * exact);
    };
    same(oscillating.limit(row).h, a.imaginary_limit / 10.0);
    same(decaying.limit(row).h, a.real_limit / fastest);
    if (!t.is_explicit()) continue;
    const chart::Chart region = chart::stability_region(decaying, {chart::RegionLane{row, 0.01}});
    ASSERT_TRUE(region.x.min);
    EXPECT_LE(*region.x.min, -a.real_limit);
    EXPECT_GE(*region.y.max, a.imaginary_limit);
  }
}

}  // namespace
}  // namespace springlab::ui
