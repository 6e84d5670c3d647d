#version 330 core
// Lambert, and for balls (compiled with BALL defined) their pattern and a little specular. u_pattern: 1 solid ball
// (white number circles at the poles); 2 striped ball (white with a coloured band); 3 cue ball (white with red dots
// on the six axes, so its spin shows). u_number (1 to 15, 0: none) is printed in the number circles from u_digits, an
// atlas of the glyphs 0 to 9. Plain surfaces take the program without BALL: a software renderer would otherwise pay
// for the balls' branch on every pixel of the cloth.
in vec3 v_normal;
in vec3 v_object;
in vec3 v_world;
uniform vec3 u_color;
uniform float u_alpha;
uniform int u_pattern;
uniform vec3 u_eye;
uniform int u_number;
uniform sampler2D u_digits;
out vec4 frag_color;

#ifdef BALL
// Ink (0 to 1) of the number at p, in the number circle's own coordinates (its radius is 1).
float number_ink(vec2 p) {
  const float h = 1.1, w = h * 32.0 / 48.0;  // glyph box, in circle radii (atlas cells are 32 x 48)
  int digits = u_number >= 10 ? 2 : 1;
  float x = p.x + w * float(digits) * 0.5, t = (h * 0.5 - p.y) / h;
  int k = int(floor(x / w));
  if (x < 0.0 || k >= digits || t < 0.0 || t > 1.0) return 0.0;
  int digit = digits == 2 && k == 0 ? u_number / 10 : u_number % 10;
  return texture(u_digits, vec2((float(digit) + fract(x / w)) / 10.0, t)).r;
}

vec3 ball_color(vec3 n) {
  vec3 white = vec3(0.95, 0.94, 0.88);
  if (u_pattern == 3) {
    float d = max(max(abs(n.x), abs(n.y)), abs(n.z));
    return d > 0.96 ? vec3(0.85, 0.08, 0.08) : white;
  }
  float pole = abs(n.y);
  if (pole > 0.82) {  // the number circle: the numeral, or a dot, so that the pole's turning shows
    if (u_number == 0) return pole > 0.985 ? vec3(0.08) : white;
    vec2 p = vec2(n.y > 0.0 ? n.x : -n.x, -n.z) / 0.572;
    return mix(white, vec3(0.05), number_ink(p));
  }
  if (u_pattern == 2 && pole > 0.45) return white;
  return u_color;
}
#endif

void main() {
  vec3 n = normalize(v_normal);
  vec3 light = normalize(vec3(0.3, 1.0, 0.45));
  float diffuse = max(dot(n, light), 0.0);
#ifdef BALL
  vec3 base = ball_color(normalize(v_object));
  vec3 view = normalize(u_eye - v_world);
  float specular = pow(max(dot(reflect(-light, n), view), 0.0), 40.0) * 0.5;
#else
  vec3 base = u_color;
  float specular = 0.0;
#endif
  frag_color = vec4(base * (0.35 + 0.7 * diffuse) + vec3(specular), u_alpha);
}
