// The interactive app in a desktop window: GLFW makes the window and its OpenGL 3.3 context and
// gives the input; platform/interactive_app.hpp is the app itself, shared with the browser.
#pragma once

#include <optional>
#include <string>

#include "platform/app_settings.hpp"

namespace springlab::app {

// What only a desktop window has.
struct WindowOptions {
  std::optional<std::string> screenshot;
  std::optional<long> frames;  // run this many frames as fast as they come, then exit
  int width = 1280, height = 720;
  int msaa = -1;  // samples; -1: 4 on a GPU, none on a software rasteriser (to keep 60 frames/s)
  bool threads_given =
      false;  // --threads was given (else a software rasteriser leaves one core to the simulation)
  std::optional<std::string> homework;  // a student's rope.cpp: its steps as lanes (app/homework/)
  std::optional<std::string> keys;  // keys pressed, one every other frame (window/key_presses.hpp)
};

// Runs until the window closes (or after `frames` frames). Throws InputError for a bad scene,
// option or script, std::runtime_error (saying what is missing) when no window can be opened.
int run_window(const AppSettings& settings, const WindowOptions& options);

}  // namespace springlab::app
