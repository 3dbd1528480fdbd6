// A correct rope.cpp: semi-implicit Euler with a global drag, Verlet with a damping factor (the
// way the exercise is usually solved; rope_with.hpp, with no mistake planted).
// expect: pass
// expect-euler: symplectic-euler
// expect-verlet: verlet
// expect-says: simulateEuler is Symplectic Euler (springlab's symplectic-euler), with a global drag f = -c v, c = 0.01 N s/m
// expect-says: energy falls: x0.9999609
// expect-says: energy falls: x0.99995000
#include "rope_with.hpp"
