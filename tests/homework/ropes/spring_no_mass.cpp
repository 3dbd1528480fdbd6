// A rope.cpp with one planted mistake (rope_with.hpp: SPRING_NO_MASS).
// expect: fail spring-no-mass spring-no-mass
#define SPRING_NO_MASS
#include "rope_with.hpp"
