// Text drawn over the scene itself: in compare mode a legend (each method's colour, and where it
// diverged); without the panels, a caption (scene, method, time), so that a video or a frame dump
// says what it shows.
#pragma once

#include <string>

#include "draw/frame.hpp"
#include "session/session.hpp"

namespace springlab::ui {

void draw_overlay(const app::Session& session, const draw::Viewport& viewport, float scale,
                  const std::string& scene_name, bool caption);

}  // namespace springlab::ui
