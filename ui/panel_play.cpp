// The left panel (players and coaches, and the teacher's presets): scene, playback, aim, practice, balls and view;
// the help panel; the message banner; the status line.
#include <imgui.h>
#include <imgui_internal.h>  // BringWindowToDisplayFront: the banner stays over the help window
#include <imgui_stdlib.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <string>

#include "shotlab/cue.hpp"
#include "ui/aim.hpp"
#include "ui/panels.hpp"
#include "ui/widgets.hpp"

namespace shotlab {

namespace {

const char* end_text(const Shot& s) {
  switch (s.end()) {
    case ShotEnd::Rest: return "every ball at rest";
    case ShotEnd::SafetyLimit: return "stopped at the safety limit, balls still moving";
    case ShotEnd::EngineStop: return "the simulation stopped";
    case ShotEnd::Running: break;
  }
  return "";
}

void transport_buttons(Lab& lab) {
  const char* main = lab.shot ? (lab.playing ? "Pause" : "Play") : "Shoot";
  // As wide as its widest label: Play and Pause taking turns must not move the buttons after it to another row.
  float width = 0;
  for (const char* label : {"Pause", "Play", "Shoot"}) width = std::max(width, ImGui::CalcTextSize(label).x);
  if (ImGui::Button(main, ImVec2(width + 2 * ImGui::GetStyle().FramePadding.x, 0))) {
    if (!lab.shot) lab.shoot();
    else if (lab.shot_over() && !lab.playing) lab.replay();
    else lab.playing = !lab.playing;
  }
  mark(lab.shot ? "Play" : "Shoot");
  same_line_if_fits("<");
  if (ImGui::ArrowButton("back", ImGuiDir_Left)) lab.step(-1);
  mark("Step back");
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("step back one frame of simulated time (,)");
  same_line_if_fits(">");
  if (ImGui::ArrowButton("forward", ImGuiDir_Right)) lab.step(+1);
  mark("Step");
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("step forward one frame of simulated time (.)");
  same_line_if_fits("Replay");
  ImGui::BeginDisabled(!lab.shot);
  if (ImGui::Button("Replay")) lab.replay();
  if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
    ImGui::SetTooltip(lab.shot ? "play the shot again from its start (R)" : "no shot yet: S or Space shoots");
  ImGui::EndDisabled();
  same_line_if_fits("Undo");
  ImGui::BeginDisabled(!lab.history.can_undo() && !lab.in_hand);
  if (ImGui::Button("Undo")) lab.undo();
  mark("Undo");
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("undo %s (U, Ctrl+Z)", lab.history.undo_label().c_str());
  ImGui::EndDisabled();
  same_line_if_fits("Redo");
  ImGui::BeginDisabled(!lab.history.can_redo());
  if (ImGui::Button("Redo")) lab.redo();
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("redo %s (Ctrl+Y)", lab.history.redo_label().c_str());
  ImGui::EndDisabled();
  same_line_if_fits("Next");
  ImGui::BeginDisabled(!lab.shot || lab.shot->end() != ShotEnd::Rest);
  if (ImGui::Button("Next")) lab.continue_from_rest();
  mark("Next");
  if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
    ImGui::SetTooltip("next shot from where the balls stopped (N); once every ball rests");
  ImGui::EndDisabled();
}

void playback_section(Lab& lab) {
  transport_buttons(lab);
  const Fields f({"clock", "time", "safety limit"});
  f.label("clock");
  slider("##clock", lab.settings.slowmo, 1e-3, 4.0, "%.3gx real time", true);
  mark("clock slider");
  if (!lab.shot) {
    hint("aiming: S or Space shoots");
  } else {
    double t = lab.view_time;
    f.label("time");
    if (slider("##time", t, 0.0, std::max(lab.shot->sim().time(), 1e-9), lab.contact_on_screen() ? "%.6f s" : "%.4f s")) {
      lab.playing = false;
      lab.view_time = t;
    }
    mark("time slider");
    // The slider shows the time; while a contact is on screen it is to the microsecond, and this says why.
    if (lab.contact_on_screen()) hint("a contact on screen: time to the microsecond");
    if (lab.shot->finished())
      coloured_wrapped(lab.shot->end() == ShotEnd::Rest ? ImVec4(0.6f, 0.9f, 0.6f, 1) : ImVec4(1, 0.7f, 0.3f, 1),
                         "%s after %.2f s", end_text(*lab.shot), lab.shot->sim().time());
    if (lab.shot->end() == ShotEnd::SafetyLimit && lab.shot_over()) {
      if (ImGui::Button("Run on")) lab.run_on();
      char more[48];
      std::snprintf(more, sizeof more, "for another %.0f s", lab.settings.safety_limit);
      same_line_if_fits(more);
      ImGui::TextDisabled("%s", more);
    }
    if (lab.playing && lab.achieved_speed < 0.95)
      coloured_wrapped(ImVec4(1, 0.7f, 0.2f, 1), "physics behind: clock slowed to %.0f%% of the set speed",
                         100 * lab.achieved_speed);
  }
  f.label("safety limit");
  slider("##limit", lab.settings.safety_limit, 5.0, 600.0, "%.0f s simulated", true);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("a shot runs until every ball rests, or this long (the next shot)");
  // Kept from session to session: said here, so that a shot that stops by itself is not a mystery.
  const PauseOn& p = lab.settings.pause_on;
  if (p.ball_ball || p.cushion || p.pocketed) {
    std::string on;
    for (const auto& [set, name] : {std::pair{p.ball_ball, "ball-ball contacts"},
                                    std::pair{p.cushion, "cushion contacts"}, std::pair{p.pocketed, "pocketed balls"}})
      if (set) on += (on.empty() ? "" : ", ") + std::string(name);
    text_wrapped("pauses at %s (Tuning: Pause on events)", on.c_str());
    mark("pause on events");
  }
}

void tool_buttons(Lab& lab) {
  const struct {
    Tool tool;
    const char* name;
    const char* tip;
  } tools[] = {{Tool::Aim, "Aim", "click the cloth to aim there, click a ball to aim at its centre; shift+drag aims finely"},
               {Tool::Move, "Move balls", "drag a ball to move it; shift+click the cloth adds one (also Ctrl+drag in Aim)"},
               {Tool::Target, "Target", "click where the cue ball should stop: the miss shows after the shot"}};
  for (const auto& t : tools) {
    if (t.tool != Tool::Aim) same_line_if_checkbox_fits(t.name);  // a radio button is a checkbox's size
    // "##tool": the Aim section's header has the label "Aim" too; one ID for both left this button dead.
    if (ImGui::RadioButton((std::string(t.name) + "##tool").c_str(), lab.tool == t.tool)) lab.tool = t.tool;
    mark(std::string("tool ") + t.name);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", t.tip);
  }
}

void aim_readouts(const Lab& lab, const CueStrike& cue) {
  const int c = scene_ball(lab.scene, cue.ball);
  if (c < 0) return;
  const StrikeResult r = strike(cue, lab.scene.balls[c].spec.mass, lab.scene.balls[c].spec.radius);
  // Wrapped: presentation mode's large text in a narrow panel cut these lines at the edge.
  if (r.squirt != 0)
    text_wrapped("squirt %.2f deg %s of the cue line", std::abs(r.squirt) * 180 / M_PI, r.squirt > 0 ? "left" : "right");
  std::optional<Scene> greyed;  // an unticked cue strike's stroke reads as it would struck: the lines stay
  if (!lab.scene.cue) greyed = lab.scene, greyed->cue = cue;
  if (const auto line = aim_line(greyed ? *greyed : lab.scene); line && line->hit >= 0)
    text_wrapped("first ball %s, cut %.1f deg", lab.scene.balls[line->hit].spec.id.c_str(), line->cut_deg);
  if (const auto miss = lab.target_miss())
    text_wrapped("%s miss of the target: %.1f cm", lab.shot ? "cue ball's" : "predicted", *miss * 100);
}

// The stroke of the cue strike: ball in hand, pocket aims, speed, aim, elevation, tip and what they give.
void aim_controls(Lab& lab, CueStrike& cue) {
  if (ImGui::Button(lab.in_hand ? "Put down (click)" : "Ball in hand (B)")) lab.pick_up_cue_ball();
  mark("Ball in hand");
  same_line_if_fits("< pocket");
  if (ImGui::Button("< pocket")) lab.aim_for_pocket(-1);
  same_line_if_fits("pocket >");
  if (ImGui::Button("pocket >")) lab.aim_for_pocket(+1);
  mark("pocket aim");
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("aim the ball you aim at into the next pocket (P, Shift+P)");
  const Fields f({"cue speed", "aim", "elevation"});
  f.label("cue speed");
  if (slider("##speed", cue.speed, 0.05, 15.0, "%.2f m/s")) lab.set_cue(cue, "speed");
  mark("speed slider");
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("the cue stick's speed at the tip; the ball leaves faster, as the stick is heavier (the speed "
                      "it leaves at is shown under the slider)\nUp/Down 0.25 m/s, Shift 1 m/s, Ctrl 0.02 m/s");
  // Right under it: a preset's notes speak of the ball's speed, which a trial compared with the stick's.
  if (const int c = scene_ball(lab.scene, cue.ball); c >= 0) {
    const BallSpec& ball = lab.scene.balls[c].spec;
    text_wrapped("the cue ball leaves at %.2f m/s", glm::length(strike(cue, ball.mass, ball.radius).velocity));
  }
  double aim = cue.aim * 180 / M_PI, elevation = cue.elevation * 180 / M_PI;
  f.label("aim");
  if (ImGui::DragScalar("##aim", ImGuiDataType_Double, &aim, 0.01f, nullptr, nullptr, "%.2f deg")) {
    cue.aim = aim * M_PI / 180;
    lab.set_cue(cue, "aim");
  }
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("drag: 0.01 deg a pixel; Left/Right 0.1 deg, Shift 1, Ctrl 0.01");
  f.label("elevation");
  if (slider("##elevation", elevation, 0.0, 85.0, "%.1f deg")) {
    cue.elevation = elevation * M_PI / 180;
    lab.set_cue(cue, "elevation");
  }
  if (tip_widget(cue, em(104))) lab.set_cue(cue, "tip");
  if (ImGui::IsItemDeactivated()) lab.end_gesture();
  same_line_if_fits("follow 0.00 R");  // the readouts' widest line: beside the pad, or under it in a narrow panel
  ImGui::BeginGroup();
  ImGui::Text("side %+.2f R", cue.side);
  ImGui::Text("%s %.2f R", cue.height >= 0 ? "follow" : "draw", std::abs(cue.height));
  if (std::hypot(cue.side, cue.height) > cue.miscue_limit) ImGui::TextColored(ImVec4(1, 0.4f, 0.3f, 1), "MISCUE risk");
  if (ImGui::SmallButton("centre")) cue.side = cue.height = 0, lab.set_cue(cue, "tip");
  ImGui::EndGroup();
  aim_readouts(lab, cue);
}

// The ball the cue strikes, any of the scene's: the stroke (speed, aim, tip) stays as it is.
void struck_ball(Lab& lab, CueStrike& cue) {
  same_line_if_fits("on 00000000");
  ImGui::TextUnformatted("on");
  ImGui::SameLine();
  ImGui::SetNextItemWidth(-FLT_MIN);
  if (ImGui::BeginCombo("##struck ball", cue.ball.c_str())) {
    for (const InitialBall& b : lab.scene.balls)
      if (ImGui::Selectable(b.spec.id.c_str(), b.spec.id == cue.ball) && b.spec.id != cue.ball) {
        cue.ball = b.spec.id;
        lab.set_cue(cue, "struck ball");
      }
    ImGui::EndCombo();
  }
  mark("struck ball");
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("the ball the cue strikes; speed, aim and tip stay");
}

void aim_section(Lab& lab) {
  if (lab.scene.balls.empty()) return;
  bool has_cue = lab.scene.cue.has_value();
  if (ImGui::Checkbox("cue strike", &has_cue) && !lab.shot) lab.set_cue_strike(has_cue);
  mark("cue strike");
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("untick for a scene whose balls start as placed (moving or not); the stroke stays, greyed");
  // Unticked, the stroke stays drawn greyed: the panel keeps its height (unticking once pulled the checkbox from
  // under the pointer), and ticking brings the same stroke back.
  CueStrike cue = lab.scene.cue ? *lab.scene.cue : lab.spare_cue();
  ImGui::BeginDisabled(!lab.scene.cue);
  struck_ball(lab, cue);
  ImGui::EndDisabled();
  tool_buttons(lab);  // Move balls and Target serve a scene without a cue strike too
  ImGui::BeginDisabled(!lab.scene.cue);
  aim_controls(lab, cue);
  ImGui::EndDisabled();
}

void balls_section(Lab& lab) {
  text_wrapped("With the Move tool, drag a ball to move it and shift+click the cloth to add one; Del removes "
                     "the selected ball. Every edit can be undone.");
  if (ImGui::Button("Remove selected")) lab.remove_ball(lab.selected);
  if (ImGui::Checkbox("allow overlaps", &lab.scene.allow_overlap)) lab.scene_changed();
}

// The scene's notes ("What to look for"), read or edited in place: a teacher's own words for a scene made from a
// preset, saved with it. Typing is one undo entry until Done.
void notes_section(Lab& lab) {
  static bool editing = false;
  if (!editing) {
    // Long notes scroll in a box of at most a sixth of the window's height: on a laptop they pushed the aim and the
    // tip picture below the panel's edge.
    const char* text = lab.scene.description.c_str();
    // Whole lines: a trial read the box's last line cut in half.
    const float line = ImGui::GetTextLineHeight();
    const float cap = line * std::floor(std::max(ImGui::GetMainViewport()->Size.y / 6, 4 * line + 4) / line);
    const float tall = ImGui::CalcTextSize(text, nullptr, false, ImGui::GetContentRegionAvail().x).y;
    if (tall > cap && ImGui::BeginChild("##notes view", ImVec2(0, cap))) {
      text_wrapped("%s", text);
      pass_wheel_on();
    }
    if (tall > cap) ImGui::EndChild();
    else if (*text) text_wrapped("%s", text);
    // The long label where it fits: presentation mode's large text cut it to "Edit name and note".
    const bool fits = ImGui::CalcTextSize("Edit name and notes").x + 2 * ImGui::GetStyle().FramePadding.x <=
                      ImGui::GetContentRegionAvail().x;
    const char* edit = lab.scene.description.empty() ? "Add notes###edit" : fits ? "Edit name and notes###edit"
                                                                                  : "Edit###edit";
    if (ImGui::SmallButton(edit)) editing = true;
    mark("Edit notes");
    return;
  }
  // The scene's name too: a drill saved from a preset kept the preset's name, with nowhere to change it.
  std::string name = lab.scene.name;
  const Fields f({"name"});
  f.label("name");
  ImGui::SetNextItemWidth(-FLT_MIN);
  if (ImGui::InputText("##scene name", &name)) {
    lab.history.record("name and notes", lab.scene, "notes");  // one step with the notes, until Done
    lab.scene.name = std::move(name);
  }
  mark("scene name");
  std::string text = lab.scene.description;
  if (ImGui::InputTextMultiline("##notes", &text, ImVec2(-FLT_MIN, em(100)))) {
    lab.history.record("name and notes", lab.scene, "notes");
    lab.scene.description = std::move(text);
  }
  mark("notes");
  // The box does not wrap (ImGui 1.86): the notes as they will read, wrapped, under it.
  ImGui::PushTextWrapPos(0.0f);
  ImGui::TextDisabled("%s", lab.scene.description.c_str());
  ImGui::PopTextWrapPos();
  if (ImGui::SmallButton("Done")) {
    editing = false;
    lab.history.seal();
  }
  mark("Done");
}

}  // namespace

bool left_panel(Lab& lab, Camera& camera, const Layout& layout) {
  static bool shown = true;
  if (begin_side_panel("Shot lab", layout.left, lab.settings.panels.left_open, shown)) {
    PanelState& panels = lab.settings.panels;
    const Rect& grip = layout.left_grip;
    const float bar = ImGui::GetFrameHeight();
    const PanelWidths widths{panels.left_width, panels.right_width, layout.left_shown(),
                             layout.right_shown(panels.right_open), lab.settings.presentation};
    panel_width_grip("left panel width grip", Rect{grip.x, grip.y + bar, grip.w, grip.h - bar}, layout.left.x, widths,
                     ImGui::GetFontSize() / kBaseFontPx, PanelState{}.left_width);
    text_wrapped("%s", lab.scene.name.c_str());
    if (section("What to look for", "Notes", ImGuiTreeNodeFlags_DefaultOpen)) notes_section(lab);
    if (section("Scene and files", "Files", ImGuiTreeNodeFlags_DefaultOpen)) scene_section(lab);
    if (ImGui::CollapsingHeader("Playback", ImGuiTreeNodeFlags_DefaultOpen)) playback_section(lab);
    if (ImGui::CollapsingHeader("Aim", ImGuiTreeNodeFlags_DefaultOpen)) aim_section(lab);
    if (ImGui::CollapsingHeader("Practice")) practice_section(lab);
    lab.margin.open = ImGui::CollapsingHeader("Shot margin");
    mark("Shot margin");
    if (lab.margin.open) margin_section(lab);
    else update_margin(lab, lab.margin);  // closed: cancels what runs
    if (ImGui::CollapsingHeader("Balls")) balls_section(lab);
    const bool view_open = ImGui::CollapsingHeader("View");
    mark("View");
    if (view_open) view_section(lab, camera);
  }
  shown = end_side_panel("panel Shot lab");
  ImGui::End();
  return shown;
}

void help_panel(bool* open, float top) {
  static int frames_open = 0;  // centred over its first frames: the first one's size is not the table's yet
  static ImVec2 at;            // its corner in the last frame (the user may drag it)
  if (!*open) return void(frames_open = 0);
  // Below `top` (the banner), with its title and close box; what does not fit below it scrolls.
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowSizeConstraints(ImVec2(0, 0), ImVec2(FLT_MAX, std::max(display.y - top - em(4), em(120))));
  if (frames_open++ < 3)
    ImGui::SetNextWindowPos(ImVec2(display.x / 2, (top + display.y) / 2), ImGuiCond_Always, ImVec2(0.5f, 0.5f));
  else if (at.y < top)
    ImGui::SetNextWindowPos(ImVec2(at.x, top), ImGuiCond_Always);
  ImGui::Begin("Help", open, ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoSavedSettings);
  at = ImGui::GetWindowPos();
  mark_rect("help window", Rect{at.x, at.y, ImGui::GetWindowWidth(), ImGui::GetWindowHeight()});
  static const char* rows[][2] = {
      {"Left click cloth / drag", "aim the cue there (Aim tool)"}, {"Left click a ball", "aim at its centre"},
      {"Shift + left drag", "fine aim (0.01 deg a pixel)"}, {"Ctrl + left drag a ball", "move it"},
      {"Move tool: drag / shift+click", "move a ball / add one"}, {"B", "ball in hand (click puts it down, Esc back)"},
      {"P / Shift+P", "aim the next / previous pocket"}, {"Del", "remove the selected ball"},
      {"Right drag / shift+right, middle", "orbit / pan the camera"}, {"Wheel", "zoom towards the pointer"},
      {"T / Home", "top view / fit the table"}, {"Left, Right (Shift, Ctrl)", "aim 0.1 deg (1, 0.01)"},
      {"Up, Down (Shift, Ctrl)", "cue speed 0.25 m/s (1, 0.02)"}, {"S or Enter", "shoot"},
      {"Space", "play / pause (shoot when aiming)"}, {", and .", "step back / forward one frame"},
      {"[ ]", "slower / faster clock (1/1000 to 4x)"}, {"R", "replay the shot"},
      {"U or Ctrl+Z, Ctrl+Y", "undo (edits and shots), redo"}, {"N", "next shot from where the balls stopped"},
      {"K", "keep this shot's trails to compare"}, {"V / F / L", "vectors / contact forces / ball labels"},
      {"F2 / F3", "show or hide the left / right panel"}, {"F5", "presentation mode (large fonts)"},
      {"F12", "screenshot"}, {"H or F1", "this help"}};
  if (ImGui::BeginTable("keys", 2)) {
    for (const auto& r : rows) {
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(r[0]);
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(r[1]);
    }
    ImGui::EndTable();
  }
  text_wrapped("Trail colours: orange sliding, blue rolling, magenta airborne, yellow spinning in place.");
  readout("help scroll px", ImGui::GetScrollY());
  readout("help scroll max px", ImGui::GetScrollMaxY());
  ImGui::End();
}

float message_banner(Lab& lab, const Rect& view) {
  if (lab.message_kind == MessageKind::None || lab.message.empty()) return 0;
  // Below a title bar's height: a collapsed panel's title lies over the view's top corner.
  ImGui::SetNextWindowPos(ImVec2(view.x + view.w / 2, view.y + ImGui::GetFrameHeight() + em(6)), ImGuiCond_Always,
                          ImVec2(0.5f, 0));
  ImGui::SetNextWindowSizeConstraints(ImVec2(em(200), 0), ImVec2(std::max(view.w * 0.9f, em(200)), em(300)));
  ImGui::Begin("##message", nullptr, ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize |
                                         ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing);
  mark("banner");
  // Over the help window and the panels (it says why), but not over an open dialog or list, which would lose clicks.
  if (!ImGui::IsPopupOpen("", ImGuiPopupFlags_AnyPopupId)) ImGui::BringWindowToDisplayFront(ImGui::GetCurrentWindow());
  const bool problem = lab.message_kind == MessageKind::LoadError || lab.message_kind == MessageKind::EngineStop;
  ImGui::PushStyleColor(ImGuiCol_Text, problem ? ImVec4(1, 0.45f, 0.4f, 1)
                                               : lab.message_kind == MessageKind::Refused ? ImVec4(1, 0.8f, 0.4f, 1)
                                                                                          : ImVec4(1, 1, 1, 1));
  ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + std::max(view.w * 0.85f, em(200)));
  ImGui::TextUnformatted(lab.message.c_str());
  ImGui::PopTextWrapPos();
  ImGui::PopStyleColor();
  if (lab.message_kind == MessageKind::LoadError && lab.scene_kept)
    hint("The scene you had is still loaded.");
  if (ImGui::SmallButton("Dismiss")) lab.say(MessageKind::None, "");
  mark("Dismiss");
  if (lab.message_kind == MessageKind::EngineStop) {
    ImGui::SameLine();
    if (ImGui::SmallButton("Undo the shot")) lab.undo();
  }
  const ImVec2 at = ImGui::GetWindowPos();
  const Rect banner{at.x, at.y, ImGui::GetWindowWidth(), ImGui::GetWindowHeight()};
  mark_rect("banner window", banner);
  ImGui::End();
  return banner.bottom();
}

void status_line(const Lab& lab, const Rect& view, double frame_seconds, bool slept) {
  char part[3][80] = {};
  const double physics = lab.shot && lab.playing ? lab.shot->last_wall() * 1e3 : 0.0;
  const auto prediction = lab.prediction_seconds();
  // At idle the window sleeps until input (or half a second): the frame's time is then the wait, not the drawing.
  if (slept) std::snprintf(part[0], sizeof part[0], "idle: drawn on input");
  else std::snprintf(part[0], sizeof part[0], "frame %.1f ms (%.0f fps)", frame_seconds * 1e3,
                     frame_seconds > 0 ? 1 / frame_seconds : 0.0);
  if (!slept) std::snprintf(part[1], sizeof part[1], "physics %.2f ms/frame", physics);
  if (prediction) std::snprintf(part[2], sizeof part[2], "prediction %.1f ms", *prediction * 1e3);
  // As many parts as the view has room for (a narrow view at a large UI scale keeps the first), never over a panel.
  std::string text = part[0];
  for (int k = 1; k < 3; ++k)
    if (*part[k] && ImGui::CalcTextSize((text + "   " + part[k]).c_str()).x <= view.w - em(12))
      text += std::string("   ") + part[k];
  ImDrawList* d = ImGui::GetBackgroundDrawList();
  const ImVec2 size = ImGui::CalcTextSize(text.c_str());
  const ImVec2 at{std::max(view.x + view.w - size.x - em(8), view.x + em(4)), view.bottom() - size.y - em(6)};
  d->PushClipRect({view.x, view.y}, {view.x + view.w, view.bottom()});
  d->AddRectFilled({at.x - 4, at.y - 2}, {at.x + size.x + 4, at.y + size.y + 2}, IM_COL32(0, 0, 0, 140));
  d->AddText(at, IM_COL32(220, 220, 220, 255), text.c_str());
  d->PopClipRect();
}

}  // namespace shotlab
