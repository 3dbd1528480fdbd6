// The words and the colour of a lane's stability gauge (ui/mass_spring_panels.cpp draws them): h
// against its method's limit, or what a method stable at any step pays instead
// (iterative_cost.hpp), what it breaks (a free body's momentum, momentum.hpp; a box's cells,
// cells.hpp), and its divergence. Kept apart from the drawing, so that the tests read the verdicts
// a class would.
#pragma once

#include <string>

#include "session/session.hpp"

namespace springlab::ui {

enum class Tone { Neutral, Safe, Near, Beyond };

struct GaugeVerdict {
  double fraction = 0.0;  // of the bar, the limit at two thirds
  Tone tone = Tone::Neutral;
  std::string text;      // "safe: 0.50x", "bounded; at rest acts as k_s x0.0011", "diverged"
  std::string momentum;  // a free body's: what changed, and what the method keeps ("" if not free)
};

// `analysis`: the one the lane shows (none yet: "analysing..."); `explain`: a divergence's time.
GaugeVerdict gauge_verdict(const app::Lane& lane, const StabilityAnalysis* analysis, bool explain);

}  // namespace springlab::ui
