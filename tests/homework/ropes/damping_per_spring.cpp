// A rope.cpp with one planted mistake (rope_with.hpp: DAMPING_PER_SPRING).
// expect: fail damping-per-spring
#define DAMPING_PER_SPRING
#include "rope_with.hpp"
