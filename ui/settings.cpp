#include "ui/settings.hpp"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

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

namespace {

std::string settings_file() {
  const std::string dir = config_dir();
  return dir.empty() ? "" : dir + "/settings.json";
}

// Reads `key` into `value` when present with the right type: an old or hand-edited file never stops the program.
template <class T> void get(const nlohmann::json& j, const char* key, T& value) {
  if (j.contains(key)) try {
      value = j.at(key).get<T>();
    } catch (const nlohmann::json::exception&) {
    }
}

}  // namespace

Settings load_settings() {
  Settings s;
  std::ifstream in(settings_file());
  if (!in) return s;
  const nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
  if (!j.is_object()) return s;
  if (j.contains("camera") && j["camera"].is_object()) {
    const auto& c = j["camera"];
    std::vector<double> target;
    get(c, "target", target);
    if (target.size() == 3) s.camera.target = {target[0], target[1], target[2]};
    get(c, "yaw", s.camera.yaw);
    get(c, "pitch", s.camera.pitch);
    get(c, "distance", s.camera.distance);
  }
  if (j.contains("view") && j["view"].is_object()) {
    const auto& v = j["view"];
    get(v, "trails", s.view.trails);
    get(v, "ghost", s.view.ghost);
    get(v, "predicted", s.view.predicted);
    get(v, "aim", s.view.aim);
    get(v, "velocity", s.view.velocity);
    get(v, "spin", s.view.spin);
    get(v, "forces", s.view.forces);
    get(v, "inspector", s.view.inspector);
    get(v, "tab", s.view.tab);
  }
  get(j, "slowmo", s.slowmo);
  get(j, "impact_speed", s.impact_speed);
  get(j, "budget_ms", s.budget_ms);
  get(j, "last_scene", s.last_scene);
  return s;
}

void save_settings(const Settings& s) {
  const std::string path = settings_file();
  if (path.empty()) return;
  const ViewFlags& v = s.view;
  const nlohmann::json j{
      {"camera",
       {{"target", {s.camera.target.x, s.camera.target.y, s.camera.target.z}},
        {"yaw", s.camera.yaw},
        {"pitch", s.camera.pitch},
        {"distance", s.camera.distance}}},
      {"view",
       {{"trails", v.trails}, {"ghost", v.ghost}, {"predicted", v.predicted}, {"aim", v.aim}, {"velocity", v.velocity},
        {"spin", v.spin}, {"forces", v.forces}, {"inspector", v.inspector}, {"tab", v.tab}}},
      {"slowmo", s.slowmo},
      {"impact_speed", s.impact_speed},
      {"budget_ms", s.budget_ms},
      {"last_scene", s.last_scene}};
  std::ofstream(path) << j.dump(2) << '\n';
}

}  // namespace shotlab
