#include "ui/settings.hpp"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "ui/files.hpp"

namespace shotlab {

std::string config_dir() {
  std::filesystem::path dir;
  if (const char* xdg = std::getenv("XDG_CONFIG_HOME"); xdg && *xdg) dir = xdg;
  else if (const char* home = std::getenv("HOME"); home && *home) dir = std::filesystem::path(home) / ".config";
  else return "";
  dir /= "shotlab";
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  return ec ? "" : dir.string();
}

void remember_file(Settings& s, const std::string& path) {
  std::error_code ec;
  const std::string abs = std::filesystem::absolute(path, ec).lexically_normal().string();
  const std::string p = ec ? path : abs;
  s.recent.erase(std::remove(s.recent.begin(), s.recent.end(), p), s.recent.end());
  s.recent.insert(s.recent.begin(), p);
  if (s.recent.size() > kRecentFiles) s.recent.resize(kRecentFiles);
  s.last_scene = p;
}

namespace {

std::string settings_file() {
  const std::string dir = config_dir();
  return dir.empty() ? "" : dir + "/settings.json";
}

// Reads `key` into `value` when present with the right type: an old or hand-edited file never stops the program.
template <class T> void get(const nlohmann::json& j, const char* key, T& value) {
  if (j.is_object() && j.contains(key)) try {
      value = j.at(key).get<T>();
    } catch (const nlohmann::json::exception&) {
    }
}

const nlohmann::json& section(const nlohmann::json& j, const char* key) {
  static const nlohmann::json none = nlohmann::json::object();
  return j.contains(key) && j[key].is_object() ? j[key] : none;
}

void read_view(const nlohmann::json& v, ViewFlags& f) {
  get(v, "trails", f.trails), get(v, "ghost", f.ghost), get(v, "predicted", f.predicted), get(v, "aim", f.aim);
  get(v, "velocity", f.velocity), get(v, "spin", f.spin), get(v, "forces", f.forces), get(v, "labels", f.labels);
  get(v, "centre_of_mass", f.centre_of_mass), get(v, "follow_cue", f.follow_cue), get(v, "compare", f.compare);
  get(v, "tab", f.tab);
  f.tab = std::clamp(f.tab, 0, 1);
}

}  // namespace

Settings load_settings() {
  Settings s;
  std::ifstream in(settings_file());
  if (!in) return s;
  const nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
  if (!j.is_object()) return s;
  const auto& c = section(j, "camera");
  std::vector<double> target;
  get(c, "target", target);
  if (target.size() == 3) s.camera.target = {target[0], target[1], target[2]};
  get(c, "yaw", s.camera.yaw), get(c, "pitch", s.camera.pitch), get(c, "distance", s.camera.distance);
  get(c, "auto_fit", s.camera.auto_fit);
  read_view(section(j, "view"), s.view);
  const auto& p = section(j, "panels");
  get(p, "left_open", s.panels.left_open), get(p, "right_open", s.panels.right_open);
  get(p, "left_width", s.panels.left_width), get(p, "right_width", s.panels.right_width);
  const auto& e = section(j, "pause_on");
  get(e, "ball_ball", s.pause_on.ball_ball), get(e, "cushion", s.pause_on.cushion), get(e, "pocketed", s.pause_on.pocketed);
  get(j, "slowmo", s.slowmo), get(j, "impact_speed", s.impact_speed), get(j, "budget_ms", s.budget_ms);
  get(j, "safety_limit", s.safety_limit), get(j, "ui_scale", s.ui_scale);
  get(j, "last_scene", s.last_scene), get(j, "recent", s.recent), get(j, "export_dir", s.export_dir);
  s.slowmo = std::clamp(s.slowmo, 1e-3, 4.0);
  s.safety_limit = std::clamp(s.safety_limit, 1.0, 3600.0);
  s.ui_scale = std::clamp(s.ui_scale, 0.75f, 3.0f);
  if (s.recent.size() > kRecentFiles) s.recent.resize(kRecentFiles);
  return s;
}

bool save_settings(const Settings& s, std::string* error) {
  const std::string path = settings_file();
  if (path.empty()) return true;
  const ViewFlags& v = s.view;
  const nlohmann::json j{
      {"camera",
       {{"target", {s.camera.target.x, s.camera.target.y, s.camera.target.z}},
        {"yaw", s.camera.yaw}, {"pitch", s.camera.pitch}, {"distance", s.camera.distance},
        {"auto_fit", s.camera.auto_fit}}},
      {"view",
       {{"trails", v.trails}, {"ghost", v.ghost}, {"predicted", v.predicted}, {"aim", v.aim}, {"velocity", v.velocity},
        {"spin", v.spin}, {"forces", v.forces}, {"labels", v.labels}, {"centre_of_mass", v.centre_of_mass},
        {"follow_cue", v.follow_cue}, {"compare", v.compare}, {"tab", v.tab}}},
      {"panels",
       {{"left_open", s.panels.left_open}, {"right_open", s.panels.right_open},
        {"left_width", s.panels.left_width}, {"right_width", s.panels.right_width}}},
      {"pause_on", {{"ball_ball", s.pause_on.ball_ball}, {"cushion", s.pause_on.cushion}, {"pocketed", s.pause_on.pocketed}}},
      {"slowmo", s.slowmo}, {"impact_speed", s.impact_speed}, {"budget_ms", s.budget_ms},
      {"safety_limit", s.safety_limit}, {"ui_scale", s.ui_scale},
      {"last_scene", s.last_scene}, {"recent", s.recent}, {"export_dir", s.export_dir}};
  try {
    // Paths are bytes; a name that is not UTF-8 is written with replacement characters rather than lost.
    write_file_atomic(path, j.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n");
    return true;
  } catch (const std::exception& e) {
    if (error) *error = e.what();
    return false;
  }
}

}  // namespace shotlab
