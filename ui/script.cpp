#include "ui/script.hpp"

#include <cmath>
#include <fstream>
#include <iostream>

#include "shotlab/io/scene_json.hpp"
#include "ui/files.hpp"
#include "ui/framing.hpp"
#include "ui/panels.hpp"

namespace shotlab {

namespace {

constexpr int kMaxWaitFrames = 3000;  // a wait-* that takes longer fails the script instead of hanging the test

double number(std::istringstream& in) {
  double v = NAN;
  in >> v;
  return v;
}

std::string word(std::istringstream& in) {
  std::string w;
  in >> w;
  return w;
}

}  // namespace

Script::Script(const std::string& path, std::string data_root) : data_root_(std::move(data_root)) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read script " + path);
  for (std::string line; std::getline(in, line);) {
    const auto start = line.find_first_not_of(" \t");
    if (start == std::string::npos || line[start] == '#') continue;
    lines_.push_back(line.substr(start));
  }
}

void Script::run(ScriptHost& host) {
  ++frame_;
  if (wait_frames_ > 0 && --wait_frames_ > 0) return;
  while (next_ < lines_.size()) {
    if (!execute(host, lines_[next_])) {
      if (++waited_ > kMaxWaitFrames) {
        std::cerr << "script: gave up waiting at: " << lines_[next_] << '\n';
        ++failures_;
      } else {
        return;
      }
    }
    waited_ = 0;
    ++next_;
    if (wait_frames_ > 0) return;
  }
}

void Script::fail(const std::string& line, const std::string& why) {
  std::cerr << "script: " << line << ": " << why << '\n';
  ++failures_;
}

// Editing the table and the cue, as the mouse and the panels do.
bool Script::edit(ScriptHost& host, const std::string& cmd, std::istringstream& in) {
  Lab& lab = host.lab;
  if (cmd == "aim" || cmd == "speed" || cmd == "elevation" || cmd == "tip") {
    if (!lab.scene.cue) return fail(line_, "the scene has no cue strike"), true;
    CueStrike c = *lab.scene.cue;
    if (cmd == "aim") c.aim = number(in) * M_PI / 180;
    if (cmd == "speed") c.speed = number(in);
    if (cmd == "elevation") c.elevation = number(in) * M_PI / 180;
    if (cmd == "tip") c.side = number(in), c.height = number(in);
    lab.set_cue(c, cmd);
    lab.end_gesture();
  } else if (cmd == "aim-at") {  // aim-at X Z: as a click on the cloth
    const double x = number(in), z = number(in);
    lab.aim_at({x, 0, z});
    lab.end_gesture();
  } else if (cmd == "aim-ball") {  // aim-ball ID: as a click on the ball
    const int i = scene_ball(lab.scene, word(in));
    if (i < 0) return fail(line_, "no such ball"), true;
    lab.aim_at_ball(i);
  } else if (cmd == "pocket") {
    lab.aim_for_pocket(1);
    lab.finish_pocket_aim(true);
  } else if (cmd == "place") {  // place ID X Z: as a drag of the ball
    const int i = scene_ball(lab.scene, word(in));
    const double x = number(in), z = number(in);
    if (i < 0) return fail(line_, "no such ball"), true;
    if (!lab.begin_move(i) || !lab.move_ball(i, {x, 0, z}))
      fail(line_, "cannot place it there (a shot is shown, or it would overlap)");
    lab.end_gesture();
  } else if (cmd == "remove") {
    const int i = scene_ball(lab.scene, word(in));
    if (i < 0) return fail(line_, "no such ball"), true;
    lab.remove_ball(i);
  } else if (cmd == "add") {  // add X Z: as a shift+click with the Move tool
    const double x = number(in), z = number(in);
    lab.add_ball({x, 0, z});
  } else if (cmd == "select") {
    if (const int i = scene_ball(lab.scene, word(in)); i >= 0) lab.selected = i;
    else fail(line_, "no such ball");
  } else if (cmd == "break") {
    lab.setup_break();
  } else if (cmd == "hand") {  // hand X Z: ball in hand, put down at X Z
    if (!lab.in_hand) lab.pick_up_cue_ball();
    const double x = number(in), z = number(in);
    lab.place_cue_ball({x, 0, z}, true);
  } else if (cmd == "target") {
    const double x = number(in), z = number(in);
    lab.set_target({x, 0, z});
  } else if (cmd == "material") {  // material PAIR FIELD VALUE
    const std::string pair = word(in), field = word(in);
    ContactMaterial& m = lab.scene.model.materials[pair];
    const double v = number(in);
    if (field == "stiffness") m.stiffness = v;
    else if (field == "damping") m.damping = v;
    else if (field == "friction") m.friction = v;
    else if (field == "friction_law") m.friction_law = v > 0 ? FrictionLaw::SpeedDependent : FrictionLaw::Constant;
    else return fail(line_, "unknown material field"), true;
    lab.physics_changed();
  } else if (cmd == "integrator") {  // integrator METHOD [FIXED_STEP]
    if (!parse_method(word(in), lab.scene.model.integrator.method)) return fail(line_, "unknown method"), true;
    if (const double step = number(in); std::isfinite(step)) lab.scene.model.integrator.fixed_step = step;
    lab.physics_changed();
  } else if (cmd == "reset-physics") {
    lab.reset_physics();
  } else {
    return false;
  }
  return true;
}

bool Script::view(ScriptHost& host, const std::string& cmd, std::istringstream& in) {
  Lab& lab = host.lab;
  if (cmd == "view") {  // view NAME on|off
    const std::string name = word(in), state = word(in);
    ViewFlags& v = lab.settings.view;
    bool* flag = name == "trails" ? &v.trails : name == "ghost" ? &v.ghost : name == "predicted" ? &v.predicted
               : name == "aim" ? &v.aim : name == "velocity" ? &v.velocity : name == "spin" ? &v.spin
               : name == "forces" ? &v.forces : name == "labels" ? &v.labels : name == "centre" ? &v.centre_of_mass
               : name == "help" ? &v.help : name == "left" ? &lab.settings.panels.left_open
               : name == "right" ? &lab.settings.panels.right_open : nullptr;
    if (!flag) return fail(line_, "unknown view flag"), true;
    *flag = state == "on";
  } else if (cmd == "panel") {  // panel teach|tune: the inspector's tab, as a click on it
    const std::string name = word(in);
    if (name != "teach" && name != "tune") return fail(line_, "unknown panel"), true;
    lab.settings.view.tab_request = name == "tune";
    lab.settings.panels.right_open = true;
  } else if (cmd == "presentation") {
    lab.settings.presentation = word(in) == "on";
  } else if (cmd == "camera") {
    const std::string what = word(in);
    if (what == "top") host.camera.top_view();
    else if (what == "reset") home_view(host.camera, host.lab.scene);
    else if (what == "orbit") {  // camera orbit YAW_DEG PITCH_DEG DISTANCE [TARGET_X TARGET_Z]
      host.camera.yaw = number(in) * M_PI / 180;
      host.camera.pitch = number(in) * M_PI / 180;
      host.camera.distance = number(in);
      host.camera.auto_fit = false;
      const double x = number(in), z = number(in);
      if (std::isfinite(x) && std::isfinite(z)) host.camera.target = {x, 0, z};
    } else fail(line_, "unknown camera command");
  } else {
    return false;
  }
  return true;
}

bool Script::execute(ScriptHost& host, const std::string& line) {
  Lab& lab = host.lab;
  line_ = line;
  std::istringstream in(line);
  const std::string cmd = word(in);
  if (edit(host, cmd, in) || view(host, cmd, in)) return true;
  if (cmd == "preset") {
    lab.load(data_root_ + "/presets/" + word(in) + ".json");
  } else if (cmd == "load") {
    lab.load(word(in));  // a bad file sets the message, which `dump` reports
  } else if (cmd == "shoot") {
    lab.shoot();
  } else if (cmd == "play") {
    lab.playing = lab.shot != nullptr;
  } else if (cmd == "pause") {
    lab.playing = false;
  } else if (cmd == "seek") {
    lab.seek(number(in));
  } else if (cmd == "step") {  // step [-1]
    const double d = number(in);
    lab.step(std::isfinite(d) && d < 0 ? -1 : 1);
  } else if (cmd == "replay") {
    lab.replay();
  } else if (cmd == "undo") {
    lab.undo();
  } else if (cmd == "redo") {
    lab.redo();
  } else if (cmd == "next") {
    lab.continue_from_rest();
  } else if (cmd == "keep") {
    lab.keep_shot();
  } else if (cmd == "run-on") {
    lab.run_on();
  } else if (cmd == "slowmo") {
    lab.settings.slowmo = number(in);
  } else if (cmd == "safety-limit") {
    lab.settings.safety_limit = number(in);
  } else if (cmd == "clock") {
    host.real_clock = word(in) == "real";
  } else if (cmd == "frames") {
    wait_frames_ = std::max(1, static_cast<int>(number(in)));
  } else if (cmd == "wait-prediction") {
    return lab.shot || lab.prediction().has_value();
  } else if (cmd == "wait-rest") {
    return !lab.shot || lab.shot_over();
  } else if (cmd == "screenshot") {
    const std::string path = word(in);
    if (!host.screenshot(path)) fail(line, "cannot write " + path);
  } else if (cmd == "dump") {
    const std::string path = word(in);
    nlohmann::json j = state_json(lab, host.screen ? *host.screen : ScreenInfo{});
    j["script_frame"] = frame_;
    write_file_atomic(path, j.dump(2) + "\n");
  } else if (cmd == "save") {
    save_scene(word(in), lab.scene);
  } else if (cmd == "export") {
    if (lab.shot) export_trajectory(lab, word(in));
    else fail(line, "no shot to export");
  } else if (cmd == "quit") {
    next_ = lines_.size();
  } else {
    fail(line, "unknown command");
  }
  return true;
}

}  // namespace shotlab
