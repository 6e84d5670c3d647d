// The 3D part of the view: table (cloth, cushions from the cushion colliders, rails, pockets, diamonds), other
// colliders of table-less scenes, and the balls with a pattern that turns with their orientation. Lines, arrows and
// labels are drawn over it with ImGui's draw list (overlay.cpp).
#pragma once
#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>
#include <optional>
#include <string>

#include "shotlab/scene.hpp"
#include "ui/camera.hpp"

namespace shotlab {

struct BallLook {
  glm::vec3 color;
  int pattern;     // as in assets/shaders/mesh.frag
  int number = 0;  // printed in the number circles, 0: none
};
// Pool colours by number, the cue ball by id "cue", carom balls by their names; anything else by a hash of the id.
BallLook ball_look(const std::string& id);

class Renderer {
 public:
  // Needs a current OpenGL 3.3 context; reads its shaders from data_root/assets; throws std::runtime_error when a
  // shader cannot be read or built.
  explicit Renderer(const std::string& data_root);
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  // Clears the window and draws into the viewport (its height is the window's).
  void begin(const Viewport& viewport);
  // `model` is the prepared model (table colliders added) of `scene`.
  void draw_scene(const Scene& scene, const Model& model);
  void draw_ball(const glm::dvec3& p, const glm::dquat& orientation, double radius, const BallLook& look,
                 float alpha = 1.0f);

 private:
  struct Mesh {
    unsigned vao = 0, vbo = 0;
    int count = 0;
  };
  Mesh upload(const std::vector<float>& interleaved);
  void draw(const Mesh& mesh, const glm::dmat4& model, const glm::vec3& color, int pattern, float alpha);
  void draw_table(const TableSpec& table, const Model& model);
  void draw_colliders(const Model& model);
  void draw_arc_wall(const ArcWall& w, const glm::vec3& color, double bottom, double top);  // m: its drawn height
  void build_digits();  // the numerals' glyph atlas (none when the font is missing)

  // The mesh shader built twice: for plain surfaces (pattern 0: the table, colliders) and for balls (BALL defined).
  struct Program {
    unsigned id = 0;
    int view_proj, model, normal, color, alpha, pattern, eye, number, digits;
  };
  static Program link(const std::string& data_root, const char* define);
  Program plain_, ball_;
  const Program* current_ = nullptr;  // in use (begin, draw)
  // A ball small on screen takes the coarse sphere (draw_ball): its outline stays within a fifth of a pixel of the
  // circle, and a software renderer pays for every triangle.
  Mesh sphere_, coarse_sphere_, cube_, cylinder_;
  std::optional<Viewport> viewport_;  // of the frame being drawn (begin)
  unsigned digits_ = 0;  // texture
  int number_ = 0;       // of the ball being drawn
};

}  // namespace shotlab
