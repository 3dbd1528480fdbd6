#include "springlab/script.hpp"

#include <algorithm>
#include <sstream>

#include "loading/script_events.hpp"

namespace springlab {

using json_reader::json;
using json_reader::ObjectReader;
using json_reader::positive;

namespace {

std::string three_digits(double x) {
  std::ostringstream s;
  s.precision(3);
  s << x;
  return s.str();
}

// A particle: an index, or "name:index" where name is a generator of the scene.
int particle_of(const json& value, const std::string& pointer, const std::string& where,
                const Scene& scene) {
  const int n = scene.model.particle_count();
  if (value.is_string()) {
    const std::string s = value.get<std::string>();
    const auto colon = s.rfind(':');
    if (colon != std::string::npos) {
      for (const auto& [name, range] : scene.named)
        if (name == s.substr(0, colon)) {
          const auto [first, count] = range;
          const long i = json_reader::as_integer(json::parse(s.substr(colon + 1), nullptr, false),
                                                 pointer, where, -count, count - 1);
          return first + static_cast<int>(i < 0 ? i + count : i);
        }
    }
    std::string names;
    for (const auto& [name, range] : scene.named) names += (names.empty() ? "" : ", ") + name;
    json_reader::fail_at(where, pointer,
                         "must be a particle index in [0, " + std::to_string(n - 1) +
                             "] or \"name:index\" with a generator of scene '" + scene.name +
                             "' (" + (names.empty() ? "it has none" : names) + "), got \"" + s +
                             "\"");
  }
  return static_cast<int>(json_reader::as_integer(value, pointer, where, 0, n - 1));
}

Vec3 point(const json& value, const std::string& pointer, const std::string& where) {
  if (!value.is_array() || value.size() != 3)
    json_reader::fail_at(where, pointer,
                         "must be a point [x, y, z], " + json_reader::describe(value));
  Vec3 p;
  for (int c = 0; c < 3; ++c)
    p[c] = json_reader::as_number(value[c], pointer + "/" + std::to_string(c), where, {-1e9, 1e9});
  return p;
}

ScriptEvent read_event(ObjectReader& r, const Scene& scene) {
  ScriptEvent e;
  e.t = r.number("t", json_reader::non_negative(1e7));
  const char* actions[] = {"grab", "path", "move", "release", "set", "pause", "resume", "reset"};
  int found = 0;
  for (const char* a : actions) found += r.has(a);
  if (found != 1)
    r.fail("must have exactly one action: grab, path, move, release, set, pause, resume or reset");

  if (const json* g = r.raw("grab")) {
    e.kind = ScriptEvent::Kind::Grab;
    if (g->is_object()) {
      ObjectReader near(*g, r.path("grab"), r.where());
      e.near = near.vec3("near");
      near.finish();
    } else {
      e.particle = particle_of(*g, r.path("grab"), r.where(), scene);
    }
  } else if (const json* p = r.raw("path")) {
    e.kind = ScriptEvent::Kind::Path;
    if (!p->is_array() || p->empty())
      r.fail("path", "must be a non-empty array of waypoints [dt, x, y, z]");
    double last = -1.0;
    for (std::size_t k = 0; k < p->size(); ++k) {
      const json& w = (*p)[k];
      const std::string pointer = r.path("path") + "/" + std::to_string(k);
      if (!w.is_array() || w.size() != 4)
        json_reader::fail_at(r.where(), pointer,
                             "must be a waypoint [dt, x, y, z], " + json_reader::describe(w));
      const double dt = json_reader::as_number(w[0], pointer + "/0", r.where(), {0.0, 1e7});
      if (dt <= last)
        json_reader::fail_at(r.where(), pointer + "/0",
                             "waypoint times must increase, got " + three_digits(dt) + " after " +
                                 three_digits(last));
      last = dt;
      Vec3 x;
      for (int c = 0; c < 3; ++c)
        x[c] = json_reader::as_number(w[c + 1], pointer + "/" + std::to_string(c + 1), r.where(),
                                      {-1e9, 1e9});
      e.path.emplace_back(dt, x);
    }
  } else if (const json* m = r.raw("move")) {
    e.kind = ScriptEvent::Kind::Move;
    const Vec3 to = point(*m, r.path("move"), r.where());
    const double over = r.number("over", positive(1e7));
    e.path = {{over, to}};
  } else if (r.has("set")) {
    e.kind = ScriptEvent::Kind::Set;
    ObjectReader s = *r.object("set");
    if (const json* name = s.raw("method")) {
      const auto m = name->is_string() ? find_method(name->get<std::string>()) : std::nullopt;
      if (!m)
        s.fail("method",
               "must be a method name (" + method_names() + "), " + json_reader::describe(*name));
      e.method = m;
    }
    if (s.has("ks")) e.ks = s.number("ks", json_reader::non_negative(1e12));
    if (s.has("kd")) e.kd = s.number("kd", json_reader::non_negative(1e12));
    if (s.has("dt")) e.dt = s.number("dt", {0.0, 1.0, true, false});
    if (s.has("substeps")) e.substeps = static_cast<int>(s.integer("substeps", 1, 100000));
    if (s.has("gravity")) e.gravity = s.vec3("gravity");
    if (s.has("drag")) e.drag = s.number("drag", json_reader::non_negative(1e9));
    if (s.has("friction")) e.friction = s.number("friction", json_reader::non_negative(100.0));
    if (s.has("mass")) e.mass = s.number("mass", json_reader::mass_range());
    if (s.has("speed")) e.speed = s.number("speed", {1.0 / 16.0, 4.0});
    s.finish();
  } else {
    const char* key = r.has("release")  ? "release"
                      : r.has("pause")  ? "pause"
                      : r.has("resume") ? "resume"
                                        : "reset";
    if (!r.boolean(key, false)) r.fail(key, "must be true");
    e.kind = key == std::string("release")  ? ScriptEvent::Kind::Release
             : key == std::string("pause")  ? ScriptEvent::Kind::Pause
             : key == std::string("resume") ? ScriptEvent::Kind::Resume
                                            : ScriptEvent::Kind::Reset;
  }
  r.finish();
  return e;
}

}  // namespace

std::vector<ScriptEvent> read_events(std::vector<ObjectReader> events, const Scene& scene) {
  std::vector<ScriptEvent> out;
  out.reserve(events.size());
  for (auto& e : events) out.push_back(read_event(e, scene));
  std::stable_sort(out.begin(), out.end(),
                   [](const ScriptEvent& a, const ScriptEvent& b) { return a.t < b.t; });
  return out;
}

std::string ScriptEvent::describe() const {
  std::string s = "t = " + three_digits(t) + " s: ";
  switch (kind) {
    case Kind::Grab:
      return s + (near ? "grab the particle nearest (" + three_digits(near->x()) + ", " +
                             three_digits(near->y()) + ", " + three_digits(near->z()) + ")"
                       : "grab particle " + std::to_string(particle));
    case Kind::Path:
      return s + "drag along " + std::to_string(path.size()) + " waypoints";
    case Kind::Move:
      return s + "drag to (" + three_digits(path[0].second.x()) + ", " +
             three_digits(path[0].second.y()) + ", " + three_digits(path[0].second.z()) + ")";
    case Kind::Release:
      return s + "release";
    case Kind::Pause:
      return s + "pause";
    case Kind::Resume:
      return s + "resume";
    case Kind::Reset:
      return s + "reset";
    case Kind::Set: {
      std::string what;
      const auto add = [&](const std::string& x) { what += (what.empty() ? "" : ", ") + x; };
      if (method) add(std::string("method ") + method_info(*method).name);
      if (ks) add("k_s " + three_digits(*ks));
      if (kd) add("k_d " + three_digits(*kd));
      if (dt) add("dt " + three_digits(*dt));
      if (substeps) add("substeps " + std::to_string(*substeps));
      if (gravity) add("gravity " + three_digits(gravity->y()));
      if (drag) add("drag " + three_digits(*drag));
      if (friction) add("friction " + three_digits(*friction));
      if (mass) add("mass " + three_digits(*mass));
      if (speed) add("speed " + three_digits(*speed));
      return s + "set " + what;
    }
  }
  return s;
}

double Script::end_time() const {
  double end = 0.0;
  for (const ScriptEvent& e : events)
    end = std::max(end, e.t + (e.path.empty() ? 0.0 : e.path.back().first));
  return end;
}

Script parse_script(const std::string& text, const std::string& file, const Scene& scene) {
  const std::string where = "script '" + file + "'";
  json doc = json_reader::parse_document(text, where);
  Script script;
  script.file = file;
  ObjectReader top(doc, "", where);
  top.expect({"description", "events"});
  top.finish();
  script.description = top.text("description", "");
  auto events = top.objects("events");
  if (events.empty()) top.fail("events", "is required: a non-empty array of events");
  script.events = read_events(std::move(events), scene);
  return script;
}

Script load_script(const std::string& path, const Scene& scene) {
  return parse_script(json_reader::read_document(path, "script"), path, scene);
}

Vec3 path_position(const std::vector<std::pair<double, Vec3>>& path, double elapsed) {
  if (elapsed <= path.front().first) return path.front().second;
  for (std::size_t k = 1; k < path.size(); ++k)
    if (elapsed <= path[k].first) {
      const double s = (elapsed - path[k - 1].first) / (path[k].first - path[k - 1].first);
      return path[k - 1].second + s * (path[k].second - path[k - 1].second);
    }
  return path.back().second;
}

}  // namespace springlab
