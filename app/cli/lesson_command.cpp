// springlab lesson list | check [NAME...]: the shipped lessons in the course's order, and their
// physics claims checked by playing them (lesson/lesson_checks.hpp): what a teacher writing a
// lesson runs, and what the tests run.
#include <cstdio>
#include <memory>

#include "cli/commands.hpp"
#include "lesson/lesson_checks.hpp"
#include "lesson/lesson_library.hpp"
#include "util/text_table.hpp"

namespace springlab::app {

namespace {

struct LessonCli {
  std::vector<std::string> names;
  double fps = 60.0;
};

int list() {
  std::vector<std::vector<std::string>> rows;
  const auto files = shipped_lesson_files();
  for (std::size_t k = 0; k < files.size(); ++k) {
    const Lesson lesson = open_lesson(files[k]);
    char about[64];
    std::snprintf(about, sizeof about, "%zu step%s, %.0f s:", lesson.steps.size(),
                  lesson.steps.size() == 1 ? "" : "s", lesson.duration());
    rows.push_back({(k < 9 ? " " : "") + std::to_string(k + 1), lesson.name, lesson.title,
                    about + std::string(" ") + lesson.summary});
  }
  std::fputs(text_table(rows).c_str(), stdout);
  return kOk;
}

int check(const LessonCli& o) {
  std::vector<std::string> names = o.names;
  if (names.empty()) names = shipped_lesson_files();
  int failed = 0, claims = 0;
  for (const std::string& name : names) {
    const Lesson lesson = open_lesson(name);
    std::printf("lesson %s: %s\n", lesson.name.c_str(), lesson.title.c_str());
    for (std::size_t s = 0; s < lesson.steps.size(); ++s) {
      const LessonStep& step = lesson.steps[s];
      std::printf("  step %zu: %s\n", s + 1, step.title.c_str());
      for (const ClaimResult& r : check_step(step, o.fps)) {
        ++claims;
        failed += !r.passed;
        std::printf("    %s  %s: %s\n", r.passed ? "ok  " : "FAIL", r.claim.describe().c_str(),
                    r.measured.c_str());
      }
      std::fflush(stdout);
    }
  }
  std::printf("%d of %d claims hold\n", claims - failed, claims);
  return failed ? kFailure : kOk;
}

}  // namespace

Command add_lesson_command(CLI::App& app) {
  auto o = std::make_shared<LessonCli>();
  CLI::App* c = app.add_subcommand(
      "lesson", "the guided lessons: list them, or check their claims by playing them");
  c->require_subcommand(1, 1);
  CLI::App* l = c->add_subcommand("list", "the shipped lessons in the course's order");
  CLI::App* k =
      c->add_subcommand("check", "play lessons headlessly and check what their captions claim");
  k->add_option("lessons", o->names,
                "lesson names, numbers or files (default: every shipped lesson)");
  return [o, l, k] { return l->parsed() ? list() : check(*o); };
}

}  // namespace springlab::app
