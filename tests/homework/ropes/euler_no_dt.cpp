// A rope.cpp with one planted mistake (rope_with.hpp: EULER_NO_DT).
// expect: fail euler-no-dt
#define EULER_NO_DT
#include "rope_with.hpp"
