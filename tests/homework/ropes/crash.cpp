// A rope.cpp with one planted mistake (rope_with.hpp: CRASH).
// expect: fail code-failed
// expect-says: simulateVerlet (step 1 of 1, h = 1/1024 s) was killed by signal 11 (Segmentation fault)
// expect-euler: symplectic-euler
#define CRASH
#include "rope_with.hpp"
