#version 330 core
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;

uniform mat4 model;
uniform mat4 view;
uniform mat4 projection;

out vec3 v_normal_view;
out vec3 v_position_view;

void main() {
  vec4 p = view * model * vec4(position, 1.0);
  v_position_view = p.xyz;
  v_normal_view = mat3(view) * mat3(model) * normal;
  gl_Position = projection * p;
}
