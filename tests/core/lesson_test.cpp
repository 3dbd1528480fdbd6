// The lesson format (core/include/springlab/lesson.hpp): what a valid lesson gives, and one clear
// message naming the file and the field for each way a lesson can be wrong.
#include "springlab/lesson.hpp"

#include <gtest/gtest.h>

#include "springlab/error.hpp"
#include "support.hpp"

namespace springlab {
namespace {

Scene open(const std::string& scene, const std::vector<std::string>& sets) {
  if (scene.find('/') != std::string::npos) return load_scene(scene, sets);
  return test::shipped(scene, sets);
}

// A one-step lesson with the step's fields given as JSON text (inside the step's braces).
std::string lesson_text(const std::string& step, const std::string& top = "") {
  return R"({"title": "A lesson", "summary": "What it shows.", )" + top +
         R"("steps": [{"title": "A step", )" + step + "}]}";
}

Lesson parse(const std::string& step, const std::string& top = "") {
  return parse_lesson(lesson_text(step, top), "lessons/07-test.json", open);
}

// The message parsing `step` throws.
std::string lesson_error_of(const std::string& step, const std::string& top = "") {
  try {
    parse(step, top);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

const std::string kValid =
    R"("scene": "spring", "method": "euler", "dt": 0.01, "substeps": 1, "duration": 4, "caption": "Watch it.",
       "try": "Halve dt.", "chart": ["energy", "region"],
       "events": [{"t": 1, "set": {"kd": 2}}],
       "claims": [{"claim": "energy-grows", "per_step": 1.01, "to": 1}, {"claim": "diverges", "by": 4}])";

TEST(Lesson, ReadsEveryFieldOfAStep) {
  const Lesson lesson =
      parse(kValid + R"(, "set": {"gravity": [0, -1, 0]}, "ks": 200, "kd": 1, "speed": 0.5)");
  EXPECT_EQ(lesson.name, "test");
  EXPECT_EQ(lesson.title, "A lesson");
  ASSERT_EQ(lesson.steps.size(), 1u);
  const LessonStep& s = lesson.steps[0];
  EXPECT_EQ(s.scene, "spring");
  EXPECT_EQ(s.sets, std::vector<std::string>{"gravity=[0,-1,0]"});
  EXPECT_EQ(s.method, Method::Euler);
  EXPECT_EQ(*s.dt, 0.01);
  EXPECT_EQ(*s.substeps, 1);
  EXPECT_EQ(*s.ks, 200);
  EXPECT_EQ(*s.kd, 1);
  EXPECT_EQ(s.speed, 0.5);
  EXPECT_EQ(s.duration, 4);
  EXPECT_EQ(s.charts, (std::vector<LessonChart>{LessonChart::Energy, LessonChart::Region}));
  EXPECT_EQ(s.prompt, "Halve dt.");
  ASSERT_EQ(s.script.events.size(), 1u);
  EXPECT_EQ(*s.script.events[0].kd, 2);
  ASSERT_EQ(s.claims.size(), 2u);
  EXPECT_EQ(s.claims[0].kind, LessonClaim::Kind::EnergyGrows);
  EXPECT_EQ(*s.claims[0].per_step, 1.01);
  EXPECT_EQ(*s.claims[0].to, 1);
  EXPECT_EQ(*s.claims[1].by, 4);
  EXPECT_DOUBLE_EQ(lesson.duration(), 4.0);
}

TEST(Lesson, NamesComeFromTheFileWithoutItsNumber) {
  EXPECT_EQ(lesson_name("assets/lessons/01-hooke.json"), "hooke");
  EXPECT_EQ(lesson_name("10-inverse-kinematics.json"), "inverse-kinematics");
  EXPECT_EQ(lesson_name("mine.json"), "mine");
  EXPECT_EQ(lesson_name("2024.json"), "2024");
}

TEST(Lesson, ASceneInTheLessonsFolderIsFoundFromThere) {
  const std::string dir = std::string(SPRINGLAB_SOURCE_DIR) + "/assets/scenes";
  const Lesson lesson =
      parse_lesson(lesson_text(R"("scene": "spring.json", "duration": 1, "caption": "x")"),
                   dir + "/my-lesson.json", open);
  EXPECT_EQ(lesson.steps[0].scene, dir + "/spring.json");
}

TEST(Lesson, EachMistakeGetsOneMessageNamingTheFileAndTheField) {
  const std::string file = "lesson 'lessons/07-test.json': ";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {R"("scene": "sprung", "duration": 1, "caption": "x")", "/steps/0/scene: scene '"},
      {R"("scene": "spring", "set": {"nodez": 3}, "duration": 1, "caption": "x")",
       "/steps/0/set: "},
      {R"("scene": "spring", "method": "eulr", "duration": 1, "caption": "x")",
       "/steps/0/method: must be a method name"},
      {R"("scene": "spring", "dt": 2, "duration": 1, "caption": "x")", "/steps/0/dt: must be"},
      {R"("scene": "spring", "substeps": 0, "duration": 1, "caption": "x")",
       "/steps/0/substeps: must be"},
      {R"("scene": "spring", "duration": 0, "caption": "x")", "/steps/0/duration: must be"},
      {R"("scene": "spring", "duration": 1)", "/steps/0/caption: is required"},
      {R"("scene": "spring", "duration": 1, "caption": "  ")",
       "/steps/0/caption: must not be empty"},
      {R"("scene": "spring", "duration": 1, "caption": ")" + std::string(171, 'a') + "\"",
       "/steps/0/caption: has 171 characters; at most 170 fit on a projector"},
      {R"("scene": "spring", "duration": 1, "caption": "x", "try": ")" + std::string(111, 'a') +
           "\"",
       "/steps/0/try: has 111 characters; at most 110"},
      {R"("scene": "spring", "duration": 1, "caption": "a \u4e2d")",
       "/steps/0/caption: has the character U+4E2D"},
      {R"("scene": "spring", "duration": 1, "caption": "x", "chart": "speed")",
       "/steps/0/chart: must be one or two of"},
      {R"("scene": "spring", "duration": 1, "caption": "x", "captoin": "y")",
       "/steps/0/captoin: unknown field; did you mean \"caption\"?"},
      {R"("scene": "spring", "compare": ["euler"], "duration": 1, "caption": "x")",
       "/steps/0/compare: must name 2 to 4 lanes"},
      {R"("scene": "spring", "compare": ["euler", "rk5"], "duration": 1, "caption": "x")",
       "/steps/0/compare/1: unknown method 'rk5'"},
      {R"("scene": "spring", "method": "rk4", "compare": ["euler", "rk4"], "duration": 1, "caption": "x")",
       "/steps/0/method: give either"},
      {R"("scene": "ik-arm", "method": "rk4", "duration": 1, "caption": "x")",
       "/steps/0/method: scene 'ik-arm' is an inverse-kinematics scene"},
      {R"("scene": "spring", "duration": 1, "caption": "x", "events": [{"t": 0, "grab": 7}])",
       "/steps/0/events/0/grab: must be an integer in [0, 1], got 7"},
      {R"("scene": "spring", "duration": 1, "caption": "x", "claims": [{"claim": "grows"}])",
       "/steps/0/claims/0/claim: unknown value \"grows\" (one of energy-grows,"},
      {R"("scene": "spring", "duration": 1, "caption": "x", "claims": [{"claim": "holds", "lane": "rk4"}])",
       "/steps/0/claims/0/lane: 'rk4' is not a lane of this step (its lanes: symplectic-euler)"},
      {R"("scene": "rope", "duration": 1, "caption": "x", "claims": [{"claim": "follows-exact", "within": 1}])",
       "/steps/0/claims/0/claim: follows-exact needs a scene with an exact solution"},
      {R"("scene": "spring", "duration": 1, "caption": "x", "claims": [{"claim": "out-of-reach"}])",
       "/steps/0/claims/0/claim: 'out-of-reach' is about inverse kinematics"},
      {R"("scene": "spring", "duration": 2, "caption": "x", "claims": [{"claim": "diverges", "by": 3}])",
       "/steps/0/claims/0/by: must be"},
      {R"("scene": "spring", "duration": 2, "caption": "x", "claims": [{"claim": "holds", "from": 1, "to": 0.5}])",
       "/steps/0/claims/0/to: must come after from"},
      {R"("scene": "spring", "duration": 2, "caption": "x", "claims": [{"claim": "bursts", "count": 10}])",
       "/steps/0/claims/0/claim: bursts needs a scene with emitters"},
      {R"("scene": "spring", "duration": 2, "caption": "x", "claims": [{"claim": "orders", "orders": {"euler": 1, "rk45": 5}}])",
       "/steps/0/claims/0/orders/rk45: must be a fixed-step method"},
      {R"("scene": "spring", "duration": 2, "caption": "x", "claims": [{"claim": "orders", "orders": {"euler": 1, "rk4": 4}, "best": "midpoint"}])",
       "/steps/0/claims/0/best: must be one of the methods in \"orders\""},
      {R"("scene": "spring", "method": "xpbd", "iterations": 0, "duration": 2, "caption": "x")",
       "/steps/0/iterations: must be an integer in [1, 10000], got 0"},
      {R"("scene": "spring", "duration": 2, "caption": "x", "claims": [{"claim": "acts-as", "below": 0.5}])",
       "/steps/0/claims/0/lane: acts-as is about an iterative method's lane (xpbd, local-global, "
       "vbd), not 'symplectic-euler'"},
      {R"("scene": "spring", "method": "vbd", "duration": 2, "caption": "x", "claims": [{"claim": "acts-as"}])",
       "/steps/0/claims/0/claim: acts-as needs \"below\", \"above\" or both"},
      {R"("scene": "spring", "compare": ["rk4", "local-global"], "duration": 2, "caption": "x", "claims": [{"claim": "solver-converges", "lane": "rk4", "below": 0.9}])",
       "/steps/0/claims/0/lane: solver-converges is about an iterative method's lane"},
  };
  for (const auto& [step, expected] : cases) {
    const std::string message = lesson_error_of(step);
    EXPECT_EQ(message.rfind(file, 0), 0u) << message;
    EXPECT_NE(message.find(expected), std::string::npos)
        << "expected '" << expected << "' in: " << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
}

TEST(Lesson, TheLessonItselfIsChecked) {
  const auto error = [](const std::string& text) {
    try {
      parse_lesson(text, "x.json", open);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("(no error)");
  };
  EXPECT_NE(error("{").find("lesson 'x.json': not valid JSON"), std::string::npos);
  EXPECT_NE(error("[]").find("must be a JSON object"), std::string::npos);
  EXPECT_NE(error(R"({"title": "t", "summary": "s", "steps": []})")
                .find("/steps: is required: 1 to 12 steps"),
            std::string::npos);
  EXPECT_NE(error(R"({"summary": "s", "steps": []})").find("/title: is required"),
            std::string::npos);
  EXPECT_NE(error(R"({"title": "t", "summary": "s", "steps": [], "lang": "en"})")
                .find("/lang: unknown field"),
            std::string::npos);
  EXPECT_THROW(load_lesson("/no/such/lesson.json", open), InputError);
}

}  // namespace
}  // namespace springlab
