// A rope.cpp with one planted mistake (rope_with.hpp: DUPLICATE_SPRINGS).
// expect: fail spring-duplicated
// expect-says: 2 springs between masses 0 and 1
#define DUPLICATE_SPRINGS
#include "rope_with.hpp"
