// A rope.cpp with one planted mistake (rope_with.hpp: PINS_AS_FLAGS): pinned_nodes, the indices
// of the pinned masses, read as a flag per node, so the loop reads past its end. Unchecked, that
// read is whatever lies there: masses pinned at random.
// expect: fail constructor-failed
// expect-says: read or wrote a std::vector at an index not below its size()
#define PINS_AS_FLAGS
#include "rope_with.hpp"
