// A student's step (simulateEuler or simulateVerlet, wherever it runs: a child process on the
// desktop, RopeProcess; the page's JavaScript in the browser, web/js_rope) as the step of an app
// lane (Session::set_own_lanes): the lane's rope is built with the student's own constructor (or
// springlab's, homework::exercise_rope, where the code brings only the steps), from the model
// (nodes, node mass, k, the pins), again whenever a slider changes those (springlab's rope, through
// the code's Rope(masses, springs), where the checker found the constructor wrong:
// `springlab_rope`); its state goes to the code when it is not what the code last made (a reset, a
// drag), and each step comes back. Verlet's last position travels as the velocity (x - x_last) / h.
// A crash, an exception or a call past its limit becomes the lane's divergence (a StepFailure with
// what happened): the lane stops, marked, and the app goes on.
#pragma once

#include <memory>

#include "springlab/homework.hpp"

namespace springlab::app {

homework::OwnStep rope_lane_step(std::shared_ptr<homework::RopeCode> code, homework::Step step,
                                 bool springlab_rope = false);

// Whether the model is one rope the exercise's constructor can build: n masses of one mass, n - 1
// springs joining neighbours, of one k and one rest length.
bool is_one_rope(const Model& model);

}  // namespace springlab::app
