#include "ui/margin_view.hpp"

#include <numbers>

#include "shotlab/io/scene_json.hpp"
#include "ui/aim.hpp"
#include "ui/lab.hpp"

namespace shotlab {

std::optional<MarginOptions> margin_options(const Lab& lab, const MarginView& view, std::string& why) {
  const Scene& s = lab.scene;
  if (!s.cue) {
    why = "the scene has no cue strike";
    return std::nullopt;
  }
  MarginOptions o;
  o.noise = stroke_noise(stroke_levels()[static_cast<size_t>(view.level)]);
  o.samples = static_cast<size_t>(view.samples);
  if (view.target_goal) {
    if (!lab.target) {
      why = "set a target first (the Target tool in Aim)";
      return std::nullopt;
    }
    o.goal.kind = ShotGoal::Zone, o.goal.ball = s.cue->ball;
    o.goal.x = lab.target->x, o.goal.z = lab.target->z, o.goal.radius = lab.target_radius;
    return o;
  }
  const auto& pockets = lab.table_model.pockets;
  if (pockets.empty()) {  // a carom table: potting is no goal there (the measured shots are carom shots)
    why = "this table has no pockets: set a target, and the goal \"cue ball stops in the target\"";
    return std::nullopt;
  }
  const auto line = aim_line(s);
  if (!line || line->hit < 0) {
    why = "aim at a ball: the margin is that of potting it";
    return std::nullopt;
  }
  o.goal.ball = s.balls[line->hit].spec.id;
  if (view.pocket > 0 && view.pocket <= static_cast<int>(pockets.size())) o.goal.pocket = pockets[view.pocket - 1].name;
  return o;
}

namespace {
std::string goal_text(const MarginOptions& o) {
  const double numbers[] = {o.goal.x, o.goal.z, o.goal.radius, o.noise.aim_deg, o.noise.speed_pct, o.noise.tip_mm,
                            o.noise.elevation_deg, static_cast<double>(o.samples)};
  std::string text = o.goal.ball + "|" + o.goal.pocket;
  for (double v : numbers) text.append("|").append(std::to_string(v));
  return text;
}
}  // namespace

std::string margin_key(const Lab& lab, const MarginOptions& o) {
  return scene_to_json(lab.scene).dump() + goal_text(o);
}

std::string margin_map_key(const Lab& lab, const MarginView& view, const MarginOptions& o) {
  nlohmann::json doc = scene_to_json(lab.scene);
  doc["cue"].erase("aim_deg");
  doc["cue"].erase("speed");
  return doc.dump() + goal_text(o) + "|" + std::to_string(view.map_size) + "|" + std::to_string(view.map_samples);
}

namespace {

// The map still answers for the current aim and speed: they lie inside its range (to round-off: a click on an edge
// cell sets its centre, converted to radians and back).
bool covers(const MarginMap& m, const CueStrike& cue) {
  const double aim = cue.aim * 180 / std::numbers::pi, slack = 1e-9;
  return aim >= m.aim_lo_deg - slack && aim <= m.aim_hi_deg + slack && cue.speed >= m.speed_lo - slack &&
         cue.speed <= m.speed_hi + slack;
}

void start_map(const Lab& lab, MarginView& view, const MarginOptions& o, const std::string& key) {
  MarginOptions cell = o;
  cell.samples = static_cast<size_t>(view.map_samples);
  const int aims = kMapSizes[view.map_size][0], speeds = kMapSizes[view.map_size][1];
  view.map.start([scene = lab.scene, cell, key, aims, speeds, aim = view.map_aim(), speed = view.map_speed](
                     const auto& progress, const std::atomic<bool>& cancel) {
    return MarginMapResult{key, margin_map(scene, cell, aims, speeds, aim, speed, progress, &cancel)};
  });
  view.map_asked = key;
}

}  // namespace

void update_margin(const Lab& lab, MarginView& view) {
  view.map_current = false;  // until shown to hold below
  auto stop = [&] {  // nothing (more) to work out: leave the cores to the rest
    if (view.estimate.busy()) view.estimate.cancel(), view.asked.clear();
    if (view.map.busy()) view.map.cancel(), view.map_asked.clear();
  };
  if (!view.open || lab.shot) return stop();
  view.problem.clear();
  const auto o = margin_options(lab, view, view.problem);
  if (!o) return stop();  // a scene the goal does not fit (no pockets, no ball aimed at) any more
  if (const std::string key = margin_key(lab, *o); key != view.asked) {
    view.estimate.start([scene = lab.scene, opts = *o, key](const auto& progress, const std::atomic<bool>& cancel) {
      return MarginEstimate{key, opts, shot_margin(scene, opts, progress, &cancel)};
    });
    view.asked = key;
  }
  if (!view.map_wanted) return;
  const std::string key = margin_map_key(lab, view, *o);
  const auto done = view.map.result();
  view.map_current = done && done->key == key && covers(done->map, *lab.scene.cue);
  if (!view.map_current && (key != view.map_asked || (done && done->key == key && !view.map.busy())))
    start_map(lab, view, *o, key);
}

std::optional<MarginEstimate> fresh_estimate(const Lab& lab, const MarginView& view) {
  auto e = view.estimate.result();
  if (!e || e->key != view.asked || lab.shot) return std::nullopt;
  return e;
}

}  // namespace shotlab
