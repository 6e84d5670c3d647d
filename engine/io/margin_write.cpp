// Shot margins written out: the JSON of `shotlab margin --out` and the CSV of its replays.
#include <cmath>
#include <map>
#include <numbers>
#include <sstream>

#include "shotlab/io/margin.hpp"
#include "csv.hpp"

namespace shotlab {
namespace {

using nlohmann::json;

// The table seen from above, for pictures: every capsule (cushions, jaws) as a segment and every hole in a plane (a
// pocket) as a circle, in the x-z plane, m.
json table_outline(const Scene& scene) {
  Prepared p = prepare(scene);
  json lines = json::array(), holes = json::array();
  for (const Collider& c : p.model.colliders) {
    if (const auto* cap = std::get_if<Capsule>(&c.shape)) lines.push_back({cap->a.x, cap->a.z, cap->b.x, cap->b.z});
    const std::vector<Hole>* hs = nullptr;
    if (const auto* pl = std::get_if<Plane>(&c.shape)) hs = &pl->holes;
    if (const auto* bp = std::get_if<BoundedPlane>(&c.shape)) hs = &bp->holes;
    for (size_t k = 0; hs && k < hs->size(); ++k) holes.push_back({(*hs)[k].center.x, (*hs)[k].center.z, (*hs)[k].radius});
  }
  return {{"lines", lines}, {"holes", holes}};
}

json goal_json(const ShotGoal& g) {
  if (g.kind == ShotGoal::Pocket) return {{"kind", "pocket"}, {"ball", g.ball}, {"pocket", g.pocket}};
  return {{"kind", "zone"}, {"ball", g.ball}, {"x", g.x}, {"z", g.z}, {"radius", g.radius}};
}

// Per ball: end positions of every replay (x, z and whether it succeeded) and their mean and deviation over the
// replays where the ball stayed on the table.
json scatter(const MarginResult& r) {
  json out = json::object();
  for (size_t b = 0; b < r.ball_ids.size(); ++b) {
    json xs = json::array(), zs = json::array(), ok = json::array();
    double n = 0, sx = 0, sz = 0, sxx = 0, szz = 0, dropped = 0;
    for (const MarginSample& s : r.samples) {
      if (s.end_x.size() <= b) continue;
      xs.push_back(s.end_x[b]), zs.push_back(s.end_z[b]), ok.push_back(s.success);
      if (s.left[b]) {  // the spread is of the balls that stayed on the table
        dropped += s.pocketed[b];
        continue;
      }
      ++n, sx += s.end_x[b], sz += s.end_z[b], sxx += s.end_x[b] * s.end_x[b], szz += s.end_z[b] * s.end_z[b];
    }
    const double mx = n ? sx / n : 0, mz = n ? sz / n : 0;
    out[r.ball_ids[b]] = {{"x", xs}, {"z", zs}, {"success", ok}, {"pocketed", dropped},
                          {"mean", {mx, mz}},
                          {"sd", {n > 1 ? std::sqrt(std::max(0.0, (sxx - n * mx * mx) / (n - 1))) : 0.0,
                                  n > 1 ? std::sqrt(std::max(0.0, (szz - n * mz * mz) / (n - 1))) : 0.0}}};
  }
  return out;
}

}  // namespace

json margin_to_json(const Scene& scene, const MarginOptions& o, const MarginResult& r, const MarginMap* map) {
  json out;
  out["scene"] = scene.name;
  out["goal"] = goal_json(o.goal);
  out["cue_ball"] = scene.cue ? scene.cue->ball : "";
  out["noise"] = {{"aim_deg", o.noise.aim_deg}, {"speed_pct", o.noise.speed_pct}, {"tip_mm", o.noise.tip_mm},
                  {"elevation_deg", o.noise.elevation_deg}};
  out["samples"] = o.samples;
  out["seed"] = o.seed;
  out["nominal_success"] = r.nominal_success;
  out["probability"] = r.probability;
  out["standard_error"] = r.standard_error;
  std::map<std::string, int> statuses;
  for (const MarginSample& s : r.samples) ++statuses[s.status];
  out["statuses"] = statuses;
  if (o.sensitivity) {
    json sens = json::object();
    for (int k = 0; k < kNoiseSources; ++k)
      sens[noise_source_name(k)] = {{"alone", r.alone[k]},
                                    {"tolerance", r.nominal_success ? json{r.tolerance[k].lo, r.tolerance[k].hi}
                                                                    : json(nullptr)},  // none round a miss
                                    {"bounded", r.nominal_success ? json{r.tolerance[k].bounded_lo,
                                                                         r.tolerance[k].bounded_hi}
                                                                  : json(nullptr)}};
    out["sensitivity"] = sens;
  }
  out["ends"] = scatter(r);
  out["start"] = json::object();
  for (const InitialBall& b : scene.balls) out["start"][b.spec.id] = {b.position.x, b.position.z, b.spec.radius};
  out["table"] = table_outline(scene);
  if (map) {
    json rows = json::array();
    for (int i = 0; i < map->speeds; ++i)
      rows.push_back(std::vector<double>(map->cells.begin() + i * map->aims, map->cells.begin() + (i + 1) * map->aims));
    out["map"] = {{"aims", map->aims}, {"speeds", map->speeds}, {"aim_deg", {map->aim_lo_deg, map->aim_hi_deg}},
                  {"speed", {map->speed_lo, map->speed_hi}}, {"nominal", {scene.cue->aim * 180 / std::numbers::pi, scene.cue->speed}},
                  {"success", rows}, {"cancelled", map->cancelled}};
  }
  out["cancelled"] = r.cancelled;
  return out;
}

std::string margin_csv(const MarginResult& r) {
  std::ostringstream out;
  out << "replay";
  for (int k = 0; k < kNoiseSources; ++k) out << ',' << noise_source_name(k);
  out << ",success,status,reason";
  for (const std::string& id : r.ball_ids) out << ',' << csv_field(id + ".x") << ',' << csv_field(id + ".z") << ','
                                               << csv_field(id + ".pocketed");
  out << '\n';
  for (size_t i = 0; i < r.samples.size(); ++i) {
    const MarginSample& s = r.samples[i];
    out << i;
    for (double e : s.error) out << ',' << number_text(e);
    out << ',' << (s.success ? 1 : 0) << ',' << s.status << ',' << csv_field(s.reason);
    for (size_t b = 0; b < r.ball_ids.size(); ++b)
      if (b < s.end_x.size()) out << ',' << number_text(s.end_x[b]) << ',' << number_text(s.end_z[b]) << ',' << (s.pocketed[b] ? 1 : 0);
      else out << ",,,";
    out << '\n';
  }
  return out.str();
}

}  // namespace shotlab
