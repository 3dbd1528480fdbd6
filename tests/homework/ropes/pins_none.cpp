// A rope.cpp with one planted mistake (rope_with.hpp: PINS_NONE).
// expect: fail pins-none
// expect-says: no mass is pinned
#define PINS_NONE
#include "rope_with.hpp"
