// The homework checker's parts (springlab/homework.hpp): the reference model and steps, the
// probes of the usual mistakes and the spring's measurements, each a file.
#pragma once

#include <string>

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

/// The largest difference between `after` (the code's) and `reference`, in units of the step's
/// own motion: max |x - x_ref| / max |x - x_before|, and the same for velocities where asked.
double step_deviation(const RopeState& before, const RopeState& after, const RopeState& reference, bool velocities);

/// The force on each mass that a step from `before` to `after` implies: m (v1 - v0) / h for
/// Euler (whose probes start with v0 = 0 or measure drag), m (x1 - x - (1 - d)(x - x_last)) / h^2
/// for Verlet.
std::vector<Vec2> implied_forces(Step step, const std::vector<double>& masses,
                                 const RopeState& before, const RopeState& after, double h, double verlet_damping);

/// Which row a step is: the code run from its own rope on `request`, each step compared with
/// springlab's rows from the code's state, the damping fitted first.
Identified identify(RopeCode& code, Step step, const RopeRequest& request, CheckSection& section);

/// The usual mistakes, one probe each (probes.cpp).
void probe_mistakes(RopeCode& code, Step step, const Identified& found, CheckSection& section);

/// Order, stability and energy on a spring, for the row the step was found to be (spring_checks.cpp).
void check_on_a_spring(RopeCode& code, Step step, const Identified& found, CheckSection& section);

inline void pass(CheckSection& s, std::string text) { s.lines.push_back({CheckLine::Pass, std::move(text)}); }
inline void fail(CheckSection& s, std::string text) { s.lines.push_back({CheckLine::Fail, std::move(text)}); }
inline void note(CheckSection& s, std::string text) { s.lines.push_back({CheckLine::Note, std::move(text)}); }

}  // namespace springlab::homework
