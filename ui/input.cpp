// Mouse: left on a ball selects it and drags it (before the shot); left on the cloth aims the cue there (drag to
// sweep); shift+left adds a ball; right drag orbits, middle or shift+right drag pans, the wheel zooms.
// Keys: listed in help_panel (panel_play.cpp), which is the single place the user reads them.
#include <GLFW/glfw3.h>

#include <algorithm>
#include <cmath>

#include "ui/panels.hpp"

namespace shotlab {

namespace {

double ball_height(const Lab& lab) { return lab.scene.balls.empty() ? kPoolBall.radius : lab.scene.balls[0].spec.radius; }

int ball_under(const Lab& lab, const Vec3& p) {
  const Frame& f = lab.frame();
  for (int i = 0; i < f.state.ball_count(); ++i) {
    const Vec3 c = position(f.state.x, i);
    if (glm::length(Vec3{c.x - p.x, 0, c.z - p.z}) < lab.scene.balls[i].spec.radius * 1.2) return i;
  }
  return -1;
}

void keys(Lab& lab, Camera& camera) {
  const ImGuiIO& io = ImGui::GetIO();
  auto pressed = [](int key) { return ImGui::IsKeyPressed(key, false); };
  auto repeat = [](int key) { return ImGui::IsKeyPressed(key, true); };
  if (pressed(GLFW_KEY_SPACE)) {
    if (lab.shot) lab.playing = !lab.playing;
    else lab.shoot();
  }
  if (pressed(GLFW_KEY_S) || pressed(GLFW_KEY_ENTER)) lab.shoot();
  if (pressed(GLFW_KEY_R)) lab.replay();
  if (pressed(GLFW_KEY_U) || (io.KeyCtrl && pressed(GLFW_KEY_Z))) lab.undo();
  if (pressed(GLFW_KEY_N)) lab.continue_from_rest();
  if (repeat(GLFW_KEY_PERIOD)) lab.step();
  if (pressed(GLFW_KEY_LEFT_BRACKET)) lab.settings.slowmo = std::max(1e-3, lab.settings.slowmo / 2);
  if (pressed(GLFW_KEY_RIGHT_BRACKET)) lab.settings.slowmo = std::min(4.0, lab.settings.slowmo * 2);
  if (pressed(GLFW_KEY_T)) camera.top_view();
  if (pressed(GLFW_KEY_HOME)) camera.reset();
  if (pressed(GLFW_KEY_DELETE)) lab.remove_ball(lab.selected);
  if (pressed(GLFW_KEY_F1) || pressed(GLFW_KEY_H)) lab.settings.view.help = !lab.settings.view.help;
  if (pressed(GLFW_KEY_V)) lab.settings.view.velocity = lab.settings.view.spin = !lab.settings.view.velocity;
  if (pressed(GLFW_KEY_F)) lab.settings.view.forces = !lab.settings.view.forces;
  if (pressed(GLFW_KEY_F12)) lab.screenshot_request = "shotlab-screenshot.png";
  if (lab.scene.cue && !lab.shot) {
    // Fine aim: 0.1 degree a press, shift 1 degree, ctrl 0.01 degree.
    const double step = (io.KeyShift ? 1.0 : io.KeyCtrl ? 0.01 : 0.1) * M_PI / 180;
    const int turn = repeat(GLFW_KEY_LEFT) - repeat(GLFW_KEY_RIGHT);
    const int faster = repeat(GLFW_KEY_UP) - repeat(GLFW_KEY_DOWN);
    if (turn || faster) {
      lab.scene.cue->aim += turn * step;
      lab.scene.cue->speed = std::clamp(lab.scene.cue->speed + 0.1 * faster, 0.05, 15.0);
      lab.scene_changed();
    }
  }
}

}  // namespace

void handle_input(Lab& lab, Camera& camera, const Viewport& vp, MouseDrag& drag) {
  const ImGuiIO& io = ImGui::GetIO();
  if (!io.WantCaptureKeyboard) keys(lab, camera);
  const glm::dvec2 mouse{io.MousePos.x, io.MousePos.y};
  const auto on_table = vp.pick_plane(mouse, ball_height(lab));

  if (!io.WantCaptureMouse) {
    if (io.MouseWheel != 0) camera.zoom(io.MouseWheel);
    if (ImGui::IsMouseClicked(ImGuiMouseButton_Right)) drag.kind = io.KeyShift ? MouseDrag::Pan : MouseDrag::Orbit;
    if (ImGui::IsMouseClicked(ImGuiMouseButton_Middle)) drag.kind = MouseDrag::Pan;
    if (ImGui::IsMouseClicked(ImGuiMouseButton_Left) && on_table) {
      const int ball = ball_under(lab, *on_table);
      if (io.KeyShift && ball < 0) {
        lab.add_ball(*on_table);
      } else if (ball >= 0) {
        lab.selected = ball;
        drag = {MouseDrag::Ball, ball};
      } else {
        drag.kind = MouseDrag::Aim;
        lab.aim_at(*on_table);
      }
    }
  }
  const bool held = ImGui::IsMouseDown(ImGuiMouseButton_Left) || ImGui::IsMouseDown(ImGuiMouseButton_Right) ||
                    ImGui::IsMouseDown(ImGuiMouseButton_Middle);
  if (!held) {
    drag = {};
    return;
  }
  const ImVec2 d = io.MouseDelta;
  switch (drag.kind) {
    case MouseDrag::Orbit: camera.orbit(d.x, d.y); break;
    case MouseDrag::Pan: camera.pan(d.x, d.y, vp.height); break;
    case MouseDrag::Ball:
      if (on_table && (d.x != 0 || d.y != 0)) lab.move_ball(drag.ball, *on_table);
      break;
    case MouseDrag::Aim:
      if (on_table && (d.x != 0 || d.y != 0)) lab.aim_at(*on_table);
      break;
    case MouseDrag::None: break;
  }
}

}  // namespace shotlab
