// A rope.cpp with one planted mistake (rope_with.hpp: PIN_FALLS).
// expect: fail pin-moves pin-moves
#define PIN_FALLS
#include "rope_with.hpp"
