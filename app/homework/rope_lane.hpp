// A student's step (simulateEuler or simulateVerlet, run by its rope runner: RopeProcess) as the
// step of an app lane (Session::set_own_lanes): the lane's rope is built with the student's own
// constructor, from the model (nodes, node mass, k, the pins), again whenever a slider changes
// those; its state goes to the runner when it is not what the runner last made (a reset, a drag),
// and each step comes back. Verlet's last position travels as the velocity (x - x_last) / h.
// A crash, an exception or a call past its limit becomes the lane's divergence (a StepFailure with
// what happened): the lane stops, marked, and the app goes on.
#pragma once

#include <memory>

#include "homework/rope_process.hpp"
#include "springlab/homework.hpp"

namespace springlab::app {

homework::OwnStep rope_lane_step(std::shared_ptr<RopeProcess> code, homework::Step step);

// Whether the model is one rope the exercise's constructor can build: n masses of one mass, n - 1
// springs joining neighbours, of one k and one rest length.
bool is_one_rope(const Model& model);

}  // namespace springlab::app
