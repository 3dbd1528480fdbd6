// The mass-spring kind (scene_kind.hpp): a lane is a method's row, its simulation all it has.
#include <sstream>

#include "session/scene_kind.hpp"
#include "session/session.hpp"
#include "springlab/error.hpp"
#include "springlab/text.hpp"
#include "util/data_dir.hpp"

namespace springlab::app {

namespace {

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
  int initial_row(Method method) const override { return static_cast<int>(method); }
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
  void start(Lane&, int) const override {}
  void switch_to(Lane& lane, int row) const override {
    lane.sim.set_method(static_cast<Method>(row));
  }
  void after_steps(Lane&, Steps) const override {}
  void sample(Lane&) const override {}

 private:
  std::vector<Method> scene_methods_;  // the scene's own list to compare
};

}  // namespace

std::unique_ptr<SceneKind> make_mass_spring_kind(const std::vector<Method>& methods) {
  return std::make_unique<MassSpringKind>(methods);
}

}  // namespace springlab::app
