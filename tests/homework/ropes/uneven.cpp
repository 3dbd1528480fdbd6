// A rope.cpp with one planted mistake (rope_with.hpp: UNEVEN).
#define UNEVEN
#include "rope_with.hpp"
