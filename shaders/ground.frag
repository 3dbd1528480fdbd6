#version 330 core
// A checkerboard that fades into the background with distance, filtered so that it does not
// shimmer at grazing angles.
in vec3 v_world;

uniform vec3 origin;
uniform vec3 unit_u;
uniform vec3 unit_v;
uniform float cell;
uniform float extent;
uniform vec4 background;

out vec4 frag;

void main() {
  vec2 p = vec2(dot(v_world - origin, unit_u), dot(v_world - origin, unit_v)) / cell;
  vec2 w = fwidth(p);
  // Box-filtered checker: the integral of the square wave over the pixel footprint.
  vec2 i = 2.0 * (abs(fract((p - 0.5 * w) * 0.5) - 0.5) - abs(fract((p + 0.5 * w) * 0.5) - 0.5)) / max(w, vec2(1e-6));
  float checker = 0.5 - 0.5 * i.x * i.y;
  vec3 light = vec3(0.33, 0.35, 0.38), dark = vec3(0.25, 0.27, 0.30);
  vec3 rgb = mix(dark, light, checker);
  float fade = smoothstep(0.45, 1.0, length(v_world - origin) / extent);
  frag = vec4(mix(rgb, background.rgb, fade), 1.0);
}
