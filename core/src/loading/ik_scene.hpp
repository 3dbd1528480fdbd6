// Reading an inverse-kinematics chain from a scene. Internal to the core's loaders.
//
//   {"base": [0, 0, 0], "links": [1.0, 0.8, 0.6], "angles": [20, 10, -5],
//    "limits": [[-90, 90], null, [-120, 120]]}
//
// base: the fixed first joint, [x, y, 0] in metres (the chain is planar, in the x-y plane);
//       optional, default the origin.
// links: the link lengths in metres, 1 to 1000 of them, each in (0, 1000].
// angles: the starting joint angles in degrees, each relative to the link before (the first to
//       the +x axis), in [-180, 180]; optional, default all 0 (straight along +x).
// limits: per joint, [min, max] in degrees with -180 <= min < max <= 180, or null for none;
//       optional, default none. A starting angle must lie within its joint's limits.
#pragma once

#include "loading/json_reader.hpp"
#include "springlab/ik.hpp"

namespace springlab {

inline constexpr long kMaxIkLinks = 1000;

// Reads base, links, angles and limits (marking them known), converting degrees to radians.
// Other keys ("target", "solvers", ...) are the caller's, and so is r.finish().
IkChain read_ik_chain(json_reader::ObjectReader& r);

}  // namespace springlab
