// A rope.cpp with two planted mistakes at once, as a published solution has them (rope_with.hpp:
// WRONG_SIGN and SPRING_NO_MASS): each named.
// expect: fail wrong-sign spring-no-mass wrong-sign spring-no-mass
#define WRONG_SIGN
#define SPRING_NO_MASS
#include "rope_with.hpp"
