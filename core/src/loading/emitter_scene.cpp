#include "loading/emitter_scene.hpp"

#include <cmath>
#include <numbers>

namespace springlab {

using json_reader::between;
using json_reader::json;
using json_reader::non_negative;
using json_reader::ObjectReader;
using json_reader::positive;

namespace {

constexpr double kDegree = std::numbers::pi / 180.0;

Vec3 unit(ObjectReader& r, const char* key, const Vec3& fallback) {
  const Vec3 d = r.vec3(key, fallback);
  if (!(d.norm() > 1e-12)) r.fail(key, "must not be zero: it is a direction");
  return d.normalized();
}

// speed, speed_spread, direction, spread (degrees), lifetime, lifetime_spread, mass.
Spawn read_spawn(ObjectReader& r, double default_spread) {
  Spawn s;
  s.speed = r.number("speed", 1.0, non_negative(1e6));
  s.speed_spread = r.number("speed_spread", 0.0, non_negative(1e6));
  if (s.speed_spread > s.speed)
    r.fail("speed_spread",
           "must not exceed \"speed\" (" + json(s.speed).dump() + "): a speed is never negative");
  s.direction = unit(r, "direction", Vec3::UnitY());
  s.cone = r.number("spread", default_spread, between(0.0, 180.0)) * kDegree;
  s.lifetime = r.number("lifetime", 1.0, positive(1e6));
  s.lifetime_spread = r.number("lifetime_spread", 0.0, non_negative(1e6));
  if (s.lifetime_spread >= s.lifetime)
    r.fail("lifetime_spread", "must be less than \"lifetime\" (" + json(s.lifetime).dump() +
                                  "): every particle lives a while");
  s.mass = r.number("mass", 0.01, positive(1e9));
  return s;
}

std::vector<Vec3> read_colors(ObjectReader& r) {
  std::vector<Vec3> colors;
  const json* list = r.raw("colors");
  if (!list) return colors;
  if (!list->is_array() || list->empty() || list->size() > 64)
    r.fail("colors", "must be an array of 1 to 64 colours [r, g, b], each in [0, 1]");
  for (std::size_t k = 0; k < list->size(); ++k) {
    const json& c = (*list)[k];
    const std::string pointer = r.path("colors") + "/" + std::to_string(k);
    if (!c.is_array() || c.size() != 3)
      json_reader::fail_at(
          r.where(), pointer,
          "must be a colour [r, g, b], each in [0, 1], " + json_reader::describe(c));
    Vec3 rgb;
    for (int i = 0; i < 3; ++i)
      rgb[i] = json_reader::as_number(c[i], pointer + "/" + std::to_string(i), r.where(),
                                      between(0.0, 1.0));
    colors.push_back(rgb);
  }
  return colors;
}

Pool make_pool(ObjectReader& r, const char* key, long fallback, generators::Builder& b,
               const Vec3& at, double mass) {
  const long max = r.integer(key, fallback, 1, kMaxPool);
  b.reserve(r, max, 0);
  Pool pool{b.model.particle_count(), static_cast<int>(max)};
  for (long i = 0; i < max; ++i) b.particle(at, Vec3::Zero(), mass, true);
  return pool;
}

}  // namespace

void read_emitter(ObjectReader& r, const std::string& name, generators::Builder& b) {
  Emitter e;
  e.name = name;
  e.position = r.vec3("position");
  const std::string shape = r.choice("shape", "point", {"point", "disc", "ball"});
  e.shape = shape == "disc"   ? EmitterShape::Disc
            : shape == "ball" ? EmitterShape::Ball
                              : EmitterShape::Point;
  e.radius = r.number("radius", 0.0, non_negative(1e6));
  if (e.shape != EmitterShape::Point && !(e.radius > 0.0))
    r.fail("radius", "must be above 0 for a " + shape + " (in metres)");
  e.rate = r.number("rate", non_negative(kMaxRate));
  e.start = r.number("start", 0.0, non_negative(1e7));
  e.stop = r.number("stop", 1e7, non_negative(1e7));
  if (e.stop < e.start)
    r.fail("stop", "must not come before \"start\" (" + json(e.start).dump() + " s)");
  e.seed = static_cast<std::uint64_t>(r.integer("seed", 1, 0, std::int64_t{1} << 53));
  e.spawn = read_spawn(r, 0.0);
  e.colors = read_colors(r);
  e.pool = make_pool(r, "max", 1000, b, e.position, e.spawn.mass);
  b.named[name] = {e.pool.first, e.pool.capacity};
  if (auto burst = r.object("burst")) {
    Emitter::Burst s;
    s.count = static_cast<int>(burst->integer("count", 1, 10000));
    s.spawn = read_spawn(*burst, 180.0);
    s.colors = read_colors(*burst);
    s.pool = make_pool(*burst, "max", std::min<long>(kMaxPool, 10L * s.count), b, e.position,
                       s.spawn.mass);
    if (s.pool.capacity < s.count)
      burst->fail("max", "must hold at least one burst (" + std::to_string(s.count) + " sparks)");
    burst->finish();
    b.named[name + "-sparks"] = {s.pool.first, s.pool.capacity};
    e.burst = std::move(s);
  }
  b.model.emitters.push_back(std::move(e));
}

Attractor read_attractor(ObjectReader& r) {
  Attractor a;
  a.center = r.vec3("center");
  a.strength = r.number("strength", 0.0, between(-1e9, 1e9));
  a.softening = r.number("softening", 0.1, positive(1e6));
  a.swirl = r.number("swirl", 0.0, between(-1e9, 1e9));
  a.axis = unit(r, "axis", Vec3::UnitY());
  if (a.strength == 0.0 && a.swirl == 0.0)
    r.fail(
        "does nothing: give it a \"strength\" (pull, m^3/s^2) or a \"swirl\" (m^2/s^2), or both");
  return a;
}

}  // namespace springlab
