// A rope.cpp with one planted mistake (rope_with.hpp: WRONG_SIGN).
// expect: fail wrong-sign wrong-sign
#define WRONG_SIGN
#include "rope_with.hpp"
