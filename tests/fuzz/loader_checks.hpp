// What a loaded scene promises every later stage (the simulation, the renderer, the scripts):
// checked by the fuzz targets after each successful load, so that a value the loader lets
// through but should not (a NaN, an index out of range) is found as surely as a crash.
#pragma once

#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "springlab/scene.hpp"

namespace springlab::fuzz {

inline void require(bool ok, const char* what) {
  if (ok) return;
  std::fprintf(stderr, "loader let through a scene that breaks: %s\n", what);
  std::abort();
}

inline void check_scene(const Scene& s) {
  const Model& m = s.model;
  const int n = m.particle_count();
  require(n > 0 && n <= kMaxParticles, "particle count in [1, kMaxParticles]");
  require(m.spring_count() <= kMaxSprings, "spring count within kMaxSprings");
  require(static_cast<int>(m.inv_mass.size()) == n && s.state.particle_count() == n,
          "one mass, inverse mass and state row per particle");
  for (int i = 0; i < n; ++i) {
    require(m.mass[i] > 0.0 && std::isfinite(m.mass[i]), "masses positive and finite");
    require(m.inv_mass[i] >= 0.0 && std::isfinite(m.inv_mass[i]), "inverse masses finite");
  }
  require(s.state.x.allFinite() && s.state.v.allFinite(), "positions and velocities finite");
  for (int k = 0; k < m.spring_count(); ++k) {
    const int a = m.spring_a[k], b = m.spring_b[k];
    require(a >= 0 && b < n && a < b, "spring ends in range, a < b");
    require(std::isfinite(m.rest_length[k]) && m.rest_length[k] >= 0.0,
            "rest lengths finite, >= 0");
    require(m.spring_material[k] < m.materials.size(), "spring materials in range");
  }
  for (const SpringMaterial& mat : m.materials)
    require(std::isfinite(mat.ks) && std::isfinite(mat.kd) && mat.ks >= 0 && mat.kd >= 0,
            "materials finite, >= 0");
  long spanned = 0;
  for (const SpringSpan& span : m.spans) spanned += span.count;
  require(spanned == m.spring_count(), "spans cover every spring once");
  require(m.gravity.allFinite() && std::isfinite(m.drag) && m.drag >= 0, "forces finite");
  for (const PlaneCollider& p : m.planes)
    require(p.point.allFinite() && std::abs(p.normal.norm() - 1.0) < 1e-9, "plane normals unit");
  for (const SphereCollider& c : m.spheres)
    require(c.center.allFinite() && c.radius > 0 && std::isfinite(c.radius), "spheres valid");
  for (const Surface& surface : s.surfaces)
    for (const auto& t : surface.triangles)
      for (int i : t) require(i >= 0 && i < n, "surface triangles index particles");
  for (int i : s.trails) require(i >= 0 && i < n, "trails index particles");
  for (const auto& [name, range] : s.named)
    require(range.first >= 0 && range.second > 0 && range.first + range.second <= n,
            "named generators index particles");
  require(!s.methods.empty(), "at least one method");
  // substeps 0 is "auto": chosen from the stability analysis, within (0, 10] times its limit.
  require(s.dt > 0 && s.dt <= 1 && s.substeps >= 0, "a usable step");
  require(s.safety > 0 && s.safety <= 10, "a usable safety fraction");
  require(s.duration > 0 && std::isfinite(s.duration), "a finite duration");
}

}  // namespace springlab::fuzz
