// Text drawn over the scene itself: in compare mode a legend (each lane's colour and its own
// clock, or where it diverged; apart, each view's title at its top), a red label beside a lane that
// diverged (drawn as its last sane state), "analysing stability" while a lane waits for its
// sub-steps; without the panels, a caption (scene, method, time, and the real-time factor when the
// simulation cannot keep up), so that a video or a frame dump says what it shows.
#pragma once

#include <string>
#include <vector>

#include "draw/frame.hpp"
#include "draw/lane_views.hpp"
#include "session/session.hpp"

namespace springlab::ui {

struct OverlayOptions {
  float scale = 1.0f;
  bool caption = false;
  double realtime = 1.0;  // simulated seconds a second of wall time (below 0.95 it is shown)
  bool trails = true;     // the view draws the trails (the labels keep off them too)
};

// `views`: the session's (lane_views.hpp), in the same units as `viewport`, the scene's whole
// place.
void draw_overlay(const app::Session& session, const std::vector<draw::LaneView>& views,
                  const draw::Viewport& viewport, const std::string& scene_name,
                  const OverlayOptions& options);

// "0.42x real time", or "" at (or near) real time.
std::string realtime_text(double realtime);

// The mass-spring kind's caption and legend words (kind_panels.hpp).
std::string mass_spring_caption(const app::Session& session, const std::string& scene_name,
                                const std::string& slow);
std::string mass_spring_progress(const app::Lane& lane);

}  // namespace springlab::ui
