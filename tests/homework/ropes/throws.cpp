// A rope.cpp with one planted mistake (rope_with.hpp: THROWS).
#define THROWS
#include "rope_with.hpp"
