// The shipped lessons (assets/lessons/NN-name.json, in the lecture's order) and opening one by
// name or path, with each step's scene opened through the same loader as `springlab run`.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "options/scene_options.hpp"
#include "session/session.hpp"
#include "springlab/lesson.hpp"

namespace springlab::app {

// Files of the shipped lessons, in the course's order (their leading numbers).
std::vector<std::string> shipped_lesson_files();

// A lesson by name ("hooke"), number in the course ("3"), or path to a file. Throws InputError
// naming the shipped lessons.
Lesson open_lesson(const std::string& name_or_path);

// A lesson's place in the course, from 1 (0: not a shipped lesson, a file of one's own).
int course_number(const Lesson& lesson);

// Checks a step number from 1 given with `option` ("--step", "link: step"). Throws InputError:
// "--step: lesson 'hooke' has steps 1 to 2, got 5".
void check_lesson_step(const Lesson& lesson, int step, const std::string& option);

// What a step starts with: the scene prepared with the step's settings, the lanes side by side
// (its kind's rows: methods, or an IK scene's solvers), the script.
struct StepSetup {
  Prepared prepared;
  std::vector<int> compare;
};
StepSetup setup_step(const LessonStep& step);

// A session for the step at `fps`, from its frame 0: its lanes, its speed and its script.
std::unique_ptr<Session> step_session(const LessonStep& step, double fps, bool background);
// The same on a session already made from setup.prepared (the app's, which sets it up its way).
void begin_step(Session& session, const LessonStep& step, const StepSetup& setup);

}  // namespace springlab::app
