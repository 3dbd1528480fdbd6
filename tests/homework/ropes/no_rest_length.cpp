// A rope.cpp with one planted mistake (rope_with.hpp: NO_REST_LENGTH).
// expect: fail no-rest-length no-rest-length
#define NO_REST_LENGTH
#include "rope_with.hpp"
