// A rope.cpp with one planted mistake (rope_with.hpp: LAST_OVERWRITTEN).
// expect: fail last-overwritten
// expect-verlet: none
#define LAST_OVERWRITTEN
#include "rope_with.hpp"
