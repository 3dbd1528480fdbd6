// The student's two steps as lanes of the session shown, on every platform: the checker's report
// says which row each step is (its lane then has that row's theory: gauge, limit), and the lanes
// go into each session the app shows that is one rope (a scene opened, a lesson's step), made
// afresh from `make_code` (a RopeCode of its own for each lane: a rope runner on the desktop,
// the page's JavaScript in the browser). What the class does with the lanes after that (compare
// other methods) is theirs.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>

#include "session/session.hpp"
#include "springlab/homework.hpp"
#include "ui/homework_status.hpp"

namespace springlab::app {

class HomeworkLanes {
 public:
  using MakeCode = std::function<std::shared_ptr<homework::RopeCode>()>;

  // A new build, checked in `seconds`: its lanes replace the last at the next poll.
  void set(homework::Report report, double seconds, MakeCode make);
  bool has_code() const { return static_cast<bool>(make_); }
  const homework::Report& report() const { return report_; }

  // Every frame: the lanes into a session new to them; `status.lines` says what was found.
  void poll(Session& session, ui::HomeworkStatus& status);

 private:
  void install(Session& session, ui::HomeworkStatus& status);

  homework::Report report_;
  double seconds_ = 0.0;
  MakeCode make_;
  std::uint64_t installed_in_ = 0;  // the serial of the session given the lanes (0: none)
};

}  // namespace springlab::app
