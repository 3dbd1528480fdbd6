// "Your method" (ui/tableau_panel.hpp) without a window: the cells checked as a student types them
// (the order, the first failing condition, a bad cell named by row and column), a shipped tableau
// loaded into them, and "Run beside" adding the tableau as a lane whose limit the gauge can show.
#include <gtest/gtest.h>

#include <cmath>

#include "support.hpp"
#include "ui/tableau_panel.hpp"
#include "util/data_dir.hpp"

namespace springlab::ui {
namespace {

void type(TableauPanel::Cell& cell, const char* text) { std::snprintf(cell.data(), cell.size(), "%s", text); }

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
  EXPECT_NE(panel.error.find("A row 2, column 1 \"1/0\" is not a number"), std::string::npos) << panel.error;
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
  EXPECT_NEAR(before.limit(mine).h, before.limit(Method::Midpoint).h, 1e-9 * before.limit(Method::Midpoint).h);
  EXPECT_NEAR(before.limit(mine).h, 0.105, 1e-3);
  // Another tableau takes the next name; the same one again keeps its row.
  type(panel.a[1][0], "2/3");
  type(panel.b[0], "1/4");
  type(panel.b[1], "3/4");  // Ralston's
  panel.check();
  EXPECT_NE(run_beside(*panel.tableau, session).find("'mine-2'"), std::string::npos);
  EXPECT_EQ(session.lanes().size(), 3u);
}

}  // namespace
}  // namespace springlab::ui
