#include "shotlab/io/scene_json.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <memory>
#include <numbers>
#include <set>
#include <sstream>

#include "shotlab/io/atomic_file.hpp"
#include "shotlab/rack.hpp"
#include "shotlab/restitution.hpp"
#include "scene_fields.hpp"

namespace shotlab {
namespace {

using nlohmann::json;

void read_material(const JsonNode& n, ContactMaterial& m) {
  read_fields(n, m, kMaterialNumbers);
  n.optional("damping_law", [&](const JsonNode& v) {
    const std::string law = v.string();
    if (law == "linear") m.damping_law = DampingLaw::Linear;
    else if (law == "hunt_crossley") m.damping_law = DampingLaw::HuntCrossley;
    else v.fail("unknown damping law '" + law + "' (linear, hunt_crossley)");
  });
  n.optional("friction_law", [&](const JsonNode& v) {
    const std::string law = v.string();
    if (law == "constant") m.friction_law = FrictionLaw::Constant;
    else if (law == "speed_dependent") m.friction_law = FrictionLaw::SpeedDependent;
    else v.fail("unknown friction law '" + law + "' (constant, speed_dependent)");
  });
  for (const auto& [key, member] : {std::pair{"friction_fast_ratio", &ContactMaterial::friction_fast_ratio},
                                    std::pair{"restitution", &ContactMaterial::restitution}})
    n.optional(key, [&](const JsonNode& v) {  // shares, 0 to 1
      m.*member = v.non_negative();
      if (m.*member > 1) v.fail("must be at most 1, got " + describe(v.raw()));
    });
  n.finish();
}

void read_integrator(const JsonNode& n, IntegratorOptions& o) {
  n.optional("method", [&](const JsonNode& v) {
    if (!parse_method(v.string(), o.method))
      v.fail("unknown integrator '" + v.string() + "' (euler, rk4, cash_karp54, dopri5, bulirsch_stoer, rosenbrock4)");
  });
  n.optional("abs_tol", o.abs_tol, &JsonNode::positive);
  n.optional("rel_tol", o.rel_tol, &JsonNode::positive);
  n.optional("fixed_step", o.fixed_step, &JsonNode::positive);
  n.optional("initial_step", o.initial_step, &JsonNode::positive);
  n.optional("max_steps_per_call", [&](const JsonNode& v) { o.max_steps_per_call = v.integer(1, 1 << 30); });
  n.finish();
}

void read_table(const JsonNode& n, TableSpec& t) {
  const std::string type = n["type"].string();
  if (type == "pool") t = pool_table();
  else if (type == "carom") t = carom_table();
  else if (type == "snooker") t = snooker_table();
  else n["type"].fail("unknown table type '" + type + "' (pool, carom, snooker)");
  read_fields(n, t, kTableFields);
  n.finish();
}

std::vector<Hole> read_holes(const JsonNode& n) {
  std::vector<Hole> holes;
  for (const JsonNode& h : n.items()) {
    holes.push_back({h["center"].vec3(), h["radius"].positive()});
    h.finish();
  }
  return holes;
}

ArcWall read_arc_wall(const JsonNode& n) {
  Vec3 toward = n["toward"].vec3();
  toward.y = 0;
  if (glm::length(toward) == 0) n["toward"].fail("must have a horizontal part (x or z not zero)");
  const double half_deg = n["half_angle_deg"].number();
  if (!(half_deg > 0 && half_deg <= 180)) n["half_angle_deg"].fail("must be more than 0 and at most 180");
  const double half = half_deg * std::numbers::pi / 180;
  const double bottom = n["bottom"].number(), top = n["top"].number();
  if (!(top > bottom)) n["top"].fail("must be above bottom");
  return ArcWall{n["center"].vec3(), n["radius"].positive(), n["thickness"].positive(), glm::normalize(toward),
                 half, bottom, top};
}

Collider read_collider(const JsonNode& n, const Model& model) {
  Collider c;
  const std::string type = n["type"].string();
  c.name = n.has("name") ? n["name"].string() : type;
  c.material = n.has("material") ? n["material"].string() : kBallCushion;
  if (!model.materials.count(c.material)) n["material"].fail("unknown material '" + c.material + "'");
  std::vector<Hole> holes;
  n.optional("holes", [&](const JsonNode& v) { holes = read_holes(v); });
  if (type == "plane") {
    const Vec3 normal = n["normal"].vec3();
    if (glm::length(normal) == 0) n["normal"].fail("must not be zero");
    c.shape = Plane{n["point"].vec3(), glm::normalize(normal), holes};
  } else if (type == "bounded_plane") {
    const Vec3 u = n["u"].vec3(), v = n["v"].vec3();
    if (glm::length(glm::cross(u, v)) == 0) n["v"].fail("u and v must span a parallelogram");
    c.shape = BoundedPlane{n["origin"].vec3(), u, v, holes};
  } else if (type == "sphere") {
    c.shape = StaticSphere{n["center"].vec3(), n["radius"].positive()};
  } else if (type == "capsule") {
    c.shape = Capsule{n["a"].vec3(), n["b"].vec3(), n["radius"].positive()};
  } else if (type == "arc_wall") {
    c.shape = read_arc_wall(n);
  } else {
    n["type"].fail("unknown collider type '" + type + "' (plane, bounded_plane, sphere, capsule, arc_wall)");
  }
  n.finish();
  return c;
}

InitialBall read_ball(const JsonNode& n, const BallKind& default_kind) {
  const BallKind* kind = &default_kind;
  n.optional("kind", [&](const JsonNode& v) {
    kind = find_ball_kind(v.string());
    if (!kind) v.fail("unknown ball kind '" + v.string() + "' (pool, snooker, carom)");
  });
  InitialBall b;
  b.spec = {n["id"].string(), kind->mass, kind->radius};
  n.optional("mass", b.spec.mass, &JsonNode::positive);
  n.optional("radius", b.spec.radius, &JsonNode::positive);
  b.position = n["position"].vec3();
  n.optional("velocity", [&](const JsonNode& v) { b.velocity = v.vec3(); });
  n.optional("angular_velocity", [&](const JsonNode& v) { b.angular_velocity = v.vec3(); });
  n.finish();
  return b;
}

void read_rack(const JsonNode& n, const BallKind& kind, Scene& s) {
  RackSpec r;
  const std::string type = n["type"].string();
  if (type == "snooker") r.type = RackType::Snooker;
  else if (type != "triangle") n["type"].fail("unknown rack type '" + type + "' (triangle, snooker)");
  if (s.table) r.table_length = s.table->length;
  n.optional("rows", [&](const JsonNode& v) { r.rows = v.integer(1, 50); });
  n.optional("apex", [&](const JsonNode& v) {
    const Vec3 p = v.vec3();
    r.apex_x = p.x;
    r.apex_z = p.z;
  });
  n.optional("gap", r.gap, &JsonNode::non_negative);
  n.optional("jitter", r.jitter, &JsonNode::non_negative);
  n.optional("seed", [&](const JsonNode& v) { r.seed = static_cast<uint32_t>(v.integer(0, 1 << 30)); });
  n.optional("first_number", [&](const JsonNode& v) { r.first_number = v.integer(0, 1 << 20); });
  n.finish();
  s.rack = RackOrigin{r, kind.name, s.balls.size()};
  for (InitialBall& b : make_rack(r, kind)) s.balls.push_back(std::move(b));
}

void read_cue(const JsonNode& n, CueStrike& c) {
  c.ball = n["ball"].string();
  c.speed = n["speed"].positive();
  n.optional("aim_deg", [&](const JsonNode& v) { c.aim = v.angle_degrees(); });
  n.optional("elevation_deg", [&](const JsonNode& v) {
    c.elevation = v.angle_degrees();
    if (c.elevation < 0 || c.elevation > kMaxElevation) v.fail("must be between 0 and 90 degrees");
  });
  n.optional("side", c.side, &JsonNode::number);
  n.optional("height", c.height, &JsonNode::number);
  if (c.side * c.side + c.height * c.height >= 1) n.fail("side, height: the tip offset must lie inside the ball");
  n.optional("cue_mass", c.cue_mass, &JsonNode::positive);
  n.optional("end_mass", c.end_mass, &JsonNode::non_negative);
  n.optional("tip_restitution", [&](const JsonNode& v) {
    c.tip_restitution = v.non_negative();
    if (c.tip_restitution > 1) v.fail("must be at most 1");
  });
  n.optional("miscue_limit", c.miscue_limit, &JsonNode::positive);
  n.finish();
}

void read_options(const JsonNode& m, Options& o) {
  m.optional("path", [&](const JsonNode& v) {  // first: the switches below override it
    if (v.string() == "fast") use_path(o, SolverPath::Fast);
    else if (v.string() == "plain") use_path(o, SolverPath::Plain);
    else v.fail("must be \"fast\" or \"plain\", got " + describe(v.raw()));
  });
  m.optional("contact", [&](const JsonNode& v) {
    if (!parse_contact_model(v.string(), o.contact)) v.fail("must be \"soft\" or \"rigid\", got " + describe(v.raw()));
  });
  read_fields(m, o, kOptionNumbers);
  read_fields(m, o, kOptionSwitches);
  m.finish();
}

// Rods name their ball by id; the length defaults to the distance from the anchor.
void read_rods(const JsonNode& v, Scene& s) {
  std::map<std::string, int> index;
  for (size_t i = 0; i < s.balls.size(); ++i) index[s.balls[i].spec.id] = static_cast<int>(i);
  for (const JsonNode& r : v.items()) {
    const std::string id = r["ball"].string();
    if (!index.count(id)) r["ball"].fail("no ball with id '" + id + "'");
    Rod rod{index[id], r["anchor"].vec3(), 0.0};
    rod.length = glm::length(s.balls[rod.ball].position - rod.anchor);
    r.optional("length", [&](const JsonNode& l) { rod.length = l.positive(); });
    if (!(rod.length > 0)) r["anchor"].fail("is at the ball's centre: a rod needs a length (give \"length\")");
    r.finish();
    s.model.rods.push_back(rod);
  }
}

// Materials given by their restitution get their damping (and stiffness) here, for impacts of the scene's first ball
// (of its ball kind when it has none): docs/model.md#restitution.
void derive_restitution(Scene& s, const BallKind& kind, const std::string& source) {
  const double mass = s.balls.empty() ? kind.mass : s.balls[0].spec.mass;
  for (auto& [name, m] : s.model.materials) {
    if (m.restitution <= 0) continue;
    const std::string problem = apply_restitution(m, effective_mass(name == kBallBall, mass));
    if (!problem.empty()) throw InputError(source + ": materials." + name + ".restitution: " + problem);
  }
}

}  // namespace

Scene parse_scene(const json& doc, const std::string& source) {
  const JsonNode n(doc, source, "");
  if (!doc.is_object()) n.fail("a scene file must hold a JSON object");
  Scene s;
  s.model = empty_model();
  n.optional("name", [&](const JsonNode& v) { s.name = v.string(); });
  n.optional("description", [&](const JsonNode& v) { s.description = v.string(); });
  n.optional("duration", [&](const JsonNode& v) {
    s.duration = v.positive();
    if (s.duration > kMaxDuration) v.fail("must be at most " + std::to_string(static_cast<int>(kMaxDuration)) + " s");
  });
  n.optional("allow_overlap", s.allow_overlap, &JsonNode::boolean);
  n.optional("gravity", [&](const JsonNode& v) { s.model.options.gravity = v.vec3(); });
  n.optional("model", [&](const JsonNode& m) { read_options(m, s.model.options); });
  n.optional("integrator", [&](const JsonNode& v) { read_integrator(v, s.model.integrator); });
  n.optional("table", [&](const JsonNode& v) {  // first: the table's cloth and cushion, then the scene's materials
    s.table.emplace();
    read_table(v, *s.table);
    set_table_materials(s.table->kind, s.model);
  });
  n.optional("materials", [&](const JsonNode& m) {
    for (const auto& item : m.raw().items()) {
      const bool known = s.model.materials.count(item.key()) > 0;
      read_material(m[item.key()], s.model.materials[item.key()]);
      const ContactMaterial& read = s.model.materials[item.key()];
      if (!known && read.stiffness == 0)
        m[item.key()].fail("a new material needs a stiffness (the standard ones are ball_ball, ball_cloth, "
                           "ball_cushion; a table with pockets adds ball_pocket)");
      if (item.key() != kBallBall && read.friction_law == FrictionLaw::SpeedDependent)
        m[item.key()]["friction_law"].fail("speed_dependent is for ball_ball only (the bed's closed forms assume a constant coefficient)");
    }
  });
  n.optional("colliders", [&](const JsonNode& v) {
    for (const JsonNode& c : v.items()) s.model.colliders.push_back(read_collider(c, s.model));
  });
  const BallKind* kind = &kPoolBall;
  n.optional("ball_kind", [&](const JsonNode& v) {
    kind = find_ball_kind(v.string());
    if (!kind) v.fail("unknown ball kind '" + v.string() + "' (pool, snooker, carom)");
  });
  n.optional("balls", [&](const JsonNode& v) {
    for (const JsonNode& b : v.items()) s.balls.push_back(read_ball(b, *kind));
  });
  n.optional("rack", [&](const JsonNode& v) { read_rack(v, *kind, s); });
  n.optional("rods", [&](const JsonNode& v) { read_rods(v, s); });
  n.optional("cue", [&](const JsonNode& v) {
    s.cue.emplace();
    read_cue(v, *s.cue);
  });
  n.finish();
  derive_restitution(s, *kind, source);
  try {
    validate(s);
  } catch (const std::invalid_argument& e) {
    throw InputError(source + ": " + e.what());
  }
  return s;
}

std::string read_scene_file(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw InputError(path + ": is a folder, not a scene file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot open the file");
  // Read in chunks up to one byte past the limit: /dev/zero or a wrong file must not fill memory, and a scene of a few
  // kilobytes must not cost a buffer of the limit's size.
  std::string text;
  char chunk[1 << 16];
  while (text.size() <= kMaxSceneBytes && in.read(chunk, sizeof chunk).gcount() > 0)
    text.append(chunk, static_cast<size_t>(in.gcount()));
  if (text.size() > kMaxSceneBytes)
    throw InputError(path + ": larger than " + std::to_string(kMaxSceneBytes >> 20) + " MiB, not a scene file");
  return text;
}

Scene load_scene(const std::string& path, const std::vector<std::string>& overrides) {
  json doc = parse_json_text(read_scene_file(path), path);
  for (const std::string& o : overrides) apply_override(doc, o);
  return parse_scene(doc, overrides.empty() ? path : path + " (with --set overrides)");
}

}  // namespace shotlab
