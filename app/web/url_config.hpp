// The page's link as the app's settings, and back: `index.html#scene=rope&method=euler&dt=1e-4
// &substeps=4&ks=7500&kd=0.75&compare=euler,verlet&script=rope-drag-euler-to-rk4&ui-scale=1.25`,
// set=KEY%3DVALUE (as many as wanted) for any other scene field, as the command line's --set, and
// accuracy=1 to open the Compare panel and start its sweep (--accuracy), region=1 to open the
// stability region, lesson=NAME&step=N to teach a lesson from a step (--lesson, --step), and
// tableau=<a tableau's JSON> (assets/tableaux/README.md) to add a method of one's own, named after
// its "name" ("My RK" is my-rk), for method= and compare= to use: a teacher sends the link.
// homework=<the student's JavaScript> opens Homework 8's panel with that code and runs it.
// Every value gets the checks the command line's flags get (options/scene_options.hpp).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "platform/app_settings.hpp"
#include "platform/interactive_app.hpp"

namespace springlab::app::web {

// The settings a link's fragment (what follows '#', percent-encoded) asks for. Throws InputError
// naming the parameter and what it allows: "link: dt: must be a number, got 'fast'".
AppSettings settings_from_link(const std::string& fragment);

// A prepared scene for those settings, and the script it plays. Throws InputError as the command
// line does, with "link: " and the parameter's name (no "--") in front.
struct Opened {
  Prepared prepared;
  std::optional<Script> script;
};
Opened open_settings(const AppSettings& settings);

// The fragment that reopens what `app` shows now: its scene (with the `sets` it was opened with),
// and whatever differs from that (method, dt, fixed sub-steps, k_s, k_d, compare lanes).
// The homework's code (empty: none) travels too.
std::string link_of(const InteractiveApp& app, const std::vector<std::string>& sets,
                    double ui_scale, const std::string& homework_js = {});

// The names a link takes, for messages.
inline constexpr const char* kLinkParameters =
    "scene, method, tableau, dt, substeps, ks, kd, iterations, rho, compare, compare-layout, "
    "script, set, accuracy, region, lesson, step, ui-scale, lang, homework";
// The longest code a link carries (browsers take links of 2 MB; 64 KB is many times a rope's).
inline constexpr std::size_t kMaxHomework = 65536;

}  // namespace springlab::app::web
