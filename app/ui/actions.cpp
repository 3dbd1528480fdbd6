#include "ui/actions.hpp"

#include "ui/kind_panels.hpp"

namespace springlab::ui {

void perform(Action action, app::Session& session, UiState& ui) {
  switch (action) {
    case Action::TogglePause:
      session.set_paused(!session.paused());
      break;
    case Action::Step:
      session.set_paused(true);
      session.step_once();
      break;
    case Action::Reset:
      session.reset();
      break;
    case Action::TogglePanels:
      ui.panels = !ui.panels;
      break;
    case Action::ToggleHelp:
      ui.help = !ui.help;
      break;
    case Action::ToggleAccuracy:
      ui.accuracy = !ui.accuracy;
      break;
    case Action::ToggleRegion:
      ui.region = !ui.region;
      break;
    case Action::ToggleTableau:
      ui.tableau = !ui.tableau;
      break;
    case Action::ToggleMode:
      ui.view.mode = !ui.view.mode;
      break;
    case Action::TogglePresentation:
      ui.presentation = !ui.presentation;
      break;
    case Action::ToggleCompare:  // the kind's choice side by side, from the same start; or back to
                                 // one lane
      session.set_compare_rows(session.comparing()
                                   ? std::vector<int>{}
                                   : kind_panels(session.kind()).compare_choice(session, ui));
      break;
    default: {  // keys 1 to 9: the kind's rows (methods, solvers)
      const int k = static_cast<int>(action) - static_cast<int>(Action::Method1);
      if (!session.comparing() && k < session.kind().row_count()) session.choose(k);
      break;
    }
  }
}

}  // namespace springlab::ui
