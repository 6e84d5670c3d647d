#include "ui/script.hpp"

#include <cmath>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "app/paths.hpp"
#include "engine/io/scene_json.hpp"
#include "ui/panels.hpp"

namespace shotlab {

namespace {
constexpr int kMaxWaitFrames = 3000;  // a wait-* that takes longer fails the script instead of hanging the test
}

Script::Script(const std::string& path) {
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

bool Script::execute(ScriptHost& host, const std::string& line) {
  Lab& lab = host.lab;
  std::istringstream in(line);
  std::string cmd, arg;
  in >> cmd;
  auto number = [&] {
    double v = NAN;
    in >> v;
    return v;
  };
  auto fail = [&](const std::string& why) {
    std::cerr << "script: " << line << ": " << why << '\n';
    ++failures_;
  };
  auto cue = [&]() -> CueStrike* {
    if (!lab.scene.cue) fail("the scene has no cue strike");
    return lab.scene.cue ? &*lab.scene.cue : nullptr;
  };
  if (cmd == "preset") {
    in >> arg;
    lab.load(preset_path(arg + ".json"));
  } else if (cmd == "load") {
    in >> arg;
    lab.load(arg);  // a bad file sets lab.error, which `dump` reports
  } else if (cmd == "aim" || cmd == "speed" || cmd == "elevation" || cmd == "tip") {
    CueStrike* c = cue();
    if (!c) return true;
    if (cmd == "aim") c->aim = number() * M_PI / 180;
    if (cmd == "speed") c->speed = number();
    if (cmd == "elevation") c->elevation = number() * M_PI / 180;
    if (cmd == "tip") c->side = number(), c->height = number();
    lab.scene_changed();
  } else if (cmd == "shoot") {
    lab.shoot();
  } else if (cmd == "play") {
    lab.playing = lab.shot != nullptr;
  } else if (cmd == "pause") {
    lab.playing = false;
  } else if (cmd == "seek") {
    lab.seek(number());
  } else if (cmd == "step") {
    lab.step();
  } else if (cmd == "replay") {
    lab.replay();
  } else if (cmd == "undo") {
    lab.undo();
  } else if (cmd == "next") {
    lab.continue_from_rest();
  } else if (cmd == "slowmo") {
    lab.settings.slowmo = number();
  } else if (cmd == "clock") {
    in >> arg;
    host.real_clock = arg == "real";
  } else if (cmd == "material") {  // material PAIR FIELD VALUE
    std::string pair, field;
    in >> pair >> field;
    ContactMaterial& m = lab.scene.model.materials[pair];
    const double v = number();
    if (field == "stiffness") m.stiffness = v;
    else if (field == "damping") m.damping = v;
    else if (field == "friction") m.friction = v;
    else return fail("unknown material field"), true;
    lab.physics_changed();
  } else if (cmd == "integrator") {  // integrator METHOD [FIXED_STEP]
    in >> arg;
    if (!parse_method(arg, lab.scene.model.integrator.method)) return fail("unknown method"), true;
    if (const double step = number(); std::isfinite(step)) lab.scene.model.integrator.fixed_step = step;
    lab.physics_changed();
  } else if (cmd == "aim-at") {  // aim-at X Z: as a click on the cloth
    const double x = number(), z = number();
    lab.aim_at({x, 0, z});
  } else if (cmd == "place" || cmd == "remove") {  // place ID X Z (as a drag) / remove ID
    in >> arg;
    const int i = scene_ball(lab.scene, arg);
    if (i < 0) return fail("no such ball"), true;
    if (cmd == "remove") {
      lab.remove_ball(i);
    } else {
      const double x = number(), z = number();
      if (!lab.move_ball(i, {x, 0, z})) fail("cannot place it there (a shot is shown, or it would overlap)");
    }
  } else if (cmd == "add") {  // add X Z: as a shift+click on the cloth
    const double x = number(), z = number();
    lab.add_ball({x, 0, z});
  } else if (cmd == "select") {
    in >> arg;
    if (const int i = scene_ball(lab.scene, arg); i >= 0) lab.selected = i;
    else fail("no such ball");
  } else if (cmd == "view" || cmd == "panel") {  // view NAME on|off
    std::string name, state;
    in >> name >> state;
    ViewFlags& v = lab.settings.view;
    bool* flag = name == "trails" ? &v.trails : name == "ghost" ? &v.ghost : name == "predicted" ? &v.predicted
               : name == "aim" ? &v.aim : name == "velocity" ? &v.velocity : name == "spin" ? &v.spin
               : name == "forces" ? &v.forces : name == "inspector" ? &v.inspector
               : name == "help" ? &v.help : nullptr;
    if (name == "teach" || name == "tune") v.tab = name == "tune";  // panel teach|tune: the inspector's tab
    else if (flag) *flag = state == "on";
    else fail("unknown view flag");
  } else if (cmd == "camera") {
    in >> arg;
    if (arg == "top") host.camera.top_view();
    else if (arg == "reset") host.camera.reset();
    else if (arg == "orbit") {  // camera orbit YAW_DEG PITCH_DEG DISTANCE [TARGET_X TARGET_Z]
      host.camera.yaw = number() * M_PI / 180;
      host.camera.pitch = number() * M_PI / 180;
      host.camera.distance = number();
      const double x = number(), z = number();
      if (std::isfinite(x) && std::isfinite(z)) host.camera.target = {x, 0, z};
    } else fail("unknown camera command");
  } else if (cmd == "frames") {
    wait_frames_ = std::max(1, static_cast<int>(number()));
  } else if (cmd == "wait-prediction") {
    return lab.shot || lab.prediction().has_value();
  } else if (cmd == "wait-rest") {
    return !lab.shot || (lab.shot->finished() && lab.view_time >= lab.shot->sim().time());
  } else if (cmd == "screenshot") {
    in >> arg;
    if (!host.screenshot(arg)) fail("cannot write " + arg);
  } else if (cmd == "dump") {
    in >> arg;
    dump(host, arg);
  } else if (cmd == "save") {
    in >> arg;
    save_scene(arg, lab.scene);
  } else if (cmd == "export") {
    in >> arg;
    if (lab.shot) export_trajectory(lab, arg);
    else fail("no shot to export");
  } else if (cmd == "quit") {
    next_ = lines_.size();
  } else {
    fail("unknown command");
  }
  return true;
}

// The program's own state as JSON, for the GUI test's assertions.
void Script::dump(const ScriptHost& host, const std::string& path) const {
  const Lab& lab = host.lab;
  const Frame& f = lab.frame();
  nlohmann::json balls = nlohmann::json::array();
  const Trails trails = lab.trails(lab.view_time);
  for (int i = 0; i < f.state.ball_count(); ++i) {
    const Vec3 p = position(f.state.x, i);
    balls.push_back({{"id", lab.scene.balls[i].spec.id},
                     {"position", {p.x, p.y, p.z}},
                     {"speed", glm::length(velocity(f.state.x, i))},
                     {"in_play", f.state.in_play[i] != 0},
                     {"trail_points", i < static_cast<int>(trails.size()) ? trails[i].size() : 0}});
  }
  const auto prediction = lab.prediction();
  size_t moving_paths = 0;
  if (prediction)
    for (const auto& p : prediction->paths) moving_paths += p.size() > 1 && glm::length(p.back().position - p.front().position) > 1e-3;
  nlohmann::json j{{"frame", frame_},
                   {"scene", lab.scene.name},
                   {"view_time", lab.view_time},
                   {"playing", lab.playing},
                   {"has_shot", lab.shot != nullptr},
                   {"sim_time", lab.shot ? lab.shot->sim().time() : 0.0},
                   {"status", lab.shot ? status_name(lab.shot->sim().status()) : "none"},
                   {"finished", lab.shot && lab.shot->finished()},
                   {"history", lab.history.size()},
                   {"ghost_balls", lab.ghost.size()},
                   {"prediction_ready", prediction.has_value()},
                   {"predicted_moving_balls", moving_paths},
                   {"error", lab.error},
                   {"fps", host.fps},
                   {"achieved_speed", lab.achieved_speed},
                   {"balls", balls}};
  if (lab.scene.cue) j["cue"] = {{"ball", lab.scene.cue->ball}, {"aim_deg", lab.scene.cue->aim * 180 / M_PI}, {"speed", lab.scene.cue->speed}};
  std::ofstream(path) << j.dump(2) << '\n';
}

}  // namespace shotlab
