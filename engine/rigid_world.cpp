#include "rigid_world.hpp"

#include <algorithm>
#include <chrono>
#include <limits>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "events.hpp"
#include "shotlab/restitution.hpp"

namespace shotlab {

namespace {

constexpr double kNever = std::numeric_limits<double>::infinity();
// s: the longest a pair's or a ball's events are looked for ahead where neither track ends (no rolling resistance).
constexpr double kFarthest = 1e4;
// m: how far a ball's centre may sit off its resting height on the bed (a soft scene's static sink is 1e-5 m).
constexpr double kOnBed = 1e-3;
// m/s: an upward speed above this leaves the bed, which the rigid model cannot follow.
constexpr double kLeaving = 1e-6;
// m: the highest hop off the bed a ball driven down into it may make (under a fifth of a pool ball's radius: a swerve's
// 1.6 mm); the rigid model drops the downward speed.
constexpr double kHop = 5e-3;

const Shape* bed_of(const Model& model, int* index) {
  for (size_t c = 0; c < model.colliders.size(); ++c) {
    const Shape& s = model.colliders[c].shape;
    const Vec3* n = std::holds_alternative<BoundedPlane>(s) ? &std::get<BoundedPlane>(s).normal
                    : std::holds_alternative<Plane>(s)      ? &std::get<Plane>(s).normal
                                                            : nullptr;
    if (n && n->y > 1 - 1e-12) return *index = static_cast<int>(c), &s;
  }
  return nullptr;
}

double bed_height(const Shape& bed) {
  return std::holds_alternative<BoundedPlane>(bed) ? std::get<BoundedPlane>(bed).origin.y : std::get<Plane>(bed).point.y;
}

const std::vector<Hole>& bed_holes(const Shape& bed) {
  return std::holds_alternative<BoundedPlane>(bed) ? std::get<BoundedPlane>(bed).holes : std::get<Plane>(bed).holes;
}

// The problem with the bed's holes and the rails for the rigid model, or "": every hole must be a pocket's (the rigid
// model pockets a ball whose centre crosses a pocket's edge), and no rail may lie below a ball's centre (it would lift
// the ball off the bed).
std::string bed_and_rails_problem(const Model& model, const State& state, int bed) {
  const Shape& shape = model.colliders[bed].shape;
  for (const Hole& hole : bed_holes(shape)) {
    const bool pocket = std::any_of(model.pockets.begin(), model.pockets.end(), [&](const Pocket& p) {
      return glm::length(horizontal(p.center - hole.center)) < 1e-9 && std::abs(p.radius - hole.radius) < 1e-9;
    });
    if (!pocket) {
      std::ostringstream msg;
      msg << "the bed '" << model.colliders[bed].name << "' has a hole at x = " << hole.center.x << ", z = "
          << hole.center.z << " m that is not a pocket's";
      return msg.str();
    }
  }
  for (const Collider& c : model.colliders) {
    const auto* cap = std::get_if<Capsule>(&c.shape);
    for (int i = 0; cap && i < state.ball_count(); ++i) {
      const double below = bed_height(shape) + model.balls[i].radius - cap->a.y;  // m, under the resting centre
      if (state.in_play[i] && below > 1e-9 && below < model.balls[i].radius + cap->radius)
        return "collider '" + c.name + "' lies below ball '" + model.balls[i].id +
               "''s centre, within its reach, and would lift it off the bed";
    }
  }
  return "";
}

// A pocket's own back as add_table builds it (named after its pocket, an arc wall standing on the hole's rim and
// leaving the mouth open): a ball on the bed meets it only over the hole, where the rigid model has pocketed it.
bool pocket_back(const Model& model, const Collider& c) {
  const auto* wall = std::get_if<ArcWall>(&c.shape);
  return wall && std::any_of(model.pockets.begin(), model.pockets.end(), [&](const Pocket& p) {
           return c.name == p.name + "-back" && glm::length(horizontal(p.center - wall->center)) < 1e-9 &&
                  std::abs(wall->radius - p.radius) < 1e-9;
         });
}

}  // namespace

std::string rigid_unsupported(const Model& model, const State& state) {
  const Vec3& g = model.options.gravity;
  if (!(g.y < 0) || g.x != 0 || g.z != 0) return "gravity must point straight down (along -y)";
  if (!model.rods.empty()) return "it has rods; the rigid model moves balls on a bed only";
  int bed = -1;
  const Shape* shape = bed_of(model, &bed);
  if (!shape) return "it has no flat, level bed for the balls to move on";
  const ContactMaterial& cloth = model.material(model.colliders[bed].material);
  for (size_t c = 0; c < model.colliders.size(); ++c) {
    if (static_cast<int>(c) == bed || pocket_back(model, model.colliders[c])) continue;
    const auto* cap = std::get_if<Capsule>(&model.colliders[c].shape);
    if (!cap || cap->a.y != cap->b.y)
      return "collider '" + model.colliders[c].name +
             "' is not a level cushion or jaw (a horizontal capsule) nor a pocket's back";
  }
  if (std::string problem = bed_and_rails_problem(model, state, bed); !problem.empty()) return problem;
  for (int i = 0; i < state.ball_count(); ++i) {
    if (!state.in_play[i]) continue;
    const BallSpec& b = model.balls[i];
    const double above = position(state.x, i).y - bed_height(*shape) - b.radius;
    if (std::abs(above) > kOnBed) {
      std::ostringstream msg;
      msg << "ball '" << b.id << "' is " << above << " m off its resting height on the bed";
      return msg.str();
    }
    const double vy = velocity(state.x, i).y;
    if (vy > kLeaving) return "ball '" + b.id + "' leaves the bed upwards (a jump or a hop)";
    // Driven down into the bed (an elevated cue), it would bounce off it: the bed's restitution at that speed.
    const double rebound = -vy * restitution_at(cloth, b.mass, -vy);
    if (rebound * rebound / (2 * -g.y) > kHop) {
      std::ostringstream msg;
      msg << "ball '" << b.id << "' is driven into the bed at " << -vy << " m/s and would hop "
          << 1e3 * rebound * rebound / (2 * -g.y) << " mm off it (a jump or masse shot: use the soft model)";
      return msg.str();
    }
  }
  return "";
}

RigidWorld::RigidWorld(Model model, State initial) : model_(std::move(model)), state_(std::move(initial)) {
  const std::string problem = rigid_unsupported(model_, state_);
  if (!problem.empty()) throw std::invalid_argument("the rigid model cannot run this scene: " + problem);
  int bed = -1;
  const Shape& shape = *bed_of(model_, &bed);
  if (const auto* bp = std::get_if<BoundedPlane>(&shape))
    has_edge_ = true, edge_origin_ = bp->origin, edge_u_ = bp->u, edge_v_ = bp->v;
  const ContactMaterial& cloth = model_.material(model_.colliders[bed].material);
  for (size_t c = 0; c < model_.colliders.size(); ++c)
    if (const auto* cap = std::get_if<Capsule>(&model_.colliders[c].shape))
      rails_.push_back({static_cast<int>(c), cap->a, cap->b, cap->radius});
  const int n = state_.ball_count();
  state_.asleep.clear(), state_.rolling_on.clear(), state_.sliding_on.clear(), state_.still_for.clear();
  for (int i = 0; i < n; ++i) {
    const BallSpec& b = model_.balls[i];
    laws_.push_back({b.radius, -model_.options.gravity.y, cloth.friction, cloth.rolling_resistance, cloth.spin_friction});
    tracks_.push_back(state_.in_play[i] ? bed_track(laws_[i], state_.time, position(state_.x, i),
                                                    velocity(state_.x, i), spin(state_.x, i))
                                        : out_track(state_.time, position(state_.x, i),
                                                    model_.pocket_under(position(state_.x, i), b.radius)
                                                        ? Motion::Pocketed
                                                        : Motion::OffTable));
  }
  own_.assign(n, {kNever, Kind::Change, -1});
  pairs_.assign(static_cast<size_t>(n) * n, kNever);
  for (int i = 0; i < n; ++i) plan(i);
  for (int i = 0; i < n; ++i) {  // the state as the tracks have it (on the bed, no vertical speed)
    const BallState k = at(laws_[i], tracks_[i], state_.time);
    set_position(state_.x, i, k.p), set_velocity(state_.x, i, k.v), set_spin(state_.x, i, k.w);
  }
}

RigidWorld::Next RigidWorld::own_next(int i) const {
  const Track& t = tracks_[i];
  if (out_of_play(t.kind) || t.kind == Motion::Stationary || t.kind == Motion::Spinning)
    return {t.ends, Kind::Change, -1};
  // A track that outlasts the search's horizon (no rolling resistance) is taken up again there and searched anew.
  const double h = std::min(t.ends - t.t0, kFarthest);
  Next best{t.t0 + h, Kind::Change, -1};
  const Parabola p = parabola(laws_[i], t, t.t0);
  auto take = [&](double s, Kind kind, int other) {
    if (t.t0 + s < best.time) best = {t.t0 + s, kind, other};
  };
  const Sweep box = sweep(p, h);
  const double radius = model_.balls[i].radius;
  for (size_t r = 0; r < rails_.size(); ++r)
    if (box.near(rails_[r].a, rails_[r].b, radius + rails_[r].radius))
      take(rail_entry(p, radius, rails_[r], h), Kind::Rail, static_cast<int>(r));
  for (size_t k = 0; k < model_.pockets.size(); ++k) {
    const Pocket& pocket = model_.pockets[k];
    if (box.near(pocket.center, pocket.center, pocket.radius))
      take(point_entry(p, pocket.center, pocket.radius, h), Kind::Pocket, static_cast<int>(k));
  }
  if (has_edge_) take(edge_exit(p, edge_origin_, edge_u_, edge_v_, h), Kind::Edge, -1);
  return best;
}

double RigidWorld::pair_next(int i, int j) const {
  const Track &a = tracks_[i], &b = tracks_[j];
  const auto still = [](const Track& t) { return t.kind != Motion::Rolling && t.kind != Motion::Sliding; };
  if (out_of_play(a.kind) || out_of_play(b.kind) || (still(a) && still(b))) return kNever;
  const double t0 = std::max(a.t0, b.t0);
  const double h = std::min({a.ends, b.ends, t0 + kFarthest}) - t0;
  const Parabola pa = parabola(laws_[i], a, t0), pb = parabola(laws_[j], b, t0);
  const double reach = horizontal_reach(i, j);
  // Out of reach within h even at the greatest closing speed and acceleration: no need to solve.
  const double gap = glm::length(Vec3{pb.p.x - pa.p.x, 0.0, pb.p.z - pa.p.z}) - reach;
  if (gap > glm::length(pb.v - pa.v) * h + 0.5 * glm::length(pb.a - pa.a) * h * h) return kNever;
  const Sweep other = sweep(pb, h);
  if (!sweep(pa, h).near(other.lo, other.hi, reach)) return kNever;  // the boxes they sweep do not come within reach
  return t0 + first_entry(gap_between(pa, pb, reach), h);
}

double RigidWorld::horizontal_reach(int i, int j) const {
  const double full = model_.balls[i].radius + model_.balls[j].radius, dy = tracks_[i].p.y - tracks_[j].p.y;
  return std::sqrt(std::max(0.0, full * full - dy * dy));  // on one bed |dy| is about a difference of radii
}

void RigidWorld::plan(int i) {
  const int n = state_.ball_count();
  own_[i] = own_next(i);
  for (int j = 0; j < n; ++j)
    if (j != i) pairs_[std::min(i, j) * n + std::max(i, j)] = pair_next(std::min(i, j), std::max(i, j));
}

void RigidWorld::restart(int i, double t, const BallState& k) {
  const Motion before = tracks_[i].kind;
  tracks_[i] = bed_track(laws_[i], t, k.p, k.v, k.w);
  const Motion now = tracks_[i].kind;
  if (now != before) events_.push_back({t, transition_kind(before, now), {model_.balls[i].id}});
}

Bounce RigidWorld::bounce(const ContactMaterial& material, double m_eff, double closing) const {
  // Never slower than rest_speed: a ball pushing another that slides ahead of it (or a rack's touching balls, or a ball
  // spun into a cushion from rest) would otherwise meet it again and again ever sooner, without end; so it bounces
  // every 2 rest_speed / (their deceleration difference), within a micrometre of it.
  const double e = closing < model_.options.rest_speed ? 1.0 : restitution_at(material, m_eff, closing);
  return {e, model_.options.rest_speed};
}

void RigidWorld::handle(int i, const Next& next) {
  const double t = next.time;
  BallState k = at(laws_[i], tracks_[i], t);
  const std::string& id = model_.balls[i].id;
  switch (next.kind) {
    case Kind::Change: restart(i, t, k); break;
    case Kind::Ball: {
      const int j = next.other;
      BallState kj = at(laws_[j], tracks_[j], t);
      const Vec3 d{kj.p.x - k.p.x, 0.0, kj.p.z - k.p.z};
      const Vec3 n = glm::normalize(d);
      const double m_eff = 1 / (1 / model_.balls[i].mass + 1 / model_.balls[j].mass);
      const Bounce out = bounce(model_.material(kBallBall), m_eff, closing_speed(k, kj, n));
      collide_balls(k, model_.balls[i], kj, model_.balls[j], n, out, model_.material(kBallBall));
      events_.push_back({t, "contact_begin", {id, model_.balls[j].id}});
      events_.push_back({t, "contact_end", {id, model_.balls[j].id}});
      restart(i, t, k), restart(j, t, kj);
      plan(j);
      break;
    }
    case Kind::Rail: {
      const Rail& rail = rails_[next.other];
      const Collider& c = model_.colliders[rail.collider];
      const Vec3 n = rail_normal(k, rail);
      const Bounce out = bounce(model_.material(c.material), model_.balls[i].mass, -glm::dot(k.v, n));
      collide_rail(k, model_.balls[i], n, out, model_.material(c.material).friction, laws_[i].friction);
      events_.push_back({t, "contact_begin", {id, c.name}});
      events_.push_back({t, "contact_end", {id, c.name}});
      restart(i, t, k);
      break;
    }
    case Kind::Pocket:
    case Kind::Edge: {
      const bool pocket = next.kind == Kind::Pocket;
      // Below the bed, as the soft model leaves it.
      tracks_[i] = out_track(t, Vec3{k.p.x, -model_.balls[i].radius, k.p.z}, pocket ? Motion::Pocketed : Motion::OffTable);
      state_.in_play[i] = 0;
      events_.push_back({t, pocket ? "pocketed" : "off_table",
                         pocket ? std::vector<std::string>{id, model_.pockets[next.other].name}
                                : std::vector<std::string>{id}});
      break;
    }
  }
  plan(i);
}

Status RigidWorld::advance(double dt) {
  call_events_ = 0;
  return advance_on(dt);
}

Status RigidWorld::advance_on(double dt) {  // dt checked by Simulation
  if (status_ != Status::Ok) return status_;
  const auto wall0 = std::chrono::steady_clock::now();
  const double target = state_.time + dt;
  const int n = state_.ball_count();
  double reached = target;  // s: where the state is left, the last event handled when the limit stops the loop
  double last = state_.time;
  while (true) {
    int who = -1;
    Next next{kNever, Kind::Change, -1};
    for (int i = 0; i < n; ++i) {
      if (own_[i].time < next.time) next = own_[i], who = i;
      for (int j = i + 1; j < n; ++j)
        if (pairs_[i * n + j] < next.time) next = {pairs_[i * n + j], Kind::Ball, j}, who = i;
    }
    if (who < 0 || next.time > target) break;
    if (call_events_ >= model_.integrator.max_steps_per_call) {
      std::ostringstream msg;
      msg << "event limit: " << model_.integrator.max_steps_per_call << " events (integrator.max_steps_per_call) did "
          << "not reach t = " << target << " s; stopped at t = " << next.time << " s at ball '" << model_.balls[who].id
          << "'";
      stop(Status::StepLimit, msg.str());
      reached = last;
      break;
    }
    handle(who, next);
    last = next.time;
    ++call_events_, ++stats_.steps;
  }
  for (int i = 0; i < n; ++i) {
    const BallState k = at(laws_[i], tracks_[i], reached);
    set_position(state_.x, i, k.p), set_velocity(state_.x, i, k.v), set_spin(state_.x, i, k.w);
  }
  state_.time = reached;
  stats_.wall_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  return status_;
}

bool RigidWorld::at_rest() const {
  for (const Track& t : tracks_)
    if (t.kind != Motion::Stationary && !out_of_play(t.kind)) return false;
  return true;
}

std::vector<std::vector<int>> RigidWorld::island_balls() const {
  std::vector<std::vector<int>> out;
  for (int i = 0; i < static_cast<int>(tracks_.size()); ++i)
    if (tracks_[i].kind != Motion::Stationary && !out_of_play(tracks_[i].kind)) out.push_back({i});
  return out;
}

void RigidWorld::stop(Status why, std::string message) {
  status_ = why;
  diagnostic_ = std::move(message);
}

}  // namespace shotlab
