// The threads beside the frame loop, stressed: what the window does in a class, many times over and
// faster, without a window. Every frame of a background-analysed session changes something that
// starts an analysis on a worker thread (k_s, the method, compare lanes, a drag), an accuracy
// sweep is started and cancelled, and the session is replaced by a lesson's step (the old one's
// analyses cancelled and left to finish). At the end every analysis thread is joined. A bounded
// run here (SPRINGLAB_STRESS_SECONDS, default 2 s); scripts/stress.sh runs it longer, built with
// AddressSanitizer or ThreadSanitizer, beside render and view runs.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdlib>
#include <memory>
#include <thread>

#include "lesson/lesson_library.hpp"
#include "session/stability_job.hpp"
#include "support.hpp"
#include "ui/compare_panel.hpp"

namespace springlab::app {
namespace {

double seconds_to_run() {
  const char* set = std::getenv("SPRINGLAB_STRESS_SECONDS");
  return set ? std::atof(set) : 2.0;
}

TEST(Stress, AnalysesSweepsAndLessonStepsBesideTheFrameLoop) {
  using Clock = std::chrono::steady_clock;
  const auto deadline = Clock::now() + std::chrono::duration<double>(seconds_to_run());
  const std::vector<std::string> lessons = shipped_lesson_files();
  ASSERT_FALSE(lessons.empty());
  std::unique_ptr<Session> session;
  ui::ComparePanel accuracy;
  long frames = 0, sessions = 0, sweeps = 0;
  const auto fresh_cloth = [&] {
    Scene scene = test::shipped("cloth", {"cloth.width=32", "cloth.height=32"});
    const SimulationSettings settings = settings_for(scene);
    session = std::make_unique<Session>(std::move(scene), settings, 60.0);
    session->set_background_analysis(true);
    ++sessions;
  };
  fresh_cloth();
  for (int round = 0; Clock::now() < deadline; ++round) {
    // A lesson's step now and then: the old session and its analyses go (cancelled).
    if (round % 40 == 39) {
      const Lesson lesson = open_lesson(lessons[(round / 40) % lessons.size()]);
      session = step_session(lesson.steps[(round / 40) % lesson.steps.size()], 60.0, true);
      ++sessions;
    } else if (round % 40 == 19) {
      fresh_cloth();
    }
    Session& s = *session;
    switch (round % 6) {
      case 0:
        s.set_stiffness(s.stiffness() * (round % 12 ? 1.1 : 0.9));
        break;
      case 1:
        s.choose(test::method_row(round % 12 == 1 ? Method::RK4 : Method::SymplecticEuler));
        break;
      case 2:
        s.set_compare_rows(test::method_rows({Method::SymplecticEuler, Method::Verlet}));
        break;
      case 3:
        s.set_compare_rows({});
        break;
      case 4:
        s.grab(s.nearest(Vec3(0, 0, 0)));
        s.drag_to(Vec3(0.1, 0.1, 0.0));
        break;
      case 5:
        s.release();
        break;
    }
    if (round % 25 == 0) {  // an accuracy sweep on a worker thread, cancelled a few frames on
      accuracy.start(s);
      ++sweeps;
    }
    if (round % 25 == 3) accuracy.sweep.cancel();
    s.advance_frame();
    ++frames;
  }
  accuracy.sweep.cancel();
  // Last, a session whose analysis takes seconds (a 128 x 128 cloth), closed while it runs: it is
  // cancelled and stops within a second on its own, before shutdown() joins anything.
  {
    Scene scene = test::shipped("cloth", {"cloth.width=128", "cloth.height=128"});
    const SimulationSettings settings = settings_for(scene);
    session = std::make_unique<Session>(std::move(scene), settings, 60.0);
    session->set_background_analysis(true);
    session->advance_frame();
    EXPECT_TRUE(session->analysing());
  }
  session.reset();
  const auto closed = Clock::now();
  while (StabilityJob::analyses_running() > 0 && Clock::now() - closed < std::chrono::seconds(1))
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  EXPECT_EQ(StabilityJob::analyses_running(), 0)
      << "analyses still running a second after their sessions closed";
  StabilityJob::shutdown();
  EXPECT_EQ(StabilityJob::threads_alive(), 0);
  std::printf("  %ld frames, %ld sessions, %ld sweeps\n", frames, sessions, sweeps);
  EXPECT_GT(frames, 20);
}

}  // namespace
}  // namespace springlab::app
