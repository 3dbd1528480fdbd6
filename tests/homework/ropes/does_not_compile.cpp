// A rope.cpp that does not compile: simulateVerlet uses a name it never declared.
// expect: exit 2
// expect-err: does_not_compile.cpp does not compile: 
// expect-err: does_not_compile.cpp:14:
// expect-err: damping
#include "CGL/vector2D.h"
#include "mass.h"
#include "rope.h"
#include "spring.h"

namespace CGL {
Rope::Rope(Vector2D start, Vector2D end, int num_nodes, float node_mass, float k, vector<int> pinned_nodes) {}
void Rope::simulateEuler(float delta_t, Vector2D gravity) {}
void Rope::simulateVerlet(float delta_t, Vector2D gravity) { damping += 1; }
}  // namespace CGL
