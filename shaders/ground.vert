#version 330 core
layout(location = 0) in vec2 corner;  // -1..1

uniform vec3 origin;
uniform vec3 axis_u;  // in the plane, scaled by the half extent
uniform vec3 axis_v;
uniform mat4 view_projection;

out vec3 v_world;

void main() {
  v_world = origin + corner.x * axis_u + corner.y * axis_v;
  gl_Position = view_projection * vec4(v_world, 1.0);
}
