// A rope.cpp with one planted mistake (rope_with.hpp: LAST_STALE).
// expect: fail last-stale
#define LAST_STALE
#include "rope_with.hpp"
