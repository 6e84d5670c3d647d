// Writing a scene file: the inverse of parse_scene (scene_json.cpp), every field it reads written back; a rack that
// is as its spec generates it is written as the spec, so a saved scene keeps its seed and jitter.
#include <cmath>
#include <numbers>

#include "shotlab/io/atomic_file.hpp"
#include "shotlab/io/scene_json.hpp"
#include "shotlab/rack.hpp"
#include "scene_fields.hpp"

namespace shotlab {
namespace {

using nlohmann::json;

json vec(const Vec3& v) { return json::array({v.x, v.y, v.z}); }
double degrees(double rad) { return rad * 180.0 / M_PI; }

json material_json(const ContactMaterial& m) {
  json j = {{"damping_law", m.damping_law == DampingLaw::Linear ? "linear" : "hunt_crossley"},
            {"friction_law", m.friction_law == FrictionLaw::Constant ? "constant" : "speed_dependent"},
            {"friction_fast_ratio", m.friction_fast_ratio},
            {"restitution", m.restitution}};
  write_fields(j, m, kMaterialNumbers);
  return j;
}

json table_json(const TableSpec& t) {
  json j = {{"type", table_kind_name(t.kind)}};
  write_fields(j, t, kTableFields);
  return j;
}

json holes_json(const std::vector<Hole>& holes) {
  json out = json::array();
  for (const Hole& h : holes) out.push_back({{"center", vec(h.center)}, {"radius", h.radius}});
  return out;
}

struct ColliderJson {
  json operator()(const Plane& s) const {
    return {{"type", "plane"}, {"point", vec(s.point)}, {"normal", vec(s.normal)}, {"holes", holes_json(s.holes)}};
  }
  json operator()(const BoundedPlane& s) const {
    return {{"type", "bounded_plane"}, {"origin", vec(s.origin)}, {"u", vec(s.u)}, {"v", vec(s.v)},
            {"holes", holes_json(s.holes)}};
  }
  json operator()(const StaticSphere& s) const {
    return {{"type", "sphere"}, {"center", vec(s.center)}, {"radius", s.radius}};
  }
  json operator()(const Capsule& s) const {
    return {{"type", "capsule"}, {"a", vec(s.a)}, {"b", vec(s.b)}, {"radius", s.radius}};
  }
  json operator()(const ArcWall& s) const {
    return {{"type", "arc_wall"}, {"center", vec(s.center)}, {"radius", s.radius}, {"thickness", s.thickness},
            {"toward", vec(s.toward)}, {"half_angle_deg", s.half_angle * 180 / std::numbers::pi},
            {"bottom", s.bottom}, {"top", s.top}};
  }
};

// The racked balls as a rack generates them (ids, positions, no motion): then a saved scene writes the rack.
bool racked_as_generated(const Scene& s) {
  if (!s.rack || !find_ball_kind(s.rack->kind)) return false;
  const std::vector<InitialBall> rack = make_rack(s.rack->spec, *find_ball_kind(s.rack->kind));
  if (s.balls.size() != s.rack->first + rack.size()) return false;
  for (size_t k = 0; k < rack.size(); ++k) {
    const InitialBall& a = s.balls[s.rack->first + k];
    if (a.spec.id != rack[k].spec.id || a.position != rack[k].position || a.velocity != Vec3{0.0} ||
        a.angular_velocity != Vec3{0.0} || a.spec.mass != rack[k].spec.mass || a.spec.radius != rack[k].spec.radius)
      return false;
  }
  return true;
}

}  // namespace

json scene_to_json(const Scene& s) {
  json doc;
  doc["name"] = s.name;
  doc["description"] = s.description;
  doc["duration"] = s.duration;
  doc["allow_overlap"] = s.allow_overlap;
  doc["gravity"] = vec(s.model.options.gravity);
  doc["model"] = json::object();
  doc["model"]["contact"] = contact_model_name(s.model.options.contact);
  write_fields(doc["model"], s.model.options, kOptionNumbers);
  write_fields(doc["model"], s.model.options, kOptionSwitches);
  const IntegratorOptions& o = s.model.integrator;
  doc["integrator"] = {{"method", method_name(o.method)}, {"abs_tol", o.abs_tol}, {"rel_tol", o.rel_tol},
                       {"fixed_step", o.fixed_step}, {"initial_step", o.initial_step},
                       {"max_steps_per_call", o.max_steps_per_call}};
  for (const auto& [name, m] : s.model.materials) doc["materials"][name] = material_json(m);
  if (s.table) doc["table"] = table_json(*s.table);
  doc["colliders"] = json::array();
  for (const Collider& c : s.model.colliders) {
    json j = std::visit(ColliderJson{}, c.shape);
    j["name"] = c.name;
    j["material"] = c.material;
    doc["colliders"].push_back(j);
  }
  doc["balls"] = json::array();
  const bool rack = racked_as_generated(s);
  if (rack) {
    const RackSpec& r = s.rack->spec;
    doc["ball_kind"] = s.rack->kind;
    doc["rack"] = {{"type", r.type == RackType::Snooker ? "snooker" : "triangle"}, {"rows", r.rows}, {"apex", {r.apex_x, 0.0, r.apex_z}}, {"gap", r.gap},
                   {"jitter", r.jitter}, {"seed", r.seed}, {"first_number", r.first_number}};
  }
  for (size_t i = 0; i < (rack ? s.rack->first : s.balls.size()); ++i) {
    const InitialBall& b = s.balls[i];
    doc["balls"].push_back({{"id", b.spec.id}, {"mass", b.spec.mass}, {"radius", b.spec.radius},
                            {"position", vec(b.position)}, {"velocity", vec(b.velocity)},
                            {"angular_velocity", vec(b.angular_velocity)}});
  }
  doc["rods"] = json::array();
  for (const Rod& r : s.model.rods)
    doc["rods"].push_back({{"ball", s.balls[r.ball].spec.id}, {"anchor", vec(r.anchor)}, {"length", r.length}});
  if (s.cue) {
    const CueStrike& c = *s.cue;
    doc["cue"] = {{"ball", c.ball}, {"speed", c.speed}, {"aim_deg", degrees(c.aim)},
                  {"elevation_deg", degrees(c.elevation)}, {"side", c.side}, {"height", c.height},
                  {"cue_mass", c.cue_mass}, {"end_mass", c.end_mass}, {"tip_restitution", c.tip_restitution},
                  {"miscue_limit", c.miscue_limit}};
  }
  return doc;
}

void save_scene(const std::string& path, const Scene& scene) {
  write_file_atomic(path, scene_to_json(scene).dump(2, ' ', false, json::error_handler_t::replace) + "\n");
}

}  // namespace shotlab
