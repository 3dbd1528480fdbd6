// A rope.cpp with one planted mistake (rope_with.hpp: THROWS).
// expect: fail code-failed
// expect-says: simulateEuler (step 1 of 1, h = 1/1024 s) threw an exception: not written yet
#define THROWS
#include "rope_with.hpp"
