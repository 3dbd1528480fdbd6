// A rope.cpp with one planted mistake (rope_with.hpp: FORCES_ASSIGNED).
// expect: fail forces-assigned forces-assigned
#define FORCES_ASSIGNED
#include "rope_with.hpp"
