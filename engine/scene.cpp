#include "shotlab/scene.hpp"

#include <cmath>
#include <set>
#include <stdexcept>

#include "message.hpp"
#include "shotlab/simulation.hpp"

namespace shotlab {

const BallKind* find_ball_kind(const std::string& name) {
  for (const BallKind* k : {&kPoolBall, &kSnookerBall, &kCaromBall})
    if (name == k->name) return k;
  return nullptr;
}

namespace {

void fail(const std::string& what) { throw std::invalid_argument(what); }

const auto number = message_number;

// A ball starts over the bed between the cushion noses (or above it): off it, it would start inside a cushion or in
// the air beside the table.
void check_over_bed(const TableSpec& t, const Vec3& p, const std::string& where) {
  const double half_length = t.length / 2, half_width = t.width / 2;
  if (std::abs(p.x) <= half_length && std::abs(p.z) <= half_width) return;
  fail(where + ".position: (" + number(p.x) + ", " + number(p.z) + ") m is off the table: x and z must be within " +
       number(half_length) + " and " + number(half_width) + " m of its centre (the cushion noses)");
}

}  // namespace

void validate(const Scene& s) {
  std::set<std::string> ids;
  for (size_t i = 0; i < s.balls.size(); ++i) {
    const InitialBall& b = s.balls[i];
    const std::string where = "balls[" + std::to_string(i) + "]";
    if (!ids.insert(b.spec.id).second) fail(where + ".id: duplicate id '" + b.spec.id + "'");
    if (!(b.spec.mass > 0)) fail(where + ".mass: must be positive");
    if (!(b.spec.radius > 0)) fail(where + ".radius: must be positive");
    for (const Vec3& v : {b.position, b.velocity, b.angular_velocity})
      if (!is_finite(v)) fail(where + ": non-finite number");
    if (s.table && b.position.y < 0)  // inside or under the slate: the bed would fling it out with any energy
      fail(where + ".position: below the table's bed (y = " + std::to_string(b.position.y) + " m; the bed is y = 0)");
    if (s.table) check_over_bed(*s.table, b.position, where);
    if (glm::length(b.velocity) > kMaxStartSpeed)
      fail(where + ".velocity: " + number(glm::length(b.velocity)) + " m/s is faster than a ball starts (at most " +
           number(kMaxStartSpeed) + " m/s)");
    if (b.spec.radius * glm::length(b.angular_velocity) > kMaxStartSpeed)
      fail(where + ".angular_velocity: a surface speed R|w| of " +
           number(b.spec.radius * glm::length(b.angular_velocity)) + " m/s is beyond a ball's (at most " +
           number(kMaxStartSpeed) + " m/s)");
  }
  if (!s.allow_overlap)
    for (size_t i = 0; i < s.balls.size(); ++i)
      for (size_t j = i + 1; j < s.balls.size(); ++j) {
        const double gap = glm::length(s.balls[i].position - s.balls[j].position) - s.balls[i].spec.radius -
                           s.balls[j].spec.radius;
        if (gap < -1e-9 && s.rack && i >= s.rack->first)  // both racked: the rack's spacing made them
          fail("rack: the racked balls '" + s.balls[i].spec.id + "' and '" + s.balls[j].spec.id + "' overlap by " +
               std::to_string(-gap * 1e3) + " mm (rack.jitter " + std::to_string(s.rack->spec.jitter) +
               " radii is too much for rack.gap " + std::to_string(s.rack->spec.gap) +
               " m; set \"allow_overlap\": true if this is intended)");
        if (gap < -1e-9)
          fail("balls[" + std::to_string(j) + "].position: ball '" + s.balls[j].spec.id + "' overlaps ball '" +
               s.balls[i].spec.id + "' by " + std::to_string(-gap * 1e3) +
               " mm (set \"allow_overlap\": true if this is intended)");
      }
  if (s.table && !(s.table->nose_height < 2 * s.table->ball_radius))  // a resting ball could not reach it
    fail("table.nose_height: must be below the ball's diameter (" + std::to_string(2 * s.table->ball_radius) + " m)");
  for (size_t r = 0; r < s.model.rods.size(); ++r)
    if (s.model.rods[r].ball < 0 || s.model.rods[r].ball >= static_cast<int>(s.balls.size()))
      fail("rods[" + std::to_string(r) + "].ball: no such ball");
  if (s.cue && !ids.count(s.cue->ball)) fail("cue.ball: no ball with id '" + s.cue->ball + "'");
  if (s.cue)
    if (const std::string problem = cue_problem(*s.cue); !problem.empty()) fail("cue." + problem);
  if (!(s.duration > 0) || !std::isfinite(s.duration)) fail("duration: must be a positive number of seconds");
}

Prepared prepare(const Scene& scene) {
  Prepared out{scene.model, {}, std::nullopt};
  if (scene.table) add_table(out.model, *scene.table);
  out.model.balls.clear();
  const int n = static_cast<int>(scene.balls.size());
  out.state.x.assign(kBallDofs * n, 0.0);
  out.state.in_play.assign(n, 1);
  const ContactMaterial& cloth = out.model.material(kBallCloth);
  const double g = glm::length(out.model.options.gravity);
  for (int i = 0; i < n; ++i) {
    const InitialBall& b = scene.balls[i];
    out.model.balls.push_back(b.spec);
    Vec3 p = b.position;
    // Static sink on the bed: C_s d^m = m g gives d = (m g / C_s)^(1/m) (6.5 um for a pool ball on the cloth).
    for (const Collider& c : out.model.colliders) {
      if (c.material != kBallCloth) continue;
      const auto pen = penetration(c.shape, p, b.spec.radius);
      if (pen && std::abs(pen->depth) < 1e-9 && glm::dot(pen->normal, kUp) > 0.999)
        p -= pen->normal * std::pow(b.spec.mass * g / cloth.stiffness, 1.0 / cloth.exponent);
    }
    set_position(out.state.x, i, p);
    set_velocity(out.state.x, i, b.velocity);
    set_spin(out.state.x, i, b.angular_velocity);
  }
  if (scene.cue) {
    const int i = out.model.ball_index(scene.cue->ball);
    out.strike = strike(*scene.cue, scene.balls[i].spec.mass, scene.balls[i].spec.radius);
    set_velocity(out.state.x, i, velocity(out.state.x, i) + out.strike->velocity);
    set_spin(out.state.x, i, spin(out.state.x, i) + out.strike->spin);
  }
  if (out.model.options.contact == ContactModel::Rigid) {
    const std::string problem = rigid_unsupported(out.model, out.state);
    if (!problem.empty()) fail("model.contact: the rigid model cannot run this scene: " + problem);
  }
  return out;
}

}  // namespace shotlab
