// Widgets every panel shares, whatever the scene's kind: a slider that a thumb can set, the row's
// picker, the transport (pause, step, reset), the clocks, charts side by side, and the tones the
// verdicts are drawn in. No session kind is asked which it is here.
#pragma once

#include <imgui.h>

#include <vector>

#include "chart/chart.hpp"
#include "session/session.hpp"
#include "ui/panels.hpp"
#include "ui/theme.hpp"

namespace springlab::ui {

// The verdicts' tones (ui/theme.hpp): within the limit, near it, past it, neither.
inline const ImVec4 kSafe = v4(kSafeText), kNear = v4(kNearText), kBeyond = v4(kBeyondText),
                    kNeutral = v4(kNeutralText);

// A slider of a double; on a touch layout (`touch`: no hover, thumbs) with - and + beside it.
bool slider(const char* label, double& value, double lo, double hi, bool log, bool touch,
            const char* format = "%.3g");
// The next combo's width: all the row leaves beside its label (a short label such as "method"
// need not keep the 130 units the sliders' longer labels do: a preview cut there loses its end
// silently, "Heun, one entry wron"). A label "##..." shows nothing and leaves the width as set.
void widest_beside(const char* label);
// The single lane's row (a method, a solver): its number key and label, in its colour; nothing
// while comparing. `label`: the combo's ("##method": none shown; its width as the caller set).
void row_picker(app::Session& session, const char* label, bool coloured);
// Pause, step, reset.
void transport(app::Session& session);
// Each lane's time, the speed, the real-time factor when the simulation cannot keep up.
void clocks(app::Session& session, const FrameStats& stats);
// Charts side by side over `width` x `height`.
void charts_row(const std::vector<chart::Chart>& shown, float width, float height);

}  // namespace springlab::ui
