#version 330 core
in vec2 v_corner;
in vec3 v_center_view;
in float v_radius;
in vec4 v_color;
in float v_pinned;

uniform mat4 projection;
uniform vec3 light_dir;  // view space, towards the light

out vec4 frag;

void main() {
  float r2 = dot(v_corner, v_corner);
  if (r2 > 1.0) discard;
  // Sphere normal and depth at this pixel.
  vec3 n = vec3(v_corner, sqrt(1.0 - r2));
  vec4 clip = projection * vec4(v_center_view + n * v_radius, 1.0);
  gl_FragDepth = 0.5 * (clip.z / clip.w) + 0.5;

  vec3 base = v_color.rgb;
  // Pinned particles: a dark ring round a lighter core.
  if (v_pinned > 0.5) base = r2 > 0.45 ? vec3(0.08) : mix(base, vec3(1.0), 0.35);
  float diffuse = max(dot(n, light_dir), 0.0);
  vec3 h = normalize(light_dir + vec3(0.0, 0.0, 1.0));
  float specular = pow(max(dot(n, h), 0.0), 40.0);
  vec3 rgb = base * (0.35 + 0.75 * diffuse) + 0.35 * specular;
  // Soft edge, turned into coverage by alpha-to-coverage under MSAA.
  float edge = fwidth(r2);
  float alpha = 1.0 - smoothstep(1.0 - 2.0 * edge, 1.0, r2);
  frag = vec4(rgb, alpha * v_color.a);
}
