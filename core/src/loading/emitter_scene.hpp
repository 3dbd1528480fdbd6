// Reading the particle-system parts of a scene: emitters (with their pools of particles) and
// attractors. Internal to the core's loaders; assets/scenes/README.md documents the fields.
#pragma once

#include <string>

#include "loading/generators.hpp"
#include "loading/json_reader.hpp"
#include "springlab/fields.hpp"

namespace springlab {

// Most particles one emitter (or its bursts) may have alive at once, and the fastest rate.
inline constexpr long kMaxPool = 1'000'000;
inline constexpr double kMaxRate = 1e6;  // births per second

// Appends the emitter to b.model.emitters and its pools to the particles (pinned, at its
// position), named `name` (and `name-sparks` for a burst's) for scripts.
void read_emitter(json_reader::ObjectReader& r, const std::string& name, generators::Builder& b);

Attractor read_attractor(json_reader::ObjectReader& r);

}  // namespace springlab
