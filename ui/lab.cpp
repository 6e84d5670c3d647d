#include "ui/lab.hpp"

#include <algorithm>
#include <cmath>

#include "engine/io/scene_json.hpp"
#include "engine/rack.hpp"

namespace shotlab {

namespace {
constexpr double kTrailSpacing = 0.002;  // m between trail points: long shots stay cheap to draw
}  // namespace

int scene_ball(const Scene& s, const std::string& id) {
  for (size_t i = 0; i < s.balls.size(); ++i)
    if (s.balls[i].spec.id == id) return static_cast<int>(i);
  return -1;
}

bool Lab::load(const std::string& path) {
  try {
    Scene s = load_scene(path);
    validate(s);
    set_scene(std::move(s));
    scene_path = path;
    settings.last_scene = path;
    history.clear();
    ghost.clear();
    note = "loaded " + path;
    if (on_load) on_load(scene);
    return true;
  } catch (const std::exception& e) {
    error = e.what();
    return false;
  }
}

void Lab::set_scene(Scene s) {
  scene = std::move(s);
  shot.reset();
  view_time = 0;
  playing = false;
  selected = 0;
  if (scene.cue) selected = std::max(0, scene_ball(scene, scene.cue->ball));
  scene_changed();
}

void Lab::scene_changed() {
  if (selected >= static_cast<int>(scene.balls.size())) selected = 0;
  Scene still = scene;
  still.cue.reset();
  Prepared p = prepare(still);
  table_model = p.model;
  if (!shot) {
    frame_ = Frame{0, p.state, std::vector<glm::dquat>(scene.balls.size(), glm::dquat(1, 0, 0, 0)), {}, 0};
    const ContactCache cache(p.model);
    for (int i = 0; i < p.state.ball_count(); ++i) frame_.motion.push_back(classify(p.model, cache, p.state, p.state.x.data(), i));
  }
  wanted_ = predictor_.request(scene);
}

void Lab::physics_changed() {
  scene_changed();
  if (!shot) return;
  Scene start = shot->start();
  start.model = scene.model;
  const bool was_playing = playing;
  start_shot(start);
  playing = was_playing || shot != nullptr;
}

void Lab::start_shot(const Scene& start) {
  try {
    shot = std::make_unique<Shot>(start);
  } catch (const std::exception& e) {
    shot.reset();
    error = std::string("cannot simulate this scene: ") + e.what();
  }
  view_time = 0;
  achieved_speed = 1;
  if (shot) show(0);
  else scene_changed();
}

void Lab::shoot() {
  if (shot) ghost = trails(shot->sim().time());
  history.push_back(scene);
  start_shot(scene);
  playing = shot != nullptr;
}

void Lab::replay() {
  if (!shot) return;
  start_shot(shot->start());
  playing = shot != nullptr;
}

void Lab::undo() {
  if (history.empty()) return;
  Scene previous = std::move(history.back());
  history.pop_back();
  previous.model = scene.model;  // undo restores position and aim; tuned physics stays
  if (shot) ghost = trails(shot->sim().time());
  scene = std::move(previous);
  shot.reset();
  playing = false;
  view_time = 0;
  error.clear();
  scene_changed();
}

void Lab::continue_from_rest() {
  if (!shot) return;
  const State& s = shot->sim().state();
  Scene next = scene;
  next.balls = shot->start().balls;
  // Pocketed balls leave the table, except in scenes with rods (their ball indices must stay).
  std::vector<InitialBall> kept;
  for (int i = 0; i < s.ball_count(); ++i) {
    InitialBall b = next.balls[i];
    b.position = position(s.x, i);
    b.position.y = std::max(b.position.y, b.spec.radius);  // back on the bed, off its static sink
    b.velocity = b.angular_velocity = Vec3{0.0};
    if (s.in_play[i] || !next.model.rods.empty()) kept.push_back(b);
  }
  next.balls = std::move(kept);
  if (next.cue && scene_ball(next, next.cue->ball) < 0) next.cue.reset();  // the cue ball was pocketed
  ghost = trails(shot->sim().time());
  scene = std::move(next);
  shot.reset();
  playing = false;
  view_time = 0;
  scene_changed();
}

void Lab::show(double t) {
  view_time = t;
  if (shot) frame_ = shot->frame_at(t);
}

void Lab::step() {
  if (!shot) return;
  playing = false;
  const double target = view_time + settings.slowmo / 60.0;
  show(std::min(target, shot->advance(target, 1.0)));
}

void Lab::seek(double t) {
  if (!shot) return;
  playing = false;
  show(std::min(t, shot->advance(t, 10.0)));
}

void Lab::update(double real_dt) {
  if (!shot) return;
  if (!playing) {
    show(std::min(view_time, shot->sim().time()));  // scrubbing moves view_time within what is recorded
    return;
  }
  const double wanted = real_dt * settings.slowmo;
  const double target = view_time + wanted;
  // Physics wall time this frame: the configured budget, or more when frames are slow anyway (software rendering),
  // but never above 50 ms, so that the window keeps answering.
  const double budget = std::clamp(0.6 * real_dt, settings.budget_ms * 1e-3, std::max(0.05, settings.budget_ms * 1e-3));
  const double reached = target <= shot->sim().time() ? target : shot->advance(target, budget);
  const double got = std::min(target, reached) - view_time;
  if (wanted > 0 && !shot->finished()) achieved_speed = 0.9 * achieved_speed + 0.1 * std::clamp(got / wanted, 0.0, 1.0);
  show(std::min(target, reached));
  if (shot->finished() && view_time >= shot->sim().time()) {
    playing = false;
    achieved_speed = 1;
    const std::string undo_hint = "  Undo (U) returns to the position before the shot.";
    if (shot->sim().status() != Status::Ok)
      error = std::string("the simulation stopped (") + status_name(shot->sim().status()) + "): " +
              shot->sim().diagnostic() + undo_hint;
  }
}

Trails Lab::trails(double until) const {
  Trails out;
  if (!shot) return out;
  const auto& frames = shot->frames();
  out.resize(frames.front().state.ball_count());
  for (const Frame& f : frames) {
    if (f.time > until) break;
    for (size_t i = 0; i < out.size(); ++i) {
      if (!f.state.in_play[i] && !out[i].empty() && out[i].back().motion == Motion::Pocketed) continue;
      const PathPoint p{position(f.state.x, i), f.state.in_play[i] ? f.motion[i] : Motion::Pocketed};
      if (out[i].empty() || glm::length(p.position - out[i].back().position) > kTrailSpacing || p.motion != out[i].back().motion)
        out[i].push_back(p);
    }
  }
  return out;
}

std::optional<Prediction> Lab::prediction() const {
  auto p = predictor_.latest();
  if (!p || p->generation != wanted_) return std::nullopt;
  return p;
}

void Lab::aim_at(const Vec3& point) {
  if (!scene.cue || shot) return;
  const int cue = scene_ball(scene, scene.cue->ball);
  if (cue < 0) return;
  const Vec3 d = point - scene.balls[cue].position;
  if (std::hypot(d.x, d.z) < 1e-4) return;
  scene.cue->aim = std::atan2(-d.z, d.x);  // CueStrike: 0 = +x, pi/2 = -z
  scene_changed();
}

bool Lab::fits(int i, const Vec3& p) const {
  if (scene.allow_overlap) return true;
  for (int j = 0; j < static_cast<int>(scene.balls.size()); ++j)
    if (j != i && glm::length(scene.balls[j].position - p) < scene.balls[j].spec.radius + scene.balls[i].spec.radius)
      return false;
  return true;
}

bool Lab::move_ball(int i, const Vec3& to) {
  if (shot || i < 0 || i >= static_cast<int>(scene.balls.size())) return false;
  const Vec3 p{to.x, scene.balls[i].position.y, to.z};
  if (!fits(i, p)) return false;
  scene.balls[i].position = p;
  scene_changed();
  return true;
}

void Lab::add_ball(const Vec3& at) {
  if (shot) return;
  InitialBall b;
  b.spec = scene.balls.empty() ? BallSpec{"", kPoolBall.mass, kPoolBall.radius} : scene.balls.back().spec;
  for (int n = 1;; ++n)  // the smallest free number
    if (scene_ball(scene, std::to_string(n)) < 0) {
      b.spec.id = std::to_string(n);
      break;
    }
  b.position = {at.x, b.spec.radius, at.z};
  scene.balls.push_back(b);
  if (!fits(static_cast<int>(scene.balls.size()) - 1, b.position)) {
    scene.balls.pop_back();
    note = "no room for a ball there";
    return;
  }
  selected = static_cast<int>(scene.balls.size()) - 1;
  scene_changed();
}

void Lab::remove_ball(int i) {
  if (shot || i < 0 || i >= static_cast<int>(scene.balls.size())) return;
  if (!scene.model.rods.empty()) {
    note = "this scene's rods hold its balls: they cannot be removed";
    return;
  }
  if (scene.cue && scene.cue->ball == scene.balls[i].spec.id) scene.cue.reset();
  scene.balls.erase(scene.balls.begin() + i);
  scene_changed();
}

void Lab::rack() {
  if (shot) return;
  std::vector<InitialBall> balls;
  for (const InitialBall& b : scene.balls)
    if (scene.cue && b.spec.id == scene.cue->ball) balls.push_back(b);
  const BallKind& kind = balls.empty() ? kPoolBall : BallKind{"", balls[0].spec.mass, balls[0].spec.radius};
  for (InitialBall& b : triangle_rack(RackSpec{}, kind)) balls.push_back(b);
  scene.balls = std::move(balls);
  scene_changed();
}

}  // namespace shotlab
