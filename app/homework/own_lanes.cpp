#include "homework/own_lanes.hpp"

#include <tuple>

#include "homework/rope_lane.hpp"
#include "springlab/text.hpp"

namespace springlab::app {

using namespace homework;

namespace {

std::string identified(const char* step, const Identified& found) {
  if (found.method.empty()) return format_text(tr("%s: none of the textbook methods (the checker's report says why)"), step);
  std::string damping;
  if (found.drag != 0.0) damping = format_text(tr(", drag %.3g N s/m"), found.drag);
  if (found.verlet_damping != 0.0) damping = format_text(tr(", d = %.3g"), found.verlet_damping);
  return format_text("%s: %s%s", step, tr(method_info(*find_method(found.method)).label), damping.c_str());
}

}  // namespace

void HomeworkLanes::set(Report report, double seconds, MakeCode make) {
  report_ = std::move(report);
  seconds_ = seconds;
  make_ = std::move(make);
  installed_in_ = 0;  // installed again at the next poll
}

void HomeworkLanes::poll(Session& session, ui::HomeworkStatus& status) {
  if (!make_ || installed_in_ == session.serial()) return;
  installed_in_ = session.serial();
  if (is_one_rope(session.scene().model)) install(session, status);
  else status.lines = {tr("open a rope scene to see your rope's lanes")};
}

void HomeworkLanes::install(Session& session, ui::HomeworkStatus& status) {
  std::vector<OwnLane> own;
  std::vector<Method> beside;
  const Report& r = report_;
  for (const auto& [step, found, label] : {std::tuple{Step::Euler, r.euler, tr("Your simulateEuler")},
                                           std::tuple{Step::Verlet, r.verlet, tr("Your simulateVerlet")}}) {
    // The row it was found to be (its theory is the lane's), or, found none, the exercise's own.
    Method like = step == Step::Euler ? Method::SymplecticEuler : Method::Verlet;
    const bool known = !found.method.empty();
    if (known) like = method_info(*find_method(found.method)).id;
    own.push_back({rope_lane_step(make_(), step), label, like, known});
    beside.push_back(like);
  }
  session.set_own_lanes(own, beside);

  status.lines.clear();
  status.lines.push_back(format_text(tr("built and checked in %.1f s: %d checks passed, %d failed"), seconds_,
                                     r.passed(), r.failed()));
  status.lines.push_back(identified("simulateEuler", r.euler));
  status.lines.push_back(identified("simulateVerlet", r.verlet));
  if (r.passed() == 0 && r.failed() > 0) status.lines.push_back(tr("the rope is not built right: the checker's report says how"));
}

}  // namespace springlab::app
