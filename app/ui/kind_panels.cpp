#include "ui/kind_panels.hpp"

#include <mutex>
#include <stdexcept>
#include <utility>
#include <vector>

namespace springlab::ui {

namespace {

struct PanelsRegistry {
  std::mutex mutex;  // (a session's frames and the browser's words may ask from two threads)
  std::vector<std::pair<std::string, const KindPanels*>> panels;
};

PanelsRegistry& registry() {
  static PanelsRegistry r{
      {}, {{"mass-spring", &mass_spring_panels()}, {"inverse-kinematics", &ik_panels()}}};
  return r;
}

}  // namespace

void add_kind_panels(std::string_view kind_name, const KindPanels& panels) {
  PanelsRegistry& r = registry();
  const std::lock_guard lock(r.mutex);
  for (auto& [name, known] : r.panels)
    if (name == kind_name) {
      known = &panels;
      return;
    }
  r.panels.emplace_back(std::string(kind_name), &panels);
}

const KindPanels& kind_panels(const app::SceneKind& kind) {
  PanelsRegistry& r = registry();
  const std::lock_guard lock(r.mutex);
  for (const auto& [name, panels] : r.panels)
    if (name == kind.kind_name()) return *panels;
  throw std::logic_error("no panels for the scene kind '" + std::string(kind.kind_name()) +
                         "': add them with ui::add_kind_panels before its first frame");
}

}  // namespace springlab::ui
