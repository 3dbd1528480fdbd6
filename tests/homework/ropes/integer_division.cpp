// A rope.cpp with one planted mistake (rope_with.hpp: INTEGER_DIVISION).
// expect: fail integer-division
// expect-says: divided as integers
#define INTEGER_DIVISION
#include "rope_with.hpp"
