// A rope.cpp with one planted mistake (rope_with.hpp: NULL_MASS).
// expect: fail constructor-failed
// expect-says: left masses[0] a null pointer
#define NULL_MASS
#include "rope_with.hpp"
