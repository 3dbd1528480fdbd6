// A rope.cpp with one planted mistake (rope_with.hpp: ENDLESS).
// expect: fail code-failed
// expect-options: --time-limit 0.5
// expect-says: simulateVerlet (step 1 of 1, h = 1/1024 s) did not return within 0.5 s and was stopped
#define ENDLESS
#include "rope_with.hpp"
