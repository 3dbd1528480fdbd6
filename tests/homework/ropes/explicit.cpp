// A correct rope.cpp whose simulateEuler is explicit Euler (rope_with.hpp: EXPLICIT).
#define EXPLICIT
#include "rope_with.hpp"
