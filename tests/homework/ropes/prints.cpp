// A correct rope.cpp that prints as it steps (rope_with.hpp: PRINTS).
#define PRINTS
#include "rope_with.hpp"
