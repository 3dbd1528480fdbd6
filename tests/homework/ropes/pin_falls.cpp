// A rope.cpp with one planted mistake (rope_with.hpp: PIN_FALLS).
#define PIN_FALLS
#include "rope_with.hpp"
