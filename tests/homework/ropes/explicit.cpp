// A correct rope.cpp whose simulateEuler is explicit Euler (rope_with.hpp: EXPLICIT).
// expect: pass
// expect-euler: euler
// expect-verlet: verlet
// expect-says: energy grows: x1.00093
// expect-says: explicit Euler's own instability, as predicted; not a mistake
#define EXPLICIT
#include "rope_with.hpp"
