// A rope.cpp with one planted mistake (rope_with.hpp: CRASH).
#define CRASH
#include "rope_with.hpp"
