// The mass-spring kind (mass_spring_kind.hpp): a lane is a method's row, with the trails, the
// free body's momentum and the inverted cells it samples each frame.
#include "session/mass_spring_kind.hpp"

#include <cmath>
#include <sstream>

#include "session/session.hpp"
#include "springlab/cells.hpp"
#include "springlab/error.hpp"
#include "springlab/text.hpp"
#include "util/data_dir.hpp"

namespace springlab::app {

namespace {

MassSpringLane& mass_spring_part(Lane& lane) {
  return dynamic_cast<MassSpringLane&>(*lane.part);
}

bool moving(const Momentum& m, const Model& model) {
  double mass = 0.0;
  for (double each : model.mass) mass += each;
  return m.linear_scale > 1e-9 * mass;
}

// A free body's momentum from when it is free and moving: at rest its scale, sum m |v|, is
// rounding's, and a change against it noise over noise. Moving: a mean speed past 1 nm/s.
void sample_momentum(MassSpringLane& part, const Simulation& sim) {
  if (!free_body(sim.model())) {
    part.free_since.reset();
  } else if (!part.free_since || !moving(*part.free_since, sim.model())) {
    part.free_since = momentum(sim.model(), sim.state());
    if (!moving(*part.free_since, sim.model())) part.free_since.reset();
  }
  const MomentumChange change =
      part.free_since && !sim.diverged()
          ? momentum_change(*part.free_since, momentum(sim.model(), sim.state()))
          : MomentumChange{std::nan(""), std::nan("")};
  part.linear_change.push(change.linear);
  part.angular_change.push(change.angular);
}

// Trails follow sane states only (a diverged lane's last good one may be far off).
void sample_trails(MassSpringLane& part, const Lane& lane, const Scene& scene) {
  const Simulation& sim = lane.sim;
  part.trails.resize(scene.trails.size());
  if (sim.diverged() || lane.sane.t != sim.state().t) return;
  for (std::size_t k = 0; k < part.trails.size(); ++k) {
    auto& trail = part.trails[k];
    trail.push_back(sim.state().x.row(scene.trails[k]).transpose());
    if (trail.size() > MassSpringLane::kTrailLength) trail.erase(trail.begin());
  }
}

class MassSpringKind final : public SceneKind {
 public:
  explicit MassSpringKind(std::vector<Method> scene_methods)
      : scene_methods_(std::move(scene_methods)) {}

  std::string_view kind_name() const override { return "mass-spring"; }

  // The rows are the method table's, in its order: row k is Method k (methods/table.cpp checks
  // the order).
  int row_count() const override { return static_cast<int>(methods().size()); }
  LaneRow row(int k) const override {
    const MethodInfo& m = methods()[static_cast<std::size_t>(k)];
    return {m.name, m.label, LaneRow::Table::Method, static_cast<int>(m.id)};
  }
  int row_of(const Lane& lane) const override {
    return static_cast<int>(lane.sim.settings().method);
  }
  std::optional<int> find(const std::string& name) const override {
    if (const std::optional<Method> m = lookup_method(name)) return static_cast<int>(*m);
    return std::nullopt;
  }
  const char* row_noun() const override { return N_("method"); }
  std::string choices() const override { return method_choices(); }
  int initial_row(const SimulationSettings& settings) const override {
    return static_cast<int>(settings.method);
  }
  std::vector<int> compared_first() const override {
    std::vector<int> rows;
    if (scene_methods_.size() >= 2)
      for (Method m : scene_methods_) rows.push_back(static_cast<int>(m));
    else
      for (const MethodInfo& m : methods())
        if (m.compared_first) rows.push_back(static_cast<int>(m.id));
    return rows;
  }

  void configure(SimulationSettings& settings, int row) const override {
    settings.method = static_cast<Method>(row);
  }
  void start(Lane& lane, int) const override { lane.part = std::make_unique<MassSpringLane>(); }
  void switch_to(Lane& lane, int row) const override {
    lane.sim.set_method(static_cast<Method>(row));
  }
  void after_steps(Lane&, Steps) const override {}
  void sample(Lane& lane, const Session& session) const override;

 private:
  std::vector<Method> scene_methods_;  // the scene's own list to compare
};

void MassSpringKind::sample(Lane& lane, const Session& session) const {
  MassSpringLane& part = mass_spring_part(lane);
  const Scene& scene = session.scene();
  const Simulation& sim = lane.sim;
  // Inverted cells: every frame, or twice a second for a box past 32768 cells (a 128^3 lattice's
  // two million take tens of milliseconds).
  if (!scene.cells.empty() && (scene.cells.size() <= 32768 || session.frame() % 30 == 0))
    part.inverted_cells =
        sim.diverged() ? 0 : springlab::inverted_cells(scene.cells, sim.state().x);
  sample_momentum(part, sim);
  sample_trails(part, lane, scene);
}

}  // namespace

const MassSpringLane* mass_spring_lane(const Lane& lane) {
  return dynamic_cast<const MassSpringLane*>(lane.part.get());
}

std::unique_ptr<SceneKind> make_mass_spring_kind(const std::vector<Method>& methods) {
  return std::make_unique<MassSpringKind>(methods);
}

}  // namespace springlab::app
