#version 330 core
// Meshes of the table and the balls. v_object is the unrotated unit normal of a ball, so the ball pattern turns with
// the ball's orientation.
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
uniform mat4 u_view_proj;
uniform mat4 u_model;
uniform mat3 u_normal_matrix;
out vec3 v_normal;
out vec3 v_object;
out vec3 v_world;
void main() {
  vec4 world = u_model * vec4(a_position, 1.0);
  v_world = world.xyz;
  v_normal = u_normal_matrix * a_normal;
  v_object = a_normal;
  gl_Position = u_view_proj * world;
}
