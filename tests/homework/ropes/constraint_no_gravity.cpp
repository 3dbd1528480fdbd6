// A rope.cpp with one planted mistake (rope_with.hpp: CONSTRAINT_NO_GRAVITY).
// expect: fail no-gravity
// expect-verlet: constraints
#define CONSTRAINT_NO_GRAVITY
#include "rope_with.hpp"
