// A correct rope.cpp that prints as it steps (rope_with.hpp: PRINTS).
// expect: pass
#define PRINTS
#include "rope_with.hpp"
