#include "lesson/lesson_library.hpp"

#include <algorithm>
#include <filesystem>

#include "springlab/error.hpp"
#include "util/data_dir.hpp"

namespace springlab::app {

namespace fs = std::filesystem;

std::vector<std::string> shipped_lesson_files() {
  std::vector<std::string> files;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(data_dir() / "assets" / "lessons", ec))
    if (entry.path().extension() == ".json") files.push_back(entry.path().string());
  std::sort(files.begin(), files.end());
  return files;
}

Lesson open_lesson(const std::string& name) {
  const LessonSceneOpener open = [](const std::string& scene,
                                    const std::vector<std::string>& sets) {
    return load_scene(resolve_scene(scene), sets);
  };
  const LessonMethodFinder find = [](const std::string& method) { return lookup_method(method); };
  std::error_code ec;
  if (fs::is_regular_file(name, ec)) return load_lesson(name, open, find);
  const std::vector<std::string> files = shipped_lesson_files();
  std::vector<std::string> names;
  for (std::size_t k = 0; k < files.size(); ++k) {
    names.push_back(lesson_name(files[k]));
    if (names.back() == name || std::to_string(k + 1) == name)
      return load_lesson(files[k], open, find);
  }
  std::string list;
  for (const auto& n : names) list += (list.empty() ? "" : ", ") + n;
  const std::string near = closest_match(name, names.data(), names.size());
  throw InputError("lesson '" + name + "': no such file, and no shipped lesson of that name" +
                   (near.empty() ? "" : "; did you mean '" + near + "'?") + " (shipped: " + list +
                   ")");
}

int course_number(const Lesson& lesson) {
  const std::vector<std::string> files = shipped_lesson_files();
  const auto at = std::find(files.begin(), files.end(), lesson.file);
  return at == files.end() ? 0 : static_cast<int>(at - files.begin()) + 1;
}

void check_lesson_step(const Lesson& lesson, int step, const std::string& option) {
  if (step < 1 || step > static_cast<int>(lesson.steps.size()))
    throw InputError(option + ": lesson '" + lesson.name + "' has steps 1 to " +
                     std::to_string(lesson.steps.size()) + ", got " + std::to_string(step));
}

StepSetup setup_step(const LessonStep& step) {
  SimOptions o;
  if (step.method) o.method = method_info(*step.method).name;
  o.dt = step.dt;
  if (step.substeps) o.substeps = *step.substeps == 0 ? "auto" : std::to_string(*step.substeps);
  o.ks = step.ks;
  o.kd = step.kd;
  o.iterations = step.iterations;
  o.sets = step.sets;
  StepSetup setup{prepare(step.scene, o), {}};
  const std::unique_ptr<SceneKind> kind = make_scene_kind(setup.prepared.scene);
  for (const std::string& lane : step.compare)
    setup.compare.push_back(*kind->find(lane));  // (checked as the lesson loaded)
  return setup;
}

void begin_step(Session& session, const LessonStep& step, const StepSetup& setup) {
  if (!setup.compare.empty()) session.set_compare_rows(setup.compare);
  session.set_speed(step.speed);
  if (!step.script.events.empty()) session.play(step.script);
}

std::unique_ptr<Session> step_session(const LessonStep& step, double fps, bool background) {
  StepSetup setup = setup_step(step);
  auto session = std::make_unique<Session>(setup.prepared.scene, setup.prepared.settings, fps);
  session->set_background_analysis(background);
  begin_step(*session, step, setup);
  return session;
}

}  // namespace springlab::app
