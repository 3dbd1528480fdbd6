#include "loading/generators.hpp"

#include <Eigen/Geometry>
#include <cmath>

namespace springlab::generators {

using json_reader::between;
using json_reader::non_negative;
using json_reader::ObjectReader;
using json_reader::positive;

void Builder::reserve(ObjectReader& r, long particles, long springs) {
  const long total_particles = static_cast<long>(x.size()) + particles;
  if (total_particles > kMaxParticles)
    r.fail("would make the scene " + std::to_string(total_particles) + " particles; the limit is " +
           std::to_string(kMaxParticles));
  springs_planned += springs;
  if (springs_planned > kMaxSprings)
    r.fail("would make the scene " + std::to_string(springs_planned) + " springs; the limit is " +
           std::to_string(kMaxSprings));
  x.reserve(total_particles);
  v.reserve(total_particles);
}

namespace {

// "pinned": node indices (negative counts from the end) or, where `corners` names them, strings.
std::vector<int> pinned_nodes(ObjectReader& r, int count, const std::vector<int>& fallback,
                              const std::map<std::string, int>& corners = {}) {
  const auto* list = r.raw("pinned");
  if (!list) return fallback;
  std::string names;
  for (const auto& [name, index] : corners) names += (names.empty() ? "" : ", ") + name;
  const std::string allowed = "node indices in [" + std::to_string(-count) + ", " +
                              std::to_string(count - 1) + "]" +
                              (names.empty() ? "" : " or corner names (" + names + ")");
  if (!list->is_array()) r.fail("pinned", "must be an array of " + allowed);
  std::vector<int> out;
  for (std::size_t k = 0; k < list->size(); ++k) {
    const auto& item = (*list)[k];
    const std::string pointer = r.path("pinned") + "/" + std::to_string(k);
    if (item.is_string() && !corners.empty()) {
      const auto it = corners.find(item.get<std::string>());
      if (it == corners.end())
        json_reader::fail_at(r.where(), pointer, "must be one of " + allowed);
      out.push_back(it->second);
      continue;
    }
    const long i = json_reader::as_integer(item, pointer, r.where(), -count, count - 1);
    out.push_back(static_cast<int>(i < 0 ? i + count : i));
  }
  return out;
}

Eigen::Matrix3d rotation_degrees(const Vec3& angles) {
  constexpr double kDeg = 3.14159265358979323846 / 180.0;
  return (Eigen::AngleAxisd(angles.z() * kDeg, Vec3::UnitZ()) *
          Eigen::AngleAxisd(angles.y() * kDeg, Vec3::UnitY()) *
          Eigen::AngleAxisd(angles.x() * kDeg, Vec3::UnitX()))
      .toRotationMatrix();
}

}  // namespace

// Node positions of a rope: equally spaced along the polyline start, via..., end, so that every
// segment starts at its rest length (a chain can start as a V, at rest, and swing down).
std::vector<Vec3> rope_nodes(const std::vector<Vec3>& corners, long nodes) {
  std::vector<double> at(corners.size(), 0.0);  // arc length at each corner
  for (std::size_t k = 1; k < corners.size(); ++k)
    at[k] = at[k - 1] + (corners[k] - corners[k - 1]).norm();
  std::vector<Vec3> p(nodes);
  std::size_t k = 1;
  for (long i = 0; i < nodes; ++i) {
    const double s = at.back() * static_cast<double>(i) / static_cast<double>(nodes - 1);
    while (k + 1 < corners.size() && s > at[k]) ++k;
    const double f = at[k] > at[k - 1] ? (s - at[k - 1]) / (at[k] - at[k - 1]) : 0.0;
    p[i] = corners[k - 1] + f * (corners[k] - corners[k - 1]);
  }
  return p;
}

void rope(ObjectReader& r, const std::string& name, Builder& b) {
  const Vec3 start = r.vec3("start");
  const Vec3 end = r.vec3("end");
  const long nodes = r.integer("nodes", 2, kMaxParticles);
  const double mass = r.number("mass", 1.0, json_reader::mass_range());
  const double stiffness = r.number("stiffness", non_negative(1e12));
  const double damping = r.number("damping", 0.0, non_negative(1e12));
  const Vec3 velocity = r.vec3("velocity", Vec3::Zero());
  std::vector<Vec3> corners{start};
  if (const auto* via = r.raw("via")) {
    if (!via->is_array()) r.fail("via", "must be an array of points [x, y, z]");
    for (std::size_t k = 0; k < via->size(); ++k) {
      const auto& q = (*via)[k];
      const std::string pointer = r.path("via") + "/" + std::to_string(k);
      if (!q.is_array() || q.size() != 3)
        json_reader::fail_at(r.where(), pointer,
                             "must be a point [x, y, z], " + json_reader::describe(q));
      Vec3 point;
      for (int c = 0; c < 3; ++c)
        point[c] =
            json_reader::as_number(q[c], pointer + "/" + std::to_string(c), r.where(), {-1e9, 1e9});
      corners.push_back(point);
    }
  }
  corners.push_back(end);
  double length = 0.0;
  for (std::size_t k = 1; k < corners.size(); ++k) length += (corners[k] - corners[k - 1]).norm();
  if (!(length > 0.0)) r.fail("end", "must differ from start (the rope needs a length)");
  b.reserve(r, nodes, nodes - 1);
  std::vector<bool> pinned(nodes, false);
  for (int i : pinned_nodes(r, static_cast<int>(nodes), {0})) pinned[i] = true;

  const std::vector<Vec3> p = rope_nodes(corners, nodes);
  // The rest length: the length along the polyline a segment spans (equal to the distance
  // between its ends except across a corner, where it is slightly longer).
  const double segment = length / static_cast<double>(nodes - 1);
  const int material = add_material(b.model, {stiffness / segment, damping / segment});
  const int first = b.model.particle_count();
  for (long i = 0; i < nodes; ++i)
    b.particle(p[i], velocity, mass / static_cast<double>(nodes), pinned[i]);
  for (long i = 0; i + 1 < nodes; ++i)
    add_spring(b.model, first + static_cast<int>(i), first + static_cast<int>(i) + 1, segment,
               material);
  b.named[name] = {first, static_cast<int>(nodes)};
}

namespace {

// The cloth's surface: two triangles a square of the lattice, node (i, j) being first + j W + i.
Surface cloth_surface(const std::string& name, int first, long W, long H) {
  const auto node = [&](long i, long j) { return first + static_cast<int>(j * W + i); };
  Surface surface{name, {}};
  surface.triangles.reserve(2 * (W - 1) * (H - 1));
  for (long j = 0; j + 1 < H; ++j)
    for (long i = 0; i + 1 < W; ++i) {
      surface.triangles.push_back({node(i, j), node(i, j + 1), node(i + 1, j)});
      surface.triangles.push_back({node(i + 1, j), node(i, j + 1), node(i + 1, j + 1)});
    }
  return surface;
}

// Every neighbour in the 3 x 3 x 3 cell around a node: edges, face and body diagonals. The
// 13 "forward" offsets visit each pair once. k_s = stiffness x rest length (see the header).
// Rest lengths from the lattice's spacing (as for the cloth), one material for each length.
// Node (i, j, k) of the n[0] x n[1] x n[2] lattice is first + (k n[1] + j) n[0] + i.
void box_springs(Builder& b, int first, const long (&n)[3], const Vec3& size, double stiffness,
                 double damping) {
  const auto index = [&](long i, long j, long k) {
    return first + static_cast<int>((k * n[1] + j) * n[0] + i);
  };
  const Vec3 spacing(size.x() / double(n[0] - 1), size.y() / double(n[1] - 1),
                     size.z() / double(n[2] - 1));
  std::map<double, int> material_by_length;
  for (long k = 0; k < n[2]; ++k)
    for (long j = 0; j < n[1]; ++j)
      for (long i = 0; i < n[0]; ++i)
        for (int dk = 0; dk <= 1; ++dk)
          for (int dj = -1; dj <= 1; ++dj)
            for (int di = -1; di <= 1; ++di) {
              if (dk == 0 && (dj < 0 || (dj == 0 && di <= 0))) continue;
              const long i2 = i + di, j2 = j + dj, k2 = k + dk;
              if (i2 < 0 || j2 < 0 || i2 >= n[0] || j2 >= n[1] || k2 >= n[2]) continue;
              const int a = index(i, j, k), c = index(i2, j2, k2);
              const double L =
                  Vec3(std::abs(di) * spacing.x(), std::abs(dj) * spacing.y(), dk * spacing.z())
                      .norm();
              auto it = material_by_length.find(L);
              if (it == material_by_length.end())
                it = material_by_length
                         .emplace(L, add_material(b.model, {stiffness * L, damping * L}))
                         .first;
              add_spring(b.model, a, c, L, it->second);
            }
}

// The box's six faces, outward: two triangles a square of the lattice on each.
Surface box_surface(const std::string& name, int first, const long (&n)[3]) {
  const auto index = [&](long i, long j, long k) {
    return first + static_cast<int>((k * n[1] + j) * n[0] + i);
  };
  Surface surface{name, {}};
  const auto quad = [&](int p00, int p10, int p01, int p11) {
    surface.triangles.push_back({p00, p10, p11});
    surface.triangles.push_back({p00, p11, p01});
  };
  for (long j = 0; j + 1 < n[1]; ++j)
    for (long i = 0; i + 1 < n[0]; ++i) {
      quad(index(i, j, 0), index(i, j + 1, 0), index(i + 1, j, 0), index(i + 1, j + 1, 0));
      const long z = n[2] - 1;
      quad(index(i, j, z), index(i + 1, j, z), index(i, j + 1, z), index(i + 1, j + 1, z));
    }
  for (long k = 0; k + 1 < n[2]; ++k)
    for (long i = 0; i + 1 < n[0]; ++i) {
      quad(index(i, 0, k), index(i + 1, 0, k), index(i, 0, k + 1), index(i + 1, 0, k + 1));
      const long y = n[1] - 1;
      quad(index(i, y, k), index(i, y, k + 1), index(i + 1, y, k), index(i + 1, y, k + 1));
    }
  for (long k = 0; k + 1 < n[2]; ++k)
    for (long j = 0; j + 1 < n[1]; ++j) {
      quad(index(0, j, k), index(0, j, k + 1), index(0, j + 1, k), index(0, j + 1, k + 1));
      const long x = n[0] - 1;
      quad(index(x, j, k), index(x, j + 1, k), index(x, j, k + 1), index(x, j + 1, k + 1));
    }
  return surface;
}

}  // namespace

void cloth(ObjectReader& r, const std::string& name, Builder& b) {
  const Vec3 center = r.vec3("center", Vec3::Zero());
  const auto* size_json = r.raw("size");
  double size[2] = {1.0, 1.0};
  if (size_json) {
    if (!size_json->is_array() || size_json->size() != 2)
      r.fail("size", "must be [width, height] in metres, " + json_reader::describe(*size_json));
    for (int k = 0; k < 2; ++k)
      size[k] = json_reader::as_number((*size_json)[k], r.path("size") + "/" + std::to_string(k),
                                       r.where(), positive(1e6));
  }
  const long W = r.integer("width", 2, 2048);
  const long H = r.integer("height", 2, 2048);
  const std::string plane = r.choice("plane", "xz", {"xz", "xy"});
  const double mass = r.number("mass", 1.0, json_reader::mass_range());
  const double stretch = r.number("stretch", non_negative(1e12));
  const double shear = r.number("shear", 0.0, non_negative(1e12));
  const double bend = r.number("bend", 0.0, non_negative(1e12));
  const double damping = r.number("damping", 0.0, non_negative(1e12));
  const Vec3 velocity = r.vec3("velocity", Vec3::Zero());
  // A spin about the centre, rad/s, as a box's: a cloth thrown turning, every lane alike.
  const Vec3 spin = r.vec3("spin", Vec3::Zero());
  const long springs = (W - 1) * H + W * (H - 1) + (shear > 0 ? 2 * (W - 1) * (H - 1) : 0) +
                       (bend > 0 ? (W - 2) * H + W * (H - 2) : 0);
  b.reserve(r, W * H, springs);
  const int count = static_cast<int>(W * H);
  const std::map<std::string, int> corners = {{"top-left", 0},
                                              {"top-right", static_cast<int>(W - 1)},
                                              {"bottom-left", static_cast<int>(W * (H - 1))},
                                              {"bottom-right", count - 1}};
  std::vector<bool> pinned(count, false);
  for (int i : pinned_nodes(r, count, {}, corners)) pinned[i] = true;

  // Node (i, j), index j W + i: i runs along +x, j along +z ("xz", lying flat, "top" = -z) or
  // down -y ("xy", hanging).
  const Vec3 across = Vec3::UnitX() * size[0];
  const Vec3 down = plane == "xz" ? Vec3(Vec3::UnitZ() * size[1]) : Vec3(-Vec3::UnitY() * size[1]);
  const Vec3 origin = center - 0.5 * across - 0.5 * down;
  const int first = b.model.particle_count();
  const double node_mass = mass / static_cast<double>(count);
  for (long j = 0; j < H; ++j)
    for (long i = 0; i < W; ++i) {
      const Vec3 x =
          origin + across * (double(i) / double(W - 1)) + down * (double(j) / double(H - 1));
      b.particle(x, velocity + spin.cross(x - center), node_mass, pinned[j * W + i]);
    }

  const auto node = [&](long i, long j) { return first + static_cast<int>(j * W + i); };
  // Rest lengths from the lattice's spacing, not from the nodes' rounded positions: every spring
  // of a kind gets the very same length, so the springs group into long spans (model.hpp).
  const double sx = size[0] / double(W - 1), sy = size[1] / double(H - 1);
  const auto spring = [&](int a, int c, double rest, int material) {
    add_spring(b.model, a, c, rest, material);
  };
  const int structural = add_material(b.model, {stretch, damping});
  for (long j = 0; j < H; ++j)
    for (long i = 0; i + 1 < W; ++i) spring(node(i, j), node(i + 1, j), sx, structural);
  for (long j = 0; j + 1 < H; ++j)
    for (long i = 0; i < W; ++i) spring(node(i, j), node(i, j + 1), sy, structural);
  if (shear > 0) {
    const int m = add_material(b.model, {shear, damping});
    const double diagonal = std::hypot(sx, sy);
    for (long j = 0; j + 1 < H; ++j)
      for (long i = 0; i + 1 < W; ++i) {
        spring(node(i, j), node(i + 1, j + 1), diagonal, m);
        spring(node(i + 1, j), node(i, j + 1), diagonal, m);
      }
  }
  if (bend > 0) {
    const int m = add_material(b.model, {bend, damping});
    for (long j = 0; j < H; ++j)
      for (long i = 0; i + 2 < W; ++i) spring(node(i, j), node(i + 2, j), 2.0 * sx, m);
    for (long j = 0; j + 2 < H; ++j)
      for (long i = 0; i < W; ++i) spring(node(i, j), node(i, j + 2), 2.0 * sy, m);
  }

  b.surfaces.push_back(cloth_surface(name, first, W, H));
  b.named[name] = {first, count};
}

void box(ObjectReader& r, const std::string& name, Builder& b) {
  const Vec3 center = r.vec3("center", Vec3::Zero());
  const Vec3 size = r.vec3("size", Vec3::Ones());
  for (int c = 0; c < 3; ++c)
    if (!(size[c] > 0.0)) r.fail("size", "must have three positive sides in metres");
  long n[3] = {3, 3, 3};
  if (const auto* nodes = r.raw("nodes")) {
    if (!nodes->is_array() || nodes->size() != 3)
      r.fail("nodes", "must be [nx, ny, nz], each in [2, 128], " + json_reader::describe(*nodes));
    for (int c = 0; c < 3; ++c)
      n[c] = json_reader::as_integer((*nodes)[c], r.path("nodes") + "/" + std::to_string(c),
                                     r.where(), 2, 128);
  }
  const double mass = r.number("mass", 1.0, json_reader::mass_range());
  const double stiffness = r.number("stiffness", non_negative(1e12));
  const double damping = r.number("damping", 0.0, non_negative(1e12));
  const Eigen::Matrix3d R = rotation_degrees(r.vec3("rotation", Vec3::Zero()));
  const Vec3 velocity = r.vec3("velocity", Vec3::Zero());
  // A spin about the centre, rad/s: each node starts at velocity + spin x (x - center), a body
  // thrown turning (a free body's angular momentum, momentum.hpp).
  const Vec3 spin = r.vec3("spin", Vec3::Zero());
  const long count = n[0] * n[1] * n[2];
  b.reserve(r, count, 13 * count);
  std::vector<bool> pinned(count, false);
  for (int i : pinned_nodes(r, static_cast<int>(count), {})) pinned[i] = true;

  const int first = b.model.particle_count();
  const auto index = [&](long i, long j, long k) {
    return first + static_cast<int>((k * n[1] + j) * n[0] + i);
  };
  for (long k = 0; k < n[2]; ++k)
    for (long j = 0; j < n[1]; ++j)
      for (long i = 0; i < n[0]; ++i) {
        const Vec3 local(size.x() * (double(i) / double(n[0] - 1) - 0.5),
                         size.y() * (double(j) / double(n[1] - 1) - 0.5),
                         size.z() * (double(k) / double(n[2] - 1) - 0.5));
        b.particle(center + R * local, velocity + spin.cross(R * local), mass / double(count),
                   pinned[index(i, j, k) - first]);
      }
  for (long k = 0; k + 1 < n[2]; ++k)
    for (long j = 0; j + 1 < n[1]; ++j)
      for (long i = 0; i + 1 < n[0]; ++i) {
        Cell cell;
        for (int c = 0; c < 8; ++c)
          cell[c] = index(i + (c & 1), j + (c >> 1 & 1), k + (c >> 2 & 1));
        b.cells.push_back(cell);
      }
  box_springs(b, first, n, size, stiffness, damping);

  b.surfaces.push_back(box_surface(name, first, n));
  b.named[name] = {first, static_cast<int>(count)};
}

}  // namespace springlab::generators
