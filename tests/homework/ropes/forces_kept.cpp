// A rope.cpp with one planted mistake (rope_with.hpp: FORCES_KEPT).
// expect: fail forces-kept forces-kept
#define FORCES_KEPT
#include "rope_with.hpp"
