// A correct rope.cpp: semi-implicit Euler with a global drag, Verlet with a damping factor (the
// way the exercise is usually solved; rope_with.hpp, with no mistake planted).
#include "rope_with.hpp"
