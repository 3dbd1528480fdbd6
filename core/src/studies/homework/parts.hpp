// The homework checker's parts (springlab/homework.hpp), a file each:
//   report.cpp        numbers and vectors as the report writes them; the report as text and JSON
//   reference.cpp     the rope as a springlab Model, one step of springlab's rows from any state
//   the
//                     code made (with every damping form), the forces a step implies, the floors
//   construction.cpp  the constructor checked, and what is wrong with it named
//   bench.cpp         the ropes the probes use, built by the code (or springlab) and checked in
//   shape probes.cpp        the usual mistakes, each shown by a probe built for it damping.cpp the
//   damping fitted from probes, each form apart identify.cpp      which row a step is, and the
//   named mistakes that explain a step that is none spring_checks.cpp order, stability and energy
//   on a spring check.cpp         the whole report, in order step_check.cpp    a whole step of (x,
//   v) (Python's), checked the same way
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "springlab/homework.hpp"
#include "springlab/methods.hpp"
#include "springlab/model.hpp"
#include "springlab/text.hpp"

namespace springlab::homework {

/// The float the exercise's step receives: every step is rounded to it before use, so that the
/// code and the references step by the same h.
inline double as_float(double h) {
  return static_cast<double>(static_cast<float>(h));
}
/// Float's unit roundoff, 2^-24: a float holds a number to this fraction of itself.
inline constexpr double kFloatRounding = 0x1p-24;

// --- Words (report.cpp) ---------------------------------------------------------------------
/// A number to 4 significant digits, a vector "(x, y)".
std::string num(double value);
std::string vec(const Vec2& v);
/// Two vectors that differ, each with as many digits as it takes to tell them apart.
std::pair<std::string, std::string> apart(const Vec2& a, const Vec2& b);

inline void pass(CheckSection& s, const char* key, std::string text) {
  s.lines.push_back({CheckLine::Pass, std::move(text), key});
}
inline void fail(CheckSection& s, const char* key, std::string text) {
  s.lines.push_back({CheckLine::Fail, std::move(text), key});
}
inline void note(CheckSection& s, const char* key, std::string text) {
  s.lines.push_back({CheckLine::Note, std::move(text), key});
}
bool any_failed(const CheckSection& s);

// --- References (reference.cpp) -------------------------------------------------------------
/// The rope as asked, in springlab's terms (springs of the spacing's rest length, k, the pins),
/// with gravity and the damping springlab's model has (drag, damping along the springs, Verlet's
/// d).
Model rope_model(const RopeRequest& request, const Vec2& gravity, const Damping& damping = {});
/// The rope as the code built it (its masses, its springs' k and rest lengths, its pins).
Model built_model(const BuiltRope& rope, const Vec2& gravity, const Damping& damping = {});

/// One step of a springlab row from a state the code made: x, v (Euler rows) or x, x_last
/// (rows with a history, Verlet, whose workspace is given x_last as its previous positions), with
/// the damping forms springlab's model lacks added: damping along the relative velocity (as a
/// force held over the step: exact for the rows that evaluate the force once, at the start) and
/// Verlet's factor on the whole displacement (x1 less d h^2 a).
RopeState reference_step(Method method, const Model& model, const Damping& damping,
                         const RopeState& state, double h);
/// The same from springlab's own State (x, v), with a fresh workspace: Verlet then starts from
/// the velocity, which makes it velocity Verlet (verlet.cpp's start).
State reference_step(Method method, const Model& model, const State& state, double h);

/// The rows a step can be: the explicit fixed-step rows of springlab's table that step (x, v)
/// (for simulateEuler and Python's step), or those that keep the previous positions (Verlet).
std::vector<Method> candidate_rows(bool history);

/// The largest difference between `after` (the code's) and `reference`, in units of the step's
/// own motion: max |x - x_ref| / max |x - x_before|, and the same for velocities where asked.
double step_deviation(const RopeState& before, const RopeState& after, const RopeState& reference,
                      bool velocities);
/// The same difference that float's rounding of the forces a step sums can make (2^-24 of each
/// mass's spring forces k l, weight m |g| and damping, 8 roundings' worth), in the same units:
/// work done in float matches to this, work in double to 1e-8.
/// `stored_in_float`: the positions and velocities themselves are kept in float (NumPy's float32).
double float_floor(const Model& model, const Damping& damping, const RopeState& before,
                   const RopeState& after, double h, bool velocities, bool stored_in_float = false);

/// The force on each mass that a step from `before` to `after` implies: m (v1 - v0) / h for
/// Euler, m (x1 - x - (1 - d)(x - x_last)) / h^p for Verlet (p = 2, or `h_power` where the code
/// was found to scale its acceleration by another power of the step).
std::vector<Vec2> implied_forces(Step step, const std::vector<double>& masses,
                                 const RopeState& before, const RopeState& after, double h,
                                 double verlet_damping, int h_power = 2);

/// The accelerations of the springs and gravity alone (no damping) at a state's positions.
std::vector<Vec2> undamped_accelerations(const Model& model, const RopeState& s);
/// Each mass's force from the damping forms springlab's model lacks (along the relative velocity).
std::vector<Vec2> relative_damping_forces(const Model& model, const RopeState& s, double relative);
/// Each mass's force from every damping form but Verlet's: drag, along the springs, relative.
std::vector<Vec2> damping_forces(const Model& model, const RopeState& s, const Damping& damping);

// --- The ropes the checks use (bench.cpp) ---------------------------------------------------
/// The rope the steps are identified on: 16 masses of 0.25 kg, 0.5 m apart, k = 64 N/m, pinned at
/// one end (every figure exact in float, so the code and springlab see the same numbers).
inline RopeRequest checked_rope() {
  return {Vec2(0, 0), Vec2(7.5, 0), 16, 0.25, 64.0, {0}};
}
/// A second, slanted and pinned at both ends, for the constructor only.
inline RopeRequest slanted_rope() {
  return {Vec2(1, 2), Vec2(-3, -1), 5, 0.5, 100.0, {0, 4}};
}
/// Three masses 0.5 m apart, free or pinned at one end (the probes of the usual mistakes).
inline RopeRequest three_masses(std::vector<int> pinned) {
  return {Vec2(0, 0), Vec2(1, 0), 3, 0.25, 64.0, std::move(pinned)};
}
/// The same three masses, free, four times heavier (a drag written as an acceleration, -c v, is
/// four times the force on them; a drag written as a force, -c v, the same).
inline RopeRequest three_heavy_masses() {
  return {Vec2(0, 0), Vec2(1, 0), 3, 1.0, 64.0, {}};
}
/// One free spring of 1 m (the constraint probe).
inline RopeRequest pair_rope() {
  return {Vec2(0, 0), Vec2(1, 0), 2, 0.25, 64.0, {}};
}
/// The spring the steps are measured on (spring_checks.cpp): a mass of 1 kg hanging from a pin by a
/// spring of 64 N/m and rest length 1 m under g = 8 m/s^2, let go at rest from the rest length.
inline constexpr double kSpringMass = 1.0, kSpringK = 64.0, kSpringG = 8.0, kSpringRest = 1.0;
inline RopeRequest hanging_spring() {
  return {Vec2(0, 0), Vec2(0, -kSpringRest), 2, kSpringMass, kSpringK, {0}};
}
/// Every rope the checks build, the constructor checks each.
std::vector<RopeRequest> every_rope();

/// The gravity the identification's rope falls under, m/s^2, and its step, s.
inline const Vec2 kCheckGravity(0.0, -8.0);
inline constexpr double kCheckStep = 1.0 / 1024;
inline constexpr int kCheckSteps = 64;
/// The probes' step, s, and each mass, kg (probes.cpp, damping.cpp).
inline constexpr double kProbeH = 1.0 / 1024, kProbeMass = 0.25;
/// A match to springlab's row in double: within this fraction of a step's motion (rounding is
/// 1e-10 here).
inline constexpr double kMatch = 1e-8;

/// The code, and which constructor its ropes come from: its own, or, once that was found wrong,
/// springlab's (RopeCode::build_exercise). Every rope is checked in shape (its masses' count, its
/// springs' ends) before a probe reads it, so that nothing the code builds can make the checker
/// read past a rope: a rope of another shape than its request ends the step's checks, said.
struct Bench {
  RopeCode& code;
  bool springlab_rope = false;
  /// Verlet: the power of h the code's acceleration moves a mass by (2; 1 for a h).
  int h_power = 2;
  BuiltRope build(const RopeRequest& request) const;
  /// set_state, then simulate: the states after each step, each checked to hold every mass.
  std::vector<RopeState> run(const RopeState& from, Step step, double h, const Vec2& gravity,
                             int steps) const;
};

/// A state at rest at the rope's positions (x_last = x, v = 0, no forces).
RopeState at_rest(const BuiltRope& rope);

// --- The constructor (construction.cpp) -----------------------------------------------------
/// Checks the code's constructor on every rope the checks use, a line each for the two shown
/// ropes and a line for anything wrong with the others; names what is wrong. Returns whether
/// every rope was built right. A CodeFailure (a crash, an exception) is told here, with what it
/// says of the pins where a rope without pins builds.
bool check_construction(RopeCode& code, CheckSection& section);

// --- The steps' probes (probes.cpp, damping.cpp) --------------------------------------------
/// What the probes found, for the identification and the spring's checks.
struct Probed {
  Damping damping;
  bool constraints = false;  ///< Verlet holding its springs as constraints
  bool silent = false;       ///< the step moves nothing: nothing else is checked
};

/// Whether a step moves anything at all (the skeleton's steps do not): fails "not-written" if not.
bool probe_moves(const Bench& bench, Step step, CheckSection& section);
/// The damping, fitted from one step of masses in three motions (together; the middle one across
/// its springs; along them): each form apart, each named with its coefficient; a negative one, or
/// one applied once a spring, is a mistake.
Damping probe_damping(const Bench& bench, Step step, CheckSection& section);
/// Verlet: whether a spring stretched by 25 % is pulled back by its force (by h^2 k s / m, four
/// times less at h / 2) or held as a constraint (the same fraction at any step), and the power of
/// h the code moves masses by (set in bench.h_power; a h instead of a h^2 is named).
bool probe_verlet_kind(Bench& bench, CheckSection& section);
/// The spring forces (Hooke's law and its misreadings), whether they are cleared between steps,
/// gravity (and its misreadings), the pins, and Verlet's last_position.
void probe_forces(const Bench& bench, Step step, const Damping& damping, CheckSection& section);
/// For a step that holds its springs as constraints: gravity, the pins, last_position.
void probe_constraint_step(const Bench& bench, const Damping& damping, CheckSection& section);

// --- Which row (identify.cpp) ---------------------------------------------------------------
/// Which row a step is: the code run from its own rope on the checked rope, each step compared
/// with springlab's rows from the code's state, with the damping the probes found (and without).
/// `judged`: whether a miss is the step's own failing (the probes found nothing wrong) or only
/// a note (the probes above named what is wrong with the forces). A miss explained by a named
/// mistake (the acceleration applied twice, the position stepped from last_position) says it.
Identified identify(const Bench& bench, Step step, const Damping& damping, bool judged,
                    CheckSection& section);

// --- On a spring (spring_checks.cpp) --------------------------------------------------------
/// The hanging mass's y after each step (y_0 first), and its velocity where the code keeps one.
struct Swing {
  std::vector<double> y, v;
  bool has_velocity = true;
};
/// Runs the code on the spring for `steps` steps of h; `y_before` is the exact y(-h), for a code
/// that starts from a last position (Verlet) rather than a velocity.
using SwingRunner = std::function<Swing(double h, int steps, double y_before)>;

/// The rope code's own 2-mass rope as the spring.
Swing rope_swing(const Bench& bench, Step step, double h, int steps, double y_before);

/// Order, stability and energy on the spring, for the row the step was found to be.
void check_on_a_spring(const SwingRunner& run, const Identified& found, CheckSection& section);

}  // namespace springlab::homework
