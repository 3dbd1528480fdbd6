// A rope.cpp with one planted mistake (rope_with.hpp: ENDLESS).
#define ENDLESS
#include "rope_with.hpp"
