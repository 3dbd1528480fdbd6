#include "homework/homework_watch.hpp"

#include <algorithm>
#include <chrono>
#include <ctime>

#include "homework/rope_process.hpp"
#include "springlab/error.hpp"
#include "springlab/text.hpp"

namespace springlab::app {

using namespace homework;

struct HomeworkWatch::Built {
  std::unique_ptr<RopeBuild> build;
  Report report;
  double seconds = 0.0;
};

namespace {

// A call of the student's code in the app: short, so that an endless loop stops one lane, not
// the frame loop, for long.
constexpr std::chrono::milliseconds kLaneLimit{500};

}  // namespace

std::unique_ptr<HomeworkWatch::Built> HomeworkWatch::build(const std::filesystem::path& file) {
  const auto start = std::chrono::steady_clock::now();
  auto built = std::make_unique<Built>();
  built->build = std::make_unique<RopeBuild>(file);
  RopeProcess checking(built->build->runner(), built->build->folder());
  built->report = check_rope(checking);
  built->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return built;
}

HomeworkWatch::HomeworkWatch(std::filesystem::path file) : file_(std::move(file)) {
  std::error_code ec;
  seen_ = std::filesystem::last_write_time(file_, ec);
  use(build(file_));
  status_.file = file_.filename().string();
}

HomeworkWatch::~HomeworkWatch() {
  worker_.join();
}

void HomeworkWatch::use(std::unique_ptr<Built> built) {
  current_ = std::move(built);
  const std::filesystem::path runner = current_->build->runner(),
                              folder = current_->build->folder();
  lanes_.set(current_->report, current_->seconds, [runner, folder] {
    return std::make_shared<RopeProcess>(runner, folder, kLaneLimit);
  });
}

void HomeworkWatch::poll(Session& session) {
  // A finished build, good or bad.
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (fresh_) {
      use(std::move(fresh_));
      status_.error.clear();
    }
    if (failed_) {
      status_.error = *failed_;
      failed_.reset();
    }
  }
  status_.building = building_;
  // Lanes of one's own in a session new to them (the first, a scene opened, a lesson's step) or
  // after a new build.
  lanes_.poll(session, status_);

  // The file saved since the last look (twice a second): built and checked on the worker.
  const auto now = std::chrono::steady_clock::now();
  if (building_ || now < next_look_) return;
  next_look_ = now + std::chrono::milliseconds(500);
  std::error_code ec;
  const auto written = std::filesystem::last_write_time(file_, ec);
  if (ec || written == seen_) return;
  seen_ = written;
  building_ = true;
  status_.building = true;
  worker_.start([this] {
    std::unique_ptr<Built> built;
    std::optional<std::string> error;
    try {
      built = build(file_);
    } catch (const std::exception& e) {
      error = e.what();
    }
    std::lock_guard<std::mutex> lock(mutex_);
    if (built)
      fresh_ = std::move(built);
    else
      failed_ = error;
    building_ = false;
  });
}

}  // namespace springlab::app
