#include "draw/scene_frame.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numbers>

#include "draw/camera.hpp"
#include "draw/palette.hpp"
#include "session/mass_spring_kind.hpp"

namespace springlab::draw {

namespace {

Vec3f f(const Eigen::RowVector3d& x) {
  return x.transpose().cast<float>();
}

Mesh surface_mesh(const Surface& surface, const State& state, Rgba front, Rgba back) {
  Mesh m;
  m.front = front;
  m.back = back;
  const int n = state.particle_count();
  m.positions.resize(n);
  m.normals.assign(n, Vec3f::Zero());
  for (int i = 0; i < n; ++i) m.positions[i] = f(state.x.row(i));
  m.indices.reserve(surface.triangles.size() * 3);
  for (const auto& t : surface.triangles) {
    const Vec3f& a = m.positions[t[0]];
    const Vec3f& b = m.positions[t[1]];
    const Vec3f& c = m.positions[t[2]];
    const Vec3f normal = (b - a).cross(c - a);  // area-weighted
    for (int k : t) m.normals[k] += normal;
    m.indices.insert(m.indices.end(),
                     {static_cast<std::uint32_t>(t[0]), static_cast<std::uint32_t>(t[1]),
                      static_cast<std::uint32_t>(t[2])});
  }
  for (Vec3f& nrm : m.normals) {
    const float length = nrm.norm();
    nrm = length > 0 ? Vec3f(nrm / length) : Vec3f::UnitY();
  }
  return m;
}

}  // namespace

ViewOptions ViewOptions::for_scene(const Scene& scene) {
  ViewOptions o;
  o.camera = scene.camera;
  const bool has_surface = !scene.surfaces.empty();
  o.springs = !has_surface;
  o.particles = !has_surface;
  std::vector<double> lengths(scene.model.rest_length);
  for (double& l : lengths)
    if (l == 0.0) l = 0.5;  // zero-length springs: a generic scale
  if (lengths.empty() && scene.model.particle_radius > 0.0) {
    o.spacing = 5.0 * scene.model.particle_radius;  // drawn at the size they collide at
  } else if (!lengths.empty()) {
    std::nth_element(lengths.begin(), lengths.begin() + lengths.size() / 2, lengths.end());
    o.spacing = lengths[lengths.size() / 2];
  } else {
    o.spacing = 0.1 * scene.camera.height;
  }
  return o;
}

Frame build_frame(const app::Session& session, const ViewOptions& options, Viewport viewport) {
  return build_frame(
      session, options,
      lane_views(session, options.camera, CompareLayout::Together, viewport).front());
}

std::vector<Frame> build_frames(const app::Session& session, const ViewOptions& options,
                                Viewport viewport) {
  std::vector<Frame> frames;
  for (const LaneView& view : lane_views(session, options.camera, options.compare_layout, viewport))
    frames.push_back(build_frame(session, options, view));
  return frames;
}

namespace {

// What the scene holds besides its particles: colliders, attractors (a small ball the size of
// the softening) and the kind's guides (an IK chain: the circles bounding what its end can reach).
void add_fixtures(Frame& frame, const Model& model, const app::SceneKind& kind,
                  const ViewOptions& options) {
  // Colliders.
  const float size = std::max(1.0f, static_cast<float>(options.spacing) * 20.0f);
  for (const PlaneCollider& p : model.planes)
    frame.planes.push_back({p.point.cast<float>(), p.normal.cast<float>(), 4.0f * size, 0.5f});
  for (const SphereCollider& s : model.spheres)
    frame.spheres.push_back({s.center.cast<float>(), static_cast<float>(s.radius), kCollider});
  // Attractors: a small ball at the centre, the size of the softening.
  for (const Attractor& a : model.attractors)
    frame.spheres.push_back({a.center.cast<float>(),
                             static_cast<float>(std::min(a.softening, 2.0 * options.spacing)),
                             kAttractor});
  // The kind's guides (an IK chain: the circles bounding what its end can reach), in the x-y plane.
  for (const app::GuideCircle& guide : kind.guides()) {
    const Vec3f centre = guide.centre.cast<float>();
    constexpr int kSegments = 128;
    for (int k = 0; k < kSegments; ++k) {
      const double a0 = 2 * std::numbers::pi * k / kSegments,
                   a1 = 2 * std::numbers::pi * (k + 1) / kSegments;
      const Vec3f p0 =
          centre + static_cast<float>(guide.radius) * Vec3f(std::cos(a0), std::sin(a0), 0.0f);
      const Vec3f p1 =
          centre + static_cast<float>(guide.radius) * Vec3f(std::cos(a1), std::sin(a1), 0.0f);
      frame.lines.push_back({p0, p1, kReach, kReach, 1.5f});
    }
  }
}

// The limiting mode (a lane analysed, not diverged): each particle's displacement in it, as an
// arrow from the particle.
void add_mode_arrows(Frame& frame, const app::Lane& lane, const State& state,
                     const ViewOptions& options) {
  const StabilityLimit& limit = lane.analysis->limit(lane.sim.settings().method);
  if (!limit.mode || limit.mode->shape.rows() != state.particle_count()) return;
  const Points& shape = limit.mode->shape;
  const double length = 3.0 * options.spacing;
  for (int i = 0; i < state.particle_count(); ++i) {
    const double size = shape.row(i).norm();
    if (size < 0.02) continue;
    const Vec3f a = f(state.x.row(i)), b = f(state.x.row(i) + length * shape.row(i));
    Rgba tip = kDiverged, tail = kDiverged;
    tail.a = 0.3f;
    tip.a = 0.4f + 0.6f * static_cast<float>(size);
    frame.lines.push_back({a, b, tail, tip, 2.5f * options.line_scale});
  }
}

// A lane's springs as lines from `state` (its last sane one when it diverged): coloured by strain
// where the kind shows strain and lanes are not compared, else in the lane's tint.
void add_lane_springs(Frame& frame, const Model& m, const State& state, Rgba tint, bool compare,
                      const app::SceneKind& kind, const ViewOptions& options, float line_width) {
  for (int k = 0; k < m.spring_count(); ++k) {
    const int a = m.spring_a[k], b = m.spring_b[k];
    const double l = (state.x.row(b) - state.x.row(a)).norm();
    const double rest = m.rest_length[k];
    const double strain = rest > 0 ? (l - rest) / rest : 0.0;
    const Rgba c = compare || !kind.strained() ? tint : strain_color(strain, options.strain_scale);
    frame.lines.push_back(
        {f(state.x.row(a)), f(state.x.row(b)), c, c, line_width});  // (sane state when diverged)
  }
}

// A mass-spring lane's trails (when shown), each fading towards its oldest end; amber, or the
// lane's tint when lanes are compared.
void add_lane_trails(Frame& frame, const app::Lane& lane, Rgba tint, bool compare,
                     const ViewOptions& options) {
  if (const app::MassSpringLane* part = app::mass_spring_lane(lane); part && options.trails)
    for (const auto& trail : part->trails)
      for (std::size_t k = 1; k < trail.size(); ++k) {
        Rgba c = compare ? tint : Rgba{1.0f, 0.78f, 0.3f, 1.0f};
        Rgba c0 = c, c1 = c;
        c0.a *= static_cast<float>(k - 1) / trail.size();
        c1.a *= static_cast<float>(k) / trail.size();
        frame.lines.push_back({trail[k - 1].cast<float>(), trail[k].cast<float>(), c0, c1, 2.0f});
      }
}

// An emitted particle (particle i, owned by the lane's emission): drawn only while alive, in its
// colour, fading out with age.
void add_emitted_particle(Frame& frame, const app::Lane& lane, const State& state, int i, bool held,
                          Rgba tint, bool compare, float radius) {
  const Emission& emission = lane.sim.emission();
  if (!emission.alive(i)) return;
  const double life = emission.lifetime(i);
  const float left =
      life > 0 ? static_cast<float>(std::clamp(1.0 - emission.age(i, state.t) / life, 0.0, 1.0))
               : 1.0f;
  const Vec3& rgb = emission.color(i);
  Rgba c = held      ? kGrabbed
           : compare ? tint
                     : Rgba{float(rgb.x()), float(rgb.y()), float(rgb.z()), 1.0f};
  c.a *= std::sqrt(left) * (lane.wild() ? 0.35f : 1.0f);
  frame.particles.push_back({f(state.x.row(i)), held ? 1.3f * radius : radius, c, false});
}

// A lane's particles: emitted ones (add_emitted_particle); the kind's handle, big enough to grab;
// the rest (pinned ones marked) where particles are shown, or pinned, held or with no surface.
void add_lane_particles(Frame& frame, const app::Session& session, const app::Lane& lane,
                        const State& state, Rgba tint, const ViewOptions& options, float radius,
                        float wpp) {
  const Scene& scene = session.scene();
  const app::SceneKind& kind = session.kind();
  const bool compare = session.comparing();
  const Model& m = lane.sim.model();
  const Emission& emission = lane.sim.emission();
  for (int i = 0; i < m.particle_count(); ++i) {
    const bool held = i == session.grabbed();
    if (emission.owned(i)) {
      add_emitted_particle(frame, lane, state, i, held, tint, compare, radius);
      continue;
    }
    const bool pinned = scene.model.pinned(i);
    if (!options.particles && !pinned && !held && !(scene.surfaces.empty())) continue;
    if (i == kind.handle()) {
      const float size = std::max(1.4f * radius, 8.0f * wpp);  // big enough to grab
      frame.particles.push_back(
          {f(state.x.row(i)), held ? 1.2f * size : size, held ? kGrabbed : kTarget, false});
      continue;
    }
    Rgba c = held ? kGrabbed : compare ? tint : kParticle;
    if (lane.sim.diverged()) c.a = 0.35f;
    frame.particles.push_back({f(state.x.row(i)), held ? 1.3f * radius : radius, c, pinned});
  }
}

}  // namespace

Frame build_frame(const app::Session& session, const ViewOptions& options, const LaneView& view) {
  Frame frame;
  frame.viewport = view.viewport;
  frame.camera = view.view;
  const float wpp = frame.camera.world_per_pixel;
  const Scene& scene = session.scene();
  const Model& model = session.primary().sim.model();

  // Sizes in pixels from the spacing: particles a fifth of a spring, lines thinner.
  const float spacing_px = static_cast<float>(options.spacing) / wpp;
  const float radius =
      std::clamp(0.2f * spacing_px, 3.0f, 13.0f) * wpp * std::sqrt(options.line_scale);
  const float line_width = std::clamp(0.07f * spacing_px, 1.5f, 4.0f) * options.line_scale;

  const app::SceneKind& kind = session.kind();
  add_fixtures(frame, model, kind, options);

  const bool compare = session.comparing();
  for (const int index : view.lanes) {
    const app::Lane& lane = session.lanes()[index];
    // A lane that diverged or is blowing up: its last sane state, faded (its last good state may
    // be blown up).
    const State& state = lane.shown();
    const Model& m = lane.sim.model();
    Rgba tint = lane_color(lane);
    if (lane.wild()) tint.a = 0.35f;

    if (options.surfaces && !compare)
      for (const Surface& s : scene.surfaces)
        frame.meshes.push_back(surface_mesh(s, state, kClothFront, kClothBack));

    if (options.springs || compare || scene.surfaces.empty())
      add_lane_springs(frame, m, state, tint, compare, kind, options, line_width);
    add_lane_trails(frame, lane, tint, compare, options);
    add_lane_particles(frame, session, lane, state, tint, options, radius, wpp);
    if (options.mode && lane.analysis && !lane.wild()) add_mode_arrows(frame, lane, state, options);
  }
  return frame;
}

Eigen::Vector3d label_anchor(const app::Lane& lane) {
  const State& s = lane.shown();
  if (s.particle_count() == 0) return Eigen::Vector3d::Zero();
  const Eigen::Vector3d lo = s.x.colwise().minCoeff().transpose(),
                        hi = s.x.colwise().maxCoeff().transpose();
  Eigen::Vector3d top = 0.5 * (lo + hi);
  top.y() = hi.y();
  return top;
}

}  // namespace springlab::draw
