// Homework 8, checked: the rope exercise's code (its constructor, simulateEuler, simulateVerlet)
// measured against springlab's own methods on the same rope, wherever that code runs (a child
// process for C++: app/homework/; Python and the browser give their own RopeCode).
//
// The checker never trusts the code's account of itself: it builds ropes through the code's
// constructor, sets states, calls the steps and reads the masses back, then says
//   - whether the rope is built as asked (spacing, masses, springs, rest lengths, pins);
//   - which textbook method each step is: one step at a time from the code's own states, against
//     springlab's explicit Euler, symplectic (semi-implicit) Euler and Verlet rows, with the
//     code's global damping fitted (a drag -c v for Euler, a factor d for Verlet), to rounding;
//   - its order measured on a spring against the exact solution, its stability by runs either
//     side of the limit springlab states for that method, and its energy's rate a step against
//     the rate the method's amplification matrix predicts;
//   - the usual mistakes, each from a probe built to show it (a spring stretched one way and
//     squeezed the other, a rope at rest under gravity, a rope in uniform motion).
// docs/homework.md explains each check and its tolerances.
#pragma once

#include <Eigen/Core>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "springlab/methods.hpp"

namespace springlab::homework {

using Vec2 = Eigen::Vector2d;

/// A mass as the exercise keeps it: position, last_position (Verlet), velocity (Euler) and the
/// forces it has gathered.
struct MassState {
  Vec2 x = Vec2::Zero(), x_last = Vec2::Zero(), v = Vec2::Zero(), f = Vec2::Zero();
};
using RopeState = std::vector<MassState>;

struct BuiltMass {
  Vec2 start = Vec2::Zero();  ///< start_position
  bool pinned = false;
  double mass = 0.0;
  MassState state;
};
/// A spring as built: the indices of its masses in the rope's list (kNotInRope: a mass the rope
/// does not hold; kNoMass: a null pointer).
struct BuiltSpring {
  static constexpr int kNotInRope = -1, kNoMass = -2;
  int m1 = kNotInRope, m2 = kNotInRope;
  double k = 0.0, rest = 0.0;
};
struct BuiltRope {
  std::vector<BuiltMass> masses;
  std::vector<BuiltSpring> springs;
};

/// The constructor's arguments: Rope(start, end, num_nodes, node_mass, k, pinned_nodes).
struct RopeRequest {
  Vec2 start = Vec2::Zero(), end = Vec2::Zero();
  int nodes = 0;
  double node_mass = 0.0, k = 0.0;
  std::vector<int> pinned;
};

enum class Step { Euler, Verlet };  ///< simulateEuler, simulateVerlet
const char* step_name(Step step);
/// A step as the report writes it: "1/1024 s" where 1/h is a whole number, else "0.2249 s".
std::string step_text(double h);

/// The code could not do what it was asked: it crashed, threw, ran past its time or answered
/// nonsense. The message says what happened and when, in a sentence.
struct CodeFailure : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// A CodeFailure's words, the same wherever the code runs (a child process, the browser), in the
/// current language: the call, "simulateEuler (step 3 of 128, h = 1/128 s)", then what it did.
std::string call_text(Step step, int step_number, int steps, double h);
std::string threw_text(const std::string& call, const std::string& what);
std::string timed_out_text(const std::string& call, double seconds);
/// `how` it ended ("was killed by signal 11 (...)"); empty: it ended the program itself.
std::string ended_text(const std::string& call, const std::string& how);
/// "; it printed: ..." after any of them, where the code printed something.
std::string printed_text(const std::string& printed);
/// What a check of the C++ standard library (the checker builds with _GLIBCXX_ASSERTIONS) that
/// stopped the code says, in a sentence: "read or wrote a std::vector at an index not below its
/// size() ..." for libstdc++'s "Assertion '__n < this->size()' failed"; "" where `printed` holds
/// none.
std::string library_check_text(const std::string& printed);

/// The student's code, wherever it runs. Every call may throw CodeFailure.
class RopeCode {
 public:
  virtual ~RopeCode() = default;
  /// Builds a new rope with the code's constructor (the one later calls act on).
  virtual BuiltRope build(const RopeRequest& request) = 0;
  /// Builds springlab's rope as the exercise states it (exercise_rope) for the code's steps to act
  /// on: the C++ runner makes it through the exercise's other constructor, Rope(masses, springs).
  /// The checker uses it once the code's own constructor has been found wrong, so that the steps
  /// are still checked. Where `build` is springlab's already (own_constructor() false), the same.
  virtual BuiltRope build_exercise(const RopeRequest& request) { return build(request); }
  /// Sets every mass's position, last_position, velocity and forces.
  virtual void set_state(const RopeState& state) = 0;
  /// Calls the step `steps` times with (float) dt and gravity: the state after each call.
  virtual std::vector<RopeState> simulate(Step step, double dt, const Vec2& gravity, int steps) = 0;
  /// Whether `build` runs the code's own constructor (C++), or springlab's exercise_rope (the
  /// browser's exercise is the two steps): then the construction is not the code's, and not
  /// checked.
  virtual bool own_constructor() const { return true; }
};

/// The rope as the exercise's constructor must build it from its arguments: num_nodes masses
/// evenly spaced from start to end, node_mass each, at rest (last_position = position); a spring
/// of k between each pair of neighbours, its rest length their distance; the pinned_nodes pinned.
BuiltRope exercise_rope(const RopeRequest& request);

struct CheckLine {
  enum Kind { Pass, Fail, Note } kind = Note;
  std::string text;
  /// What the line is about, the same in every language: a failed line's mistake ("forces-kept",
  /// "one-end", ...; docs/homework.md lists them), a passed line's check ("springs", "order"), so
  /// that a course's grader or a test can read the report without reading its words.
  std::string key;
};
struct CheckSection {
  std::string title;
  std::vector<CheckLine> lines;
};

/// How a step damps, as fitted to what it does (each a term of its force, or Verlet's factor):
///   drag:      a global drag on each mass, f = -c v (N s/m), or, with `drag_rate`, as an
///              acceleration, a = f / m - c v (c in 1/s: the same rate for any mass, f = -c m v);
///   along:     the lecture's spring damping, along the spring, f_b = -k_d ((v_b - v_a) . u) u,
///              f_a = -f_b (N s/m): it damps only the springs' stretching;
///   relative:  damping along the relative velocity, f_b = -k_d (v_b - v_a), f_a = -f_b (N s/m):
///              it damps the rope's bending and spinning too;
///   verlet:    Verlet's factor d, on (x - x_last) (x1 = x + (1 - d)(x - x_last) + a h^2) or, with
///              `verlet_whole`, on the whole displacement (x1 = x + (1 - d)((x - x_last) + a h^2)).
///   drag_step: Euler's drag as a factor a step, v = (1 - d) v whatever h (`drag` is then 0): a
///              drag of rate d / h, which at_step() turns into for a step of h;
///   drag_at:   where Euler's drag (or that factor) is taken: with the forces, v1 = v + (a - c v)
///   h;
///              from the new velocity, v1 = (1 - c h)(v + a h) (symplectic Euler's position then
///              moves by it); or from it after the position has moved by the undamped one.
enum class DragAt { Forces, NewVelocity, AfterPosition };
struct Damping {
  double drag = 0.0, along = 0.0, relative = 0.0, verlet = 0.0, drag_step = 0.0;
  bool drag_rate = false;
  bool verlet_whole = false;
  DragAt drag_at = DragAt::Forces;
  /// The drag's force coefficient on a mass of `mass` kg: c, or c m for a rate (drag_step:
  /// at_step).
  double drag_on(double mass) const { return drag_rate ? drag * mass : drag; }
  /// The same damping for a step of h: a factor a step as the rate it is there, d / h.
  Damping at_step(double h) const {
    Damping d = *this;
    if (drag_step != 0.0) {
      d.drag = drag_step / h;
      d.drag_rate = true;
      d.drag_step = 0.0;
    }
    return d;
  }
  bool any() const {
    return drag != 0.0 || along != 0.0 || relative != 0.0 || verlet != 0.0 || drag_step != 0.0;
  }
};

/// The damping in words, in the current language: "a global drag f = -c v, c = 0.01 N s/m; ...",
/// "damping factor d = 5e-05 on (x - x_last), ...", "no damping".
std::string damping_text(const Damping& damping, Step step);

/// What a step was found to be: a row of springlab's table (empty: none of them) and its damping.
struct Identified {
  std::string method;
  bool velocity_verlet =
      false;                 ///< Verlet as a step of (x, v): x + h v + h^2/2 a, v + h/2 (a + a1)
  bool constraints = false;  ///< position Verlet with its springs held as constraints (no row)
  Damping damping;
  double deviation = 0.0;  ///< the largest difference from that row, in units of a step's motion
  /// Matched only to float's rounding (the code computes in float): `deviation` was within the
  /// floor float's rounding of the forces gives, `float_floor`, and above double's.
  bool in_float = false;
  double float_floor = 0.0;
};

struct Report {
  std::vector<CheckSection> sections;
  Identified euler, verlet;
  /// The steps were checked on springlab's rope (the constructor was not right, or is not the
  /// code's).
  bool springlab_rope = false;
  /// The code's own constructor was checked and found wrong.
  bool constructor_wrong = false;
  int passed() const;
  int failed() const;
  /// The keys of the failed lines, in order (CheckLine::key).
  std::vector<std::string> failed_keys() const;
};

/// Runs every check. A CodeFailure ends the report where it happened, with its message.
Report check_rope(RopeCode& code);

/// A whole step of the student's own, over springlab's state (Python's fn(x, v, force, h) ->
/// (x, v), with force(x, v) the core's accelerations): (x, v) advanced by h on `model`, the
/// forces asked for through accelerations(model, x, v, a, ws). As SimulationSettings::own_step.
using OwnStep =
    std::function<void(const Model& model, const State& in, State& out, double h, Workspace& ws)>;

/// The same checks for such a step: which of springlab's fixed-step rows it is (on the rope
/// falling from rest, step by step from its own states), whether it holds a pin, then its order,
/// stability and energy on the spring against that row's. `name` names it in the report.
/// `single_precision`, where given, says after the step's first call whether it returned its
/// arrays in single precision (NumPy's float32): its positions are then judged to float's rounding.
Report check_step(const OwnStep& step, const std::string& name,
                  const bool* single_precision = nullptr);

/// The report as `springlab homework check` prints it: a section a title, a line a check
/// ("  ok    ...", "  FAIL  ...", "        ..."), and a last line counting them. Its words are in
/// the current language (springlab/text.hpp's tr()), as the report's lines were made.
std::string format_report(const Report& report);
/// The same as JSON, for a course's grader: {"passed", "failed", "springlab_rope", "steps":
/// {"simulateEuler": {"method", "damping": {...}, ...}}, "sections": [{"title", "lines": [{"kind",
/// "key", "text"}]}]}.
std::string report_json(const Report& report);

}  // namespace springlab::homework
