#version 330 core
in vec4 v_color;
in float v_across;
in float v_half;
out vec4 frag;

void main() {
  // Distance to the edge in pixels: the last pixel fades out.
  float from_edge = (1.0 - abs(v_across)) * v_half;
  frag = vec4(v_color.rgb, v_color.a * clamp(from_edge, 0.0, 1.0));
}
