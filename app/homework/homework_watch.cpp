#include "homework/homework_watch.hpp"

#include <algorithm>
#include <chrono>
#include <ctime>

#include "homework/rope_lane.hpp"
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

std::string identified(const char* step, const Identified& found) {
  if (found.method.empty()) return format_text(tr("%s: none of the textbook methods (springlab homework check says why)"), step);
  std::string damping;
  if (found.drag != 0.0) damping = format_text(tr(", drag %.3g N s/m"), found.drag);
  if (found.verlet_damping != 0.0) damping = format_text(tr(", d = %.3g"), found.verlet_damping);
  return format_text("%s: %s%s", step, tr(method_info(*find_method(found.method)).label), damping.c_str());
}

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
  current_ = build(file_);
  status_.file = file_.filename().string();
}

HomeworkWatch::~HomeworkWatch() { worker_.join(); }

void HomeworkWatch::install(Session& session) {
  std::vector<OwnLane> own;
  std::vector<Method> beside;
  const Report& r = current_->report;
  for (const auto& [step, found, label] : {std::tuple{Step::Euler, r.euler, tr("Your simulateEuler")},
                                           std::tuple{Step::Verlet, r.verlet, tr("Your simulateVerlet")}}) {
    auto code = std::make_shared<RopeProcess>(current_->build->runner(), current_->build->folder(), kLaneLimit);
    // The row it was found to be (its theory is the lane's), or, found none, the exercise's own.
    Method like = step == Step::Euler ? Method::SymplecticEuler : Method::Verlet;
    const bool known = !found.method.empty();
    if (known) like = method_info(*find_method(found.method)).id;
    own.push_back({rope_lane_step(code, step), label, like, known});
    beside.push_back(like);
  }
  session.set_own_lanes(own, beside);

  status_.lines.clear();
  status_.lines.push_back(format_text(tr("built and checked in %.1f s: %d checks passed, %d failed"), current_->seconds,
                                      r.passed(), r.failed()));
  status_.lines.push_back(identified("simulateEuler", r.euler));
  status_.lines.push_back(identified("simulateVerlet", r.verlet));
  if (r.passed() == 0 && r.failed() > 0) status_.lines.push_back(tr("the rope is not built right: springlab homework check says how"));
}

void HomeworkWatch::poll(Session& session) {
  // A finished build, good or bad.
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (fresh_) {
      current_ = std::move(fresh_);
      status_.error.clear();
      installed_in_ = 0;  // installed again below
    }
    if (failed_) {
      status_.error = *failed_;
      failed_.reset();
    }
  }
  status_.building = building_;
  // Lanes of one's own in a session new to the watch (the first, a scene opened, a lesson's step)
  // or after a new build, where the scene is one rope that the student's constructor can build;
  // what the class does with the lanes after that (compare other methods) is theirs.
  if (installed_in_ != session.serial()) {
    installed_in_ = session.serial();
    if (is_one_rope(session.scene().model)) install(session);
    else status_.lines = {tr("open a rope scene to see your rope's lanes")};
  }

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
    if (built) fresh_ = std::move(built);
    else failed_ = error;
    building_ = false;
  });
}

}  // namespace springlab::app
