// A rope.cpp with one planted mistake (rope_with.hpp: DRAG_WRONG_SIGN).
// expect: fail damping-sign
// expect-says: c = -0.01 N s/m
#define DRAG_WRONG_SIGN
#include "rope_with.hpp"
