// Shot margins: noisy replays of a cue strike on the sweep's pool, judged by a goal. docs/margin.md.
#include "shotlab/io/margin.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <mutex>
#include <numbers>
#include <random>

#include "shotlab/io/json_reader.hpp"
#include "shotlab/io/parallel.hpp"

namespace shotlab {
namespace {

constexpr double kDeg = std::numbers::pi / 180;
constexpr double kMarginSampleRate = 60;  // Hz: how often a replay checks for rest and for a decided goal
// The deviation the tolerance search steps by where a source has no noise: 0.125 deg, 1 %, 0.5 mm, 0.5 mm, 0.1 deg.
constexpr double kToleranceScale[kNoiseSources] = {0.125, 1.0, 0.5, 0.5, 0.1};
constexpr int kToleranceSteps = 16;      // searched out in half deviations to 8 deviations
constexpr int kToleranceBisections = 10; // then halved to 0.1 % of a step

// The stroke errors' standard deviations as an array in NoiseSource order.
std::array<double, kNoiseSources> deviations(const StrokeNoise& n) {
  return {n.aim_deg, n.speed_pct, n.tip_mm, n.tip_mm, n.elevation_deg};
}

// A standard normal number by Box-Muller from 53-bit uniforms (the same on every standard library).
double normal(std::mt19937_64& gen) {
  const double u1 = static_cast<double>(gen() >> 11) * 0x1.0p-53, u2 = static_cast<double>(gen() >> 11) * 0x1.0p-53;
  return std::sqrt(-2 * std::log1p(-u1)) * std::cos(2 * std::numbers::pi * u2);
}

// The scene's strike with errors (in NoiseSource units) added. Elevation stays within 0-90 degrees.
CueStrike stroke(const CueStrike& cue, const double* error, double radius) {
  CueStrike c = cue;
  c.aim += error[kAim] * kDeg;
  c.speed *= 1 + error[kSpeed] / 100;
  c.side += error[kSide] / 1000 / radius;
  c.height += error[kHeight] / 1000 / radius;
  c.elevation = std::clamp(c.elevation + error[kElevation] * kDeg, 0.0, 90 * kDeg);
  return c;
}

int ball_index(const Scene& scene, const std::string& id) {
  for (size_t i = 0; i < scene.balls.size(); ++i)
    if (scene.balls[i].spec.id == id) return static_cast<int>(i);
  return -1;
}

// The pocket a ball dropped into, empty when it did not.
std::string pocket_of(const Simulation& sim, const std::string& ball) {
  for (const Event& e : sim.events())
    if (e.kind == "pocketed" && e.bodies.size() == 2 && e.bodies[0] == ball) return e.bodies[1];
  return {};
}

struct Judge {
  const ShotGoal& goal;
  int ball;
  // true: success; checked on a finished run.
  bool success(const Simulation& sim) const {
    if (goal.kind == ShotGoal::Pocket) {
      const std::string pocket = pocket_of(sim, goal.ball);
      return !pocket.empty() && (goal.pocket.empty() || pocket == goal.pocket);
    }
    if (!sim.state().in_play[ball]) return false;
    const Vec3 p = position(sim.state().x, ball);
    return std::hypot(p.x - goal.x, p.z - goal.z) <= goal.radius;
  }
  // true once the outcome cannot change: a pocket goal's ball has dropped.
  bool decided(const Simulation& sim) const { return goal.kind == ShotGoal::Pocket && out_of_play(sim.motion(ball)); }
};

// One replay. to_rest: run until every ball rests (for end positions); else stop once the goal is decided.
MarginSample replay(const Scene& scene, const MarginOptions& o, const Judge& judge, const double* error, bool to_rest) {
  MarginSample s;
  std::copy(error, error + kNoiseSources, s.error);
  try {
    Scene shot = scene;
    const int cue = ball_index(scene, scene.cue->ball);
    shot.cue = stroke(*scene.cue, error, scene.balls[cue].spec.radius);
    HeadlessRun run = start_run(shot);
    RunLimits limits = o.limits;
    if (!to_rest) limits.enough = [&](const Simulation& sim) { return judge.decided(sim); };
    const std::string limit = advance_run(*run.sim, run_duration(scene, {}, true), kMarginSampleRate, true, {},
                                          limits);
    const Simulation& sim = *run.sim;
    s.status = !limit.empty() ? "limit" : sim.status() == Status::Ok ? "ok" : status_name(sim.status());
    s.reason = !limit.empty() ? limit : sim.diagnostic();
    s.success = s.status == "ok" && judge.success(sim);
    for (int i = 0; i < sim.state().ball_count(); ++i) {
      const Vec3 p = position(sim.state().x, i);
      s.end_x.push_back(p.x), s.end_z.push_back(p.z);
      s.pocketed.push_back(sim.motion(i) == Motion::Pocketed);
      s.left.push_back(out_of_play(sim.motion(i)));
    }
  } catch (const std::exception& e) {  // a stroke the scene refuses (a tip offset off the ball): a failed replay
    s.status = "error", s.reason = e.what();
  }
  return s;
}

// n replays with errors for each source whose `use` bit is set. Every ensemble draws the same numbers, so that a
// source alone replays exactly the errors it had in the full ensemble (common random numbers: differences between
// ensembles are the sources', not the draws').
std::vector<MarginSample> ensemble(const Scene& scene, const MarginOptions& o, const Judge& judge, unsigned use,
                                   bool to_rest, const std::function<void(size_t)>& tick,
                                   const std::atomic<bool>* cancel) {
  const std::array<double, kNoiseSources> sd = deviations(o.noise);
  std::mt19937_64 gen(o.seed);
  std::vector<std::array<double, kNoiseSources>> errors(o.samples);
  for (auto& e : errors)
    for (int k = 0; k < kNoiseSources; ++k) {
      const double z = normal(gen);  // drawn for every source, so that a source's draws do not depend on the others
      e[k] = (use >> k & 1) ? sd[k] * (k == kElevation && scene.cue->elevation == 0 ? std::abs(z) : z) : 0;
    }
  std::vector<MarginSample> out(o.samples);
  parallel_in_order(0, o.samples, o.jobs, [&](size_t i) { out[i] = replay(scene, o, judge, errors[i].data(), to_rest); },
                    [&](size_t) { if (tick) tick(1); }, {}, cancel);
  return out;
}

double success_rate(const std::vector<MarginSample>& samples) {
  size_t ok = 0;
  for (const MarginSample& s : samples) ok += s.success;
  return samples.empty() ? 0 : static_cast<double>(ok) / static_cast<double>(samples.size());
}

}  // namespace

StrokeNoise stroke_noise(const std::string& level) {
  // robot: the noise of the Computational Pool tournaments (FastFiz): 0.125 deg aim, 0.075 m/s speed (3.75 % of a
  // 2 m/s shot), 0.5 mm tip offset, 0.1 deg elevation. The human levels are multiples of it (docs/margin.md).
  const StrokeNoise robot{0.125, 3.75, 0.5, 0.1};
  const double scale = level == "robot" ? 1 : level == "pro" ? 2 : level == "amateur" ? 4 : level == "beginner" ? 8 : 0;
  if (scale == 0) throw InputError("--level " + describe(nlohmann::json(level)) + ": one of robot, pro, amateur, beginner");
  return {robot.aim_deg * scale, robot.speed_pct * scale, robot.tip_mm * scale, robot.elevation_deg * scale};
}

std::vector<std::string> stroke_levels() { return {"robot", "pro", "amateur", "beginner"}; }

const char* noise_source_name(int source) {
  static constexpr const char* names[] = {"aim_deg", "speed_pct", "side_mm", "height_mm", "elevation_deg"};
  return names[source];
}

ShotGoal parse_goal(const std::string& text) {
  const std::string where = "--goal " + describe(nlohmann::json(text));
  ShotGoal g;
  const size_t colon = text.find(':'), at = text.find('@');
  const std::string kind = text.substr(0, colon);
  if (colon == std::string::npos || (kind != "pocket" && kind != "zone"))
    throw InputError(where + ": expected pocket:BALL, pocket:BALL@POCKET or zone:BALL@X,Z,RADIUS");
  g.kind = kind == "pocket" ? ShotGoal::Pocket : ShotGoal::Zone;
  g.ball = text.substr(colon + 1, at == std::string::npos ? std::string::npos : at - colon - 1);
  if (g.ball.empty()) throw InputError(where + ": no ball named");
  const std::string rest = at == std::string::npos ? "" : text.substr(at + 1);
  if (g.kind == ShotGoal::Pocket) {
    g.pocket = rest;
    return g;
  }
  double v[3];
  size_t from = 0;
  for (int k = 0; k < 3; ++k) {
    const size_t comma = k < 2 ? rest.find(',', from) : rest.size();
    char* end = nullptr;
    const std::string field = comma == std::string::npos ? "" : rest.substr(from, comma - from);
    v[k] = std::strtod(field.c_str(), &end);
    if (field.empty() || *end || !std::isfinite(v[k]))
      throw InputError(where + ": a zone is BALL@X,Z,RADIUS with three numbers in m");
    from = comma + 1;
  }
  if (!(v[2] > 0)) throw InputError(where + ": the zone's radius must be above 0 m");
  g.x = v[0], g.z = v[1], g.radius = v[2];
  return g;
}

namespace {
// The goal's ball in `scene` (its index), its pocket checked against the table's: InputError naming what is missing.
int goal_ball(const Scene& scene, const ShotGoal& goal) {
  if (!scene.cue) throw InputError("the scene has no cue strike: a margin is that of a cue strike");
  const int ball = ball_index(scene, goal.ball);
  if (ball < 0) throw InputError("--goal: the scene has no ball " + describe(nlohmann::json(goal.ball)));
  if (goal.kind == ShotGoal::Pocket && !goal.pocket.empty()) {
    const std::vector<Pocket> pockets = prepare(scene).model.pockets;
    std::string names;
    for (const Pocket& p : pockets) {
      if (p.name == goal.pocket) return ball;
      names += (names.empty() ? "" : ", ") + p.name;
    }
    throw InputError("--goal: the table has no pocket " + describe(nlohmann::json(goal.pocket)) +
                     (names.empty() ? " (it has none)" : "; its pockets: " + names));
  }
  return ball;
}
}  // namespace

namespace {
// One side (dir -1: lo, +1: hi) of source k's Tolerance of a stroke that succeeds: out in half deviations until a
// replay fails, then bisected to `resolution` (0: 0.1 % of a step); `tick` once a replay.
void edge_search(const Scene& scene, const MarginOptions& o, const Judge& judge, int k, int dir,
                 const std::function<void()>& tick, Tolerance& out, double resolution = 0) {
  const double sd = deviations(o.noise)[k], step = dir * 0.5 * (sd > 0 ? sd : kToleranceScale[k]);
  auto fails = [&](double x) {
    double e[kNoiseSources] = {};
    e[k] = x;
    if (tick) tick();
    return !replay(scene, o, judge, e, false).success;
  };
  double good = 0, bad = 0;
  bool found = false, level = false;  // level: the window reaches a level cue, where it ends
  const double floor = k == kElevation ? -scene.cue->elevation / kDeg : -1e300;  // no cue below level
  for (int n = 1; n <= kToleranceSteps && !found && !level; ++n) {
    const double x = std::max(floor, n * step);
    if (fails(x)) bad = x, found = true;
    else good = x, level = x == floor;
  }
  // Halvings to `resolution`, at most 60 (past a double's precision on any step).
  const int halvings = resolution > 0 ? 60 : kToleranceBisections;
  for (int n = 0; found && n < halvings && (resolution <= 0 || std::abs(bad - good) > resolution); ++n) {
    const double mid = 0.5 * (good + bad);
    (fails(mid) ? bad : good) = mid;
  }
  (dir < 0 ? out.lo : out.hi) = good + 0.0;  // + 0.0: a level cue's floor, -0, is 0
  (dir < 0 ? out.bounded_lo : out.bounded_hi) = found || level;
}
}  // namespace

MarginResult shot_margin(const Scene& scene, const MarginOptions& o, const std::function<void(size_t, size_t)>& progress,
                         const std::atomic<bool>* cancel) {
  const int ball = goal_ball(scene, o.goal);
  const Judge judge{o.goal, ball};
  MarginResult r;
  for (const InitialBall& b : scene.balls) r.ball_ids.push_back(b.spec.id);
  const size_t total = o.samples * (o.sensitivity ? 1 + kNoiseSources : 1) + 1 +
                       (o.sensitivity ? 2 * kNoiseSources * (kToleranceSteps + kToleranceBisections) : 0);
  size_t done = 0;
  std::mutex progress_mutex;  // runs finish on several threads
  auto tick = [&](size_t n) {
    std::lock_guard lock(progress_mutex);
    done = std::min(total, done + n);
    if (progress) progress(done, total);
  };
  const double zero[kNoiseSources] = {};
  r.nominal_success = replay(scene, o, judge, zero, false).success;
  tick(1);
  r.samples = ensemble(scene, o, judge, (1u << kNoiseSources) - 1, true, tick, cancel);
  r.probability = success_rate(r.samples);
  r.standard_error = std::sqrt(r.probability * (1 - r.probability) / std::max<size_t>(1, o.samples));
  if (o.sensitivity) {
    for (int k = 0; k < kNoiseSources && !(cancel && *cancel); ++k)
      r.alone[k] = success_rate(ensemble(scene, o, judge, 1u << k, false, tick, cancel));
    // The ten one-sided searches side by side on the pool.
    parallel_in_order(0, 2 * kNoiseSources, o.jobs, [&](size_t i) {
      const int k = static_cast<int>(i / 2), dir = i % 2 ? 1 : -1;
      if (r.nominal_success) edge_search(scene, o, judge, k, dir, [&] { tick(1); }, r.tolerance[k]);
    }, {}, {}, cancel);
  }
  r.cancelled = cancel && *cancel;
  if (progress && !r.cancelled) progress(total, total);  // the searches may end before their most steps
  return r;
}

Tolerance stroke_tolerance(const Scene& scene, const MarginOptions& o, int source, double resolution) {
  if (source < 0 || source >= kNoiseSources)
    throw InputError("stroke_tolerance: no noise source " + std::to_string(source));
  const int ball = goal_ball(scene, o.goal);
  const Judge judge{o.goal, ball};
  const double zero[kNoiseSources] = {};
  Tolerance t;
  if (!replay(scene, o, judge, zero, false).success) return t;
  parallel_in_order(0, 2, o.jobs, [&](size_t side) {  // each side writes its own fields of t
    edge_search(scene, o, judge, source, side ? 1 : -1, {}, t, resolution);
  });
  return t;
}

MarginMap margin_map(const Scene& scene, const MarginOptions& o, int aims, int speeds, double aim_half_range_deg,
                     double speed_half_range_pct, const std::function<void(size_t, size_t)>& progress,
                     const std::atomic<bool>* cancel) {
  const int ball = goal_ball(scene, o.goal);
  if (aims < 1 || speeds < 1 || o.samples < 1) throw InputError("--map: at least one cell and one sample per cell");
  const Judge judge{o.goal, ball};
  MarginMap m;
  m.aims = aims, m.speeds = speeds;
  const double aim0 = scene.cue->aim / kDeg, speed0 = scene.cue->speed;
  m.aim_lo_deg = aim0 - aim_half_range_deg, m.aim_hi_deg = aim0 + aim_half_range_deg;
  m.speed_lo = speed0 * (1 - speed_half_range_pct / 100), m.speed_hi = speed0 * (1 + speed_half_range_pct / 100);
  auto centre = [](double lo, double hi, int n, int i) { return n == 1 ? 0.5 * (lo + hi) : lo + (hi - lo) * i / (n - 1); };
  const size_t cells = static_cast<size_t>(aims) * static_cast<size_t>(speeds), runs = cells * o.samples;
  std::vector<char> success(runs, 0);
  const std::array<double, kNoiseSources> sd = deviations(o.noise);
  parallel_in_order(0, runs, o.jobs, [&](size_t r) {
    const size_t cell = r / o.samples;
    std::mt19937_64 gen(o.seed * 0x9E3779B97F4A7C15ull + r);  // each run its own stream: any order, same draws
    double e[kNoiseSources];
    for (int k = 0; k < kNoiseSources; ++k) {
      const double z = normal(gen);
      e[k] = sd[k] * (k == kElevation && scene.cue->elevation == 0 ? std::abs(z) : z);
    }
    e[kAim] += centre(m.aim_lo_deg, m.aim_hi_deg, aims, static_cast<int>(cell % aims)) - aim0;
    const double speed = centre(m.speed_lo, m.speed_hi, speeds, static_cast<int>(cell / aims));
    e[kSpeed] = ((1 + e[kSpeed] / 100) * speed / speed0 - 1) * 100;
    success[r] = replay(scene, o, judge, e, false).success;
  }, {}, progress, cancel);
  m.cells.assign(cells, 0);
  for (size_t r = 0; r < runs; ++r) m.cells[r / o.samples] += success[r];
  for (double& c : m.cells) c /= static_cast<double>(o.samples);
  m.cancelled = cancel && *cancel;
  return m;
}

}  // namespace shotlab
