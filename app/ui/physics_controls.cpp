#include "ui/physics_controls.hpp"

#include <algorithm>
#include <cmath>

#include "springlab/text.hpp"

namespace springlab::ui {

std::vector<PhysicsControl> physics_controls(const app::Session& session, const UiState& ui) {
  const Simulation& sim = session.primary().sim;
  const Ranges& r = ui.ranges;
  std::vector<PhysicsControl> controls;
  if (sim.model().spring_count() > 0) {  // (a particle system has none to set)
    controls.push_back({"ks", "k_s (N/m)", session.stiffness(), r.ks / 100, r.ks * 100, true,
                        "%.3g", [](app::Session& s, double v) { s.set_stiffness(v); }});
    const double kd_max = std::max(10 * r.kd, 2 * std::sqrt(r.ks * r.mass));
    controls.push_back({"kd", "k_d (N s/m)", session.damping(), 0.0, kd_max, true, "%.3g",
                        [](app::Session& s, double v) { s.set_damping(v); }});
  }
  controls.push_back({"dt", tr("dt (s)"), sim.settings().dt, r.dt / 100,
                      std::min(1.0, std::max(0.1, r.dt * 100)), true, "%.3g",
                      [](app::Session& s, double v) { s.set_dt(v); }});
  controls.push_back({"mass", tr("mass (kg)"), session.mass(), r.mass / 100, r.mass * 100, true,
                      "%.3g", [](app::Session& s, double v) { s.set_mass(v); }});
  controls.push_back({"gravity", tr("gravity (m/s^2)"), sim.model().gravity.norm(), 0.0, 30.0,
                      false, "%.2f", [](app::Session& s, double v) {
                        const Vec3 g = s.primary().sim.model().gravity;
                        const Vec3 dir = g.norm() > 0 ? Vec3(g.normalized()) : Vec3(-Vec3::UnitY());
                        s.set_gravity(v * dir);
                      }});
  controls.push_back({"drag", tr("drag (N s/m)"), sim.model().drag, 0.0,
                      std::max(1.0, 100 * r.drag), true, "%.3g",
                      [](app::Session& s, double v) { s.set_drag(v); }});
  return controls;
}

}  // namespace springlab::ui
