// A rope.cpp with one planted mistake (rope_with.hpp: ACCEL_TWICE).
// expect: fail accel-twice
// expect-says: the acceleration is applied twice
#define ACCEL_TWICE
#include "rope_with.hpp"
