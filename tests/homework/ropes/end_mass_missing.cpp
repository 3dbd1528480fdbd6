// A rope.cpp with one planted mistake (rope_with.hpp: END_MASS_MISSING).
// expect: fail mass-count
// expect-says: 15 masses, where num_nodes = 16 (one short
#define END_MASS_MISSING
#include "rope_with.hpp"
