// Draws a chart::Chart with Dear ImGui's draw list into a rectangle: in the app's panels, and
// headlessly into the PNG charts of `springlab compare`.
#pragma once

#include <imgui.h>

#include "chart/chart.hpp"
#include "draw/marks.hpp"

namespace springlab::chart {

// A mark (draw/marks.hpp) of radius r at c: filled, hollow (a 2 px outline) or two strokes.
void draw_mark(ImDrawList* list, draw::Mark mark, ImVec2 c, float r, ImU32 colour);

void draw_imgui(ImDrawList* list, ImVec2 origin, ImVec2 size, const Chart& chart);

// A panel widget: reserves `size` in the current window and draws there.
void chart_widget(const char* id, const Chart& chart, ImVec2 size);

}  // namespace springlab::chart
