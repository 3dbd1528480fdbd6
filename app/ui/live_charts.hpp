// The live charts of a session, as data (chart::Chart): the energy of each lane, the watched
// particle's position (with the exact solution where there is one), its phase plot, an adaptive
// lane's step, and what a free body's lanes keep of their momentum. The panels draw them
// (ui/mass_spring_panels.cpp) and the browser's accessible document says them in words and gives
// their data (web/access.cpp, chart/chart_text.hpp).
#pragma once

#include <string>

#include "chart/chart.hpp"
#include "session/session.hpp"

namespace springlab::ui {

// A series of a lane's history: the last points that both x and y have.
chart::Series series(const std::string& label, const draw::Rgba& color, const app::Series& x,
                     const app::Series& y, bool dashed = false);

chart::Chart energy_chart(const app::Session& session);
chart::Chart position_chart(const app::Session& session);
chart::Chart phase_chart(const app::Session& session);
chart::Chart steps_chart(const app::Session& session);
chart::Chart momentum_chart(const app::Session& session);

}  // namespace springlab::ui
