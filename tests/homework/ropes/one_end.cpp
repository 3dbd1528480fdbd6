// A rope.cpp with one planted mistake (rope_with.hpp: ONE_END).
#define ONE_END
#include "rope_with.hpp"
