// A rope.cpp with one planted mistake (rope_with.hpp: ONE_END).
// expect: fail one-end one-end
// expect-says: the spring force acts on one end only (m1)
#define ONE_END
#include "rope_with.hpp"
