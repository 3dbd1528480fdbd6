// The browser's accessible document (app/web/access.js): what the app shows, in words a screen
// reader reads, and its controls as the page's own. describe() is the state as JSON, in the app's
// language; control() and choose() make a change as the panels would (in the next frame, through
// InteractiveApp::control, so that it interrupts a lesson as theirs do).
#pragma once

#include <string>
#include <vector>

#include "chart/chart.hpp"
#include "platform/interactive_app.hpp"
#include "springlab/homework.hpp"

namespace springlab::app::web {

// {"scene", "description", "scenes": [...], "method", "methods": [{"name", "label"}], "paused",
//  "t", "controls": [{"id", "label", "value", "lo", "hi", "log"}], "lanes": [{"label", "t",
//  "verdict", "tone", "diverged", "why", "energy", "energy0", "scale"}], "lesson": {...} or null,
//  "message", "labels": {the buttons' words}}
std::string describe(const InteractiveApp& app);

// The charts the document says in words (describe's "charts": title and summary) and whose data
// it gives as CSV (chart::chart_csv): the live ones (energy, the watched particle's position, its
// phase), then, while the accuracy panel is open and its sweep has runs, that panel's (error
// against time and work, convergence, stability: each line's slope, the lowest line).
std::vector<chart::Chart> charts(const InteractiveApp& app);

// "ks", "kd", "dt", "mass", "gravity", "drag": that slider set to `value`; "pause" (1 paused, 0
// running), "step", "reset", "next", "back" (a lesson's steps); "hold" (a particle's index),
// "left", "right", "up", "down" (a held particle moved a twentieth of the scene), "release".
// False for an unknown name.
bool control(InteractiveApp& app, const std::string& name, double value);

// what = "method" or "scene": chosen by its name. False for an unknown one.
bool choose(InteractiveApp& app, const std::string& what, const std::string& name);

// The Homework 8 panel (homework.js): its words in the app's language, {"title", "code", "run",
// "starter", "close", "checking"}; and a check's result, {"text": the report, "failed": its count}.
std::string homework_words();
std::string homework_result(const homework::Report& report);

}  // namespace springlab::app::web
