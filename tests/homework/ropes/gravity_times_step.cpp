// A rope.cpp with one planted mistake (rope_with.hpp: GRAVITY_TIMES_STEP).
// expect: fail gravity-times-step gravity-times-step
#define GRAVITY_TIMES_STEP
#include "rope_with.hpp"
