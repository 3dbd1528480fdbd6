// A rope.cpp with one planted mistake (rope_with.hpp: SPRING_NOT_IN_ROPE).
// expect: fail spring-not-in-rope
// expect-euler: symplectic-euler
#define SPRING_NOT_IN_ROPE
#include "rope_with.hpp"
