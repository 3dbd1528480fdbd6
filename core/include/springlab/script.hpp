// Scripted demos: a JSON timeline of what a teacher does, played by `render --script` and by the
// app, so that a demo recorded headlessly replays identically in the window. Times are
// presentation time (frame / fps), which goes on while the simulation is paused.
//
//   {"description": "...", "events": [
//     {"t": 0.5, "grab": "rope:-1"},                 a particle: index, "name:index", or
//     {"t": 0.5, "grab": {"near": [4, 0, 0]}},       the one nearest a point
//     {"t": 0.5, "path": [[0.5, 4, 0, 0], [1, 3, 1.5, 0]]},  move the grabbed particle through
//                                                     waypoints [dt, x, y, z], dt from the event,
//                                                     starting from where it is
//     {"t": 1.0, "move": [2, 0, 0], "over": 0.5},    straight to a point in `over` seconds
//     {"t": 2.5, "release": true},
//     {"t": 3.0, "set": {"method": "rk4", "ks": 500, "kd": 1, "dt": 0.001, "substeps": 2,
//                        "gravity": [0, -9.81, 0], "drag": 0.1, "friction": 0.5, "mass": 1,
//                        "speed": 0.25}},
//     {"t": 4.0, "pause": true}, {"t": 5.0, "resume": true}, {"t": 6.0, "reset": true}]}
// Events are sorted by time (stable: file order breaks ties). A grab's particle is resolved
// against the scene it is played on.
#pragma once

#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "springlab/methods.hpp"
#include "springlab/model.hpp"
#include "springlab/scene.hpp"

namespace springlab {

struct ScriptEvent {
  enum class Kind { Grab, Path, Move, Release, Set, Pause, Resume, Reset };
  double t = 0.0;
  Kind kind = Kind::Release;

  // Grab: a particle, or the one nearest `near`.
  int particle = -1;
  std::optional<Vec3> near;
  // Path: waypoints (time from the event, position); Move: one waypoint at `over`.
  std::vector<std::pair<double, Vec3>> path;
  // Set: any of these.
  std::optional<Method> method;
  std::optional<double> ks, kd, dt, drag, friction, mass, speed;
  std::optional<int> substeps;
  std::optional<Vec3> gravity;

  std::string describe() const;  // "t = 2.50 s: set method rk4", for the UI
};

struct Script {
  std::string file;
  std::string description;
  std::vector<ScriptEvent> events;  // by time
  double end_time() const;          // the last event's time, or the end of its path
};

// Loads and checks a script against the scene it will drive (particle references must exist).
// Throws InputError naming the file and the JSON path.
Script load_script(const std::string& path, const Scene& scene);
Script parse_script(const std::string& text, const std::string& file, const Scene& scene);

// Where a path puts the particle `elapsed` seconds after its event: linear between waypoints,
// held at the ends.
Vec3 path_position(const std::vector<std::pair<double, Vec3>>& path, double elapsed);

}  // namespace springlab
