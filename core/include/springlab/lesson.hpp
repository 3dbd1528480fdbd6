// Lessons: the lecture as data (assets/lessons/README.md documents the format). A lesson is a
// short sequence of steps; a step names a scene and how to show it (method or compare lanes,
// parameters, a script of drags and changes, the chart to watch), a caption saying what to
// watch, an optional "try this" prompt for the class, and the physics claims its caption makes,
// stated so that a test can play the step and check them (the energy grows by 1 + (h w)^2 a
// step, the run diverges by t = 2 s, the target is out of reach, ...).
//
// Loading checks every field: the scene must open with the step's settings (the caller opens
// it: scene names are the app's business), the script's particles must exist in it, the lanes
// a claim names must be the step's, and a caption must fit two lines on a projector. Messages
// name the file and the field: "lesson '01-hooke.json': /steps/1/dt: must be in (0, 1], got 2".
#pragma once

#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "springlab/ik.hpp"
#include "springlab/methods.hpp"
#include "springlab/scene.hpp"
#include "springlab/script.hpp"

namespace springlab {

// What fits a projector at 1280 x 720 in the caption's font: two lines of the caption, one of
// the prompt (the app's lesson band is laid out for these).
inline constexpr int kMaxCaption = 170;
inline constexpr int kMaxPrompt = 110;
inline constexpr int kMaxTitle = 60;

// A physics claim of a step, checked by playing it (app/lesson/lesson_checks.hpp says how each
// is measured). Times are seconds into the step (presentation time).
struct LessonClaim {
  enum class Kind {
    EnergyGrows,    // lane's total energy rises; with per_step, by that factor a step
    EnergyDecays,   // falls by more than 5 % of the energy scale; with per_step, by that factor a
                    // step
    EnergyBounded,  // stays within `within` of the energy scale of its start
    Diverges,       // the lane diverges (or goes unstable) by `by`
    Holds,          // the lane neither diverges nor goes unstable
    FollowsExact,   // the watched particle stays within `within` m of the exact solution
    Limit,          // the stated stability limit is `h` to within `within` (relative)
    StepsAdapt,     // an adaptive lane rejects tries, and its step varies by `ratio` or more
    MomentumKept,   // the free particles' momentum and angular momentum are unchanged to `within`
    LinearMomentumKept,     // the momentum P alone, to `within` of sum m |v| (momentum.hpp)
    LinearMomentumChanges,  // P changes by more than `above` of sum m |v|: the method breaks it
    DragSlows,        // the centre of mass slows as exp(-k_drag t / m), to `within` (relative)
    InternalDecays,   // the motion besides the rigid one loses all but `below` of its energy
    SolverConverges,  // an iterative lane's step nears the converged implicit-Euler step by a
                      // factor below `below` an iteration (solver_error.hpp, 8 to 64 iterations)
    ActsAs,           // an iterative lane at rest stretches as springs of k_s times a factor at
                      // most `below` and at least `above` would (iterative_cost.hpp)
    OutOfReach,       // the IK target is out of reach and the chain points straight at it
    PosesDiffer,      // every IK lane reaches the target, in poses `min` m apart or more
    Orders,           // measured convergence orders, and the most accurate method for its cost
    Particles,        // about `about` particles alive at `at`, to within `within` (relative)
    Bursts,           // particles burst: `count` born at once, and at least one such burst
    InSight,          // never written: the check adds it to every step. Each lane that holds
                      // keeps its body in the scene camera's 16:9 frame (every view shows it)
  };
  Kind kind = Kind::Holds;
  std::string lane;  // a method or solver name of the step; "" for the first lane
  double from = 0.0;
  std::optional<double> to, by, at;
  std::optional<double> per_step;
  double within = 0.0, h = 0.0, ratio = 2.0, below = 0.0, min = 0.0, about = 0.0, above = 0.0;
  int count = 0;
  std::map<std::string, double> orders;  // method name -> order
  std::string best;                      // Orders: the method with the least error for its cost

  std::string describe() const;  // "euler: energy grows by x1.01 a step", for reports
};

// Charts a step shows (in the app's charts panel, side by side): energy, the watched particle's
// position (with the exact solution), its phase plot, an adaptive method's steps, the stability
// region with the scene's modes.
enum class LessonChart { Energy, Position, Phase, Steps, Region, Momentum };

struct LessonStep {
  std::string title;
  std::string scene;  // as written: a shipped scene's name, or a path from the lesson's folder
  std::vector<std::string> sets;  // "KEY=VALUE", as --set
  std::optional<Method> method;
  std::vector<std::string> compare;  // 2 to 4 methods, or an IK scene's solvers
  std::optional<double> dt, ks, kd;
  std::optional<int> substeps;    // 0: automatic
  std::optional<int> iterations;  // xpbd, local-global, vbd
  double duration = 6.0;          // s of presentation time
  double speed = 1.0;
  std::vector<LessonChart> charts{LessonChart::Energy};  // one or two
  bool region = false, accuracy = false,
       mode = false;            // the stability region, the accuracy panel, the limiting mode
  Script script;                // may have no events
  std::string caption, prompt;  // prompt: "try this", may be empty
  std::vector<LessonClaim> claims;
};

struct Lesson {
  std::string name;  // "hooke" for assets/lessons/01-hooke.json
  std::string file;
  std::string title, summary;
  std::vector<LessonStep> steps;
  double duration() const;  // of every step
};

// Opens a step's scene: `scene` as written in the lesson, with its --set overrides. Throws
// InputError (its message is put after the field's path).
using LessonSceneOpener =
    std::function<Scene(const std::string& scene, const std::vector<std::string>& sets)>;

// Finds a method a lesson names (a step's method, its lanes, its claims): the table's rows by
// default; the app also opens tableaux by name (a shipped one, or a file), adding their rows.
using LessonMethodFinder = std::function<std::optional<Method>(const std::string& name)>;
inline std::optional<Method> find_table_method(const std::string& name) {
  return find_method(name);
}

Lesson parse_lesson(const std::string& text, const std::string& file, const LessonSceneOpener& open,
                    const LessonMethodFinder& find = find_table_method);
Lesson load_lesson(const std::string& path, const LessonSceneOpener& open,
                   const LessonMethodFinder& find = find_table_method);

// "01-hooke.json" -> "hooke": a lesson file's leading number orders the course.
std::string lesson_name(const std::string& file_name);

}  // namespace springlab
