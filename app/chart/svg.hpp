// A chart::Chart as a standalone SVG document: the same axes, ticks, series, markers and legend
// as the Dear ImGui drawing (imgui_chart.cpp), for reports and web pages.
#pragma once

#include <string>

#include "chart/chart.hpp"

namespace springlab::chart {

std::string to_svg(const Chart& chart, int width, int height);

}  // namespace springlab::chart
