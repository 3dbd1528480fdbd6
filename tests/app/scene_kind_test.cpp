// Scene kinds as types (app/session/scene_kind.hpp): the inverse-kinematics kind through the
// session's calls for any kind, the keys and the command line; and a kind of the test's own, which
// the session, picking, the keys and the drawing take without a line changed elsewhere (the
// CONTRIBUTING checklist "A scene kind", followed).
#include <gtest/gtest.h>
#include <imgui.h>

#include <algorithm>
#include <set>

#include "draw/marks.hpp"
#include "draw/palette.hpp"
#include "draw/scene_frame.hpp"
#include "session/ik_kind.hpp"
#include "session/mass_spring_kind.hpp"
#include "springlab/error.hpp"
#include "springlab/text.hpp"
#include "support.hpp"
#include "ui/actions.hpp"
#include "ui/kind_panels.hpp"
#include "ui/panels.hpp"
#include "ui/theme.hpp"

namespace springlab::app {
namespace {

Session session_of(const std::string& name, std::unique_ptr<SceneKind> kind = nullptr) {
  Scene scene = test::shipped(name);
  const SimulationSettings s = settings_for(scene);
  return Session(std::move(scene), s, 60.0, std::move(kind));
}

double distance(const std::array<float, 3>& a, const std::array<float, 3>& b) {
  return std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);
}

TEST(SceneKind, EachSceneHasItsKindAndItsRows) {
  const auto spring = make_scene_kind(test::shipped("spring"));
  EXPECT_EQ(spring->kind_name(), "mass-spring");
  EXPECT_EQ(&ui::kind_panels(*spring), &ui::mass_spring_panels());
  ASSERT_EQ(spring->row_count(), static_cast<int>(methods().size()));
  for (const MethodInfo& m : methods()) {  // row k is method k, as its table says
    const LaneRow row = spring->row(static_cast<int>(m.id));
    EXPECT_EQ(row.name, m.name);
    EXPECT_EQ(row.table, LaneRow::Table::Method);  // shown as the method's row (draw's table)
    EXPECT_EQ(row.id, static_cast<int>(m.id));
  }
  EXPECT_EQ(spring->find("rk4"), static_cast<int>(Method::RK4));
  EXPECT_EQ(spring->find("ccd"), std::nullopt);
  EXPECT_EQ(spring->lanes_named("euler,verlet", "--compare"),
            (std::vector<int>{static_cast<int>(Method::Euler), static_cast<int>(Method::Verlet)}));

  const auto arm = make_scene_kind(test::shipped("ik-arm"));
  EXPECT_EQ(arm->kind_name(), "inverse-kinematics");
  EXPECT_EQ(&ui::kind_panels(*arm), &ui::ik_panels());
  ASSERT_EQ(arm->row_count(), 3);
  std::set<draw::Mark> marks;
  for (int k = 0; k < 3; ++k) {
    const IkSolverInfo& s = ik_solvers()[static_cast<std::size_t>(k)];
    EXPECT_EQ(arm->row(k).name, s.name);
    EXPECT_EQ(arm->row(k).table, LaneRow::Table::IkSolver);
    marks.insert(draw::row_style(arm->row(k)).mark);
    for (int j = 0; j < k; ++j)
      EXPECT_GT(distance(draw::row_style(arm->row(j)).colour, draw::row_style(arm->row(k)).colour),
                0.3)
          << j << " " << k;
  }
  EXPECT_EQ(marks.size(), 3u);
  EXPECT_EQ(arm->find("fabrik"), 1);
  EXPECT_EQ(arm->find("rk4"), std::nullopt);
  const auto refused = [&](const std::string& list) {
    try {
      arm->lanes_named(list, "--compare");
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("(accepted)");
  };
  EXPECT_EQ(refused("ccd,rk4"),
            "--compare: unknown solver 'rk4' (this is an inverse-kinematics scene; solvers: ccd, "
            "fabrik, dls)");
  EXPECT_EQ(refused("ccd").rfind("--compare: give 2 to 4 solvers separated by commas, e.g. ", 0),
            0u)
      << refused("ccd");
}

// The three solvers side by side from one start, by the session's calls for any kind: each
// reaches the target to its tolerance (the end within it of the target, measured on the chain),
// each in its row's colour and mark; paused, none iterates; reset, each starts again.
TEST(SceneKind, TheSolversReachTheTargetThroughTheSessionsCalls) {
  Session session = session_of("ik-arm");
  const IkScene ik = *test::shipped("ik-arm").ik;
  EXPECT_EQ(session.chosen(), static_cast<int>(ik.solvers.front()));
  session.set_compare_rows(session.kind().compared_first());
  ASSERT_EQ(session.lanes().size(), 3u);
  for (int frame = 0; frame < 600; ++frame) session.advance_frame();
  const Eigen::Vector2d target = session.scene().state.x.row(ik.target).head<2>().transpose();
  std::set<draw::Mark> marks;
  for (const Lane& lane : session.lanes()) {
    const IkLane& part = ik_lane(lane);
    EXPECT_TRUE(part.status.converged) << lane_name(lane);
    EXPECT_LE((part.chain.effector() - target).norm(), ik.settings.tolerance) << lane_name(lane);
    EXPECT_EQ(part.error.back(), part.status.error);
    EXPECT_GT(part.error[0], 100 * ik.settings.tolerance);  // it started away from it
    const LaneRow row = lane_row(lane);
    EXPECT_EQ(lane_name(lane), row.name);
    EXPECT_EQ(draw::lane_color(lane).r, draw::row_style(row).colour[0]);
    marks.insert(draw::lane_mark(lane));
  }
  EXPECT_EQ(marks.size(), 3u);

  session.reset();
  session.set_paused(true);
  for (int frame = 0; frame < 10; ++frame) session.advance_frame();
  for (const Lane& lane : session.lanes()) {
    EXPECT_EQ(ik_lane(lane).status.iterations, 0) << lane_name(lane);
    EXPECT_EQ(ik_lane(lane).chain.angles, ik.chain.angles);
  }
  session.step_once();  // one step: one iteration each
  for (const Lane& lane : session.lanes())
    EXPECT_EQ(ik_lane(lane).status.iterations, 1) << lane_name(lane);
}

// The distance to the target is the IK kind's series, kept in the IK lane's part, not in the
// History every kind has: the kind samples it once a frame with the History, the session clears
// it with the History (watching another particle), and a reset makes it again. The IK chart
// reads it there (ui/ik_panels.cpp). An IK lane has no mass-spring part.
TEST(SceneKind, TheDistanceToTheTargetIsTheIkKindsSeries) {
  Session session = session_of("ik-arm");
  for (int frame = 0; frame < 30; ++frame) session.advance_frame();
  const Lane& lane = session.primary();
  EXPECT_EQ(ik_lane(lane).error.size(), 31u);  // the start, and 30 frames
  EXPECT_EQ(lane.history.t.size(), 31u);
  EXPECT_EQ(ik_lane(lane).error.back(), ik_lane(lane).status.error);
  EXPECT_EQ(mass_spring_lane(lane), nullptr);
  session.kind().sample(session.lanes()[0], session);  // the kind's sample: its series alone
  EXPECT_EQ(ik_lane(lane).error.size(), 32u);
  EXPECT_EQ(lane.history.t.size(), 31u);
  session.watch(session.kind().handle());
  EXPECT_EQ(ik_lane(lane).error.size(), 0u);
  EXPECT_EQ(lane.history.t.size(), 0u);
  session.advance_frame();
  session.reset();
  EXPECT_EQ(ik_lane(lane).error.size(), 1u);
  EXPECT_EQ(lane.history.t.size(), 1u);
}

// A mass-spring lane's trails, free-body momentum and inverted cells are its kind's, sampled by
// it into the lane's part (mass_spring_kind.hpp) after the session's History: the rope's trail
// grows a point a frame, the kind's own sample adds to its part alone, watching another particle
// clears the momentum series with the History (the trail stays), a reset starts the trail again,
// and the drawing's trails are the part's.
TEST(SceneKind, TheMassSpringSamplesAreTheMassSpringKinds) {
  Session session = session_of("rope");
  ASSERT_FALSE(session.scene().trails.empty());
  for (int frame = 0; frame < 10; ++frame) session.advance_frame();
  const Lane& lane = session.primary();
  const MassSpringLane* part = mass_spring_lane(lane);
  ASSERT_NE(part, nullptr);
  ASSERT_EQ(part->trails.size(), session.scene().trails.size());
  const auto trail_of = [&](std::size_t k) { return mass_spring_lane(lane)->trails[k]; };
  EXPECT_EQ(trail_of(0).size(), 11u);  // the start, and 10 frames
  const Vec3 end = lane.sim.state().x.row(session.scene().trails[0]).transpose();
  EXPECT_EQ(trail_of(0).back(), end);
  EXPECT_EQ(part->linear_change.size(), lane.history.t.size());  // (NaN: the rope is pinned)
  EXPECT_FALSE(part->free_since);
  EXPECT_EQ(part->inverted_cells, 0);  // (a rope has no cells)

  session.kind().sample(session.lanes()[0], session);
  EXPECT_EQ(trail_of(0).size(), 12u);
  EXPECT_EQ(part->linear_change.size(), 12u);
  EXPECT_EQ(lane.history.t.size(), 11u);

  // Drawn from the part: each trail's segments, and only with trails shown.
  draw::ViewOptions view = draw::ViewOptions::for_scene(session.scene());
  view.trails = true;
  const std::size_t with =
      draw::build_frame(session, view, draw::Viewport{0, 0, 640, 360}).lines.size();
  view.trails = false;
  const std::size_t without =
      draw::build_frame(session, view, draw::Viewport{0, 0, 640, 360}).lines.size();
  std::size_t segments = 0;
  for (const auto& trail : part->trails) segments += trail.size() - 1;
  EXPECT_EQ(with - without, segments);

  session.watch(0);
  EXPECT_EQ(part->linear_change.size(), 0u);
  EXPECT_EQ(trail_of(0).size(), 12u);
  session.reset();  // a new part
  EXPECT_EQ(trail_of(0).size(), 1u);
  EXPECT_EQ(mass_spring_lane(lane)->linear_change.size(), 1u);
}

// The keys ask the kind: 1 to 3 choose a solver (from the pose reached), C sets the scene's
// solvers side by side and back; only the target may be held.
TEST(SceneKind, KeysAndHoldingAskTheKind) {
  Session session = session_of("ik-arm");
  ui::UiState ui;
  for (int frame = 0; frame < 5; ++frame) session.advance_frame();
  const std::vector<double> reached = ik_lane(session.primary()).chain.angles;
  ui::perform(static_cast<ui::Action>(static_cast<int>(ui::Action::Method1) + 2), session, ui);
  EXPECT_EQ(lane_name(session.primary()), "dls");
  EXPECT_EQ(ik_lane(session.primary()).chain.angles, reached);  // switched, not restarted
  ui::perform(static_cast<ui::Action>(static_cast<int>(ui::Action::Method1) + 5), session,
              ui);  // no sixth solver
  EXPECT_EQ(lane_name(session.primary()), "dls");
  ui::perform(ui::Action::ToggleCompare, session, ui);
  ASSERT_EQ(session.lanes().size(), session.kind().compared_first().size());
  ui::perform(ui::Action::ToggleCompare, session, ui);
  EXPECT_EQ(session.lanes().size(), 1u);

  const int target = session.kind().handle();
  EXPECT_EQ(target, session.scene().ik->target);
  const State& s = session.primary().sim.state();
  for (int i = 0; i < s.particle_count(); ++i) {
    const Vec3 p = s.x.row(i).transpose();
    const int picked = session.pick(p + Vec3(0, 0, 5), Vec3(0, 0, -1), 1e-3);
    EXPECT_EQ(picked, i == target ? target : -1) << "particle " << i;
  }
}

// A kind no one else names: its lanes are two methods (explicit Euler and Verlet), the rope's
// free end is its handle, and a guide circle of 0.5 m is drawn round the anchor, its springs
// in the lane's colour. Its lanes keep a part of their own, with a series it samples (the
// handle's height, a frame) and the frame it last sampled. The session, picking, the keys, the
// sampling and the drawing take it as it is.
struct TetheredLane : LanePart {
  Series height;
  std::int64_t frame = -1;
  void clear_samples() override { height.clear(); }
};

class TetheredKind : public SceneKind {
 public:
  explicit TetheredKind(int handle) : handle_(handle) {}
  std::string_view kind_name() const override { return "tethered"; }
  int row_count() const override { return 2; }
  LaneRow row(int k) const override {
    const MethodInfo& m = method_info(k == 0 ? Method::Euler : Method::Verlet);
    return {m.name, m.label, LaneRow::Table::Method, static_cast<int>(m.id)};
  }
  int row_of(const Lane& lane) const override {
    return lane.sim.settings().method == Method::Verlet ? 1 : 0;
  }
  const char* row_noun() const override { return "method"; }
  std::string choices() const override { return "euler, verlet"; }
  int initial_row(const SimulationSettings&) const override { return 1; }
  std::vector<int> compared_first() const override { return {0, 1}; }
  void configure(SimulationSettings& s, int row) const override {
    s.method = row == 0 ? Method::Euler : Method::Verlet;
  }
  void start(Lane& lane, int) const override { lane.part = std::make_unique<TetheredLane>(); }
  void switch_to(Lane& lane, int row) const override {
    lane.sim.set_method(row == 0 ? Method::Euler : Method::Verlet);
  }
  void after_steps(Lane&, Steps) const override {}
  void sample(Lane& lane, const Session& session) const override {
    auto& part = dynamic_cast<TetheredLane&>(*lane.part);
    part.height.push(lane.sim.state().x(handle_, 1));
    part.frame = session.frame();
  }
  int handle() const override { return handle_; }
  std::vector<GuideCircle> guides() const override { return {{Vec3::Zero(), 0.5}}; }
  bool strained() const override { return false; }

 private:
  int handle_;
};

// Its UI half, its own: the mass-spring panels but for its controls, which say what they are.
int g_tethered_controls_drawn = 0;
const ui::KindPanels& tethered_panels() {
  static const ui::KindPanels panels = [] {
    ui::KindPanels p = ui::mass_spring_panels();
    p.controls = [](Session&, ui::UiState&, const ui::FrameStats&, const ui::PanelLayout&, bool) {
      ImGui::TextUnformatted("tethered controls");
      ++g_tethered_controls_drawn;
    };
    return p;
  }();
  return panels;
}

// A kind whose panels no one added: asking for them is a mistake of the program, said by name.
class UnpanelledKind final : public TetheredKind {
 public:
  UnpanelledKind() : TetheredKind(0) {}
  std::string_view kind_name() const override { return "unpanelled"; }
};

TEST(SceneKind, AKindWithNoPanelsIsToldByName) {
  try {
    (void)ui::kind_panels(UnpanelledKind());
    ADD_FAILURE() << "a kind with no panels was given some";
  } catch (const std::logic_error& e) {
    EXPECT_NE(std::string(e.what()).find("'unpanelled'"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("add_kind_panels"), std::string::npos) << e.what();
  }
}

TEST(SceneKind, AKindOfOnesOwnNeedsNoOtherEdit) {
  const int end = test::shipped("rope").model.particle_count() - 1;
  Session session = session_of("rope", std::make_unique<TetheredKind>(end));
  // Its UI half, added under its name, is the one the panels draw.
  ui::add_kind_panels("tethered", tethered_panels());
  ASSERT_EQ(&ui::kind_panels(session.kind()), &tethered_panels());
  ImGui::CreateContext();
  ui::apply_theme(1.0f);
  unsigned char* pixels = nullptr;
  int tex_w = 0, tex_h = 0;
  ImGui::GetIO().Fonts->GetTexDataAsRGBA32(&pixels, &tex_w, &tex_h);
  ImGui::GetIO().DisplaySize = ImVec2(1280, 720);
  ImGui::GetIO().DeltaTime = 1.0f / 60.0f;
  {
    ui::UiState panels_ui;
    ImGui::NewFrame();
    ui::draw_panels(session, panels_ui, ui::FrameStats{}, 1280, 720);
    ImGui::Render();
  }
  ImGui::DestroyContext();
  EXPECT_EQ(g_tethered_controls_drawn, 1);
  EXPECT_EQ(session.primary().sim.settings().method, Method::Verlet);  // its initial row
  const auto* part = dynamic_cast<const TetheredLane*>(session.primary().part.get());
  ASSERT_NE(part, nullptr);  // started by it
  EXPECT_EQ(mass_spring_lane(session.primary()), nullptr);
  // Sampled by it, beside the History, with no line of Session::sample its own.
  for (int frame = 0; frame < 5; ++frame) session.advance_frame();
  EXPECT_EQ(part->height.size(), session.primary().history.t.size());
  EXPECT_EQ(part->height.back(), session.primary().sim.state().x(end, 1));
  EXPECT_EQ(part->frame, 5);
  session.watch(end);  // cleared with the History
  EXPECT_EQ(part->height.size(), 0u);
  ui::UiState ui;
  ui::perform(ui::Action::Method1, session, ui);
  EXPECT_EQ(session.primary().sim.settings().method, Method::Euler);
  ui::perform(static_cast<ui::Action>(static_cast<int>(ui::Action::Method1) + 2), session,
              ui);  // no third row
  EXPECT_EQ(session.chosen(), 0);
  ui::perform(ui::Action::ToggleCompare, session, ui);
  ASSERT_EQ(session.lanes().size(), 2u);
  EXPECT_EQ(lane_label(session.lanes()[1]), tr(method_info(Method::Verlet).label));

  // Only its handle may be held.
  const State& s = session.primary().sim.state();
  for (int i : {1, end / 2, end}) {
    const Vec3 p = s.x.row(i).transpose();
    EXPECT_EQ(session.pick(p + Vec3(0, 0, 5), Vec3(0, 0, -1), 1e-3), i == end ? end : -1)
        << "particle " << i;
  }

  // Drawn: its guide, a circle of 128 segments at 0.5 m, and its springs in each lane's colour.
  session.set_compare_rows({1});
  draw::ViewOptions view = draw::ViewOptions::for_scene(session.scene());
  view.trails = false;
  const draw::Frame frame = draw::build_frame(session, view, draw::Viewport{0, 0, 640, 360});
  int guide = 0;
  std::set<std::array<float, 4>> spring_colours;
  for (const draw::Line& line : frame.lines) {
    if (line.color_a.r == draw::kReach.r && line.color_a.a == draw::kReach.a) {
      ++guide;
      EXPECT_NEAR(line.a.norm(), 0.5f, 1e-5f);
    } else {
      spring_colours.insert({line.color_a.r, line.color_a.g, line.color_a.b, line.color_a.a});
    }
  }
  EXPECT_EQ(guide, 128);
  EXPECT_EQ(spring_colours.size(), 1u);  // not by strain: the lane's colour
  EXPECT_EQ(*spring_colours.begin(),
            (std::array<float, 4>{draw::method_style(Method::Verlet).colour[0],
                                  draw::method_style(Method::Verlet).colour[1],
                                  draw::method_style(Method::Verlet).colour[2], 1.0f}));
}

}  // namespace
}  // namespace springlab::app
