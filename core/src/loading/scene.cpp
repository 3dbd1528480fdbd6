#include "springlab/scene.hpp"

#include <filesystem>
#include <map>
#include <sstream>

#include "loading/emitter_scene.hpp"
#include "loading/generators.hpp"
#include "loading/ik_scene.hpp"
#include "loading/json_reader.hpp"
#include "springlab/stability.hpp"

namespace springlab {

using json_reader::between;
using json_reader::json;
using json_reader::non_negative;
using json_reader::ObjectReader;
using json_reader::positive;

namespace {

// --set KEY=VALUE: the value as JSON when it parses as JSON, a comma-separated list of numbers
// as an array, anything else as a string.
json parse_value(const std::string& text) {
  json value = json::parse(text, nullptr, false);
  if (!value.is_discarded()) return value;
  if (text.find(',') != std::string::npos) {
    value = json::parse("[" + text + "]", nullptr, false);
    if (!value.is_discarded()) return value;
  }
  return text;
}

void apply_override(json& doc, const std::string& assignment, const std::string& file) {
  const auto bad = [&](const std::string& what) {
    throw InputError("--set " + assignment + ": " + what);
  };
  const auto eq = assignment.find('=');
  if (eq == std::string::npos || eq == 0) bad("expected KEY=VALUE, for example cloth.width=64");
  const std::string key = assignment.substr(0, eq);
  std::vector<std::string> parts;
  std::stringstream stream(key);
  for (std::string part; std::getline(stream, part, '.');) parts.push_back(part);

  json* node = &doc;
  for (std::size_t k = 0; k < parts.size(); ++k) {
    const std::string& part = parts[k];
    const bool last = k + 1 == parts.size();
    if (node->is_array()) {
      char* end = nullptr;
      const long index = std::strtol(part.c_str(), &end, 10);
      if (part.empty() || *end != '\0' || index < 0 || index >= static_cast<long>(node->size()))
        bad("'" + part + "' is not an index of " + std::to_string(node->size()) + " elements");
      node = &(*node)[index];
      if (last) *node = parse_value(assignment.substr(eq + 1));  // "methods.0=rk4"
      continue;
    }
    if (!node->is_object()) bad("'" + part + "' goes inside a value that has no fields");
    if (k == 0 && !node->contains(part) && doc.contains("generators") &&
        doc["generators"].is_array()) {
      // A generator by name (its "name", or its "type" when it has no name). Either may be of
      // any type here: the loader reports that later, with its path.
      const auto is_named = [&](const json& g) {
        auto label = g.find("name");
        if (label == g.end()) label = g.find("type");
        return label != g.end() && label->is_string() && label->get<std::string>() == part;
      };
      json* found = nullptr;
      for (auto& g : doc["generators"])
        if (g.is_object() && is_named(g)) found = &g;
      if (found && !last) {
        node = found;
        continue;
      }
    }
    if (last) {
      (*node)[part] = parse_value(assignment.substr(eq + 1));
      return;
    }
    if (!node->contains(part))
      bad("scene '" + file + "' has no field '" + part + "' (nor a generator of that name)");
    node = &(*node)[part];
  }
}

// A particle reference in a spring: a global index, or "name:index" into a generator's nodes
// (negative indices count from the end).
int particle_ref(const json& value, const std::string& pointer, const std::string& where, int total,
                 const std::map<std::string, std::pair<int, int>>& named) {
  if (value.is_string()) {
    const std::string s = value.get<std::string>();
    const auto colon = s.rfind(':');
    const auto it = colon == std::string::npos ? named.end() : named.find(s.substr(0, colon));
    if (it == named.end())
      json_reader::fail_at(where, pointer,
                           "must be a particle index or \"generator:index\" with a generator "
                           "named in this scene, got \"" +
                               s + "\"");
    const auto [first, count] = it->second;
    const long i = json_reader::as_integer(json::parse(s.substr(colon + 1), nullptr, false),
                                           pointer, where, -count, count - 1);
    return first + static_cast<int>(i < 0 ? i + count : i);
  }
  return static_cast<int>(json_reader::as_integer(value, pointer, where, 0, total - 1));
}

Camera read_camera(ObjectReader& top, View view, const std::vector<Vec3>& x) {
  Camera camera;
  camera.view = view;
  // Defaults frame the initial bounding box.
  Vec3 lo = Vec3::Constant(-1.0), hi = Vec3::Constant(1.0);
  if (!x.empty()) {
    lo = hi = x.front();
    for (const Vec3& p : x) {
      lo = lo.cwiseMin(p);
      hi = hi.cwiseMax(p);
    }
  }
  const double extent = std::max(1.0, (hi - lo).norm());
  camera.target = 0.5 * (lo + hi);
  camera.height = 1.4 * std::max(hi.y() - lo.y(), 0.6 * (hi.x() - lo.x())) + 0.5;
  camera.distance = 1.8 * extent;
  auto r = top.object("camera");
  if (!r) return camera;
  camera.target = r->vec3("target", camera.target);
  if (view == View::Planar) {
    camera.height = r->number("height", camera.height, positive(1e6));
  } else {
    camera.distance = r->number("distance", camera.distance, positive(1e6));
    camera.yaw = r->number("yaw", camera.yaw, between(-360.0, 360.0));
    camera.pitch = r->number("pitch", camera.pitch, between(-89.0, 89.0));
    camera.fov = r->number("fov", camera.fov, between(10.0, 120.0));
  }
  r->finish();
  return camera;
}

// The "ik" object: the chain (ik_scene.hpp), the target, the solvers and their settings; its
// joints and target become pinned particles, its links springs of no stiffness.
IkScene read_ik_scene(ObjectReader& r, generators::Builder& b) {
  IkScene ik;
  ik.chain = read_ik_chain(r);
  const Vec3 target = r.vec3("target");
  if (target.z() != 0.0) r.fail("target", "must lie in the chain's plane: z = 0");
  if (const json* list = r.raw("solvers")) {
    if (!list->is_array() || list->empty())
      r.fail("solvers", "must be a non-empty array of solver names (" + ik_solver_names() + ")");
    for (std::size_t k = 0; k < list->size(); ++k) {
      const json& item = (*list)[k];
      const auto solver = item.is_string() ? find_ik_solver(item.get<std::string>()) : std::nullopt;
      if (!solver)
        json_reader::fail_at(
            r.where(), r.path("solvers") + "/" + std::to_string(k),
            "unknown solver " + item.dump() + " (solvers: " + ik_solver_names() + ")");
      ik.solvers.push_back(*solver);
    }
  } else {
    for (const IkSolverInfo& info : ik_solvers()) ik.solvers.push_back(info.id);
  }
  ik.settings.tolerance = r.number("tolerance", 1e-3, positive(1e3));
  ik.settings.damping = r.number("damping", ik.settings.damping, positive(10.0));
  ik.settings.max_iterations =
      static_cast<int>(r.integer("max_iterations", ik.settings.max_iterations, 1, 1000000));
  ik.iterations_per_frame = static_cast<int>(r.integer("iterations_per_frame", 1, 1, 10000));

  const std::vector<Eigen::Vector2d> joints = ik.chain.positions();
  b.reserve(r, static_cast<long>(joints.size()) + 1, static_cast<long>(joints.size()) - 1);
  ik.first_joint = b.model.particle_count();
  for (const Eigen::Vector2d& p : joints)
    b.particle(Vec3(p.x(), p.y(), 0.0), Vec3::Zero(), 1.0, true);
  ik.target = b.particle(target, Vec3::Zero(), 1.0, true);
  const int link = add_material(b.model, {0.0, 0.0});
  for (int i = 0; i < ik.chain.size(); ++i)
    add_spring(b.model, ik.first_joint + i, ik.first_joint + i + 1, ik.chain.lengths[i], link);
  b.named["chain"] = {ik.first_joint, static_cast<int>(joints.size())};
  b.named["target"] = {ik.target, 1};
  return ik;
}

// The forces (gravity, drag, wind, attractors, Verlet's damping) and the colliders.
void read_forces(ObjectReader& top, Model& model) {
  model.gravity = top.vec3("gravity", Vec3::Zero());
  model.drag = top.number("drag", 0.0, non_negative(1e9));
  model.wind = top.vec3("wind", Vec3::Zero());
  if (model.wind.norm() > 0.0 && model.drag == 0.0)
    top.fail("wind",
             "needs \"drag\" above 0: the air pushes particles through drag, f = -drag (v - wind)");
  for (auto& a : top.objects("attractors")) {
    model.attractors.push_back(read_attractor(a));
    a.finish();
  }
  model.verlet_damping = top.number("verlet_damping", 0.0, {0.0, 1.0, false, true});
  model.particle_radius = top.number("particle_radius", 0.0, non_negative(1e3));
  for (auto& c : top.objects("colliders")) {
    const std::string type = c.choice("type", "", {"plane", "sphere"});
    const double friction = c.number("friction", 0.0, non_negative(100.0));
    const double restitution = c.number("restitution", 0.0, between(0.0, 1.0));
    if (type == "plane") {
      const Vec3 point = c.vec3("point", Vec3::Zero());
      const Vec3 normal = c.vec3("normal", Vec3::UnitY());
      if (!(normal.norm() > 1e-12))
        c.fail("normal", "must not be zero: it is the plane's direction");
      model.planes.push_back({point, normal.normalized(), friction, restitution});
    } else {
      const Vec3 center = c.vec3("center");
      const double radius = c.number("radius", positive(1e6));
      model.spheres.push_back({center, radius, friction, restitution});
    }
    c.finish();
  }
}

// "methods": the rows to compare, by name (symplectic Euler when none is given).
std::vector<Method> read_methods(ObjectReader& top, const std::string& where) {
  std::vector<Method> out;
  if (const json* list = top.raw("methods")) {
    if (!list->is_array() || list->empty())
      top.fail("methods", "must be a non-empty array of method names (" + method_names() + ")");
    for (std::size_t k = 0; k < list->size(); ++k) {
      const json& item = (*list)[k];
      const std::string pointer = top.path("methods") + "/" + std::to_string(k);
      const auto m = item.is_string() ? find_method(item.get<std::string>()) : std::nullopt;
      if (!m) {
        std::vector<std::string> names;
        for (const auto& info : methods()) names.emplace_back(info.name);
        const std::string near =
            item.is_string() ? closest_match(item.get<std::string>(), names.data(), names.size())
                             : "";
        // A value that is not a string is described, not printed: printing a deeply nested
        // array recurses as deep as it is nested.
        json_reader::fail_at(
            where, pointer,
            (item.is_string() ? "unknown method " + json_reader::dump(item)
                              : "must be a method name, " + json_reader::describe(item)) +
                (near.empty() ? "" : "; did you mean \"" + near + "\"?") +
                " (methods: " + method_names() + ")");
      }
      out.push_back(*m);
    }
  } else {
    out = {Method::SymplecticEuler};
  }
  return out;
}

// "substeps": a whole number fixes them, "auto" (the default, 0) chooses them from the limit.
int read_substeps(ObjectReader& top) {
  const json* sub = top.raw("substeps");
  if (!sub) return 0;
  if (!sub->is_string()) return static_cast<int>(top.integer("substeps", 1, 1, 100000));
  if (sub->get<std::string>() != "auto")
    top.fail("substeps",
             "must be \"auto\" or a whole number in [1, 100000], got " + json_reader::dump(*sub));
  return 0;
}

// How to run it: the methods, dt, sub-steps, the safe fraction, the duration, the tolerance.
void read_run(ObjectReader& top, Scene& scene, const std::string& where) {
  scene.methods = read_methods(top, where);
  scene.dt = top.number("dt", 0.01, {0.0, 1.0, true, false});
  scene.substeps = read_substeps(top);
  scene.safety = top.number("safety", kSafeFraction, {0.0, 10.0, true, false});
  scene.duration = top.number("duration", 10.0, positive(1e7));
  scene.tolerance = top.number("tolerance", 1e-4, {0.0, 1.0, true, false});
}

// "trails": the particles whose paths are drawn behind them.
std::vector<int> read_trails(ObjectReader& top, const std::string& where, int total,
                             const std::map<std::string, std::pair<int, int>>& named) {
  std::vector<int> out;
  if (const json* trails = top.raw("trails")) {
    if (!trails->is_array()) top.fail("trails", "must be an array of particle indices");
    for (std::size_t k = 0; k < trails->size(); ++k)
      out.push_back(particle_ref((*trails)[k], top.path("trails") + "/" + std::to_string(k), where,
                                 total, named));
  }
  return out;
}

// Particles declared one by one.
void read_particles(ObjectReader& top, generators::Builder& builder) {
  auto particles = top.objects("particles");
  if (static_cast<long>(particles.size()) > kMaxParticles)
    top.fail("particles", "has " + std::to_string(particles.size()) + " particles; the limit is " +
                              std::to_string(kMaxParticles));
  for (auto& p : particles) {
    const Vec3 position = p.vec3("position");
    const Vec3 velocity = p.vec3("velocity", Vec3::Zero());
    const double mass = p.number("mass", 1.0, json_reader::mass_range());
    const bool pinned = p.boolean("pinned", false);
    p.finish();
    builder.particle(position, velocity, mass, pinned);
  }
}

// Generators (rope, cloth, box), each under a name of its own; then an inverse-kinematics part,
// a scene of its own.
void read_generators(ObjectReader& top, generators::Builder& builder, Scene& scene) {
  std::map<std::string, std::pair<int, int>>& named = builder.named;
  for (auto& g : top.objects("generators")) {
    const std::string type = g.choice("type", "", {"rope", "cloth", "box"});
    const std::string name = g.text("name", type);
    if (named.count(name)) g.fail("name", "\"" + name + "\" is already the name of a generator");
    if (type == "rope")
      generators::rope(g, name, builder);
    else if (type == "cloth")
      generators::cloth(g, name, builder);
    else
      generators::box(g, name, builder);
    g.finish();
  }
  if (auto ik = top.object("ik")) {
    if (builder.model.particle_count() > 0)
      top.fail("ik", "is a scene of its own: leave out \"particles\" and \"generators\"");
    scene.ik = read_ik_scene(*ik, builder);
    ik->finish();
  }
}

// The emitters, whose pools follow every other particle.
void read_emitters(ObjectReader& top, generators::Builder& builder) {
  const std::map<std::string, std::pair<int, int>>& named = builder.named;
  for (auto& e : top.objects("emitters")) {
    const std::string name = e.text("name", "emitter");
    if (named.count(name) || named.count(name + "-sparks"))
      e.fail("name", "\"" + name + "\" is already the name of a generator or emitter");
    read_emitter(e, name, builder);
    e.finish();
  }
}

// Springs declared one by one, between particles by index or by a generator's name and index
// (`total`: the particles before the emitters').
void read_springs(ObjectReader& top, generators::Builder& builder, int total,
                  const std::string& where) {
  Model& model = builder.model;
  const std::vector<Vec3>& x = builder.x;
  const std::map<std::string, std::pair<int, int>>& named = builder.named;
  auto springs = top.objects("springs");
  builder.springs_planned += static_cast<long>(springs.size());
  if (builder.springs_planned > kMaxSprings)
    top.fail("springs", "would make " + std::to_string(builder.springs_planned) +
                            " springs; the limit is " + std::to_string(kMaxSprings));
  // Materials by (k_s, k_d), starting from the generators': a lookup per spring, not add_material's
  // scan of every material so far, which made a file of N distinct springs load in N^2 steps.
  std::map<std::pair<double, double>, int> material_of;
  for (std::size_t m = 0; m < model.materials.size(); ++m)
    material_of.try_emplace({model.materials[m].ks, model.materials[m].kd}, static_cast<int>(m));
  for (auto& s : springs) {
    const json* a_json = s.raw("a");
    const json* b_json = s.raw("b");
    if (!a_json || !b_json) s.fail("needs both ends: \"a\" and \"b\" (particle indices)");
    const int a = particle_ref(*a_json, s.path("a"), where, total, named);
    const int b = particle_ref(*b_json, s.path("b"), where, total, named);
    if (a == b)
      s.fail("b", "is the same particle as \"a\" (" + std::to_string(a) + "): a spring needs two");
    const double distance = (x[b] - x[a]).norm();
    const double rest = s.number("rest_length", distance, non_negative(1e9));
    const double ks = s.number("ks", non_negative(1e12));
    const double kd = s.number("kd", 0.0, non_negative(1e12));
    s.finish();
    if (rest > 0.0 && distance == 0.0)
      s.fail("its ends start at the same point (particles " + std::to_string(a) + " and " +
             std::to_string(b) +
             "), so the spring has no direction: move one, or give it rest_length 0");
    const auto [material, added] =
        material_of.try_emplace({ks, kd}, static_cast<int>(model.materials.size()));
    if (added) {
      if (model.materials.size() == 65535)
        top.fail("springs", "use more than 65535 distinct (ks, kd) pairs");
      model.materials.push_back({ks, kd});
    }
    add_spring(model, a, b, rest, material->second);
  }
}

}  // namespace

Scene parse_scene(const std::string& text, const std::string& file,
                  const std::vector<std::string>& overrides) {
  const std::string where = "scene '" + file + "'";
  json doc = json_reader::parse_document(text, where);
  for (const std::string& o : overrides) apply_override(doc, o, file);

  Scene scene;
  scene.file = file;
  scene.name = std::filesystem::path(file).stem().string();
  ObjectReader top(doc, "", where);
  top.expect({"description", "view",           "particles",       "generators", "emitters",
              "ik",          "springs",        "gravity",         "drag",       "wind",
              "attractors",  "verlet_damping", "particle_radius", "colliders",  "methods",
              "dt",          "substeps",       "safety",          "duration",   "tolerance",
              "camera",      "trails"});
  top.finish();  // a misspelt field first: it may be why something else looks missing
  scene.description = top.text("description", "");
  const View view = top.choice("view", "3d", {"2d", "3d"}) == "2d" ? View::Planar : View::Orbit;

  Model& model = scene.model;
  std::vector<Vec3> x, v;
  std::map<std::string, std::pair<int, int>> named;
  generators::Builder builder{model, x, v, scene.surfaces, scene.cells, named};

  read_particles(top, builder);
  read_generators(top, builder, scene);

  // Springs and plain indices refer to these; the emitters' pools follow them.
  const int total = model.particle_count();
  read_emitters(top, builder);
  if (model.particle_count() == 0)
    top.fail("declares no particles: add \"particles\", \"generators\" or \"emitters\"");
  read_springs(top, builder, total, where);
  if (model.materials.size() > 65535)
    top.fail("springs", "use more than 65535 distinct (ks, kd) pairs");
  finalize(model);

  read_forces(top, model);

  read_run(top, scene, where);
  scene.camera = read_camera(top, view, x);
  scene.trails = read_trails(top, where, total, named);
  top.finish();

  const int count = model.particle_count();
  scene.state.resize(count);
  for (int i = 0; i < count; ++i) {
    scene.state.x.row(i) = x[i].transpose();
    scene.state.v.row(i) =
        model.pinned(i) ? Eigen::RowVector3d::Zero() : Eigen::RowVector3d(v[i].transpose());
  }
  scene.state.t = 0.0;
  scene.named.assign(named.begin(), named.end());
  return scene;
}

Scene load_scene(const std::string& path, const std::vector<std::string>& overrides) {
  return parse_scene(json_reader::read_document(path, "scene"), path, overrides);
}

}  // namespace springlab
