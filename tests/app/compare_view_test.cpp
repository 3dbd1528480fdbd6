// What the class sees in compare mode: every lane in a view of its own (lane_views.hpp), a lane
// that diverged drawn as its last state within the scene's bounds (never its blown-up geometry),
// a drag in a lane's view picking that lane's particle, each lane's work in the frame, and every
// lane in sight beside the accuracy chart (ui/layout.hpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "draw/camera.hpp"
#include "draw/lane_views.hpp"
#include "draw/scene_frame.hpp"
#include "springlab/error.hpp"
#include "support.hpp"
#include "ui/interaction.hpp"
#include "ui/label_place.hpp"
#include "ui/layout.hpp"
#include "ui/panels.hpp"

namespace springlab::test {
namespace {

app::Session rope_compared(double dt, const std::vector<Method>& methods) {
  Scene scene = shipped("rope");
  SimulationSettings s = settings_for(scene);
  s.dt = dt;
  s.substeps = 1;
  s.auto_substeps = false;
  app::Session session(std::move(scene), s, 60.0);
  session.set_compare_rows(test::method_rows(methods));
  return session;
}

const draw::Viewport kViewport{10, 20, 1280, 720};

bool inside(const draw::Viewport& outer, const draw::Viewport& v) {
  return v.x >= outer.x && v.y >= outer.y && v.x + v.width <= outer.x + outer.width &&
         v.y + v.height <= outer.y + outer.height;
}

bool meet(const draw::Viewport& a, const draw::Viewport& b) {
  return a.x < b.x + b.width && b.x < a.x + a.width && a.y < b.y + b.height && b.y < a.y + a.height;
}

// Apart: a view each, within the scene's place, none over another, each framing at least the
// width a 16:9 frame of the scene shows; together, one view of every lane.
TEST(CompareView, ApartEveryLaneHasAViewOfItsOwn) {
  for (std::size_t n : {2u, 3u, 4u}) {
    const std::vector<Method> all = {Method::Euler, Method::SymplecticEuler, Method::RK4,
                                     Method::ImplicitEuler};
    const app::Session session = rope_compared(1e-4, {all.begin(), all.begin() + n});
    const Camera& camera = session.scene().camera;
    const auto views = draw::lane_views(session, camera, draw::CompareLayout::Apart, kViewport);
    ASSERT_EQ(views.size(), n);
    std::vector<int> seen;
    for (std::size_t k = 0; k < views.size(); ++k) {
      const draw::LaneView& v = views[k];
      EXPECT_TRUE(inside(kViewport, v.viewport)) << n << " lanes, view " << k;
      ASSERT_EQ(v.lanes.size(), 1u);
      seen.push_back(v.lanes.front());
      // The world width it shows at its own aspect is at least a 16:9 frame's.
      const double aspect = static_cast<double>(v.viewport.width) / v.viewport.height;
      EXPECT_GE(v.camera.height * aspect, camera.height * 16.0 / 9.0 * (1 - 1e-9))
          << n << " lanes, view " << k;
      EXPECT_GE(v.camera.height, camera.height);
      for (std::size_t j = k + 1; j < views.size(); ++j)
        EXPECT_FALSE(meet(v.viewport, views[j].viewport)) << k << ", " << j;
      // The largest views it can: at least a quarter of the scene's place's height.
      EXPECT_GE(v.viewport.height, kViewport.height / 2 - 2);
    }
    std::sort(seen.begin(), seen.end());
    for (std::size_t k = 0; k < n; ++k) EXPECT_EQ(seen[k], static_cast<int>(k));
    const auto together =
        draw::lane_views(session, camera, draw::CompareLayout::Together, kViewport);
    ASSERT_EQ(together.size(), 1u);
    EXPECT_EQ(together.front().lanes.size(), n);
    EXPECT_EQ(draw::build_frames(session, draw::ViewOptions::for_scene(session.scene()), kViewport)
                  .size(),
              n);
  }
  EXPECT_EQ(draw::parse_compare_layout("together", "--compare-layout"),
            draw::CompareLayout::Together);
  EXPECT_THROW(draw::parse_compare_layout("side", "--compare-layout"), InputError);
}

bool meet(const ui::Rect& a, const draw::Viewport& b) {
  return a.x < b.x + b.width && b.x < a.x + a.w && a.y < b.y + b.height && b.y < a.y + a.h;
}

// The accuracy chart beside compare mode's lanes: in a lesson or not, on a laptop, a small one,
// a phone on its side and one held upright, every lane keeps a view of at least 150 x 84 pixels
// (a 16:9 box) that the chart does not cover, and the chart keeps at least 320 x 300 within the
// window (a phone on its side, its controls open, has 514 pixels beside them). Both ways: one lane
// in a lesson, the chart takes the scene's place (the step is about the chart); one lane outside a
// lesson on a laptop, the layout leaves it to float.
TEST(CompareView, TheAccuracyChartLeavesEveryLaneInSight) {
  const app::Session session =
      rope_compared(1e-4, {Method::Euler, Method::SymplecticEuler, Method::RK4, Method::Verlet});
  for (const auto& [width, height] :
       {std::pair{1280, 720}, {1920, 1080}, {1024, 640}, {844, 390}, {540, 960}, {390, 844}}) {
    for (const float band : {0.0f, 120.0f}) {
      if (height < 500 && band > 0.0f) continue;  // (a phone on its side: the band folds)
      ui::UiState ui;
      ui.accuracy = true;
      ui.band = band;
      if (band > 0.0f) ui.lesson = "homework-8";
      const ui::PanelLayout layout = ui::panel_layout(ui, true, width, height);
      const std::string at = std::to_string(width) + "x" + std::to_string(height) + ", band " +
                             std::to_string(static_cast<int>(band));
      const ui::Rect& chart = layout.accuracy;
      EXPECT_GE(chart.w, 320.0f) << at;
      EXPECT_GE(chart.h, 300.0f) << at;
      EXPECT_TRUE(chart.x >= 0 && chart.y >= band && chart.x + chart.w <= width &&
                  chart.y + chart.h <= height)
          << at;
      EXPECT_TRUE(layout.charts.empty()) << at;  // (under the chart)
      const auto views = draw::lane_views(session, session.scene().camera,
                                          draw::CompareLayout::Apart, layout.scene);
      ASSERT_EQ(views.size(), 4u);
      for (const draw::LaneView& v : views) {
        EXPECT_FALSE(meet(chart, v.viewport)) << at;
        EXPECT_GE(std::min(v.viewport.width / 16.0, v.viewport.height / 9.0), 9.3) << at;
      }
    }
  }
  ui::UiState ui;
  ui.accuracy = true;
  ui.lesson = "rk4-work-precision";
  ui.band = 120.0f;
  const ui::PanelLayout lesson = ui::panel_layout(ui, false, 1280, 720);
  EXPECT_TRUE(lesson.charts.empty());
  EXPECT_GE(lesson.accuracy.w, 0.9f * lesson.scene.width);
  EXPECT_GE(lesson.accuracy.h + 16.0f, 720.0f - 120.0f);
  ui.lesson.clear();
  ui.band = 0.0f;
  const ui::PanelLayout own = ui::panel_layout(ui, false, 1280, 720);
  EXPECT_TRUE(own.accuracy.empty());
  EXPECT_FALSE(own.charts.empty());
}

// The largest ratio of a spring's length to its longest sane one (its rest length or its start).
double worst_stretch(const app::Session& session, const app::Lane& lane) {
  const Model& m = lane.sim.model();
  const Points& x = lane.sim.state().x;
  const Points& x0 = session.scene().state.x;
  double worst = 0.0;
  for (int k = 0; k < m.spring_count(); ++k) {
    const int a = m.spring_a[k], b = m.spring_b[k];
    const double ratio =
        (x.row(b) - x.row(a)).norm() / std::max(m.rest_length[k], (x0.row(b) - x0.row(a)).norm());
    worst = std::isnan(ratio) ? INFINITY : std::max(worst, ratio);
  }
  return worst;
}

// Before the divergence test fires (energy 1e6 times the scene's), a lane past its limit whose
// springs are torn to ten times their length is drawn as its last sane state, faded, and its title
// says so; a stable lane is not, nor is a stable rope sagging far on soft springs.
TEST(CompareView, ALaneBlowingUpIsDrawnAsItsLastSaneStateBeforeItDiverges) {
  app::Session session = rope_compared(2e-4, {Method::Euler, Method::SymplecticEuler, Method::RK4});
  int torn = 0;
  for (int frames = 0; frames < 300 && !session.lanes()[0].sim.diverged(); ++frames) {
    session.advance_frame();
    const app::Lane& euler = session.lanes()[0];
    if (!euler.sim.diverged() && worst_stretch(session, euler) > 10.0) {
      ++torn;
      EXPECT_TRUE(euler.blowing_up) << "frame " << frames;
      EXPECT_EQ(&euler.shown(), &euler.sane);
      EXPECT_LT(euler.sane.t, euler.sim.state().t);
    }
    for (std::size_t k = 1; k < session.lanes().size(); ++k)
      EXPECT_FALSE(session.lanes()[k].wild()) << "frame " << frames << ", lane " << k;
  }
  EXPECT_GT(torn, 0) << "explicit Euler never tore its springs before it diverged";

  // Soft springs: symplectic Euler well within its limit, the rope hanging far past ten times its
  // springs' length.
  app::Session soft = rope_compared(2e-4, {Method::SymplecticEuler});
  soft.set_stiffness(1e-3 * soft.primary().sim.model().ks(0));
  double stretched = 0.0;
  for (int frames = 0; frames < 240; ++frames) {
    soft.advance_frame();
    stretched = std::max(stretched, worst_stretch(soft, soft.primary()));
    EXPECT_FALSE(soft.primary().wild()) << "frame " << frames;
  }
  EXPECT_GT(stretched, 10.0) << "the soft rope should sag past ten times its springs' length";
}

// Explicit Euler past its limit on the rope (h = 2e-4 s, twice its limit): once it has diverged
// it is drawn as its last state within the scene's bounds, every spring short, never lines across
// the frame; symplectic Euler and RK4, stable, are drawn as they are at every frame.
TEST(CompareView, ADivergedLaneIsDrawnWithinTheScenesBounds) {
  app::Session session = rope_compared(2e-4, {Method::Euler, Method::SymplecticEuler, Method::RK4});
  const Model& model = session.primary().sim.model();
  const double reach = app::scene_reach(session.scene());
  int frames = 0;
  for (; frames < 300 && !session.lanes()[0].sim.diverged(); ++frames) {
    session.advance_frame();
    for (std::size_t k = 1; k < session.lanes().size();
         ++k)  // (a stable lane is never called insane)
      EXPECT_EQ(session.lanes()[k].sane.t, session.lanes()[k].sim.state().t)
          << "frame " << frames << ", lane " << k;
  }
  ASSERT_TRUE(session.lanes()[0].sim.diverged())
      << "explicit Euler should diverge within 300 frames";
  for (int k = 0; k < 30; ++k) session.advance_frame();
  const app::Lane& euler = session.lanes()[0];
  EXPECT_LT(euler.sane.t, euler.sim.divergence()->t);
  // Its last good state is far out; the one drawn is within the bounds, springs at most twice their
  // length.
  const auto spread = [&](const Points& x) {
    return (x.rowwise() - session.scene().camera.target.transpose()).rowwise().norm().maxCoeff();
  };
  EXPECT_GT(spread(euler.sim.state().x), reach);
  EXPECT_LE(spread(euler.sane.x), reach);
  for (int s = 0; s < model.spring_count(); ++s)
    EXPECT_LE((euler.sane.x.row(model.spring_b[s]) - euler.sane.x.row(model.spring_a[s])).norm(),
              2.0 * model.rest_length[s] + 1e-9);
  // Drawn: every line of its view within the view, none longer than a quarter of its width.
  const draw::ViewOptions options = draw::ViewOptions::for_scene(session.scene());
  const auto views =
      draw::lane_views(session, options.camera, draw::CompareLayout::Apart, kViewport);
  const draw::Frame frame = draw::build_frame(session, options, views[0]);
  ASSERT_FALSE(frame.lines.empty());
  const draw::Viewport& v = views[0].viewport;
  for (const draw::Line& line : frame.lines) {
    const Eigen::Vector3d a = draw::project(frame.camera, line.a.cast<double>(), v.width, v.height);
    const Eigen::Vector3d b = draw::project(frame.camera, line.b.cast<double>(), v.width, v.height);
    for (const Eigen::Vector3d& p : {a, b}) {
      EXPECT_GE(p.x(), -0.05 * v.width);
      EXPECT_LE(p.x(), 1.05 * v.width);
      EXPECT_GE(p.y(), -0.05 * v.height);
      EXPECT_LE(p.y(), 1.05 * v.height);
    }
    EXPECT_LE((a - b).head<2>().norm(), 0.25 * v.width);
    EXPECT_LT(line.color_a.a, 0.5f);  // faded
  }
}

// A view's title goes to the corner that covers least of what the view draws (label_place.hpp).
// The rope starts along the top of its view, under a title at the top left, and a diverged rope
// is drawn as it was then: each title of the four lanes, 0.7 of its view wide and 44 pixels high
// (a diverged lane's title wraps to two lines so), covers none of its rope's points, before and
// after explicit Euler diverged (its trail, where no corner misses it, may be covered). Both ways:
// with nothing drawn the title keeps the top left; a box covering the top left (the caption) sends
// it to the next corner free.
TEST(CompareView, TitlesKeepOffTheirLanesBodies) {
  app::Session session = rope_compared(
      2e-3, {Method::Euler, Method::SymplecticEuler, Method::RK4, Method::ImplicitEuler});
  const draw::ViewOptions options = draw::ViewOptions::for_scene(session.scene());
  using C = ui::Corner;
  const std::vector<C> order = {C::TopLeft, C::TopRight, C::BottomLeft, C::BottomRight};
  const auto room = [](const draw::Viewport& v) {
    return ui::Box{v.x + 10.0f, v.y + 6.0f, v.x + v.width - 6.0f, v.y + v.height - 8.0f};
  };
  int covered_at_top_left = 0;
  for (const int frames : {0, 150}) {
    for (int k = 0; k < frames; ++k) session.advance_frame();
    if (frames > 0) ASSERT_TRUE(session.lanes()[0].sim.diverged());
    // (The scene's place at 1280 x 720 with the panels.)
    const auto views = draw::lane_views(session, options.camera, draw::CompareLayout::Apart,
                                        draw::Viewport{376, 0, 904, 473});
    for (const draw::LaneView& view : views) {
      const ui::Drawn drawn = ui::drawn_points(session, view, true);
      const std::vector<Eigen::Vector2f>& points = drawn.body;
      ASSERT_GT(points.size(), 60u);
      const float wide = 0.7f * view.viewport.width;
      const ui::Box box = ui::corner_box(room(view.viewport), wide, 44.0f, drawn, {}, order);
      EXPECT_EQ(std::count_if(points.begin(), points.end(), [&](auto& p) { return box.holds(p); }),
                0)
          << "frame " << frames << ", lane " << view.lanes.front();
      const ui::Box top_left = ui::corner_box(room(view.viewport), wide, 44.0f, {}, {}, order);
      covered_at_top_left +=
          std::any_of(points.begin(), points.end(), [&](auto& p) { return top_left.holds(p); });
    }
  }
  EXPECT_GT(covered_at_top_left, 0);  // (the old place: over a rope)
  const ui::Box whole{0, 0, 1000, 600};
  const ui::Box first = ui::corner_box(whole, 200, 40, {}, {}, order);
  EXPECT_TRUE(first.x0 == 0 && first.y0 == 0);
  const ui::Box next = ui::corner_box(whole, 200, 40, {}, {{0, 0, 50, 50}}, order);
  EXPECT_TRUE(next.x1 == 1000 && next.y0 == 0);
}

// A press in a lane's view picks that lane's particle where that lane has it (the lanes have
// parted): the particle nearest the pointer in the view, grabbed in every lane.
TEST(CompareView, APressInALanesViewPicksItsParticle) {
  app::Session session = rope_compared(5e-4, {Method::SymplecticEuler, Method::Verlet});
  for (int k = 0; k < 30; ++k) session.advance_frame();
  // The second lane's particle 12 a metre to the right of the first's (as lanes that part have it).
  const int particle = 12;
  session.lanes()[1].sim.place(
      particle, session.lanes()[0].sim.state().x.row(particle).transpose() + Vec3(1.0, 0.0, 0.0));
  const auto views =
      draw::lane_views(session, session.scene().camera, draw::CompareLayout::Apart, kViewport);
  ASSERT_EQ(views.size(), 2u);
  const draw::LaneView& second = views[1];
  const Eigen::Vector3d at =
      draw::project(second.view, session.lanes()[1].sim.state().x.row(particle).transpose(),
                    second.viewport.width, second.viewport.height);
  // (Where the first lane has it, the pointer would miss: the pick is the second lane's.)
  const Eigen::Vector3d other =
      draw::project(second.view, session.lanes()[0].sim.state().x.row(particle).transpose(),
                    second.viewport.width, second.viewport.height);
  ASSERT_GT((at - other).head<2>().norm(), 20.0);
  const ui::Pointer pointer{at.x() + second.viewport.x, at.y() + second.viewport.y};
  const auto drag =
      ui::press(session, second.view, second.viewport, pointer, 6.0, second.lanes.front());
  ASSERT_TRUE(drag);
  EXPECT_EQ(drag->particle, particle);
  EXPECT_EQ(drag->lane, 1);
  EXPECT_EQ(session.grabbed(), particle);
}

// The cost readout counts every lane: each lane's work in the frame, the total their sum, and a
// lane that diverged none.
TEST(CompareView, TheFramesWorkIsEachLanesAndTheirSum) {
  app::Session session = rope_compared(2e-4, {Method::Euler, Method::RK4});
  ui::FrameStats stats;
  for (int k = 0; k < 200; ++k) {
    const auto before = ui::lane_counters(session);
    session.advance_frame();
    ui::count_frame(stats, session, before);
  }
  ASSERT_TRUE(session.lanes()[0].sim.diverged());
  ASSERT_EQ(stats.lanes.size(), 2u);
  EXPECT_EQ(stats.lanes[0].force_evals, 0);
  // RK4: four evaluations a step, a frame of 1/60 s at h = 2e-4 s is 83 or 84 steps.
  EXPECT_GE(stats.lanes[1].force_evals, 4 * 83);
  EXPECT_LE(stats.lanes[1].force_evals, 4 * 84);
  EXPECT_EQ(stats.force_evals, stats.lanes[0].force_evals + stats.lanes[1].force_evals);
}

}  // namespace
}  // namespace springlab::test
