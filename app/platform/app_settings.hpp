// What the interactive app starts with, on any platform: the scene and its options, the compare
// lanes, a script to play, the panels' scale. A plain struct: the command line (`springlab view`)
// fills it from its flags, the browser from the page's link (app/web/url_config.hpp).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "draw/lane_views.hpp"
#include "options/scene_options.hpp"

namespace springlab::app {

struct AppSettings {
  std::string scene = "rope";  // a shipped scene's name or a path
  SimOptions sim;
  // The lanes side by side, as named ("euler,verlet", or an IK scene's "ccd,fabrik"): the scene
  // kind's rows, checked against the scene where it is prepared (compare_rows).
  std::optional<std::string> compare;
  // How they are shown: apart (a view each) or together (one view).
  draw::CompareLayout compare_layout = draw::CompareLayout::Apart;
  std::optional<std::string> script;
  double ui_scale = 1.0;  // times the display's own scale
  std::string language;   // "zh-CN", "en"; empty: the environment's (desktop) or the browser's
  bool accuracy = false;  // open the Compare panel and start its sweep
  bool region = false;    // open the stability region's window
  // A lesson to teach (a shipped lesson's name or number, or a file), from this step (from 1).
  std::optional<std::string> lesson;
  int lesson_step = 1;
  // The browser's Homework 8: the student's JavaScript steps (a link's homework=), run at start.
  std::string homework_js;
};

}  // namespace springlab::app
