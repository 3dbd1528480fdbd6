#include "ui/kind_panels.hpp"

namespace springlab::ui {

const KindPanels& kind_panels(const app::SceneKind& kind) {
  switch (kind.id()) {
    case app::SceneKind::Id::InverseKinematics: return ik_panels();
    case app::SceneKind::Id::MassSpring: break;
  }
  return mass_spring_panels();
}

}  // namespace springlab::ui
