#include "ui/aim.hpp"

#include <algorithm>
#include <cmath>
#include <future>
#include <string>

#include "shotlab/io/margin.hpp"
#include "shotlab/rack.hpp"
#include "shotlab/simulation.hpp"

namespace shotlab {

namespace {
constexpr double kNoHitLength = 4.0;   // m: an aim line that meets no ball or cushion stops here
constexpr double kMaxCutDeg = 85.0;    // thinner cuts are not offered as pocket aims
constexpr double kBreakSpeed = 8.0;    // m/s of the cue: the ball leaves at about 10.6 m/s

int cue_index(const Scene& s) {
  if (!s.cue) return -1;
  for (size_t i = 0; i < s.balls.size(); ++i)
    if (s.balls[i].spec.id == s.cue->ball) return static_cast<int>(i);
  return -1;
}

}  // namespace

double squirt_of(const Scene& s) {
  const int cue = cue_index(s);
  if (cue < 0) return 0;
  const CueStrike& q = *s.cue;
  if (q.side * q.side + q.height * q.height >= 1) return 0;  // strike() refuses it; the cue panel lets none through
  return strike(q, s.balls[cue].spec.mass, s.balls[cue].spec.radius).squirt;
}

double heading(const Vec3& a, const Vec3& b) { return std::atan2(-(b.z - a.z), b.x - a.x); }

std::optional<AimLine> aim_line(const Scene& scene) {
  const int c = cue_index(scene);
  if (c < 0) return std::nullopt;
  AimLine out;
  out.from = scene.balls[c].position;
  const double r = scene.balls[c].spec.radius;
  // Along the heading the ball leaves on: the cue's, turned by the squirt of side spin.
  const Vec3 dir = aim_direction(scene.cue->aim + squirt_of(scene));
  double best = kNoHitLength;
  for (int j = 0; j < static_cast<int>(scene.balls.size()); ++j) {
    if (j == c) continue;
    // Where the centre line comes within r_c + r_j of ball j: |p + s dir - q| = R.
    const Vec3 w = out.from - scene.balls[j].position;
    const double R = r + scene.balls[j].spec.radius;
    const double b = glm::dot(w, dir), disc = b * b - (glm::dot(w, w) - R * R);
    if (disc < 0) continue;
    const double s = -b - std::sqrt(disc);
    if (s > 0 && s < best) best = s, out.hit = j;
  }
  if (scene.table) {  // stop the line at the cushion noses
    const double hx = scene.table->length / 2 - r, hz = scene.table->width / 2 - r;
    double wall = kNoHitLength;
    if (dir.x != 0) wall = std::min(wall, ((dir.x > 0 ? hx : -hx) - out.from.x) / dir.x);
    if (dir.z != 0) wall = std::min(wall, ((dir.z > 0 ? hz : -hz) - out.from.z) / dir.z);
    if (wall < best) best = wall, out.hit = -1;
  }
  out.ghost = out.from + dir * std::max(best, 0.0);
  if (out.hit >= 0) {
    const Vec3 q = scene.balls[out.hit].position;
    out.object_dir = glm::normalize(Vec3{q.x - out.ghost.x, 0, q.z - out.ghost.z});
    out.cut_deg = std::acos(std::clamp(glm::dot(out.object_dir, dir), -1.0, 1.0)) * 180 / M_PI;
  }
  return out;
}

std::vector<PocketAim> pocket_aims(const Scene& scene, const std::vector<Pocket>& pockets, int cue_ball, int object) {
  std::vector<PocketAim> out;
  const int n = static_cast<int>(scene.balls.size());
  if (cue_ball < 0 || object < 0 || cue_ball >= n || object >= n || cue_ball == object) return out;
  const Vec3 c = scene.balls[cue_ball].position, o = scene.balls[object].position;
  const double reach = scene.balls[cue_ball].spec.radius + scene.balls[object].spec.radius;
  for (const Pocket& p : pockets) {
    const Vec3 to_pocket{p.center.x - o.x, 0, p.center.z - o.z};
    if (glm::length(to_pocket) < 1e-6) continue;
    const Vec3 ghost = o - glm::normalize(to_pocket) * reach;
    const Vec3 travel{ghost.x - c.x, 0, ghost.z - c.z};
    if (glm::length(travel) < 1e-6) continue;
    const double cut = std::acos(std::clamp(glm::dot(glm::normalize(travel), glm::normalize(to_pocket)), -1.0, 1.0));
    const double cut_deg = cut * 180 / M_PI;
    if (cut_deg < kMaxCutDeg) out.push_back({p.name, heading(c, ghost), cut_deg});
  }
  std::sort(out.begin(), out.end(), [](const PocketAim& a, const PocketAim& b) { return a.cut_deg < b.cut_deg; });
  return out;
}

namespace {
constexpr double kDropCheckSeconds = 15.0;  // s of a shot simulated at most to see whether the ball drops

bool drops_in(const Scene& scene, const std::string& object, const std::string& pocket) {
  Prepared p = prepare(scene);
  Simulation sim(std::move(p.model), std::move(p.state));
  const int obj = sim.model().ball_index(object);
  bool moved = false;
  size_t seen = 0;
  while (sim.time() < kDropCheckSeconds && sim.advance(0.25) == Status::Ok) {
    for (; seen < sim.events().size(); ++seen) {
      const Event& e = sim.events()[seen];
      if ((e.kind == "pocketed" || e.kind == "off_table") && !e.bodies.empty() && e.bodies[0] == object)
        return e.kind == "pocketed" && e.bodies.size() > 1 && e.bodies[1] == pocket;
    }
    // Once the object ball has moved and stopped (or only spins in place), this shot does not drop it: the rest of
    // the table need not be played out.
    const bool still = obj < 0 || sim.motion(obj) == Motion::Stationary || sim.motion(obj) == Motion::Spinning;
    if (sim.at_rest() || (moved && still)) break;
    moved = moved || !still;
  }
  return false;
}

// The aim window around a ghost-ball aim that drops the ball: how far (deg) the aim alone may turn either way with the
// ball still dropping in that pocket, searched in the amateur's steps of 0.25 deg out to 4 deg and bisected to
// 0.005 deg (shotlab/io/margin.hpp), each try played as long as drops_in plays.
Tolerance aim_window(Scene scene, const std::string& object, const std::string& pocket) {
  scene.duration = std::max(scene.duration, kDropCheckSeconds);
  MarginOptions o;
  o.noise = stroke_noise("amateur");
  o.goal.ball = object, o.goal.pocket = pocket;
  return stroke_tolerance(scene, o, kAim, 0.005);
}

constexpr double kSearchStepDeg = 0.25, kSearchDeg = 4.0;  // a dropping aim is looked for this far off, in these steps

// Whether the ghost-ball aim drops the ball or, with side spin or an elevated cue, the first aim that does, tried
// outwards from it turned back by the squirt (the ball leaves off the cue's line by it, docs/model.md#cue),
// alternately either side: swerve and throw move a spinning ball further. False when none within kSearchDeg does.
// On a crowded table (a rack: each try is a break played out) only the aim turned back by the squirt is tried.
bool find_drop(Scene& s, const std::string& id, PocketAim& a) {
  constexpr size_t kSearchBalls = 4;  // at most this many balls on the table for the search
  const bool spun = s.cue->side != 0 || s.cue->elevation > 0;
  if (spun) a.aim -= squirt_of(s);
  const int steps = spun && s.balls.size() <= kSearchBalls ? static_cast<int>(kSearchDeg / kSearchStepDeg) : 0;
  for (int k = 0; k <= 2 * steps; ++k) {  // 0, +1, -1, +2, -2, ... steps
    const double off = (k % 2 ? 1 : -1) * ((k + 1) / 2) * kSearchStepDeg * M_PI / 180;
    s.cue->aim = a.aim + off;
    if (drops_in(s, id, a.pocket)) return a.aim = s.cue->aim, true;
  }
  s.cue->aim = a.aim;
  return false;
}

// One pocket's answer: whether the shot drops the ball there and, where it does, the aim moved to the middle of the
// aims that drop it too (throw and the jaws put the ghost-ball aim off that middle). The middle is played once more
// and taken only if it drops; a window open on a side (no miss within 4 deg) keeps the aim found.
PocketAim checked(Scene s, const std::string& id, PocketAim a) {
  try {
    a.drops = find_drop(s, id, a);
    if (!a.drops) return a;
  } catch (const std::exception&) {
    a.drops = false;  // a scene the engine refuses drops nothing
    return a;
  }
  try {
    const Tolerance t = aim_window(s, id, a.pocket);
    if (!t.bounded_lo || !t.bounded_hi || !(t.hi > t.lo)) return a;
    s.cue->aim = a.aim + 0.5 * (t.lo + t.hi) * M_PI / 180;
    if (!drops_in(s, id, a.pocket)) return a;
    a.aim = s.cue->aim;
    a.window_deg = 0.5 * (t.hi - t.lo);
  } catch (const std::exception&) {  // no window: the ghost-ball aim, which drops
  }
  return a;
}
}  // namespace

void check_drops(const Scene& scene, int object, std::vector<PocketAim>& aims) {
  if (!scene.cue || object < 0 || object >= static_cast<int>(scene.balls.size())) return;
  // Each pocket's shot on its own thread: P answers in the time of the longest, not of all of them.
  std::vector<std::future<PocketAim>> jobs;
  for (const PocketAim& a : aims) {
    Scene s = scene;
    s.cue->aim = a.aim;
    jobs.push_back(std::async(std::launch::async, checked, std::move(s), scene.balls[object].spec.id, a));
  }
  for (size_t k = 0; k < aims.size(); ++k) aims[k] = jobs[k].get();
  std::stable_partition(aims.begin(), aims.end(), [](const PocketAim& a) { return a.drops; });
}

std::string pocket_label(const std::string& name) {
  if (name.rfind("pocket-", 0) != 0 || name.size() == 7) return name;
  std::string where = name.substr(7);
  std::replace(where.begin(), where.end(), '-', ' ');
  if (where.rfind("side ", 0) == 0) where = where.substr(5) + " side";  // "the back side pocket", as players say
  return "the " + where + " pocket";
}

int pocket_object(const Scene& scene) {
  const auto line = aim_line(scene);
  if (!line) return -1;
  if (line->hit >= 0) return line->hit;
  const int c = cue_index(scene);
  int best = -1;
  double best_turn = INFINITY;
  const double launch = scene.cue->aim + squirt_of(scene);
  for (int j = 0; j < static_cast<int>(scene.balls.size()); ++j) {
    if (j == c) continue;
    const double turn = std::abs(std::remainder(heading(line->from, scene.balls[j].position) - launch, 2 * M_PI));
    if (turn < best_turn) best_turn = turn, best = j;
  }
  return best;
}

Vec3 Zone::clamp(const Vec3& p) const { return {std::clamp(p.x, lo_x, hi_x), p.y, std::clamp(p.z, lo_z, hi_z)}; }

Zone hand_zone(const TableSpec& t, double radius, bool behind_head_string) {
  // A resting ball's centre comes within `short_of` of the nose line where it touches the nose's capsule.
  const NoseAxis a = nose_axis(t);
  const double r = radius + t.cushion_radius, dy = a.up - radius;
  const double short_of = std::abs(dy) < r ? std::sqrt(r * r - dy * dy) - a.out : radius;
  const double hx = t.length / 2 - short_of, hz = t.width / 2 - short_of;
  return {-hx, behind_head_string ? -t.length / 4 : hx, -hz, hz};
}

bool break_position(const Scene& s) {
  const int c = cue_index(s);
  if (!s.table || s.table->kind != TableKind::Pool || c < 0 || s.balls.size() < 4) return false;
  for (size_t i = 0; i < s.balls.size(); ++i)
    if (static_cast<int>(i) != c && s.balls[i].position.x < s.table->length / 4 - 2 * s.balls[i].spec.radius) return false;
  return true;
}

Scene break_scene(const Scene& from) {
  Scene s = from;
  const TableSpec t = from.table.value_or(pool_table());
  s.table = t;
  const int c = cue_index(from);
  InitialBall cue = c >= 0 ? from.balls[c] : InitialBall{{"cue", kPoolBall.mass, kPoolBall.radius}};
  const BallKind kind{"", cue.spec.mass, cue.spec.radius};
  cue.position = {-t.length / 4, cue.spec.radius, 0.0};
  cue.velocity = cue.angular_velocity = Vec3{0.0};
  RackSpec rack;
  rack.apex_x = t.length / 4;
  s.balls = {cue};
  for (InitialBall& b : triangle_rack(rack, kind)) s.balls.push_back(b);
  s.rack.reset();
  if (const BallKind* k = find_ball_kind("pool"); cue.spec.mass == k->mass && cue.spec.radius == k->radius)
    s.rack = RackOrigin{rack, k->name, 1};  // saved as a rack
  CueStrike strike = from.cue.value_or(CueStrike{});
  strike.ball = cue.spec.id;
  strike.speed = kBreakSpeed;
  strike.aim = 0;  // straight at the apex ball
  strike.elevation = strike.side = strike.height = 0;
  s.cue = strike;
  s.name = "break";
  s.description = "A 15-ball break. The cue ball is in hand behind the head string: B picks it up, a click puts it "
                  "down. Aim at the apex ball and shoot; the rack's frozen contacts pass the impulse through the whole "
                  "triangle in about a millisecond.";
  s.allow_overlap = false;
  return s;
}

}  // namespace shotlab
