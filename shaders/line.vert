#version 330 core
// A segment of constant width in pixels: a quad stretched between the projected ends.
layout(location = 0) in vec2 corner;  // x: 0 at a, 1 at b; y: -1 or 1 across
layout(location = 1) in vec3 a;
layout(location = 2) in vec3 b;
layout(location = 3) in vec4 color_a;
layout(location = 4) in vec4 color_b;
layout(location = 5) in float width;

uniform mat4 view_projection;
uniform vec2 viewport;  // pixels

out vec4 v_color;
out float v_across;  // -1..1 across the line, in units of half the drawn width
out float v_half;    // half the drawn width, pixels

void main() {
  vec4 ca = view_projection * vec4(a, 1.0);
  vec4 cb = view_projection * vec4(b, 1.0);
  vec2 sa = ca.xy / ca.w * viewport * 0.5;
  vec2 sb = cb.xy / cb.w * viewport * 0.5;
  vec2 dir = sb - sa;
  float len = length(dir);
  dir = len > 1e-6 ? dir / len : vec2(1.0, 0.0);
  vec2 normal = vec2(-dir.y, dir.x);
  float half_width = 0.5 * width + 1.0;  // one pixel more for the soft edge
  vec4 c = corner.x < 0.5 ? ca : cb;
  vec2 offset = normal * corner.y * half_width + dir * (corner.x < 0.5 ? -0.5 : 0.5) * width;
  gl_Position = c + vec4(offset / viewport * 2.0 * c.w, 0.0, 0.0);
  v_color = corner.x < 0.5 ? color_a : color_b;
  v_across = corner.y;
  v_half = half_width;
}
