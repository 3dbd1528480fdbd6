// "Your method": a Butcher tableau typed into a grid of cells and checked as the student types
// (springlab/butcher.hpp): its order from the order conditions, the first that fails, R(z) and its
// limits on the axes. "Run beside" adds it to the method table and as a compare lane, so that the
// gauge, the charts and the stability region show it beside the built-in methods. A bad cell is
// drawn in red with its message under the grid; nothing stops the scene.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "session/session.hpp"
#include "springlab/butcher.hpp"

namespace springlab::ui {

struct TableauPanel {
  static constexpr int kMaxStages = 7;  // Dormand-Prince's
  using Cell = std::array<char, 32>;
  bool open = false;
  int stages = 2;
  std::array<std::array<Cell, kMaxStages>, kMaxStages> a{};
  std::array<Cell, kMaxStages> b{};
  std::string name = "Heun";  // the tableau's own name, from the one started from

  // The last check, redone when a cell changes.
  bool dirty = true;
  std::optional<ButcherTableau> tableau;
  std::optional<TableauAnalysis> analysis;
  std::string error;  // "" when the cells make a tableau
  int error_row = -1,
      error_col = -1;       // the cell the error names; error_col -1 with a row: b's entry
  std::string run_message;  // what "Run beside" did, or why it could not

  TableauPanel();
  // Fills the cells from a tableau (a shipped one, by the menu).
  void load(const ButcherTableau& t);
  // Checks the cells (parse_tableau, analyse_tableau), setting the fields above.
  void check();
  // The cells as the JSON parse_tableau reads.
  std::string json() const;
};

// Adds the tableau to the method table as "mine" (or "mine-2", ...: a row is never replaced, so
// another tableau takes the next name) and as a lane beside the session's (the last of four gives
// way). Returns what it did, or why it could not.
std::string run_beside(const ButcherTableau& tableau, app::Session& session);

// Draws the panel's window (when open). `shipped`: the shipped tableaux' names for its menu.
void draw_tableau_panel(TableauPanel& panel, app::Session& session,
                        const std::vector<std::string>& shipped, float scale);

}  // namespace springlab::ui
