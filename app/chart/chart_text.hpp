// A chart in words and as a table, for whoever cannot see it (the browser's accessible document,
// web/access.cpp): what it plots against what, and for each line where it starts and ends, whether
// it rises, falls or holds, and whether it left the chart (a diverged lane); and its points as
// CSV, a pair of columns a line.
#pragma once

#include <string>

#include "chart/chart.hpp"

namespace springlab::chart {

// "Energy (J) against t (s), from 0 to 4.2: Explicit Euler rises from 12.5 to 40.1; Symplectic
// Euler holds at about 12.5 (12.4 to 12.6)." A line "holds" when it moves less than 2 % of the
// chart's range of values; a line without a label is "line k". On log-log axes (work-precision,
// convergence): "euler has slope -1 on these log-log axes, from 0.3 to 0.002; ... Furthest right
// where every line has points (2000), rk4 is lowest (1e-08)."
std::string describe_chart(const Chart& chart);

// "Explicit Euler t (s),Explicit Euler J,...": a header, then a row a point (empty cells where a
// line has fewer points).
std::string chart_csv(const Chart& chart);

}  // namespace springlab::chart
