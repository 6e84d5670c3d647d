#include "ui/renderer.hpp"

#include <cmath>
#include <fstream>
#include <functional>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "ui/fonts.hpp"
#include "ui/gl.hpp"

#include <stb_truetype.h>
#include <iterator>

namespace shotlab {

namespace {

std::string read_asset(const std::string& root, const std::string& name) {
  const std::string path = root + "/assets/" + name;
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read " + path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// `define` (a macro name or nullptr) is defined right after the source's first line, its #version.
unsigned compile(GLenum kind, const std::string& root, const std::string& name, const char* define = nullptr) {
  const std::string text = read_asset(root, name);
  const size_t eol = text.find('\n') == std::string::npos ? text.size() : text.find('\n') + 1;
  const std::string version = text.substr(0, eol), defined = define ? "#define " + std::string(define) + "\n" : "";
  const char* src[3] = {version.c_str(), defined.c_str(), text.c_str() + eol};
  const unsigned shader = glCreateShader(kind);
  glShaderSource(shader, 3, src, nullptr);
  glCompileShader(shader);
  int ok = 0;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    char log[2048];
    glGetShaderInfoLog(shader, sizeof log, nullptr, log);
    throw std::runtime_error(name + ": " + log);
  }
  return shader;
}

// Position + normal, 6 floats a vertex, triangles.
void push(std::vector<float>& v, const glm::vec3& p, const glm::vec3& n) {
  v.insert(v.end(), {p.x, p.y, p.z, n.x, n.y, n.z});
}

std::vector<float> sphere_mesh(int slices, int stacks) {
  std::vector<float> v;
  auto at = [&](int i, int j) {
    const float th = float(M_PI) * j / stacks, ph = 2 * float(M_PI) * i / slices;
    return glm::vec3{std::sin(th) * std::cos(ph), std::cos(th), std::sin(th) * std::sin(ph)};
  };
  for (int j = 0; j < stacks; ++j)
    for (int i = 0; i < slices; ++i) {
      const glm::vec3 a = at(i, j), b = at(i + 1, j), c = at(i + 1, j + 1), d = at(i, j + 1);
      for (const glm::vec3& p : {a, b, c, a, c, d}) push(v, p, p);  // counter-clockwise seen from outside
    }
  return v;
}

std::vector<float> cube_mesh() {  // unit cube centred on the origin
  std::vector<float> v;
  for (int axis = 0; axis < 3; ++axis)
    for (float sign : {-1.0f, 1.0f}) {
      glm::vec3 n{0}, u{0}, w{0};
      n[axis] = sign;
      u[(axis + 1) % 3] = 0.5f;
      w[(axis + 2) % 3] = 0.5f * sign;
      const glm::vec3 c = n * 0.5f;
      for (const glm::vec3& p : {c - u - w, c + u - w, c + u + w, c - u - w, c + u + w, c - u + w}) push(v, p, n);
    }
  return v;
}

std::vector<float> cylinder_mesh(int slices) {  // radius 1, y from 0 to 1, with a top cap
  std::vector<float> v;
  for (int i = 0; i < slices; ++i) {
    const float a = 2 * float(M_PI) * i / slices, b = 2 * float(M_PI) * (i + 1) / slices;
    const glm::vec3 pa{std::cos(a), 0, std::sin(a)}, pb{std::cos(b), 0, std::sin(b)}, up{0, 1, 0};
    for (const glm::vec3& p : {pa, pb + up, pb, pa, pa + up, pb + up}) push(v, p, glm::vec3{p.x, 0, p.z});
    for (const glm::vec3& p : {up, pb + up, pa + up}) push(v, p, up);
  }
  return v;
}

// A box from `from` to `to` across a horizontal segment a-b: `outward` is the horizontal unit normal.
glm::dmat4 slab(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& outward, double from, double to,
                double bottom, double top) {
  const glm::dvec3 along = b - a;
  const glm::dvec3 centre = (a + b) * 0.5 + outward * ((from + to) / 2);
  glm::dmat4 m(1.0);
  m[0] = glm::dvec4(along, 0);
  m[1] = glm::dvec4(0, top - bottom, 0, 0);
  m[2] = glm::dvec4(outward * (to - from), 0);
  m[3] = glm::dvec4(centre.x, (top + bottom) / 2, centre.z, 1);
  return m;
}

}  // namespace

BallLook ball_look(const std::string& id) {
  static const glm::vec3 pool[8] = {{0.1f, 0.1f, 0.1f},   {0.95f, 0.78f, 0.1f}, {0.1f, 0.25f, 0.75f},
                                    {0.8f, 0.1f, 0.1f},   {0.4f, 0.15f, 0.55f}, {0.95f, 0.45f, 0.1f},
                                    {0.05f, 0.45f, 0.2f}, {0.5f, 0.12f, 0.1f}};
  if (id == "cue" || id == "white") return {{0.95f, 0.94f, 0.88f}, 3};
  if (id == "yellow") return {{0.95f, 0.8f, 0.15f}, 1};
  if (id == "red" || id.rfind("red", 0) == 0) return {{0.8f, 0.1f, 0.1f}, 1};  // carom's red, snooker's reds
  if (id == "green") return {{0.05f, 0.45f, 0.2f}, 1};
  if (id == "brown") return {{0.45f, 0.25f, 0.1f}, 1};
  if (id == "blue") return {{0.1f, 0.25f, 0.75f}, 1};
  if (id == "pink") return {{0.95f, 0.55f, 0.65f}, 1};
  if (id == "black") return {{0.1f, 0.1f, 0.1f}, 1};
  char* end = nullptr;
  const long number = std::strtol(id.c_str(), &end, 10);
  if (end != id.c_str() && *end == '\0' && number >= 1 && number <= 15)
    return {number == 8 ? pool[0] : pool[number % 8], number > 8 ? 2 : 1, static_cast<int>(number)};
  const size_t h = std::hash<std::string>{}(id);
  return {{0.3f + (h % 7) * 0.1f, 0.2f + (h / 7 % 7) * 0.1f, 0.3f + (h / 49 % 7) * 0.1f}, 1};
}

Renderer::Program Renderer::link(const std::string& data_root, const char* define) {
  Program p;
  p.id = glCreateProgram();
  const unsigned vs = compile(GL_VERTEX_SHADER, data_root, "shaders/mesh.vert");
  const unsigned fs = compile(GL_FRAGMENT_SHADER, data_root, "shaders/mesh.frag", define);
  glAttachShader(p.id, vs);
  glAttachShader(p.id, fs);
  glLinkProgram(p.id);
  glDeleteShader(vs);
  glDeleteShader(fs);
  int ok = 0;
  glGetProgramiv(p.id, GL_LINK_STATUS, &ok);
  if (!ok) throw std::runtime_error("mesh shader program does not link");
  // A uniform a variant does not use is -1, which glUniform* ignores.
  p.view_proj = glGetUniformLocation(p.id, "u_view_proj");
  p.model = glGetUniformLocation(p.id, "u_model");
  p.normal = glGetUniformLocation(p.id, "u_normal_matrix");
  p.color = glGetUniformLocation(p.id, "u_color");
  p.alpha = glGetUniformLocation(p.id, "u_alpha");
  p.pattern = glGetUniformLocation(p.id, "u_pattern");
  p.eye = glGetUniformLocation(p.id, "u_eye");
  p.number = glGetUniformLocation(p.id, "u_number");
  p.digits = glGetUniformLocation(p.id, "u_digits");
  return p;
}

Renderer::Renderer(const std::string& data_root)
    : plain_(link(data_root, nullptr)), ball_(link(data_root, "BALL")) {
  build_digits();
  sphere_ = upload(sphere_mesh(40, 20));
  coarse_sphere_ = upload(sphere_mesh(20, 10));
  cube_ = upload(cube_mesh());
  cylinder_ = upload(cylinder_mesh(32));
}

Renderer::~Renderer() {
  for (Mesh* m : {&sphere_, &coarse_sphere_, &cube_, &cylinder_}) {
    glDeleteBuffers(1, &m->vbo);
    glDeleteVertexArrays(1, &m->vao);
  }
  glDeleteTextures(1, &digits_);
  glDeleteProgram(plain_.id);
  glDeleteProgram(ball_.id);
}

void Renderer::build_digits() {
  std::ifstream in(kNumeralFont, std::ios::binary);
  const std::vector<unsigned char> ttf((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  stbtt_fontinfo font;
  if (ttf.empty() || !stbtt_InitFont(&font, ttf.data(), stbtt_GetFontOffsetForIndex(ttf.data(), 0))) return;
  constexpr int kCellW = 32, kCellH = 48;  // each glyph centred in its cell (the shader assumes this aspect)
  std::vector<unsigned char> atlas(10 * kCellW * kCellH, 0);
  const float scale = stbtt_ScaleForPixelHeight(&font, 46);
  for (int d = 0; d < 10; ++d) {
    int w = 0, h = 0, xoff = 0, yoff = 0;
    unsigned char* glyph = stbtt_GetCodepointBitmap(&font, 0, scale, '0' + d, &w, &h, &xoff, &yoff);
    const int x0 = d * kCellW + (kCellW - w) / 2, y0 = (kCellH - h) / 2;
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x)
        if (x0 + x >= d * kCellW && x0 + x < (d + 1) * kCellW && y0 + y >= 0 && y0 + y < kCellH)
          atlas[(y0 + y) * 10 * kCellW + x0 + x] = glyph[y * w + x];
    stbtt_FreeBitmap(glyph, nullptr);
  }
  glGenTextures(1, &digits_);
  glBindTexture(GL_TEXTURE_2D, digits_);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_R8, 10 * kCellW, kCellH, 0, GL_RED, GL_UNSIGNED_BYTE, atlas.data());
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
}

Renderer::Mesh Renderer::upload(const std::vector<float>& data) {
  Mesh m;
  m.count = static_cast<int>(data.size() / 6);
  glGenVertexArrays(1, &m.vao);
  glGenBuffers(1, &m.vbo);
  glBindVertexArray(m.vao);
  glBindBuffer(GL_ARRAY_BUFFER, m.vbo);
  glBufferData(GL_ARRAY_BUFFER, data.size() * sizeof(float), data.data(), GL_STATIC_DRAW);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float), nullptr);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float), reinterpret_cast<void*>(3 * sizeof(float)));
  glEnableVertexAttribArray(1);
  glBindVertexArray(0);
  return m;
}

void Renderer::begin(const Viewport& viewport) {
  viewport_ = viewport;
  const int x = static_cast<int>(viewport.x0), w = static_cast<int>(viewport.width), h = static_cast<int>(viewport.height);
  glViewport(x, 0, w, h);
  // The view's part of the window only: the side panels beside it have the window's own background (gui.cpp).
  glEnable(GL_SCISSOR_TEST);
  glScissor(x, 0, w, h);
  glClearColor(0.13f, 0.14f, 0.16f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glDisable(GL_SCISSOR_TEST);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_CULL_FACE);  // meshes wind counter-clockwise seen from outside: faces turned away go unshaded
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);  // on only for see-through draws (draw): blending costs a
                                                      // software renderer a read of every pixel it shades
  for (const Program* p : {&ball_, &plain_}) {
    glUseProgram(p->id);
    glUniformMatrix4fv(p->view_proj, 1, GL_FALSE, glm::value_ptr(glm::mat4(viewport.view_proj)));
    glUniform3fv(p->eye, 1, glm::value_ptr(glm::vec3(viewport.eye)));
    glUniform1i(p->digits, 0);
  }
  current_ = &plain_;
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, digits_);
}

void Renderer::draw(const Mesh& mesh, const glm::dmat4& model, const glm::vec3& color, int pattern, float alpha) {
  const glm::mat4 m(model);
  const glm::mat3 normal = glm::transpose(glm::inverse(glm::mat3(m)));
  const Program& p = pattern == 0 ? plain_ : ball_;
  if (current_ != &p) glUseProgram(p.id), current_ = &p;
  glUniformMatrix4fv(p.model, 1, GL_FALSE, glm::value_ptr(m));
  glUniformMatrix3fv(p.normal, 1, GL_FALSE, glm::value_ptr(normal));
  glUniform3fv(p.color, 1, glm::value_ptr(color));
  glUniform1f(p.alpha, alpha);
  glUniform1i(p.pattern, pattern);
  glUniform1i(p.number, digits_ ? number_ : 0);
  glFrontFace(glm::determinant(glm::mat3(m)) < 0 ? GL_CW : GL_CCW);  // a mirroring transform turns the winding
  glBindVertexArray(mesh.vao);
  if (alpha < 1) glEnable(GL_BLEND);
  glDrawArrays(GL_TRIANGLES, 0, mesh.count);
  glDisable(GL_BLEND);
}

void Renderer::draw_ball(const glm::dvec3& p, const glm::dquat& q, double r, const BallLook& look, float alpha) {
  constexpr double kCoarseUpTo = 12;  // px of radius: a 20-gon's outline is then within 0.15 px of the circle
  const glm::dmat4 m = glm::translate(glm::dmat4(1.0), p) * glm::mat4_cast(q) * glm::scale(glm::dmat4(1.0), glm::dvec3(r));
  if (alpha < 1) glDepthMask(GL_FALSE);  // a see-through ghost must not hide what is behind it
  number_ = look.number;
  const double on_screen = viewport_->screen_radius(p, r);  // 0 when p is behind the eye: nothing shows
  draw(on_screen <= kCoarseUpTo ? coarse_sphere_ : sphere_, m, look.color, look.pattern, alpha);
  number_ = 0;
  glDepthMask(GL_TRUE);
}

void Renderer::draw_scene(const Scene& scene, const Model& model) {
  if (scene.table) draw_table(*scene.table, model);
  else draw_colliders(model);
}

void Renderer::draw_table(const TableSpec& t, const Model& model) {
  const glm::vec3 cloth{0.05f, 0.42f, 0.22f}, rubber{0.04f, 0.34f, 0.17f}, wood{0.36f, 0.2f, 0.09f};
  const double hx = t.length / 2, hz = t.width / 2, rw = t.rail_width;
  const double rail_in = 0.05, rail_top = shotlab::rail_top(t);
  // Cushion rubber from each cushion collider's nose back to the rail.
  for (const Collider& c : model.colliders) {
    const auto* cap = std::get_if<Capsule>(&c.shape);
    if (!cap || c.material != kBallCushion) continue;
    glm::dvec3 along = cap->b - cap->a;
    along.y = 0;
    if (glm::length(along) < 1e-9) continue;
    glm::dvec3 out = glm::normalize(glm::dvec3{-along.z, 0, along.x});
    const glm::dvec3 mid = (cap->a + cap->b) * 0.5;
    if (glm::dot(out, glm::dvec3{mid.x / (hx * hx), 0, mid.z / (hz * hz)}) < 0) out = -out;
    draw(cube_, slab(cap->a, cap->b, out, -cap->radius, rail_in, 0.0, cap->a.y + cap->radius), rubber, 0, 1);
  }
  // Wooden rails outside the cushions, with the diamonds (sights) on top.
  const double o = hx + rail_in, p = hz + rail_in, w = 0.11;
  draw(cube_, slab({-o - w, 0, -p}, {o + w, 0, -p}, {0, 0, -1}, 0, w, -0.02, rail_top), wood, 0, 1);
  draw(cube_, slab({-o - w, 0, p}, {o + w, 0, p}, {0, 0, 1}, 0, w, -0.02, rail_top), wood, 0, 1);
  draw(cube_, slab({-o, 0, -p}, {-o, 0, p}, {-1, 0, 0}, 0, w, -0.02, rail_top), wood, 0, 1);
  draw(cube_, slab({o, 0, -p}, {o, 0, p}, {1, 0, 0}, 0, w, -0.02, rail_top), wood, 0, 1);
  auto diamond = [&](double x, double z) {
    draw(cylinder_, glm::translate(glm::dmat4(1.0), {x, rail_top, z}) * glm::scale(glm::dmat4(1.0), {0.008, 0.001, 0.008}),
         {0.92f, 0.92f, 0.85f}, 0, 1);
  };
  const bool sights = t.kind != TableKind::Snooker;  // a snooker table has none
  for (int k = -3; k <= 3 && sights; ++k)  // every eighth of the length on the long rails, a quarter of the width
    if (k != 0 || t.kind == TableKind::Carom)
      for (double z : {-p - w / 2, p + w / 2}) diamond(k * t.length / 8, z);
  for (int k = -1; k <= 1 && sights; ++k)
    for (double x : {-o - w / 2, o + w / 2}) diamond(x, k * t.width / 4);
  // Pockets: a black disc on the cloth and one cut into the rail top (flat, so nothing sticks up through the rail).
  for (const Pocket& pk : model.pockets)
    for (double y : {0.0005, rail_top + 0.0005})
      draw(cylinder_, glm::translate(glm::dmat4(1.0), {pk.center.x, y - 0.0005, pk.center.z}) *
                          glm::scale(glm::dmat4(1.0), {pk.radius, 0.001, pk.radius}),
           {0.02f, 0.02f, 0.02f}, 0, 1);
  // The pockets' backs (the lined wall a ball meets beyond the hole), as deep as the rails and a hair above the rail
  // top they are cut into.
  const glm::vec3 leather{0.16f, 0.09f, 0.05f};
  for (const Collider& c : model.colliders)
    if (const auto* w = std::get_if<ArcWall>(&c.shape); w && c.material == kBallPocket)
      draw_arc_wall(*w, leather, -0.02, rail_top + 0.001);
  // Cloth over the whole bed collider, which reaches rail_width beyond the noses; last, so that the depth test spares
  // shading it under the rails, cushions and pockets drawn over it.
  draw(cube_, slab({-hx - rw, 0, 0}, {hx + rw, 0, 0}, {0, 0, 1}, -hz - rw, hz + rw, -0.02, 0.0), cloth, 0, 1);
}

// In slabs of at most 10 degrees, each from the outer face's chord inward by the thickness (so that no gaps open
// between them on the outside).
void Renderer::draw_arc_wall(const ArcWall& w, const glm::vec3& color, double bottom, double top) {
  const int n = std::max(1, static_cast<int>(std::ceil(w.half_angle / 0.0873)));
  const glm::dvec3 side{-w.toward.z, 0, w.toward.x}, axis{w.center.x, 0, w.center.z};
  auto at = [&](int k) {
    const double a = w.half_angle * (2.0 * k / n - 1);
    return std::cos(a) * w.toward + std::sin(a) * side;
  };
  for (int k = 0; k < n; ++k) {
    const glm::dvec3 e0 = at(k), e1 = at(k + 1), out = glm::normalize(e0 + e1);
    const double outer = w.radius + w.thickness;
    draw(cube_, slab(axis + outer * e0, axis + outer * e1, out, -w.thickness, 0, bottom, top), color, 0, 1);
  }
}

void Renderer::draw_colliders(const Model& model) {
  const glm::vec3 grey{0.45f, 0.47f, 0.5f};
  for (const Collider& c : model.colliders) {
    if (const auto* s = std::get_if<StaticSphere>(&c.shape))
      draw(sphere_, glm::translate(glm::dmat4(1.0), s->center) * glm::scale(glm::dmat4(1.0), glm::dvec3(s->radius)), grey, 0, 1);
    else if (const auto* cap = std::get_if<Capsule>(&c.shape)) {
      glm::dvec3 along = cap->b - cap->a;
      const glm::dvec3 side = glm::length(glm::dvec3{along.x, 0, along.z}) > 1e-9
                                  ? glm::normalize(glm::dvec3{-along.z, 0, along.x}) : glm::dvec3{1, 0, 0};
      draw(cube_, slab(cap->a, cap->b, side, -cap->radius, cap->radius, cap->a.y - cap->radius, cap->a.y + cap->radius),
           grey, 0, 1);
    } else if (const auto* w = std::get_if<ArcWall>(&c.shape)) {
      draw_arc_wall(*w, grey, w->bottom, w->top);
    } else if (const auto* bp = std::get_if<BoundedPlane>(&c.shape)) {
      glm::dmat4 m(1.0);
      m[0] = glm::dvec4(bp->u, 0);
      m[2] = glm::dvec4(bp->v, 0);
      m[1] = glm::dvec4(bp->normal * 0.01, 0);
      const glm::dvec3 centre = bp->origin + (bp->u + bp->v) * 0.5 - glm::dvec3(m[1]) * 0.5;
      m[3] = glm::dvec4(centre, 1);
      draw(cube_, m, {0.25f, 0.3f, 0.35f}, 0, 1);
    } else if (const auto* pl = std::get_if<Plane>(&c.shape)) {
      // An infinite plane, drawn as a 4 m square around its point.
      const glm::dvec3 n = glm::normalize(pl->normal);
      const glm::dvec3 u = glm::normalize(glm::cross(n, std::abs(n.x) < 0.9 ? glm::dvec3{1, 0, 0} : glm::dvec3{0, 0, 1}));
      glm::dmat4 m(1.0);
      m[0] = glm::dvec4(u * 4.0, 0);
      m[1] = glm::dvec4(n * 0.01, 0);
      m[2] = glm::dvec4(glm::cross(u, n) * 4.0, 0);
      m[3] = glm::dvec4(pl->point - n * 0.005, 1);
      draw(cube_, m, {0.25f, 0.3f, 0.35f}, 0, 1);
    }
  }
}

}  // namespace shotlab
