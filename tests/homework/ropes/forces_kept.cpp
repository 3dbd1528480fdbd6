// A rope.cpp with one planted mistake (rope_with.hpp: FORCES_KEPT).
#define FORCES_KEPT
#include "rope_with.hpp"
