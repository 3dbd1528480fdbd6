// The interactive app: a GLFW window showing a Session through the shared renderer, with the
// panels, the mouse (drag particles, orbit, pan, zoom) and the keyboard shortcuts. Only where
// the context and the input come from differs from the headless renderer.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "cli/options.hpp"

namespace springlab::app {

struct WindowOptions {
  std::optional<std::string> script, screenshot;
  std::vector<Method> compare;
  std::optional<long> frames;  // run this many frames as fast as they come, then exit
  double ui_scale = 1.0;       // times the monitor's content scale
  int width = 1280, height = 720;
  int msaa = -1;  // samples; -1: 4 on a GPU, none on a software rasteriser (to keep 60 frames/s)
  bool accuracy = false;  // open the Compare panel and start its sweep
  bool threads_given = false;  // --threads was given (else a software rasteriser leaves one core to the simulation)
};

// Runs until the window closes (or after `frames` frames). Throws InputError for a bad script,
// std::runtime_error (saying what is missing) when no window can be opened.
int run_window(Prepared prepared, const WindowOptions& options);

}  // namespace springlab::app
