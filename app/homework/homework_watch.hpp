// `springlab view --homework rope.cpp`: the student's rope in the app. The file is built and
// checked (springlab homework check's checker) and its two steps become lanes of their own,
// "Your simulateEuler" and "Your simulateVerlet", beside springlab's rows, each lane's theory
// (gauge, limit) that of the row the checker found it to be. Saving the file builds it again on
// the worker and, once built and checked, the lanes start over with the new code; a file that no
// longer compiles leaves the last good build running and the panel shows the compiler's error.
#pragma once

#include <atomic>
#include <filesystem>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "homework/own_lanes.hpp"
#include "homework/rope_build.hpp"
#include "session/session.hpp"
#include "springlab/homework.hpp"
#include "ui/homework_status.hpp"
#include "util/worker.hpp"

namespace springlab::app {

class HomeworkWatch {
 public:
  // Builds and checks `file` now: InputError when it does not compile.
  explicit HomeworkWatch(std::filesystem::path file);
  ~HomeworkWatch();

  // Every frame: lanes installed in a session that has none of them yet (a new scene opened),
  // a saved file built on the worker, a finished build's lanes installed.
  void poll(Session& session);
  const ui::HomeworkStatus& status() const { return status_; }

 private:
  struct Built;  // a build, checked
  static std::unique_ptr<Built> build(const std::filesystem::path& file);
  void use(std::unique_ptr<Built> built);

  std::filesystem::path file_;
  std::filesystem::file_time_type seen_{};
  std::unique_ptr<Built> current_;
  HomeworkLanes lanes_;
  ui::HomeworkStatus status_;

  Worker worker_;
  std::mutex mutex_;
  std::unique_ptr<Built> fresh_;       // a finished build, waiting to be installed
  std::optional<std::string> failed_;  // or a finished build's error
  std::atomic<bool> building_{false};
  std::chrono::steady_clock::time_point next_look_{};
};

}  // namespace springlab::app
