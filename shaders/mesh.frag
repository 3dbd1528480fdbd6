#version 330 core
// Two-sided Blinn-Phong: the front and the back of a cloth have their own colours.
in vec3 v_normal_view;
in vec3 v_position_view;

uniform vec4 front_color;
uniform vec4 back_color;
uniform vec3 light_dir;  // view space

out vec4 frag;

void main() {
  vec3 n = normalize(v_normal_view);
  vec4 base = front_color;
  if (!gl_FrontFacing) {
    n = -n;
    base = back_color;
  }
  vec3 v = normalize(-v_position_view);
  // A key light from above, a head light from the eye (so that a surface seen face-on is never
  // dark), and a little light bounced back from below.
  float key = max(dot(n, light_dir), 0.0);
  float head = max(dot(n, v), 0.0);
  float bounce = 0.12 * max(dot(n, -light_dir), 0.0);
  vec3 h = normalize(light_dir + v);
  float specular = pow(max(dot(n, h), 0.0), 32.0);
  vec3 rgb = base.rgb * (0.22 + 0.55 * key + 0.40 * head + bounce) + 0.15 * specular;
  frag = vec4(rgb, base.a);
}
