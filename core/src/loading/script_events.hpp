// Reading a timeline of script events (script.hpp's format), for scripts and for lesson steps,
// which carry their own. Internal to the core's loaders.
#pragma once

#include <vector>

#include "loading/json_reader.hpp"
#include "springlab/script.hpp"

namespace springlab {

// Each event checked against the scene it will drive, then sorted by time (stable: file order
// breaks ties).
std::vector<ScriptEvent> read_events(std::vector<json_reader::ObjectReader> events,
                                     const Scene& scene);

}  // namespace springlab
