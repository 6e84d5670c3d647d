// Mouse and keys on the 3D view. Aiming and moving are different gestures, so that aiming at a ball never moves it:
//  - Aim tool (default): left click or drag on the cloth aims the cue there; a click on a ball aims at its centre;
//    shift+drag turns the aim by 0.01 degree a pixel; ctrl+drag on a ball moves it.
//  - Move tool: drag a ball to move it, shift+click on the cloth adds one.  Target tool: click sets the target.
//  - Ball in hand: the cue ball follows the pointer, a click puts it down, Esc puts it back.
//  - Right drag orbits, middle or shift+right drag pans, the wheel zooms.
// Keys come from the key queue (keys.hpp) so that a short tap is never lost; help_panel lists them for the user.
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_internal.h>  // ClosePopupsExceptModals

#include <algorithm>
#include <cmath>

#include "ui/keys.hpp"
#include "ui/framing.hpp"
#include "ui/panels.hpp"

namespace shotlab {

namespace {

double ball_height(const Lab& lab) { return lab.scene.balls.empty() ? kPoolBall.radius : lab.scene.balls[0].spec.radius; }

int ball_under(const Lab& lab, const Vec3& p) {
  const Frame& f = lab.frame();
  for (int i = 0; i < f.state.ball_count() && i < static_cast<int>(lab.scene.balls.size()); ++i) {
    const Vec3 c = position(f.state.x, i);
    if (std::hypot(c.x - p.x, c.z - p.z) < lab.scene.balls[i].spec.radius * 1.2) return i;
  }
  return -1;
}

// The aim and speed keys: Left/Right kAimStepDeg (shift 1 degree, ctrl 0.01), Up/Down 0.25 m/s (shift 1, ctrl 0.02).
bool nudge(Lab& lab, const KeyPress& k) {
  const bool shift = k.mods & GLFW_MOD_SHIFT, ctrl = k.mods & GLFW_MOD_CONTROL;
  const double deg = shift ? 1.0 : ctrl ? 0.01 : kAimStepDeg, mps = shift ? 1.0 : ctrl ? 0.02 : 0.25;
  switch (k.key) {
    case GLFW_KEY_LEFT: lab.nudge_aim(deg); return true;
    case GLFW_KEY_RIGHT: lab.nudge_aim(-deg); return true;
    case GLFW_KEY_UP: lab.nudge_speed(mps); return true;
    case GLFW_KEY_DOWN: lab.nudge_speed(-mps); return true;
  }
  return false;
}

void toggle(bool& flag) { flag = !flag; }

// Keys that act once per press (auto-repeat ignored), then those that repeat (stepping, aim, speed).
void key(Lab& lab, Camera& camera, const KeyPress& k) {
  ViewFlags& v = lab.settings.view;
  const bool ctrl = k.mods & GLFW_MOD_CONTROL, shift = k.mods & GLFW_MOD_SHIFT;
  if (k.key == GLFW_KEY_PERIOD) return lab.step(+1);
  if (k.key == GLFW_KEY_COMMA) return lab.step(-1);
  if (nudge(lab, k) || k.repeat) return;
  switch (k.key) {
    case GLFW_KEY_SPACE:
      if (lab.shot && !lab.shot_over()) lab.playing = !lab.playing;
      else if (lab.shot) lab.replay();
      else lab.shoot();
      break;
    case GLFW_KEY_S: case GLFW_KEY_ENTER: case GLFW_KEY_KP_ENTER: lab.shoot(); break;
    case GLFW_KEY_R: lab.replay(); break;
    case GLFW_KEY_U: lab.undo(); break;
    case GLFW_KEY_Z: if (ctrl) shift ? lab.redo() : lab.undo(); break;
    case GLFW_KEY_Y: if (ctrl) lab.redo(); break;
    case GLFW_KEY_N: lab.continue_from_rest(); break;
    case GLFW_KEY_K: lab.keep_shot(); break;
    case GLFW_KEY_B: lab.pick_up_cue_ball(); break;
    case GLFW_KEY_P: lab.aim_for_pocket(shift ? -1 : 1); break;
    case GLFW_KEY_ESCAPE: if (lab.in_hand) lab.undo(); break;
    case GLFW_KEY_LEFT_BRACKET: lab.settings.slowmo = std::max(1e-3, lab.settings.slowmo / 2); break;
    case GLFW_KEY_RIGHT_BRACKET: lab.settings.slowmo = std::min(4.0, lab.settings.slowmo * 2); break;
    case GLFW_KEY_T: camera.top_view(); break;
    case GLFW_KEY_HOME: home_view(camera, lab.scene); break;
    case GLFW_KEY_DELETE: lab.remove_ball(lab.selected); break;
    case GLFW_KEY_F1: case GLFW_KEY_H: toggle(v.help); break;
    case GLFW_KEY_V: v.velocity = v.spin = !v.velocity; break;
    case GLFW_KEY_F: toggle(v.forces); break;
    case GLFW_KEY_L: toggle(v.labels); break;
    case GLFW_KEY_F2: toggle(lab.settings.panels.left_open); break;
    case GLFW_KEY_F3: toggle(lab.settings.panels.right_open); break;
    case GLFW_KEY_F5: toggle(lab.settings.presentation); break;
    case GLFW_KEY_F12: lab.screenshot_request = export_path(lab, "screenshot", "png"); break;
  }
}

// A left press on the table: what it starts depends on the tool, the modifiers and what is under the pointer.
void left_press(Lab& lab, const Vec3& at, MouseDrag& drag, float x) {
  const ImGuiIO& io = ImGui::GetIO();
  if (lab.in_hand) return lab.place_cue_ball(at, true);
  const int ball = ball_under(lab, at);
  if (lab.tool == Tool::Target) {  // a click sets it, a drag carries it along (one undo step)
    if (lab.set_target(at)) drag.kind = MouseDrag::Target;  // a refused press (off the cloth) carries nothing
    return;
  }
  if (lab.tool == Tool::Move || (io.KeyCtrl && ball >= 0)) {
    if (ball >= 0) {
      lab.selected = ball;
      if (lab.begin_move(ball)) drag = {MouseDrag::Ball, ball};
    } else if (io.KeyShift) {
      lab.add_ball(at);
    }
    return;
  }
  if (io.KeyShift && lab.scene.cue) {
    drag = {MouseDrag::FineAim, -1, lab.scene.cue->aim, x};
    return;
  }
  if (ball >= 0 && lab.scene.cue && !lab.shot && lab.scene.balls[ball].spec.id != lab.scene.cue->ball) {
    lab.aim_at_ball(ball);  // the selection (its ring) stays: a player read its move as the cue changing balls
    return;
  }
  if (ball >= 0) {  // the cue ball, a ball while a shot is shown or in a scene without a cue strike: selected
    lab.selected = ball;
    return;
  }
  drag.kind = MouseDrag::Aim;
  lab.aim_at(at);
}

void drag_move(Lab& lab, Camera& camera, const Viewport& vp, MouseDrag& drag, const std::optional<Vec3>& at) {
  const ImGuiIO& io = ImGui::GetIO();
  const ImVec2 d = io.MouseDelta;
  if (d.x == 0 && d.y == 0) return;
  switch (drag.kind) {
    case MouseDrag::Orbit: camera.orbit(d.x, d.y); break;
    case MouseDrag::Pan: camera.pan(d.x, d.y, vp.height); break;
    case MouseDrag::Ball: if (at) lab.move_ball(drag.ball, *at); break;
    case MouseDrag::Aim: if (at) lab.aim_at(*at); break;
    case MouseDrag::Target: if (at) lab.drag_target(*at); break;
    case MouseDrag::FineAim:
      if (lab.scene.cue) {
        CueStrike c = *lab.scene.cue;
        c.aim = drag.aim0 - (io.MousePos.x - drag.x0) * 0.01 * M_PI / 180;
        lab.set_cue(c, "fine aim");
      }
      break;
    case MouseDrag::None: break;
  }
}

}  // namespace

void handle_input(Lab& lab, Camera& camera, const Viewport& vp, MouseDrag& drag, bool over_view) {
  const ImGuiIO& io = ImGui::GetIO();
  // Nothing behind a text field or an open dialog or list (Open, Save as, a combo's) hears the keys: Return in Save as
  // must not shoot, nor Delete there remove a ball.
  const bool covered = io.WantTextInput || ImGui::IsPopupOpen("", ImGuiPopupFlags_AnyPopupId);
  // Escape closes an open list or menu (ImGui does so only under keyboard navigation, which would take the arrow
  // keys from the aim); a dialog (Open, Save as) handles it itself as Cancel. From the key queue: a short tap counts.
  for (const KeyPress& k : take_key_presses())
    if (!covered) key(lab, camera, k);
    else if (k.key == GLFW_KEY_ESCAPE) ImGui::ClosePopupsExceptModals();
  const glm::dvec2 mouse{io.MousePos.x, io.MousePos.y};
  const auto at = vp.pick_plane(mouse, ball_height(lab));
  const bool free = over_view && !io.WantCaptureMouse;

  if (lab.in_hand && at && free) lab.place_cue_ball(*at, false);
  if (free) {
    if (io.MouseWheel != 0) camera.zoom(io.MouseWheel, at);  // towards the cloth under the pointer
    if (ImGui::IsMouseClicked(ImGuiMouseButton_Right)) drag.kind = io.KeyShift ? MouseDrag::Pan : MouseDrag::Orbit;
    if (ImGui::IsMouseClicked(ImGuiMouseButton_Middle)) drag.kind = MouseDrag::Pan;
    if (ImGui::IsMouseClicked(ImGuiMouseButton_Left) && at) left_press(lab, *at, drag, io.MousePos.x);
  }
  const bool held = ImGui::IsMouseDown(ImGuiMouseButton_Left) || ImGui::IsMouseDown(ImGuiMouseButton_Right) ||
                    ImGui::IsMouseDown(ImGuiMouseButton_Middle);
  if (!held) {
    if (drag.kind != MouseDrag::None) lab.end_gesture();
    drag = {};
    return;
  }
  drag_move(lab, camera, vp, drag, at);
}

}  // namespace shotlab
