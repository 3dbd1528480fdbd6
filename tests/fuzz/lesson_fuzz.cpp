// libFuzzer target: the lesson loader (parse_lesson) on any bytes. Its scenes come from a small
// opener: the shipped scenes' names stand for tiny scenes of the same kind (a spring, a rope, a
// soft box, an emitter, an IK arm), built with the step's --set overrides, so that everything a
// step refers to (lanes, particles, claims) is checked against a real scene. A loaded lesson's
// promises are then checked; any outcome but that or an InputError is a bug (see scene_fuzz.cpp).
#include <cstddef>
#include <cstdint>
#include <map>
#include <string>

#include "loader_checks.hpp"
#include "springlab/error.hpp"
#include "springlab/lesson.hpp"

namespace {

using springlab::fuzz::require;

const std::map<std::string, std::string>& scenes() {
  static const std::map<std::string, std::string> texts = {
      {"spring",
       R"({"particles": [{"position": [0, 0, 0], "pinned": true}, {"position": [1.5, 0, 0]}],
                    "springs": [{"a": 0, "b": 1, "ks": 100, "rest_length": 1}], "methods": ["rk4", "euler"]})"},
      {"rope",
       R"({"generators": [{"type": "rope", "name": "rope", "start": [0, 0, 0], "end": [4, 0, 0], "nodes": 8,
                   "stiffness": 2000}], "gravity": [0, -9.81, 0], "drag": 0.03})"},
      {"jelly",
       R"({"generators": [{"type": "box", "name": "jelly", "nodes": [2, 2, 2], "stiffness": 2000}]})"},
      {"fountain",
       R"({"emitters": [{"name": "fountain", "rate": 100, "max": 50, "speed": 5, "lifetime": 1}],
                       "gravity": [0, -9.81, 0]})"},
      {"ik-arm",
       R"({"ik": {"links": [1.0, 0.8], "target": [1, 0.5, 0], "solvers": ["ccd", "fabrik", "dls"]}})"},
  };
  return texts;
}

springlab::Scene open(const std::string& name, const std::vector<std::string>& sets) {
  const auto at = scenes().find(name);
  if (at == scenes().end()) throw springlab::InputError("scene '" + name + "': no such scene here");
  return springlab::parse_scene(at->second, name + ".json", sets);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const springlab::Lesson lesson = springlab::parse_lesson(text, "fuzz-lesson.json", open);
    require(!lesson.steps.empty() && lesson.steps.size() <= 12, "1 to 12 steps");
    require(lesson.duration() > 0.0 && std::isfinite(lesson.duration()),
            "a finite, positive duration");
    for (const springlab::LessonStep& step : lesson.steps) {
      require(!step.caption.empty() && step.caption.size() <= 4 * springlab::kMaxCaption,
              "a caption that fits");
      require(!step.charts.empty() && step.charts.size() <= 2, "one or two charts");
      require(step.compare.empty() || (step.compare.size() >= 2 && step.compare.size() <= 4),
              "2 to 4 lanes");
      for (const springlab::LessonClaim& c : step.claims) {
        require(!c.describe().empty(), "every claim describes itself");
        require(c.from >= 0.0 && c.from <= step.duration, "claims within the step");
        require(!c.to || (*c.to > c.from && *c.to <= step.duration), "windows within the step");
      }
    }
  } catch (const springlab::InputError&) {
  }
  return 0;
}
