// Checking a lesson's claims by playing it: each step runs headlessly, frame by frame as the app
// and the video show it (the same session, script and frame clock; no drawing), and each claim
// its caption makes is measured on what happened:
//
//   energy-grows     a least-squares fit of ln E against the step count over the window: its
//                    slope is ln of the growth a step (E the lane's total energy, taken before
//                    it diverges); without per_step, E must rise by 5 % of the energy scale
//   energy-decays    the same, falling (without per_step: by more than 5 % of the energy scale)
//   energy-bounded   max |E - E(from)| <= within x the energy scale
//   diverges         the lane diverged or went unstable by `by`; holds: it never did
//   follows-exact    max |x - x_exact| of the watched particle over the window
//   limit            the stated stability limit (stability.hpp) against h
//   steps-adapt      rejected tries over the window > 0, and max h / min h of the internal step
//   momentum-kept    |P(to) - P(from)| / |P(from)|, P = sum m v over free particles
//   drag-slows       |v_cm(to)| / |v_cm(from)| against exp(-k_drag n (t1 - t0) / M): drag -k v
//                    on each of n free particles of total mass M slows their centre so
//   internal-decays  E_int(to) / E_int(from), E_int = kinetic energy about the centre of mass
//                    + spring energy
//   out-of-reach     the target is past the chain's reach and the chain lies straight along
//                    base -> target (its end within 1 % of the reach of that line's point)
//   poses-differ     every lane converged, and every two lanes' joints lie >= min m apart
//                    somewhere
//   orders           the Compare panel's sweep (ui/compare_panel.hpp) on the step's scene: each
//                    fitted order within `within`; best: least error at the largest cost every
//                    method reaches (log-log interpolation)
//   particles        particles alive at `at` against `about`
//   in sight         (never written: every step gets it) each lane that holds to the step's end
//                    keeps half of its free particles or more in the scene camera's 16:9 frame,
//                    the least every lane's view shows (draw/lane_views.hpp), in every frame
#pragma once

#include <string>
#include <vector>

#include "springlab/lesson.hpp"

namespace springlab::app {

struct ClaimResult {
  LessonClaim claim;
  bool passed = false;
  std::string measured;  // "x1.0100 a step (expected x1.0100)"
};

// Plays the step at `fps` and checks every claim. Throws InputError if the step cannot be set up.
std::vector<ClaimResult> check_step(const LessonStep& step, double fps = 60.0);

}  // namespace springlab::app
