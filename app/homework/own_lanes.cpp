#include "homework/own_lanes.hpp"

#include <tuple>

#include "homework/rope_lane.hpp"
#include "springlab/text.hpp"

namespace springlab::app {

using namespace homework;

namespace {

std::string identified(const char* step, const Identified& found) {
  if (found.constraints)
    return format_text(tr("%s: position Verlet with its springs held as constraints"), step);
  if (found.method.empty())
    return format_text(tr("%s: none of the textbook methods (the checker's report says why)"),
                       step);
  return format_text(
      "%s: %s, %s", step, tr(method_info(*find_method(found.method)).label),
      damping_text(found.damping, step == std::string("simulateEuler") ? Step::Euler : Step::Verlet)
          .c_str());
}

// The row beside a lane of one's own, with the student's damping: an Euler row takes the drag and
// the spring damping (along the spring, springlab's only form), a Verlet row the factor d. A drag
// written as a factor a step is the drag it is at the session's step h.
BesideRow beside_row(Method like, Step step, const Identified& found, double node_mass, double h) {
  BesideRow row;
  row.method = like;
  const Damping d = found.damping.at_step(h);
  row.drag = step == Step::Euler ? d.drag_on(node_mass) : 0.0;
  row.kd = step == Step::Euler ? d.along + d.relative : 0.0;
  row.verlet_damping = step == Step::Verlet ? d.verlet : 0.0;
  return row;
}

std::string row_words(const BesideRow& row) {
  return format_text(tr("beside it springlab's %s with drag %s N s/m, k_d %s N s/m, d = %s"),
                     method_info(row.method).name, format_text("%.3g", *row.drag).c_str(),
                     format_text("%.3g", *row.kd).c_str(),
                     format_text("%.3g", *row.verlet_damping).c_str());
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
  if (is_one_rope(session.scene().model))
    install(session, status);
  else
    status.lines = {tr("open a rope scene to see your rope's lanes")};
}

void HomeworkLanes::install(Session& session, ui::HomeworkStatus& status) {
  std::vector<OwnLane> own;
  std::vector<BesideRow> beside;
  const Report& r = report_;
  status.lines.clear();
  status.lines.push_back(format_text(tr("built and checked in %.1f s: %d checks passed, %d failed"),
                                     seconds_, r.passed(), r.failed()));
  for (const auto& [step, found, label] :
       {std::tuple{Step::Euler, r.euler, tr("Your simulateEuler")},
        std::tuple{Step::Verlet, r.verlet, tr("Your simulateVerlet")}}) {
    // The row it was found to be (its theory is the lane's), or, found none, the exercise's own.
    Method like = step == Step::Euler ? Method::SymplecticEuler : Method::Verlet;
    const bool known = !found.method.empty();
    if (known) like = method_info(*find_method(found.method)).id;
    own.push_back({rope_lane_step(make_(), step, r.springlab_rope), label, like, known});
    const Model& model = session.scene().model;
    const double h = session.primary().sim.h();
    beside.push_back(beside_row(like, step, found, model.mass.empty() ? 0.0 : model.mass[0], h));
    status.lines.push_back(identified(step_name(step), found));
    status.lines.push_back("  " + row_words(beside.back()));
    if (step == Step::Euler && found.damping.relative != 0.0)
      status.lines.push_back(
          tr("  (its k_d is your damping along the relative velocity, run along the spring: yours "
             "also damps the rope's bending, the row's does not)"));
    if (step == Step::Euler && found.damping.drag_step != 0.0)
      status.lines.push_back(format_text(
          tr("  (your damping is a factor a step, d = %s: the row's drag is its rate at h = %s, "
             "d m / h; at another h yours damps more or less a second, the row's the same)"),
          format_text("%.3g", found.damping.drag_step).c_str(), step_text(h).c_str()));
    if (step == Step::Verlet && found.damping.verlet_whole)
      status.lines.push_back(
          tr("  (the row takes d on (x - x_last); yours takes it on the whole displacement, a "
             "difference of d a h^2 a step)"));
  }
  session.set_own_lanes(own, beside);
  if (r.constructor_wrong)
    status.lines.push_back(
        tr("your constructor is not right yet (the checker's report says how): your steps run on "
           "springlab's rope"));
}

}  // namespace springlab::app
