#version 330 core
// Lambert + a little specular. u_pattern: 0 plain; 1 solid ball (white number circles at the poles);
// 2 striped ball (white with a coloured band); 3 cue ball (white with red dots on the six axes, so its spin shows).
in vec3 v_normal;
in vec3 v_object;
in vec3 v_world;
uniform vec3 u_color;
uniform float u_alpha;
uniform int u_pattern;
uniform vec3 u_eye;
out vec4 frag_color;

vec3 ball_color(vec3 n) {
  vec3 white = vec3(0.95, 0.94, 0.88);
  if (u_pattern == 3) {
    float d = max(max(abs(n.x), abs(n.y)), abs(n.z));
    return d > 0.96 ? vec3(0.85, 0.08, 0.08) : white;
  }
  float pole = abs(n.y);
  if (pole > 0.985) return vec3(0.08);         // the number's ink: a dot, so the pole's turning shows
  if (pole > 0.82) return white;               // the number circle
  if (u_pattern == 2 && pole > 0.45) return white;
  return u_color;
}

void main() {
  vec3 n = normalize(v_normal);
  vec3 base = u_pattern == 0 ? u_color : ball_color(normalize(v_object));
  vec3 light = normalize(vec3(0.3, 1.0, 0.45));
  vec3 view = normalize(u_eye - v_world);
  float diffuse = max(dot(n, light), 0.0);
  float specular = u_pattern == 0 ? 0.0 : pow(max(dot(reflect(-light, n), view), 0.0), 40.0) * 0.5;
  frag_color = vec4(base * (0.35 + 0.7 * diffuse) + vec3(specular), u_alpha);
}
