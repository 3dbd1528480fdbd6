// The homework checker's parts (springlab/homework.hpp): the reference model and steps, the
// probes of the usual mistakes and the spring's measurements, each a file.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "springlab/homework.hpp"
#include "springlab/methods.hpp"
#include "springlab/model.hpp"

namespace springlab::homework {

/// The float the exercise's step receives: every step is rounded to it before use, so that the
/// code and the references step by the same h.
inline double as_float(double h) { return static_cast<double>(static_cast<float>(h)); }

/// Text: a number to 4 significant digits, a vector "(x, y)".
std::string num(double value);
std::string vec(const Vec2& v);


/// The rope as asked, in springlab's terms (springs of the spacing's rest length, k, the pins),
/// with gravity and the damping fitted to the code.
Model rope_model(const RopeRequest& request, const Vec2& gravity, double drag = 0.0, double verlet_damping = 0.0);

/// One step of a springlab row from a state the code made: x, v (Euler rows) or x, x_last
/// (Verlet, whose workspace is given x_last as its previous positions).
RopeState reference_step(Method method, const Model& model, const RopeState& state, double h);
/// The same from springlab's own State (x, v), with a fresh workspace: Verlet then starts from
/// the velocity, which makes it velocity Verlet (verlet.cpp's start).
State reference_step(Method method, const Model& model, const State& state, double h);

/// The largest difference between `after` (the code's) and `reference`, in units of the step's
/// own motion: max |x - x_ref| / max |x - x_before|, and the same for velocities where asked.
double step_deviation(const RopeState& before, const RopeState& after, const RopeState& reference, bool velocities);

/// The force on each mass that a step from `before` to `after` implies: m (v1 - v0) / h for
/// Euler (whose probes start with v0 = 0 or measure drag), m (x1 - x - (1 - d)(x - x_last)) / h^2
/// for Verlet.
std::vector<Vec2> implied_forces(Step step, const std::vector<double>& masses,
                                 const RopeState& before, const RopeState& after, double h, double verlet_damping);

/// The rope the steps are measured on: 16 masses of 0.25 kg, 0.5 m apart, k = 64 N/m, pinned at
/// one end (every figure exact in float, so the code and springlab see the same numbers).
inline RopeRequest checked_rope() { return {Vec2(0, 0), Vec2(7.5, 0), 16, 0.25, 64.0, {0}}; }
/// The gravity it falls under, m/s^2, and the step of the identification, s.
inline const Vec2 kCheckGravity(0.0, -8.0);
inline constexpr double kCheckStep = 1.0 / 1024;
inline constexpr int kCheckSteps = 64;
/// A match to springlab's row: within this fraction of a step's motion (rounding is 1e-10 here;
/// forces computed in float reach 1e-7).
inline constexpr double kMatch = 1e-6;

/// Which row a step is: the code run from its own rope on `request`, each step compared with
/// springlab's rows from the code's state, the damping fitted first.
Identified identify(RopeCode& code, Step step, const RopeRequest& request, CheckSection& section);

/// The usual mistakes, one probe each (probes.cpp).
void probe_mistakes(RopeCode& code, Step step, const Identified& found, CheckSection& section);

/// Whether simulateVerlet holds its springs as constraints, moving the masses (position-based, as
/// CS 184's rope and the exercise's "(solving constraints)" have it) rather than by their force:
/// what a step does to a spring stretched by 25 %, or nullopt for a force's pull.
std::optional<std::string> constraint_probe(RopeCode& code);
/// The probes that still mean something then: the damping, last_position and the pin.
void probe_constraint_mistakes(RopeCode& code, CheckSection& section);

/// The spring the steps are measured on (spring_checks.cpp): a mass of 1 kg hanging from a pin by
/// a spring of 64 N/m and rest length 1 m under g = 8 m/s^2, let go at rest from the rest length.
inline constexpr double kSpringMass = 1.0, kSpringK = 64.0, kSpringG = 8.0, kSpringRest = 1.0;

/// The hanging mass's y after each step (y_0 first), and its velocity where the code keeps one.
struct Swing {
  std::vector<double> y, v;
  bool has_velocity = true;
};
/// Runs the code on the spring for `steps` steps of h; `y_before` is the exact y(-h), for a code
/// that starts from a last position (Verlet) rather than a velocity.
using SwingRunner = std::function<Swing(double h, int steps, double y_before)>;

/// The rope code's own 2-mass rope as the spring.
Swing rope_swing(RopeCode& code, Step step, double h, int steps, double y_before);

/// Order, stability and energy on the spring, for the row the step was found to be.
void check_on_a_spring(const SwingRunner& run, const Identified& found, CheckSection& section);

inline void pass(CheckSection& s, std::string text) { s.lines.push_back({CheckLine::Pass, std::move(text)}); }
inline void fail(CheckSection& s, std::string text) { s.lines.push_back({CheckLine::Fail, std::move(text)}); }
inline void note(CheckSection& s, std::string text) { s.lines.push_back({CheckLine::Note, std::move(text)}); }

}  // namespace springlab::homework
