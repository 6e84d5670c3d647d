#include "ui/state_dump.hpp"

#include <cmath>

#include "shotlab/simulation.hpp"
#include "ui/files.hpp"

namespace shotlab {

namespace {

using nlohmann::json;

json rect_json(const Rect& r) { return {{"x", r.x}, {"y", r.y}, {"w", r.w}, {"h", r.h}}; }

json point_json(const Viewport* vp, const Vec3& p) {
  if (!vp) return nullptr;
  const auto s = vp->project(p);
  return s ? json{s->x, s->y} : json(nullptr);
}

const char* end_name(ShotEnd e) {
  switch (e) {
    case ShotEnd::Running: return "running";
    case ShotEnd::Rest: return "rest";
    case ShotEnd::SafetyLimit: return "safety_limit";
    case ShotEnd::EngineStop: return "engine_stop";
  }
  return "?";
}

const char* message_name(MessageKind k) {
  switch (k) {
    case MessageKind::None: return "none";
    case MessageKind::Note: return "note";
    case MessageKind::Refused: return "refused";
    case MessageKind::LoadError: return "load_error";
    case MessageKind::EngineStop: return "engine_stop";
  }
  return "?";
}

json balls_json(const Lab& lab, const ScreenInfo& screen) {
  const Frame& f = lab.frame();
  const Trails trails = lab.trails(lab.view_time);
  json balls = json::array();
  for (int i = 0; i < f.state.ball_count() && i < static_cast<int>(lab.scene.balls.size()); ++i) {
    const Vec3 p = position(f.state.x, i);
    balls.push_back({{"id", lab.scene.balls[i].spec.id},
                     {"position", {p.x, p.y, p.z}},
                     {"speed", glm::length(velocity(f.state.x, i))},
                     {"in_play", f.state.in_play[i] != 0},
                     {"screen", point_json(screen.viewport, p)},
                     {"trail_points", i < static_cast<int>(trails.size()) ? trails[i].size() : 0}});
  }
  return balls;
}

json shot_json(const Lab& lab) {
  if (!lab.shot) return nullptr;
  const Shot& s = *lab.shot;
  return {{"sim_time", s.sim().time()},
          {"status", status_name(s.sim().status())},
          {"end", end_name(s.end())},
          {"safety_limit", s.safety_limit()},
          {"events", s.sim().events().size()},
          {"contact_on_screen", lab.contact_on_screen()}};
}

json cue_json(const Lab& lab) {
  if (!lab.scene.cue) return nullptr;
  const CueStrike& c = *lab.scene.cue;
  return {{"ball", c.ball}, {"aim_deg", c.aim * 180 / M_PI}, {"speed", c.speed}, {"side", c.side},
          {"height", c.height}, {"elevation_deg", c.elevation * 180 / M_PI}};
}

json physics_json(const Lab& lab) {
  json m = json::object();
  for (const auto& [name, mat] : lab.scene.model.materials)
    m[name] = {{"stiffness", mat.stiffness}, {"damping", mat.damping}, {"friction", mat.friction},
               {"friction_law", mat.friction_law == FrictionLaw::Constant ? "constant" : "speed_dependent"}};
  return {{"materials", m}, {"contact", contact_model_name(lab.scene.model.options.contact)},
          {"changes", lab.physics_changes()}, {"compare_trails", lab.compare.size()},
          {"compare_label", lab.compare_label}};
}

json measured_json(const Lab& lab) {
  const MeasuredView& v = lab.measured;
  if (!v.shot) return nullptr;
  json j{{"name", v.shot->name}, {"cue_ball", v.shot->cue_ball}, {"fitting", v.fit.busy()},
         {"fit_error", v.fit.error()}};
  if (v.last && !v.last->shots.empty()) {
    const ShotFit& f = v.last->shots[0];
    j["fit"] = {{"speed", f.cue.speed}, {"aim_deg", f.cue.aim_deg}, {"side", f.cue.side}, {"height", f.cue.height},
                {"rms", f.rms}, {"paths", v.last->paths}, {"values", v.last->values}};
  }
  return j;
}

json margin_json(const Lab& lab) {
  const MarginView& v = lab.margin;
  json j{{"open", v.open}, {"problem", v.problem}, {"estimating", v.estimate.busy()}, {"mapping", v.map.busy()},
         {"map_wanted", v.map_wanted}};
  if (const auto e = fresh_estimate(lab, v))
    j["estimate"] = {{"goal_ball", e->options.goal.ball}, {"pocket", e->options.goal.pocket},
                     {"probability", e->result.probability}, {"samples", e->result.samples.size()},
                     {"aim_window", {e->result.tolerance[kAim].lo, e->result.tolerance[kAim].hi}}};
  j["map_current"] = v.map_current;
  if (const auto m = v.map.result())
    j["map"] = {{"aims", m->map.aims}, {"speeds", m->map.speeds}, {"aim_deg", {m->map.aim_lo_deg, m->map.aim_hi_deg}},
                {"speed", {m->map.speed_lo, m->map.speed_hi}}, {"cells", m->map.cells}};
  return j;
}

}  // namespace

json state_json(const Lab& lab, const ScreenInfo& screen) {
  const auto prediction = lab.prediction();
  size_t moving_paths = 0;
  if (prediction)
    for (const auto& p : prediction->paths)
      moving_paths += p.size() > 1 && glm::length(p.back().position - p.front().position) > 1e-3;
  json widgets = json::object();
  if (screen.widgets)
    for (const auto& [name, r] : *screen.widgets) widgets[name] = rect_json(r);
  json shown = json::object();
  if (screen.readouts)
    for (const auto& [name, v] : *screen.readouts) shown[name] = v;
  const Settings& st = lab.settings;
  json j{{"frame", screen.frame},
         {"window", {screen.window_w, screen.window_h}},
         {"view", rect_json(screen.view)},
         {"widgets", widgets},
         {"readouts", shown},
         {"mouse", {screen.mouse_x, screen.mouse_y}},
         {"fps", screen.fps},
         {"frame_ms", screen.frame_ms},
         {"scene", lab.scene.name},
         {"scene_path", lab.scene_path},
         {"view_time", lab.view_time},
         {"playing", lab.playing},
         {"slowmo", st.slowmo},
         {"has_shot", lab.shot != nullptr},
         {"shot", shot_json(lab)},
         {"shot_over", lab.shot_over()},
         {"history", lab.history.size()},
         {"undo_label", lab.history.undo_label()},
         {"redo_label", lab.history.redo_label()},
         {"ghost_balls", lab.ghost.size()},
         {"kept", lab.kept.size()},
         {"prediction_ready", prediction.has_value()},
         {"predicted_moving_balls", moving_paths},
         {"prediction_ms", prediction ? prediction->wall_seconds * 1e3 : 0.0},
         {"message", lab.message},
         {"message_kind", message_name(lab.message_kind)},
         {"tool", lab.tool == Tool::Aim ? "aim" : lab.tool == Tool::Move ? "move" : "target"},
         {"in_hand", lab.in_hand},
         {"selected", lab.selected},
         {"tab", st.view.tab == 0 ? "teaching" : "tuning"},
         {"panels", {{"left_open", st.panels.left_open}, {"right_open", st.panels.right_open}}},
         {"camera", {{"auto_fit", st.camera.auto_fit}, {"distance", st.camera.distance}}},
         {"achieved_speed", lab.achieved_speed},
         {"physics_ms", lab.shot && lab.playing ? lab.shot->last_wall() * 1e3 : 0.0},
         {"physics", physics_json(lab)},
         {"cue", cue_json(lab)},
         {"balls", balls_json(lab, screen)},
         {"margin", margin_json(lab)},
         {"measured", measured_json(lab)}};
  if (screen.play_frames) {
    const FrameTimes::Summary f = screen.play_frames->summary(1e3 / 60);
    j["play_frames"] = {{"frames", f.frames}, {"median_ms", f.median_ms}, {"p95_ms", f.p95_ms},
                        {"worst_ms", f.worst_ms}, {"over_60fps_budget", f.over_budget}};
  }
  if (const auto miss = lab.target_miss()) j["target_miss"] = *miss;
  if (lab.target) j["target"] = {lab.target->x, lab.target->z};
  if (lab.scene.table && screen.viewport) {
    const double hx = lab.scene.table->length / 2, hz = lab.scene.table->width / 2;
    json corners = json::array();
    for (const Vec3& c : {Vec3{-hx, 0, -hz}, Vec3{hx, 0, -hz}, Vec3{hx, 0, hz}, Vec3{-hx, 0, hz}})
      corners.push_back(point_json(screen.viewport, c));
    j["table_corners"] = corners;
  }
  return j;
}

bool write_state(const Lab& lab, const ScreenInfo& screen, const std::string& path) {
  try {
    write_file_atomic(path, state_json(lab, screen).dump(2) + "\n");
    return true;
  } catch (const std::exception&) {
    return false;
  }
}

}  // namespace shotlab
