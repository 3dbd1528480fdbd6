#version 330 core
// A particle as a camera-facing quad; the fragment shader turns it into a lit sphere.
layout(location = 0) in vec2 corner;       // (-1..1, -1..1)
layout(location = 1) in vec3 center;       // per instance
layout(location = 2) in float radius;
layout(location = 3) in vec4 color;
layout(location = 4) in float pinned;

uniform mat4 view;
uniform mat4 projection;

out vec2 v_corner;
out vec3 v_center_view;
out float v_radius;
out vec4 v_color;
out float v_pinned;

void main() {
  vec4 c = view * vec4(center, 1.0);
  v_corner = corner;
  v_center_view = c.xyz;
  v_radius = radius;
  v_color = color;
  v_pinned = pinned;
  gl_Position = projection * vec4(c.xyz + vec3(corner * radius, 0.0), 1.0);
}
