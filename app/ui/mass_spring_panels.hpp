// The mass-spring kind's UI half (kind_panels.hpp): its controls (the method, the clocks, each
// lane's stability gauge, the parameters), tools, strip, charts and compare choices.
#pragma once

#include <string>
#include <vector>

#include "chart/chart.hpp"
#include "session/session.hpp"

namespace springlab::ui {

// The stability regions of the lanes' methods (one chart a plane: z = h lambda, or h w), with the
// scene's modes; none yet while the scene is analysed (`none` says why).
std::vector<chart::Chart> region_charts(app::Session& session, std::string& none);

}  // namespace springlab::ui
