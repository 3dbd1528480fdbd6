#include "ui/actions.hpp"

namespace springlab::ui {

void perform(Action action, app::Session& session, UiState& ui) {
  switch (action) {
    case Action::TogglePause: session.set_paused(!session.paused()); break;
    case Action::Step:
      session.set_paused(true);
      session.step_once();
      break;
    case Action::Reset: session.reset(); break;
    case Action::TogglePanels: ui.panels = !ui.panels; break;
    case Action::ToggleHelp: ui.help = !ui.help; break;
    case Action::ToggleAccuracy: ui.accuracy = !ui.accuracy; break;
    case Action::ToggleRegion: ui.region = !ui.region; break;
    case Action::ToggleTableau: ui.tableau = !ui.tableau; break;
    case Action::ToggleMode: ui.view.mode = !ui.view.mode; break;
    case Action::TogglePresentation: ui.presentation = !ui.presentation; break;
    case Action::ToggleCompare: {
      if (session.scene().ik) {  // the solvers side by side, from the same start
        session.set_compare_solvers(session.comparing() ? std::vector<IkSolver>{} : session.scene().ik->solvers);
        break;
      }
      if (session.comparing()) {
        session.set_compare({});
        break;
      }
      auto chosen = compare_methods(ui);
      if (chosen.size() < 2) chosen = session.scene().methods;
      if (chosen.size() < 2) {
        chosen.clear();
        for (const MethodInfo& m : methods())
          if (m.compared_first) chosen.push_back(m.id);
      }
      session.set_compare(chosen);
      break;
    }
    default: {
      const int k = static_cast<int>(action) - static_cast<int>(Action::Method1);
      if (session.comparing()) break;
      if (session.scene().ik) {  // keys 1 to 3 pick a solver
        if (k < static_cast<int>(ik_solvers().size())) session.set_solver(ik_solvers()[k].id);
      } else {
        if (k < static_cast<int>(methods().size())) session.set_method(methods()[k].id);
      }
      break;
    }
  }
}

}  // namespace springlab::ui
