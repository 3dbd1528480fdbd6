// What every scene kind shares (scene_kind.hpp): rows found by name, a list of rows read, and the
// kind a scene is.
#include "session/scene_kind.hpp"

#include <string>

#include "session/ik_kind.hpp"
#include "session/mass_spring_kind.hpp"
#include "session/session.hpp"
#include "springlab/error.hpp"

namespace springlab::app {

std::optional<int> SceneKind::find(const std::string& name) const {
  for (int k = 0; k < row_count(); ++k)
    if (row(k).name == name) return k;
  return std::nullopt;
}

std::vector<int> SceneKind::lanes_named(const std::string& list, const char* option) const {
  std::vector<int> rows;
  std::stringstream s(list);
  for (std::string name; std::getline(s, name, ',');) {
    const std::optional<int> row = find(name);
    if (!row)
      throw InputError(std::string(option) + ": unknown " + row_noun() + " '" + name + "' (" +
                       choices() + ")");
    rows.push_back(*row);
  }
  if (rows.size() < 2 || rows.size() > Session::kMaxLanes) {
    std::string example;
    for (int k : compared_first())
      example += (example.empty() ? "" : ",") + std::string(row(k).name);
    throw InputError(std::string(option) + ": give 2 to " + std::to_string(Session::kMaxLanes) +
                     " " + row_noun() + "s separated by commas, e.g. " + example);
  }
  return rows;
}

std::unique_ptr<SceneKind> make_scene_kind(const Scene& scene) {
  if (scene.ik) return std::make_unique<IkKind>(*scene.ik);
  return make_mass_spring_kind(scene.methods);
}

}  // namespace springlab::app
