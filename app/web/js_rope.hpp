// The student's JavaScript steps (the page's homework panel, app/web/homework.js) as the
// homework checker's RopeCode, for the checker and for the app's lanes (homework/own_lanes):
// the rope is springlab's (homework::exercise_rope), held by the page; each call of the steps
// runs there, guarded by a time limit, and an exception, a call past its time or a rope left
// wrong comes back as a CodeFailure saying what happened and at which step.
#pragma once

#include "springlab/homework.hpp"

namespace springlab::app::web {

class JsRope : public homework::RopeCode {
 public:
  /// A run of n steps may take `limit_ms` + n `per_step_ms`.
  JsRope(double limit_ms, double per_step_ms);
  ~JsRope() override;
  JsRope(const JsRope&) = delete;
  JsRope& operator=(const JsRope&) = delete;

  homework::BuiltRope build(const homework::RopeRequest& request) override;
  void set_state(const homework::RopeState& state) override;
  std::vector<homework::RopeState> simulate(homework::Step step, double dt,
                                            const homework::Vec2& gravity, int steps) override;
  bool own_constructor() const override { return false; }

 private:
  int id_;
  int masses_ = 0;
  double limit_ms_, per_step_ms_;
};

/// Whether the page's code compiled (springlabHomework.compile), so that its steps can run.
bool js_code_ready();

}  // namespace springlab::app::web
