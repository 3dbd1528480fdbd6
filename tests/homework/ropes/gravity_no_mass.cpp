// A rope.cpp with one planted mistake (rope_with.hpp: GRAVITY_NO_MASS).
// expect: fail gravity-no-mass gravity-no-mass
#define GRAVITY_NO_MASS
#include "rope_with.hpp"
