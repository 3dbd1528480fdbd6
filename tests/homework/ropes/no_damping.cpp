// A correct rope.cpp with no damping (rope_with.hpp: NO_DAMPING).
#define NO_DAMPING
#include "rope_with.hpp"
