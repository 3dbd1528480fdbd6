// A rope.cpp with one planted mistake (rope_with.hpp: WRONG_SIGN).
#define WRONG_SIGN
#include "rope_with.hpp"
