#include "springlab/lesson.hpp"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <numeric>

#include "loading/script_events.hpp"
#include "springlab/exact.hpp"

namespace springlab {

using json_reader::json;
using json_reader::ObjectReader;

namespace {

std::string four_digits(double x) {
  char s[32];
  std::snprintf(s, sizeof s, "%.4g", x);
  return s;
}

std::string precise(double x) {
  char s[32];
  std::snprintf(s, sizeof s, "%.7g", x);
  return s;
}

// The code points of UTF-8 text (the parser has checked it is UTF-8).
std::vector<char32_t> code_points(const std::string& text) {
  std::vector<char32_t> out;
  for (std::size_t i = 0; i < text.size();) {
    const unsigned char c = static_cast<unsigned char>(text[i]);
    const int n = c < 0x80 ? 1 : c < 0xE0 ? 2 : c < 0xF0 ? 3 : 4;
    char32_t u = n == 1 ? c : n == 2 ? (c & 0x1F) : n == 3 ? (c & 0x0F) : (c & 0x07);
    for (int k = 1; k < n && i + k < text.size(); ++k)
      u = (u << 6) | (static_cast<unsigned char>(text[i + k]) & 0x3F);
    out.push_back(u);
    i += n;
  }
  return out;
}

// The characters the app's font holds (app/ui/theme.cpp loads the same ranges): Latin-1, Greek,
// general punctuation (dashes, quotes), superscripts and subscripts, arrows and math operators.
bool drawable(char32_t u) {
  return (u >= 0x20 && u <= 0x7E) || (u >= 0xA0 && u <= 0xFF) || (u >= 0x370 && u <= 0x3FF) ||
         (u >= 0x2010 && u <= 0x205E) || (u >= 0x2070 && u <= 0x209F) ||
         (u >= 0x2190 && u <= 0x21FF) || (u >= 0x2200 && u <= 0x22FF);
}

// Text shown to a class: required (or optional), at most `max` characters, every one drawable.
std::string shown_text(ObjectReader& r, const char* key, int max, bool required) {
  if (required && !r.has(key))
    r.fail(key,
           "is required: one or two sentences, at most " + std::to_string(max) + " characters");
  std::string text = r.text(key, "");  // (not const: returned by move)
  const std::vector<char32_t> points = code_points(text);
  if (required && std::all_of(points.begin(), points.end(), [](char32_t u) { return u == ' '; }))
    r.fail(key, "must not be empty");
  if (static_cast<int>(points.size()) > max)
    r.fail(key, "has " + std::to_string(points.size()) + " characters; at most " +
                    std::to_string(max) +
                    " fit on a projector at 1280x720 (shorten it, or split the step in two)");
  for (char32_t u : points)
    if (!drawable(u)) {
      char code[16];
      std::snprintf(code, sizeof code, "U+%04X", static_cast<unsigned>(u));
      r.fail(key, std::string("has the character ") + code +
                      ", which the app's font cannot draw (use Latin-1, Greek, dashes, arrows or "
                      "math symbols)");
    }
  return text;
}

std::vector<std::string> strings(ObjectReader& r, const char* key) {
  std::vector<std::string> out;
  const json* v = r.raw(key);
  if (!v) return out;
  if (!v->is_array()) r.fail(key, "must be an array of names, " + json_reader::describe(*v));
  for (std::size_t i = 0; i < v->size(); ++i) {
    if (!(*v)[i].is_string())
      json_reader::fail_at(r.where(), r.path(key) + "/" + std::to_string(i),
                           "must be a name, " + json_reader::describe((*v)[i]));
    out.push_back((*v)[i].get<std::string>());
  }
  return out;
}

std::string join(const std::vector<std::string>& names) {
  std::string s;
  for (const auto& n : names) s += (s.empty() ? "" : ", ") + n;
  return s;
}

const std::vector<std::pair<std::string, LessonClaim::Kind>>& claim_kinds() {
  using K = LessonClaim::Kind;
  static const std::vector<std::pair<std::string, K>> kinds = {
      {"energy-grows", K::EnergyGrows},
      {"energy-decays", K::EnergyDecays},
      {"energy-bounded", K::EnergyBounded},
      {"diverges", K::Diverges},
      {"holds", K::Holds},
      {"follows-exact", K::FollowsExact},
      {"limit", K::Limit},
      {"steps-adapt", K::StepsAdapt},
      {"momentum-kept", K::MomentumKept},
      {"linear-momentum-kept", K::LinearMomentumKept},
      {"linear-momentum-changes", K::LinearMomentumChanges},
      {"drag-slows", K::DragSlows},
      {"internal-decays", K::InternalDecays},
      {"solver-converges", K::SolverConverges},
      {"acts-as", K::ActsAs},
      {"out-of-reach", K::OutOfReach},
      {"poses-differ", K::PosesDiffer},
      {"orders", K::Orders},
      {"particles", K::Particles},
      {"bursts", K::Bursts}};
  return kinds;
}

// The lanes of a step: its compare list, else its method (or the scene's first), else the IK
// scene's first solver.
std::vector<std::string> lanes_of(const LessonStep& step, const Scene& scene) {
  if (!step.compare.empty()) return step.compare;
  if (scene.ik) return {ik_solver_info(scene.ik->solvers.front()).name};
  return {method_info(step.method.value_or(scene.methods.front())).name};
}

// An iterative method's claim (acts-as, solver-converges): its lane must be one, then its figures.
void read_iterative_claim(ObjectReader& r, LessonClaim& c, const std::string& name,
                          const std::vector<std::string>& lanes, const LessonMethodFinder& find) {
  using K = LessonClaim::Kind;
  const std::string lane = c.lane.empty() && !lanes.empty() ? lanes.front() : c.lane;
  const std::optional<Method> m = find(lane);
  if (!m || method_info(*m).family != MethodFamily::Iterative)
    r.fail("lane", name + " is about an iterative method's lane (xpbd, local-global, vbd), not '" +
                       lane + "'");
  if (c.kind == K::SolverConverges) {
    c.below = r.number("below", {0.0, 1.0, true, true});
  } else {
    if (!r.has("below") && !r.has("above"))
      r.fail("claim", "acts-as needs \"below\", \"above\" or both");
    if (r.has("below")) c.below = r.number("below", json_reader::positive(1e3));
    if (r.has("above")) c.above = r.number("above", json_reader::positive(1e3));
  }
}

// orders: {"method": order, ...}, each a fixed-step method, two or more, and the best for its cost.
void read_orders_claim(ObjectReader& r, LessonClaim& c, const LessonMethodFinder& find) {
  if (!r.has("orders"))
    r.fail("orders", "is required: {\"method\": order, ...}, e.g. {\"euler\": 1, \"rk4\": 4}");
  ObjectReader orders = *r.object("orders");
  const json* raw = r.raw("orders");
  for (const auto& [method, value] : raw->items()) {
    const auto m = find(method);
    if (!m || method_info(*m).adaptive())
      orders.fail(method.c_str(), "must be a fixed-step method (" + method_names() + ")");
    c.orders[method] = orders.number(method.c_str(), {0.5, 8.0});
  }
  if (c.orders.size() < 2) r.fail("orders", "must name two or more methods");
  c.within = r.number("within", 0.3, json_reader::positive(2.0));
  c.best = r.text("best", "");
  if (!c.best.empty() && !c.orders.count(c.best))
    r.fail("best", "must be one of the methods in \"orders\" (" + c.best + " is not)");
}

// A claim about the simulation (`name`) fails on an inverse-kinematics scene, which has none.
void claim_needs_dynamics(ObjectReader& r, const std::string& name, const Scene& scene) {
  if (scene.ik.has_value())
    r.fail("claim", "'" + name + "' is about a simulation; scene '" + scene.name +
                        "' is an inverse-kinematics scene");
}

// The figures of a claim about the simulation's motion (energy, divergence, the exact solution,
// the stability limit, adaptive steps, momentum, drag, the wiggles): none is about an
// inverse-kinematics scene.
void read_motion_claim_figures(ObjectReader& r, LessonClaim& c, const std::string& name,
                               const LessonStep& step, const Scene& scene) {
  using K = LessonClaim::Kind;
  const json_reader::Range time = {0.0, step.duration};
  switch (c.kind) {
    case K::EnergyGrows:
      claim_needs_dynamics(r, name, scene);
      if (r.has("per_step")) c.per_step = r.number("per_step", {1.0, 10.0, true, false});
      c.within = r.number("within", 0.05, {0.0, 1.0, true, false});
      break;
    case K::EnergyDecays:
      claim_needs_dynamics(r, name, scene);
      if (r.has("per_step")) c.per_step = r.number("per_step", {0.0, 1.0, true, true});
      c.within = r.number("within", 0.05, {0.0, 1.0, true, false});
      break;
    case K::Holds:
      claim_needs_dynamics(r, name, scene);
      break;
    case K::EnergyBounded:
      claim_needs_dynamics(r, name, scene);
      c.within = r.number("within", {0.0, 10.0, true, false});
      break;
    case K::Diverges:
      claim_needs_dynamics(r, name, scene);
      c.by = r.number("by", step.duration, time);
      break;
    case K::FollowsExact:
      claim_needs_dynamics(r, name, scene);
      c.within = r.number("within", json_reader::positive(1e3));
      if (!ExactOscillator::detect(scene.model, scene.state))
        r.fail("claim",
               "follows-exact needs a scene with an exact solution (one free particle on a spring, "
               "as 'spring'); '" +
                   scene.name + "' has none");
      break;
    case K::Limit:
      claim_needs_dynamics(r, name, scene);
      c.h = r.number("h", json_reader::positive(1.0));
      c.within = r.number("within", 0.01, {0.0, 1.0, true, false});
      break;
    case K::StepsAdapt:
      claim_needs_dynamics(r, name, scene);
      c.ratio = r.number("ratio", 2.0, {1.0, 1e6, true, false});
      break;
    case K::MomentumKept:
    case K::LinearMomentumKept:
      claim_needs_dynamics(r, name, scene);
      c.within = r.number("within", 1e-9, json_reader::positive(1.0));
      break;
    case K::LinearMomentumChanges:
      claim_needs_dynamics(r, name, scene);
      c.above = r.number("above", 1e-3, json_reader::positive(1.0));
      break;
    case K::DragSlows:
      claim_needs_dynamics(r, name, scene);
      c.within = r.number("within", 0.02, json_reader::positive(1.0));
      if (!(scene.model.drag > 0.0))
        r.fail("claim", "drag-slows needs drag above 0 in the step's scene (set \"drag\")");
      break;
    case K::InternalDecays:
      claim_needs_dynamics(r, name, scene);
      c.below = r.number("below", {0.0, 1.0, true, true});
      break;
    default:
      break;
  }
}

// The figures a claim of its kind takes, and what it needs of the step's scene.
void read_claim_figures(ObjectReader& r, LessonClaim& c, const std::string& name,
                        const LessonStep& step, const Scene& scene,
                        const std::vector<std::string>& lanes, const LessonMethodFinder& find) {
  using K = LessonClaim::Kind;
  const json_reader::Range time = {0.0, step.duration};
  const bool ik = scene.ik.has_value();
  switch (c.kind) {
    case K::EnergyGrows:
    case K::EnergyDecays:
    case K::Holds:
    case K::EnergyBounded:
    case K::Diverges:
    case K::FollowsExact:
    case K::Limit:
    case K::StepsAdapt:
    case K::MomentumKept:
    case K::LinearMomentumKept:
    case K::LinearMomentumChanges:
    case K::DragSlows:
    case K::InternalDecays:
      read_motion_claim_figures(r, c, name, step, scene);
      break;
    case K::ActsAs:
    case K::SolverConverges:
      claim_needs_dynamics(r, name, scene);
      read_iterative_claim(r, c, name, lanes, find);
      break;
    case K::OutOfReach:
    case K::PosesDiffer:
      if (!ik)
        r.fail("claim", "'" + name + "' is about inverse kinematics; scene '" + scene.name +
                            "' has no \"ik\" part");
      if (c.kind == K::PosesDiffer) {
        c.min = r.number("min", 0.05, json_reader::positive(100.0));
        if (lanes.size() < 2)
          r.fail("claim", "poses-differ needs two or more solvers side by side (\"compare\")");
      }
      break;
    case K::Orders:
      claim_needs_dynamics(r, name, scene);
      read_orders_claim(r, c, find);
      break;
    case K::Bursts:
      c.count = static_cast<int>(r.integer("count", 1, 10000));
      if (scene.model.emitters.empty())
        r.fail("claim", "bursts needs a scene with emitters; '" + scene.name + "' has none");
      break;
    case K::Particles:
      c.about = r.number("about", json_reader::positive(kMaxParticles));
      c.within = r.number("within", 0.1, json_reader::positive(1.0));
      c.at = r.number("at", step.duration, time);
      break;
    case K::InSight:  // (never read: not a name a lesson writes)
      break;
  }
}

LessonClaim read_claim(ObjectReader& r, const LessonStep& step, const Scene& scene,
                       const LessonMethodFinder& find) {
  LessonClaim c;
  std::vector<std::string> names;
  for (const auto& [name, kind] : claim_kinds()) names.push_back(name);
  const std::string name = r.choice("claim", "", names);
  for (const auto& [n, kind] : claim_kinds())
    if (n == name) c.kind = kind;

  const std::vector<std::string> lanes = lanes_of(step, scene);
  c.lane = r.text("lane", "");
  if (!c.lane.empty() && std::find(lanes.begin(), lanes.end(), c.lane) == lanes.end())
    r.fail("lane", "'" + c.lane + "' is not a lane of this step (its lanes: " + join(lanes) + ")");
  const json_reader::Range time = {0.0, step.duration};
  c.from = r.number("from", 0.0, time);
  if (r.has("to")) c.to = r.number("to", time);
  if (c.to && *c.to <= c.from) r.fail("to", "must come after from (" + four_digits(c.from) + " s)");

  read_claim_figures(r, c, name, step, scene, lanes, find);
  r.finish();
  return c;
}

// "chart": a name, or one or two in an array (energy, position, phase, steps, region, momentum).
std::vector<LessonChart> read_step_charts(ObjectReader& r, const json& c) {
  const std::vector<std::pair<std::string, LessonChart>> charts = {
      {"energy", LessonChart::Energy}, {"position", LessonChart::Position},
      {"phase", LessonChart::Phase},   {"steps", LessonChart::Steps},
      {"region", LessonChart::Region}, {"momentum", LessonChart::Momentum}};
  std::vector<std::string> names;
  if (c.is_string())
    names = {c.get<std::string>()};
  else if (c.is_array())
    names = strings(r, "chart");
  if (names.empty() || names.size() > 2)
    r.fail("chart", "must be one or two of energy, position, phase, steps and region, " +
                        json_reader::describe(c));
  std::vector<LessonChart> out;
  for (const std::string& n : names) {
    const auto at =
        std::find_if(charts.begin(), charts.end(), [&](const auto& x) { return x.first == n; });
    if (at == charts.end())
      r.fail("chart",
             "must be one or two of energy, position, phase, steps and region, got \"" + n + "\"");
    out.push_back(at->second);
  }
  return out;
}

// The step's lanes against its scene: an inverse-kinematics scene's solvers named in "compare"
// (no method, no dynamics' settings, no accuracy chart nor region); "compare" 2 to 4 lanes, each
// known and named once, and not with "method".
void check_step_lanes(ObjectReader& r, const LessonStep& step, const Scene& scene,
                      const LessonMethodFinder& find) {
  if (scene.ik) {
    if (step.method)
      r.fail("method", "scene '" + scene.name +
                           "' is an inverse-kinematics scene: it has solvers (" +
                           ik_solver_names() + "), not methods; name them in \"compare\"");
    for (const char* key : {"dt", "ks", "kd", "substeps", "iterations"})
      if (r.has(key))
        r.fail(key, "has no meaning on inverse-kinematics scene '" + scene.name + "'");
    if (step.accuracy || step.region)
      r.fail("show", "an inverse-kinematics scene has no accuracy chart nor stability region");
  }
  if (!step.compare.empty()) {
    if (step.compare.size() < 2 || step.compare.size() > 4)
      r.fail("compare", "must name 2 to 4 lanes");
    for (std::size_t k = 0; k < step.compare.size(); ++k) {
      const std::string& n = step.compare[k];
      const bool known = scene.ik ? find_ik_solver(n).has_value() : find(n).has_value();
      if (!known)
        json_reader::fail_at(r.where(), r.path("compare") + "/" + std::to_string(k),
                             "unknown " + std::string(scene.ik ? "solver" : "method") + " '" + n +
                                 "' (" + (scene.ik ? ik_solver_names() : method_names()) + ")");
      if (std::count(step.compare.begin(), step.compare.end(), n) > 1)
        r.fail("compare", "names '" + n + "' twice");
    }
    if (step.method)
      r.fail("method",
             "give either \"method\" (one lane) or \"compare\" (lanes side by side), not both");
  }
}

LessonStep read_step(ObjectReader& r, const std::string& folder, const LessonSceneOpener& open,
                     const LessonMethodFinder& find) {
  LessonStep step;
  step.title = shown_text(r, "title", kMaxTitle, true);
  if (!r.has("scene"))
    r.fail("scene", "is required: a shipped scene's name (rope, spring, ...) or a path");
  step.scene = r.text("scene", "");
  if (r.object("set"))  // {"KEY": VALUE}, as --set KEY=VALUE
    for (const auto& [key, value] : r.raw("set")->items())
      step.sets.push_back(key + "=" + json_reader::dump(value));
  if (const json* m = r.raw("method")) {
    const auto method = m->is_string() ? find(m->get<std::string>()) : std::nullopt;
    if (!method)
      r.fail("method",
             "must be a method name (" + method_names() + "), " + json_reader::describe(*m));
    step.method = method;
  }
  step.compare = strings(r, "compare");
  if (r.has("dt")) step.dt = r.number("dt", {0.0, 1.0, true, false});
  if (r.has("ks")) step.ks = r.number("ks", json_reader::non_negative(1e12));
  if (r.has("kd")) step.kd = r.number("kd", json_reader::non_negative(1e12));
  if (r.has("iterations")) step.iterations = static_cast<int>(r.integer("iterations", 1, 10000));
  if (const json* s = r.raw("substeps")) {
    if (s->is_string() && s->get<std::string>() == "auto")
      step.substeps = 0;
    else if (s->is_number())
      step.substeps = static_cast<int>(r.integer("substeps", 1, 100000));
    else
      r.fail("substeps",
             "must be \"auto\" or a whole number in [1, 100000], " + json_reader::describe(*s));
  }
  step.duration = r.number("duration", {0.0, 600.0, true, false});
  step.speed = r.number("speed", 1.0, {1.0 / 16.0, 4.0});
  if (const json* c = r.raw("chart")) step.charts = read_step_charts(r, *c);
  for (const std::string& s : strings(r, "show")) {
    if (s == "region")
      step.region = true;
    else if (s == "accuracy")
      step.accuracy = true;
    else if (s == "mode")
      step.mode = true;
    else
      r.fail("show", "may hold region, accuracy and mode, got \"" + s + "\"");
  }
  step.caption = shown_text(r, "caption", kMaxCaption, true);
  step.prompt = shown_text(r, "try", kMaxPrompt, false);
  r.expect({"events", "claims"});
  r.finish();

  // The scene, opened with the step's settings: a name or a path from the lesson's folder.
  std::string scene_path = step.scene;
  const bool path_like = scene_path.find('/') != std::string::npos || scene_path.ends_with(".json");
  if (path_like && !scene_path.starts_with("/") && !folder.empty())
    scene_path = folder + "/" + scene_path;
  Scene scene;
  try {
    scene = open(path_like ? scene_path : step.scene, step.sets);
  } catch (const InputError& e) {
    r.fail(step.sets.empty() ? "scene" : "set", e.what());
  }
  step.scene = path_like ? scene_path : step.scene;

  check_step_lanes(r, step, scene, find);
  step.script.file = r.where();
  step.script.events = read_events(r.objects("events"), scene);
  for (ObjectReader& c : r.objects("claims"))
    step.claims.push_back(read_claim(c, step, scene, find));
  return step;
}

}  // namespace

std::string LessonClaim::describe() const {
  using K = Kind;
  const std::string who = lane.empty() ? "" : lane + ": ";
  switch (kind) {
    case K::EnergyGrows:
      return who + "energy grows" + (per_step ? " by x" + precise(*per_step) + " a step" : "");
    case K::EnergyDecays:
      return who + "energy decays" + (per_step ? " by x" + precise(*per_step) + " a step" : "");
    case K::EnergyBounded:
      return who + "energy stays within " + four_digits(within) + " of its scale";
    case K::Diverges:
      return who + "diverges by t = " + four_digits(*by) + " s";
    case K::Holds:
      return who + "holds (no divergence, no instability)";
    case K::FollowsExact:
      return who + "follows the exact solution within " + four_digits(within) + " m";
    case K::Limit:
      return who + "stated stability limit h = " + four_digits(h) + " s";
    case K::StepsAdapt:
      return who + "rejects tries, step varies x" + four_digits(ratio) + " or more";
    case K::MomentumKept:
      return "momentum and angular momentum kept";
    case K::LinearMomentumKept:
      return who + "momentum kept to " + four_digits(within) + " of sum m|v|";
    case K::LinearMomentumChanges:
      return who + "momentum changes by more than " + four_digits(above) + " of sum m|v|";
    case K::DragSlows:
      return "centre of mass slows as exp(-k_drag n t / M)";
    case K::ActsAs:
      return who + "at rest acts as k_s x" + (above > 0.0 ? four_digits(above) + " or more" : "") +
             (above > 0.0 && below > 0.0 ? ", " : "") +
             (below > 0.0 ? four_digits(below) + " or less" : "");
    case K::SolverConverges:
      return who + "nears the converged implicit-Euler step by x" + four_digits(below) +
             " or less an iteration";
    case K::InternalDecays:
      return "the wiggles (motion besides the rigid one) keep under " + four_digits(below) +
             " of their kinetic energy";
    case K::OutOfReach:
      return who + "target out of reach, chain straight towards it";
    case K::PosesDiffer:
      return "solvers reach the target in poses " + four_digits(min) + " m apart or more";
    case K::Orders: {
      std::string s = "orders";
      for (const auto& [m, p] : orders) s += " " + m + " " + four_digits(p);
      return s + (best.empty() ? "" : "; most accurate for its cost: " + best);
    }
    case K::Particles:
      return "about " + four_digits(about) + " particles at t = " + four_digits(*at) + " s";
    case K::Bursts:
      return "bursts of " + std::to_string(count) + " particles";
    case K::InSight:
      return "every lane that holds in sight: at least half of its free particles in the "
             "scene's 16:9 frame";
  }
  return "";
}

double Lesson::duration() const {
  return std::accumulate(steps.begin(), steps.end(), 0.0,
                         [](double s, const LessonStep& x) { return s + x.duration; });
}

std::string lesson_name(const std::string& file_name) {
  std::string stem = file_name.substr(0, file_name.rfind('.'));
  const auto slash = stem.find_last_of('/');
  if (slash != std::string::npos) stem = stem.substr(slash + 1);
  std::size_t digits = 0;
  while (digits < stem.size() && std::isdigit(static_cast<unsigned char>(stem[digits]))) ++digits;
  if (digits > 0 && digits + 1 < stem.size() && stem[digits] == '-') return stem.substr(digits + 1);
  return stem;
}

Lesson parse_lesson(const std::string& text, const std::string& file, const LessonSceneOpener& open,
                    const LessonMethodFinder& find) {
  const std::string where = "lesson '" + file + "'";
  json doc = json_reader::parse_document(text, where);
  if (!doc.is_object())
    throw InputError(where + ": must be a JSON object with title, summary and steps");
  Lesson lesson;
  lesson.file = file;
  lesson.name = lesson_name(file);
  ObjectReader top(doc, "", where);
  top.expect({"steps"});
  lesson.title = shown_text(top, "title", kMaxTitle, true);
  lesson.summary = shown_text(top, "summary", kMaxCaption, true);
  top.finish();
  auto steps = top.objects("steps");
  if (steps.empty() || steps.size() > 12) top.fail("steps", "is required: 1 to 12 steps");
  const auto slash = file.find_last_of('/');
  const std::string folder = slash == std::string::npos ? "" : file.substr(0, slash);
  for (ObjectReader& s : steps) lesson.steps.push_back(read_step(s, folder, open, find));
  return lesson;
}

Lesson load_lesson(const std::string& path, const LessonSceneOpener& open,
                   const LessonMethodFinder& find) {
  return parse_lesson(json_reader::read_document(path, "lesson"), path, open, find);
}

}  // namespace springlab
