// The app's interaction, without a window, through the functions the window calls: picking a
// particle under the pointer, dragging and releasing it, camera moves, parameter changes, the
// keyboard's actions, compare mode and divergence.
#include "ui/interaction.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <thread>

#include "draw/camera.hpp"
#include "draw/scene_frame.hpp"
#include "support.hpp"
#include "ui/actions.hpp"
#include "ui/compare_panel.hpp"

namespace springlab::ui {
namespace {

app::Session session_of(const std::string& name, std::optional<Method> method = std::nullopt) {
  Scene scene = test::shipped(name);
  SimulationSettings s = settings_for(scene);
  if (method) s.method = *method;
  return app::Session(std::move(scene), s, 60.0);
}

const draw::Viewport kViewport{100, 0, 800, 450};

Pointer pixel_of(const app::Session& session, const draw::ViewCamera& camera, int particle) {
  const Eigen::Vector3d p =
      draw::project(camera, session.primary().sim.state().x.row(particle).transpose(),
                    kViewport.width, kViewport.height);
  return {p.x() + kViewport.x, p.y() + kViewport.y};
}

TEST(Interaction, PickingGrabsTheParticleUnderThePointer) {
  app::Session session = session_of("rope");
  const draw::ViewCamera camera =
      draw::view_camera(session.scene().camera, kViewport.width, kViewport.height);
  for (int particle : {0, 7, 15}) {
    const auto drag = press(session, camera, kViewport, pixel_of(session, camera, particle));
    ASSERT_TRUE(drag);
    EXPECT_EQ(drag->particle, particle);
    EXPECT_EQ(session.grabbed(), particle);
    release(session);
  }
  // Empty space, and outside the scene's viewport (over the panels): nothing.
  EXPECT_FALSE(press(session, camera, kViewport, {kViewport.x + 5.0, kViewport.y + 440.0}));
  EXPECT_FALSE(press(session, camera, kViewport, {50.0, 200.0}));
  EXPECT_EQ(session.grabbed(), -1);
}

TEST(Interaction, PickingIn3DTakesTheParticleInFront) {
  app::Session session = session_of("jelly");
  const draw::ViewCamera camera =
      draw::view_camera(session.scene().camera, kViewport.width, kViewport.height);
  // The box's centre column: several particles line up behind one another; the nearest wins.
  const State& s = session.primary().sim.state();
  int nearest = -1;
  double best = 1e9;
  for (int i = 0; i < s.particle_count(); ++i) {
    const double d = (s.x.row(i).transpose().cast<float>() - camera.eye).norm();
    if (d < best) {
      best = d;
      nearest = i;
    }
  }
  const auto drag = press(session, camera, kViewport, pixel_of(session, camera, nearest));
  ASSERT_TRUE(drag);
  EXPECT_EQ(drag->particle, nearest);
}

TEST(Interaction, DraggingMovesTheParticleToThePointerAndReleaseKeepsItsVelocity) {
  app::Session session = session_of("rope");
  const draw::ViewCamera camera =
      draw::view_camera(session.scene().camera, kViewport.width, kViewport.height);
  const Pointer start = pixel_of(session, camera, 15);
  const auto drag = press(session, camera, kViewport, start);
  ASSERT_TRUE(drag);
  // Move the pointer 100 pixels left, then keep it there for a while.
  const Pointer target{start.x - 100, start.y};
  move(session, camera, kViewport, target, *drag);
  const Vec3 expected = *session.drag_target();
  for (int k = 0; k < 5; ++k) session.advance_frame();
  EXPECT_LT((session.primary().sim.state().x.row(15).transpose() - expected).norm(), 1e-9);
  // 100 pixels in a 450-pixel-high view of 5.6 m: 1.244 m to the left, in the plane z = 0.
  EXPECT_NEAR(expected.x(), 4.0 - 100.0 * 5.6 / 450.0, 1e-4);
  EXPECT_NEAR(expected.z(), 0.0, 1e-9);

  // Drag at a steady speed, then let go: it flies on at that speed.
  const double per_frame = 0.02;  // m
  for (int k = 1; k <= 10; ++k) {
    session.drag_to(expected + Vec3(0, per_frame * k, 0));
    session.advance_frame();
  }
  release(session);
  EXPECT_EQ(session.grabbed(), -1);
  EXPECT_NEAR(session.primary().sim.state().v(15, 1), per_frame * 60.0, 1e-6);
  EXPECT_FALSE(session.primary().sim.model().pinned(15));
}

TEST(Interaction, DraggingWhilePausedPlacesTheParticle) {
  app::Session session = session_of("rope");
  session.set_paused(true);
  session.grab(15);
  session.drag_to(Vec3(2, -1, 0));
  session.advance_frame();
  EXPECT_EQ(session.primary().sim.state().x.row(15), Eigen::RowVector3d(2, -1, 0));
  EXPECT_EQ(session.primary().sim.state().t, 0.0);  // and time stood still
}

TEST(Interaction, CameraOrbitsPansAndZooms) {
  Camera c = test::shipped("jelly").camera;
  const Camera before = c;
  orbit(c, 100, 1000);
  EXPECT_NEAR(c.yaw, before.yaw - 30.0, 1e-9);
  EXPECT_EQ(c.pitch, 89.0);  // clamped short of the pole
  zoom(c, 2);
  EXPECT_NEAR(c.distance, before.distance * 0.88 * 0.88, 1e-9);
  // Panning by 50 pixels moves what was under the pointer by 50 pixels.
  Camera planar = test::shipped("rope").camera;
  const draw::ViewCamera view = draw::view_camera(planar, 800, 450);
  const Eigen::Vector3d point(1.0, -1.0, 0.0);
  const Eigen::Vector3d before_px = draw::project(view, point, 800, 450);
  pan(planar, view, 50, -20);
  const Eigen::Vector3d after_px =
      draw::project(draw::view_camera(planar, 800, 450), point, 800, 450);
  EXPECT_NEAR(after_px.x() - before_px.x(), 50.0, 1e-3);
  EXPECT_NEAR(after_px.y() - before_px.y(), -20.0, 1e-3);
  // A 2D view does not orbit.
  const Camera still = planar;
  orbit(planar, 100, 100);
  EXPECT_EQ(planar.yaw, still.yaw);
}

TEST(Interaction, ParameterChangesReachEveryLaneAndKeepTheMaterialsInProportion) {
  app::Session session = session_of("cloth");
  session.set_compare_rows(test::method_rows({Method::SymplecticEuler, Method::Verlet}));
  const auto materials = session.primary().sim.model().materials;
  session.set_stiffness(2 * session.stiffness());
  session.set_damping(0.5 * session.damping());
  session.set_dt(0.0005);
  session.set_gravity(Vec3(0, -1.6, 0));
  for (const app::Lane& lane : session.lanes()) {
    const Model& m = lane.sim.model();
    for (std::size_t k = 0; k < materials.size(); ++k) {
      EXPECT_DOUBLE_EQ(m.materials[k].ks, 2 * materials[k].ks);
      EXPECT_DOUBLE_EQ(m.materials[k].kd, 0.5 * materials[k].kd);
    }
    EXPECT_EQ(lane.sim.settings().dt, 0.0005);
    EXPECT_EQ(m.gravity, Vec3(0, -1.6, 0));
  }
}

TEST(Interaction, SwitchingMethodMidMotionKeepsTheState) {
  app::Session session = session_of("rope");
  for (int k = 0; k < 30; ++k) session.advance_frame();
  const State before = session.primary().sim.state();
  session.choose(test::method_row(Method::RK4));
  EXPECT_EQ(session.method(), Method::RK4);
  EXPECT_EQ(state_hash(session.primary().sim.state()), state_hash(before));
  session.advance_frame();
  // It goes on from where it was: a frame's worth of motion, not a restart.
  EXPECT_NEAR(session.primary().sim.state().t, before.t + 1.0 / 60.0, 1e-9);
  EXPECT_LT((session.primary().sim.state().x - before.x).norm(), 0.5);
}

TEST(Interaction, KeyboardActionsDoWhatTheHelpSays) {
  app::Session session = session_of("spring");
  UiState ui;
  perform(Action::TogglePause, session, ui);
  EXPECT_TRUE(session.paused());
  session.advance_frame();
  EXPECT_EQ(session.primary().sim.state().t, 0.0);
  perform(Action::Step, session, ui);
  EXPECT_NEAR(session.primary().sim.state().t, session.primary().sim.settings().dt, 1e-15);
  perform(Action::TogglePause, session, ui);
  for (int k = 0; k < 10; ++k) session.advance_frame();
  perform(Action::Reset, session, ui);
  EXPECT_EQ(session.primary().sim.state().t, 0.0);
  perform(Action::Method5, session, ui);  // the fifth method of the table: rk4
  EXPECT_EQ(session.method(), Method::RK4);
  perform(Action::ToggleCompare, session, ui);  // the scene's own methods
  EXPECT_TRUE(session.comparing());
  EXPECT_EQ(session.lanes().size(), session.scene().methods.size());
  perform(Action::ToggleCompare, session, ui);
  EXPECT_FALSE(session.comparing());
  perform(Action::TogglePanels, session, ui);
  EXPECT_FALSE(ui.panels);
  EXPECT_EQ(scene_viewport(ui, session, 1280, 720).width, 1280);
  perform(Action::ToggleHelp, session, ui);
  EXPECT_TRUE(ui.help);
}

TEST(Interaction, CompareModeMovesTheSameParticleInEveryCopyAndFreezesADivergedOne) {
  app::Session session = session_of("stiff");
  session.set_compare_rows(
      test::method_rows({Method::ImplicitEuler, Method::SymplecticEuler, Method::RK4}));
  ASSERT_EQ(session.lanes().size(), 3u);
  // At the scene's one step a frame (h w_max about 90) both explicit lanes are far past their
  // limits, RK4 blowing up at its first step; with automatic sub-steps each lane steps within
  // half its own limit, so all three start stable.
  session.set_auto_substeps();
  session.grab(19);
  session.drag_to(Vec3(2.0, 1.0, 0.0));
  session.advance_frame();
  // Every copy is stable, by the stability analysis and in fact, and the drag is the same in each.
  for (app::Lane& lane : session.lanes()) {
    const char* name = method_info(lane.sim.settings().method).name;
    EXPECT_LE(lane.sim.h(), lane.sim.stability_limit().h)
        << name << ": " << describe(lane.sim.stability_limit());
    EXPECT_FALSE(lane.sim.trouble()) << name << ": " << lane.sim.trouble()->message();
    EXPECT_LT((lane.sim.state().x.row(19) - Eigen::RowVector3d(2, 1, 0)).norm(), 1e-9) << name;
  }
  session.release();
  // Back to one step a frame: the explicit copies diverge, implicit Euler goes on.
  session.set_substeps(1);
  for (int k = 0; k < 120; ++k) session.advance_frame();
  const auto& lanes = session.lanes();
  EXPECT_FALSE(lanes[0].sim.diverged());  // implicit Euler goes on
  EXPECT_TRUE(lanes[1].sim.diverged());
  EXPECT_TRUE(lanes[2].sim.diverged());
  EXPECT_NEAR(lanes[0].sim.state().t, 121.0 / 60.0, 1e-9);
  // The diverged ones stopped where they diverged and stay there.
  const double frozen = lanes[1].sim.state().t;
  EXPECT_LT(frozen, 1.0);
  session.advance_frame();
  EXPECT_EQ(lanes[1].sim.state().t, frozen);
}

TEST(Interaction, DivergenceInTheSingleViewStopsAndResetRecovers) {
  app::Session session = session_of("stiff", Method::SymplecticEuler);
  for (int k = 0; k < 60; ++k) session.advance_frame();
  ASSERT_TRUE(session.primary().sim.diverged());
  EXPECT_TRUE(all_finite(session.primary().sim.state()));
  session.reset();
  EXPECT_FALSE(session.primary().sim.diverged());
  EXPECT_EQ(session.primary().sim.state().t, 0.0);
}

TEST(Interaction, SlowMotionSlowsTheSimulatedClock) {
  app::Session session = session_of("spring");
  session.set_speed(0.25);
  for (int k = 0; k < 60; ++k) session.advance_frame();
  EXPECT_NEAR(session.primary().sim.state().t, 0.25,
              1e-9);  // dt = 1/120 divides a quarter frame... twice
  EXPECT_NEAR(session.presentation_time(), 1.0, 1e-12);
}

TEST(Interaction, ScriptedEventsHappenAtTheirFrames) {
  app::Session session = session_of("rope");
  const Script script = parse_script(R"({"events": [
      {"t": 0.5, "grab": "rope:-1"}, {"t": 0.5, "move": [2, 0, 0], "over": 0.5},
      {"t": 1.5, "release": true}, {"t": 2.0, "set": {"method": "verlet", "kd": 1.5}}]})",
                                     "s.json", session.scene());
  session.play(script);
  for (int k = 0; k < 30; ++k) session.advance_frame();  // events at t = 0.5 apply in frame 30
  EXPECT_EQ(session.grabbed(), -1);
  session.advance_frame();
  EXPECT_EQ(session.grabbed(), 15);
  for (int k = 0; k < 30; ++k) session.advance_frame();  // the move is over by t = 1.0
  EXPECT_LT((session.primary().sim.state().x.row(15) - Eigen::RowVector3d(2, 0, 0)).norm(), 1e-9);
  for (int k = 0; k < 60; ++k) session.advance_frame();
  EXPECT_EQ(session.grabbed(), -1);
  for (int k = 0; k < 40; ++k) session.advance_frame();
  EXPECT_EQ(session.method(), Method::Verlet);
  EXPECT_DOUBLE_EQ(session.damping(), 1.5);
}

}  // namespace
}  // namespace springlab::ui

namespace springlab::ui {
namespace {

TEST(ComparePanel, SweepsTheSceneOnScreenInTheBackgroundAndCancels) {
  app::Session session = session_of("spring");
  session.set_stiffness(400);  // the panel sweeps the scene as it is now: w = 20
  ComparePanel panel;
  panel.points = 3;
  panel.duration = 0.5f;
  panel.methods.set(Method::RK4, true);
  panel.methods.set(Method::Euler, true);
  const SweepSettings s = panel.settings(session);
  EXPECT_EQ(s.methods.size(), 2u);
  EXPECT_DOUBLE_EQ(s.h_max, 2 * session.primary().sim.settings().dt);
  panel.start(session);
  while (panel.sweep.running()) std::this_thread::sleep_for(std::chrono::milliseconds(5));
  const SweepResult r = panel.sweep.snapshot();
  EXPECT_FALSE(r.cancelled);
  EXPECT_NEAR(r.w_max, 20.0, 1e-6);
  ASSERT_EQ(r.methods.size(), 2u);
  EXPECT_NEAR(r.methods[1].measured_stable_h, 2 * std::sqrt(2.0) / 20.0, 1e-3);  // RK4's limit
  // A long sweep, cancelled: it stops, keeping what it had.
  panel.points = 10;
  panel.duration = 5.0f;
  for (const MethodInfo& m : methods()) panel.methods.set(m.id, true);
  panel.start(session);
  std::this_thread::sleep_for(std::chrono::milliseconds(20));
  panel.sweep.cancel();
  EXPECT_FALSE(panel.sweep.running());
  const auto [done, total] = panel.sweep.progress();
  EXPECT_LT(done, total);
}

// No wait: with its analysis on a worker thread (the window), a 64 x 64 cloth's lane with
// automatic sub-steps moves in its first frame, on the sub-steps of the quick bound, never fewer
// than the analysis then chooses (a smaller step), and moves to the analysis' own when it ends.
TEST(Interaction, ALaneStartsAtOnceAndTakesTheAnalysedStepWhenItComes) {
  Scene scene = test::shipped("cloth", {"cloth.width=64", "cloth.height=64"});
  app::Session session(std::move(scene), settings_for(test::shipped("cloth")), 60.0);
  session.set_background_analysis(true);
  session.advance_frame();
  const Simulation& sim = session.primary().sim;
  EXPECT_GT(sim.state().t, 0.0) << "the lane waited for its analysis";
  ASSERT_TRUE(sim.substeps_provisional());
  const int quick = sim.settings().substeps;
  for (int k = 0; k < 600 && sim.substeps_provisional(); ++k) {
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    session.advance_frame();
  }
  ASSERT_FALSE(sim.substeps_provisional()) << "no analysis within a minute";
  ASSERT_TRUE(sim.has_stability());
  const StabilityAnalysis& analysis = *sim.stability_if_any();
  EXPECT_EQ(sim.settings().substeps, choose_substeps(analysis.limit(sim.settings().method),
                                                     sim.settings().dt, sim.settings().safety)
                                         .substeps);
  EXPECT_GE(quick, sim.settings().substeps);
  EXPECT_FALSE(sim.diverged());
}

// A session closed while its analysis runs (a lesson's next step, a scene switch, the app
// closing) leaves no thread behind: its job is cancelled, and shutdown() joins it at once rather
// than after the seconds a 64 x 64 cloth's analysis takes.
TEST(Interaction, AClosedSessionLeavesNoAnalysisRunning) {
  // A 128 x 128 cloth's analysis takes seconds; closing the session must cancel it, so that it
  // stops within milliseconds on its own, before anything joins it (shutdown() would wait for an
  // analysis left running, and this test would pass without the cancel if it only joined).
  {
    Scene scene = test::shipped("cloth", {"cloth.width=128", "cloth.height=128"});
    app::Session session(std::move(scene), settings_for(test::shipped("cloth")), 60.0);
    session.set_background_analysis(true);
    session.advance_frame();
    ASSERT_TRUE(session.analysing());
  }
  EXPECT_GE(app::StabilityJob::threads_alive(), 1);
  const auto t0 = std::chrono::steady_clock::now();
  while (app::StabilityJob::analyses_running() > 0 &&
         std::chrono::steady_clock::now() - t0 < std::chrono::seconds(1))
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  const double stopped =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  EXPECT_EQ(app::StabilityJob::analyses_running(), 0)
      << "the closed session's analysis still runs after " << stopped << " s";
  app::StabilityJob::shutdown();
  EXPECT_EQ(app::StabilityJob::threads_alive(), 0);
  std::printf("  the closed session's analysis stopped in %.3f s\n", stopped);
}

// The frame loop may take a result after its thread has finished and been joined: the job then
// holds the last reference to what it shared with the thread, and taking it must not free that
// while still using it. take() did: it released a lock on the mutex it had just freed, a write
// into freed memory (the heap corruption seen once). ThreadSanitizer reported it in the stress
// test (`scripts/stress.sh tsan`); alone, this test reaches the same path (the job the last
// owner), where neither sanitizer reports it (the write is libc's unlock, not instrumented), so
// the shared state counts being freed while its lock is held (freed_while_locked()).
TEST(StabilityJobs, AResultTakenAfterItsThreadIsJoinedIsWhole) {
  const Scene spring = test::shipped("spring");
  app::StabilityJob job;
  job.start(spring.model, spring.state, 7);
  while (job.running()) std::this_thread::sleep_for(std::chrono::milliseconds(1));
  app::StabilityJob::shutdown();  // joins the thread, and the registry lets go of its share
  EXPECT_EQ(app::StabilityJob::threads_alive(), 0);
  const int before = app::StabilityJob::freed_while_locked();
  const auto result = job.take();  // the last owner: the shared state is freed here
  EXPECT_EQ(app::StabilityJob::freed_while_locked(), before)
      << "take() freed the job's state while holding its lock";
  ASSERT_TRUE(result);
  EXPECT_EQ(result->version, 7u);
  EXPECT_NEAR(result->analysis->w_max(), 10.0, 1e-9);  // k_s = 100, m = 1
  EXPECT_FALSE(job.take());                            // once
}

}  // namespace
}  // namespace springlab::ui
