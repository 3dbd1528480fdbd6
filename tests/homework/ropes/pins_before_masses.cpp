// A rope.cpp with one planted mistake (rope_with.hpp: PINS_BEFORE_MASSES).
// expect: fail pins-before-masses
// expect-says: the pins are set before the masses exist
// expect-verlet: verlet
#define PINS_BEFORE_MASSES
#include "rope_with.hpp"
