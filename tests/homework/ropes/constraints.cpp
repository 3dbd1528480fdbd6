// A correct rope.cpp whose simulateVerlet holds the springs as constraints (rope_with.hpp: CONSTRAINTS).
#define CONSTRAINTS
#include "rope_with.hpp"
