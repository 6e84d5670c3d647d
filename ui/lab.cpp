#include "ui/lab.hpp"

#include <algorithm>
#include <limits>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <numbers>
#include <stdexcept>

#include "shotlab/io/scene_json.hpp"

namespace shotlab {

namespace {
constexpr double kTrailSpacing = 0.002;  // m between trail points: long shots stay cheap to draw
constexpr double kDisplayFrame = 1.0 / 60;  // s of real time a single step shows

std::string fixed(double v, int decimals) {
  char text[64];
  std::snprintf(text, sizeof text, "%.*f", decimals, v);
  return text;
}

// The model's tunable part as the scene format spells it (materials, model options, integrator, gravity).
nlohmann::json physics_json(const Scene& s) {
  const nlohmann::json doc = scene_to_json(s);
  nlohmann::json out;
  for (const char* key : {"materials", "model", "integrator", "gravity"}) out[key] = doc[key];
  return out;
}
}  // namespace

int scene_ball(const Scene& s, const std::string& id) {
  for (size_t i = 0; i < s.balls.size(); ++i)
    if (s.balls[i].spec.id == id) return static_cast<int>(i);
  return -1;
}

void Lab::say(MessageKind kind, std::string text) {
  message_kind = kind;
  message = std::move(text);
  message_since = std::chrono::steady_clock::now();
}

// A scene from a file (or made from a measured shot) becomes the lab's: a fresh start without trails or target, and
// one undo entry that brings back the scene, file and tuned physics it replaced; a measured shot's fit is dropped.
void Lab::adopt(Scene s, const std::string& path, const std::string& what) {
  validate(s);
  if (!scene.balls.empty() || !scene_path.empty())
    history.record_load("open " + std::filesystem::path(path).filename().string(), scene, current_file());
  loaded = s;
  set_scene(std::move(s));
  removed_cue_.reset();
  ghost.clear();
  restore({});
  std::string note = "loaded ";
  note.append(what).append(path);
  if (history.can_undo()) note += " (Undo brings back the scene before)";
  say(MessageKind::Note, std::move(note));
  if (on_load) on_load(scene);
}

bool Lab::load(const std::string& given) {
  // Kept absolute: Save and the dialogs, which take typed names inside the scene's folder, do not depend on the
  // working folder.
  std::error_code ec;
  const std::filesystem::path abs = std::filesystem::absolute(given, ec);
  const std::string path = ec ? given : abs.lexically_normal().string();
  if (std::filesystem::path(path).extension() == ".csv") return load_measured(path);
  try {
    adopt(load_scene(path), path, "");
    scene_path = path;
    remember_file(settings, path);
    return true;
  } catch (const std::exception& e) {
    say(MessageKind::LoadError, e.what());
    scene_kept = true;
    return false;
  }
}

bool Lab::load_measured(const std::string& path) {
  try {
    MeasuredShot m = read_measured(path);
    const bool carom = scene.table && scene.table->kind == TableKind::Carom;
    const Scene base = carom ? scene : load_scene(data_root + "/presets/three_cushion.json");
    Scene s = measured_scene(base, m, initial_cue(base, m));
    s.name = m.name + " (measured)";
    s.description = "A measured shot: its tracked balls are drawn as dots; fit its strike in Tuning > Measured shot.";
    adopt(std::move(s), path, "the measured shot ");
    scene_path.clear();
    measured.shot = std::move(m), measured.path = path;
    return true;
  } catch (const std::exception& e) {
    say(MessageKind::LoadError, e.what());
    scene_kept = true;
    return false;
  }
}

void Lab::start_fit() {
  if (!measured.shot) return;
  FitSettings fs;
  for (int k = 0; k < kLabFitValues; ++k)
    if (measured.fit_value[k]) fs.paths.push_back(kLabFitPaths[k][0]);
  Scene base = scene;
  base.cue.reset();
  measured.fit.start([base, shot = *measured.shot, fs](const auto& progress, const std::atomic<bool>& cancel) mutable {
    fs.progress = progress, fs.cancel = &cancel;
    return fit_measured(base, {shot}, fs);
  });
}

void Lab::apply_fit() {
  if (!measured.shot || measured.fit.finished() == measured.applied || shot) return;  // a shot shown: later
  measured.applied = measured.fit.finished();
  const auto r = measured.fit.result();
  if (!r || r->shots.empty() || !scene.cue) return;
  const Scene fitted = fitted_scene(scene, *r);
  scene.model.materials = fitted.model.materials;
  physics_changed();
  const CueFit& c = r->shots[0].cue;
  CueStrike cue = *scene.cue;
  cue.speed = c.speed, cue.aim = c.aim_deg * std::numbers::pi / 180, cue.side = c.side, cue.height = c.height;
  cue.elevation = c.elevation_deg * std::numbers::pi / 180;
  set_cue(cue, "fitted strike");
  measured.last = r;
  say(MessageKind::Note, "the fitted strike is set: shoot to compare with the measured dots");
}

void Lab::set_scene(Scene s) {
  scene = std::move(s);
  shot.reset();
  view_time = 0;
  playing = false;
  in_hand = false;
  tool = Tool::Aim;
  selected = scene.cue ? std::max(0, scene_ball(scene, scene.cue->ball)) : 0;
  scene_changed();
}

void Lab::scene_changed() {
  if (selected >= static_cast<int>(scene.balls.size())) selected = 0;
  Scene still = scene;
  still.cue.reset();
  if (scene.model.options.contact == ContactModel::Rigid) {
    // A scene the rigid model refuses (rods, gravity not straight down) goes back to the soft model, saying why.
    still.model.options.contact = ContactModel::Rigid;
    try {
      prepare(still);
    } catch (const std::invalid_argument& e) {
      scene.model.options.contact = still.model.options.contact = ContactModel::Soft;
      say(MessageKind::Refused, std::string(e.what()) + "; back to the soft model");
    }
  }
  Prepared p = prepare(still);
  table_model = p.model;
  if (!shot) {
    const Simulation at_start(p.model, p.state);
    const int n = p.state.ball_count();
    frame_ = Frame{0, p.state, std::vector<glm::dquat>(n, glm::dquat(1, 0, 0, 0)), {}, at_start.energy()};
    for (int i = 0; i < n; ++i) frame_.motion.push_back(at_start.motion(i));
  }
  // The aims an aim key press away, the last key's direction first: predicted while the window idles, so that the
  // press finds its paths finished.
  std::vector<Scene> next;
  if (scene.cue)
    for (const double deg : {last_turn_deg_, -last_turn_deg_}) {
      next.push_back(scene);
      next.back().cue = turned(*scene.cue, deg);
    }
  wanted_ = predictor_.request(scene, settings.safety_limit, std::move(next));
}

void Lab::physics_changed() {
  if (compare.empty() && settings.view.compare && take_compare())
    // A prediction still being worked out at the first change is not pinned: a later change pins the one before it.
    compare_label = shot ? "A: the shot before the first change" : "A: the prediction before the change that pinned it";
  scene_changed();
  if (!shot) return;
  // The new run is shown at the moment the old one was, playing or paused as it was: a change made while stepping
  // through a contact stays at that contact. A shot watched to its end shows the new run's end.
  const bool was_playing = playing, was_over = shot_over();
  const double at = was_over ? std::numeric_limits<double>::infinity() : view_time;
  Scene start = shot->start();
  start.model = scene.model;
  start_shot(start);
  playing = false;
  if (!shot) return;
  // Within a frame's work at most (a drag changes the value every frame): a long shot shows how far its new run got.
  if (at > shot->sim().time()) shot->advance(at, kRetuneSeconds);
  show(std::min(at, shot->sim().time()));
  playing = was_playing;
  if (shot_over()) finish_playing();  // the new run stopped before that moment: its banner
}

std::vector<std::string> Lab::physics_changes() const {
  const nlohmann::json a = physics_json(loaded), b = physics_json(scene);
  std::vector<std::string> out;
  for (const auto& op : nlohmann::json::diff(a, b)) {
    const std::string path = op["path"].get<std::string>();
    const nlohmann::json::json_pointer ptr(path);
    std::string name = path.substr(1);
    std::replace(name.begin(), name.end(), '/', '.');
    auto text = [](const nlohmann::json& v) {  // numbers as a reader writes them: 5e+08, 0.06
      if (!v.is_number_float()) return v.dump();
      char t[32];
      std::snprintf(t, sizeof t, "%g", v.get<double>());
      return std::string(t);
    };
    const std::string before = a.contains(ptr) ? text(a[ptr]) : "-";
    const std::string after = op.contains("value") ? text(op["value"]) : "-";
    out.push_back(name + ": " + before + " -> " + after);
  }
  return out;
}

void Lab::reset_physics() {
  scene.model.materials = loaded.model.materials;
  scene.model.options = loaded.model.options;
  scene.model.integrator = loaded.model.integrator;
  compare.clear(), compare_label.clear(), compare_frames.clear();
  const bool had_compare = settings.view.compare;
  settings.view.compare = false;  // the reset shot is the A itself: nothing to compare with
  physics_changed();
  settings.view.compare = had_compare;
  say(MessageKind::Note, "physics reset to the scene file's values");
}

bool Lab::take_compare() {
  if (shot) {
    compare = trails(shot->sim().time());
    compare_frames = shot->frames();
    return true;
  }
  const std::optional<Prediction> p = prediction();
  if (!p) return false;
  compare = p->paths;
  compare_frames.clear();  // a prediction keeps paths only: the plots have no A line
  return true;
}

void Lab::pin_compare() {
  if (!take_compare()) return;
  const auto changes = physics_changes();
  // Short: the line is cut at the panel's edge in presentation mode ("A: as loaded, predicte").
  const std::string what = shot ? "A: " : "A, predicted: ";
  compare_label = what + (changes.empty() ? "as loaded" : std::to_string(changes.size()) + " changes");
}

void Lab::start_shot(const Scene& start) {
  try {
    shot = std::make_unique<Shot>(start, settings.safety_limit);
  } catch (const std::exception& e) {
    shot.reset();
    say(MessageKind::Refused, std::string("cannot simulate this scene: ") + e.what());
  }
  ++shot_id_;
  view_time = 0;
  exact_time_ = -1;
  events_seen_ = 0;
  achieved_speed = 1;
  if (shot) show(0);
  else scene_changed();
}

void Lab::shoot() {
  if (in_hand) in_hand = false, history.seal();  // shooting puts the ball in hand down where it is
  if (message_kind != MessageKind::LoadError) say(MessageKind::None, "");
  launch();
  if (shot) history.record("shot", scene);  // a refused shot (its banner says why) is no step to undo
}

void Lab::launch() {
  if (shot) ghost = trails(shot->sim().time());
  start_shot(scene);
  playing = shot != nullptr;
}

void Lab::replay() {
  if (!shot) return say(MessageKind::Note, "no shot to replay yet: S or Space shoots");
  start_shot(shot->start());
  playing = shot != nullptr;
}

void Lab::undo() {
  if (in_hand) {  // putting the ball back where it was picked up
    in_hand = false;
    if (history.can_undo()) {
      take_step(history.undo(scene, [this] { return current_file(); }, target));
      history.drop_redo();  // a cancelled pick-up: Redo would only put the ball where the pointer left it
    }
    say(MessageKind::Note, "the cue ball is back where it was picked up");  // not "click to put it down" any more
    scene_changed();
    return;
  }
  if (!history.can_undo()) return say(MessageKind::Note, "nothing to undo");
  const std::string what = history.undo_label();
  HistoryStep previous = history.undo(scene, [this] { return current_file(); }, target);
  if (previous.target || previous.kept) {  // only the practice target or the kept shots change: the shot stays
    std::vector<KeptShot> since = previous.kept ? kept : std::vector<KeptShot>{};  // kept after the clear (K is no step)
    take_step(std::move(previous));
    for (KeptShot& k : since) kept.push_back(std::move(k));
    if (kept.size() > kMaxKeptShots) kept.erase(kept.begin(), kept.end() - kMaxKeptShots);
    return say(MessageKind::Note, "undone: " + what);
  }
  if (shot && !previous.file) ghost = trails(shot->sim().time());
  take_step(std::move(previous));
  if (what == kNextLabel) return back_before_next();
  shot.reset();
  playing = false;
  view_time = 0;
  if (message_kind == MessageKind::EngineStop || message_kind == MessageKind::Refused) say(MessageKind::None, "");
  say(MessageKind::Note, "undone: " + what);
  scene_changed();
}

// Undo and redo restore positions and aim; tuned physics stays (Reset in Tuning) unless the step crosses a file load.
void Lab::take_step(HistoryStep step) {
  if (step.target) target = *step.target;
  if (step.kept) kept = std::move(*step.kept);
  if (step.target || step.kept) return;  // the workbench alone: the scene stays as it is now
  if (step.file) {
    scene_path = std::move(step.file->path);
    loaded = std::move(step.file->loaded);
    if (!scene_path.empty()) remember_file(settings, scene_path);  // the next start opens the scene shown
    ghost.clear();
    restore(std::move(step.file->bench));
    if (step.same_table) {
      step.scene.model = scene.model;
      scene = std::move(step.scene);
      return;
    }
    scene = std::move(step.scene);
    if (on_load) on_load(scene);  // the camera frames the table it goes back to
    return;
  }
  step.scene.model = scene.model;
  scene = std::move(step.scene);
}

SceneFile Lab::current_file() const {
  return {scene_path, loaded,
          {kept, compare, compare_label, target, measured.shot, measured.path, measured.last, compare_frames}};
}

void Lab::restore(Workbench bench) {
  kept = std::move(bench.kept);
  compare = std::move(bench.compare), compare_label = std::move(bench.compare_label);
  compare_frames = std::move(bench.compare_frames);
  target = bench.target;
  measured.fit.cancel();  // a fit of the scene being left is not applied to the one coming back
  measured.shot = std::move(bench.measured), measured.path = std::move(bench.measured_path);
  measured.last = std::move(bench.measured_fit);
  measured.applied = measured.fit.finished();
}

void Lab::redo() {
  if (!history.can_redo()) return say(MessageKind::Note, "nothing to redo");
  const std::string what = history.redo_label();
  HistoryStep next = history.redo(scene, [this] { return current_file(); }, target);
  const bool target_only = next.target || next.kept;
  take_step(std::move(next));
  say(MessageKind::Note, "redone: " + what);
  if (target_only) return;  // the shot on screen stays
  if (what == "shot") return launch();  // the shot runs again; the redo entries after it stay
  if (shot && what == kNextLabel) ghost = trails(shot->sim().time());
  shot.reset();
  playing = false;
  view_time = 0;
  scene_changed();
}

void Lab::continue_from_rest() {
  if (!shot) return;
  if (shot->end() != ShotEnd::Rest)
    return say(MessageKind::Refused, "Next starts from where the balls stopped: wait until they rest (or Undo).");
  const State& s = shot->sim().state();
  Scene next = scene;
  next.balls = shot->start().balls;
  // Pocketed balls leave the table, except in scenes with rods (their ball indices must stay).
  std::vector<InitialBall> kept_balls;
  for (int i = 0; i < s.ball_count(); ++i) {
    InitialBall b = next.balls[i];
    b.position = position(s.x, i);
    b.position.y = std::max(b.position.y, b.spec.radius);  // back on the bed, off its static sink
    b.velocity = b.angular_velocity = Vec3{0.0};
    if (s.in_play[i] || !next.model.rods.empty()) kept_balls.push_back(b);
  }
  next.balls = std::move(kept_balls);
  if (next.cue && scene_ball(next, next.cue->ball) < 0) next.cue.reset();  // the cue ball was pocketed
  ghost = trails(shot->sim().time());
  history.seal();
  history.record(kNextLabel, scene);  // undo shows this shot at its end again
  scene = std::move(next);
  shot.reset();
  playing = false;
  view_time = 0;
  scene_changed();
}

// Undoing Next: the shot that ended in the position Next started from is run again (with the physics as tuned now)
// and shown at its end, paused, as it was when Next was pressed (the trial's undo went straight back to aiming it).
// Next needs a shot at rest, but it may have been run on past the safety limit: so is the rerun, a few times at most.
void Lab::back_before_next() {
  scene_changed();  // the predicted paths are the shot's again, not the position after it
  start_shot(scene);
  playing = false;
  for (int k = 0; shot && k < 8; ++k) {
    seek(shot->safety_limit());
    if (shot->end() != ShotEnd::SafetyLimit) break;
    shot->extend_limit(settings.safety_limit);
  }
  say(MessageKind::Note, shot && shot->end() == ShotEnd::Rest ? "undone: Next (the shot is shown at its end again)"
                                                               : "undone: Next (the shot, as far as it ran again)");
}

void Lab::show(double t) {
  view_time = t;
  if (!shot) return;
  if (playing || t >= shot->sim().time()) {
    frame_ = shot->frame_at(t);
    exact_time_ = -1;
  } else if (t != exact_time_) {
    frame_ = shot->exact_frame(t);  // paused between recorded frames: the exact state (a collision shows)
    exact_time_ = t;
  }
}

// A display frame at the clock's speed. With the clock slowed (a teacher's sign that the detail matters) a collision
// shorter than eight such steps is not stepped over: a step towards one stops at its edge, and a step inside it is an
// eighth of it (a 0.35 ms collision at 1/8 of real time would otherwise pass within one 2 ms step); at real time and
// faster the steps stay frames (a break's hundred collisions would take as many presses). The shot is run eight
// frames past the step first, so that a collision short enough to matter that begins within it is known whole.
void Lab::step(int direction) {
  if (!shot) return;
  playing = false;
  const double frame = settings.slowmo * kDisplayFrame, from = view_time;
  double target = std::max(0.0, from + direction * frame);
  const bool detail = settings.slowmo < 1;
  const double ahead = detail ? target + 8 * frame : target;
  if (direction > 0 && ahead > shot->sim().time()) shot->advance(ahead, 1.0);
  if (!detail) return show(std::min(target, shot->sim().time()));
  for (const ContactTrace& c : contact_spans(shot->sim().events(), shot->sim().model())) {
    const double begin = c.begin, end = c.end < 0 ? std::numeric_limits<double>::infinity() : c.end;
    const double fine = (end - begin) / 8;
    if (!(fine < frame)) continue;
    if (direction > 0 && begin > from && begin < target)
      target = begin;
    else if (direction > 0 && begin <= from && end > from)
      target = std::min(target, end - from < 1.5 * fine ? end : from + fine);  // no sliver of a ninth step
    else if (direction < 0 && begin < from && end > target)
      target = std::max(target, end < from ? end : (from - begin < 1.5 * fine ? begin : from - fine));
  }
  show(std::min(target, shot->sim().time()));
}

void Lab::seek(double t) {
  if (!shot) return;
  playing = false;
  if (t > shot->sim().time()) shot->advance(t, 10.0);
  show(std::clamp(t, 0.0, shot->sim().time()));
}

void Lab::run_on() {
  if (!shot || shot->end() != ShotEnd::SafetyLimit) return;
  shot->extend_limit(settings.safety_limit);
  say(MessageKind::None, "");
  playing = true;
}

void Lab::update(double real_dt) {
  const std::chrono::duration<double> age = std::chrono::steady_clock::now() - message_since;
  if (message_kind == MessageKind::Note && age.count() > kNoteSeconds) say(MessageKind::None, "");
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
  const double from = view_time;
  show(std::min(target, reached));
  pause_on_events(from, view_time);
  if (playing && shot_over()) finish_playing();
}

// Pauses at the first event in (from, to] of a kind the user asked to stop at.
void Lab::pause_on_events(double from, double to) {
  const std::vector<Event>& events = shot->sim().events();
  const PauseOn& p = settings.pause_on;
  for (; events_seen_ < events.size() && events[events_seen_].time <= to; ++events_seen_) {
    const Event& e = events[events_seen_];
    if (e.time <= from) continue;
    const bool begin = e.kind == "contact_begin" && e.bodies.size() == 2;
    const bool ball_ball = begin && scene_ball(shot->start(), e.bodies[1]) >= 0;
    const bool cushion = begin && (e.bodies[1].rfind("cushion", 0) == 0 || e.bodies[1].rfind("jaw", 0) == 0);
    const char* kind = p.ball_ball && ball_ball ? "a ball-ball contact"
                       : p.cushion && cushion    ? "a cushion contact"
                       : p.pocketed && e.kind == "pocketed" ? "a pocketed ball"
                                                            : nullptr;
    if (kind) {
      ++events_seen_;
      playing = false;
      show(e.time);
      std::string who = e.bodies.empty() ? "" : e.bodies[0] + (e.bodies.size() > 1 ? " - " + e.bodies[1] : "");
      say(MessageKind::Note, std::string("paused at ") + kind + " (" + who + "), t = " + fixed(e.time, 6) +
                                 " s: Pause on events, in the Tuning tab");
      return;
    }
  }
}

void Lab::finish_playing() {
  playing = false;
  achieved_speed = 1;
  switch (shot->end()) {
    case ShotEnd::EngineStop:
      say(MessageKind::EngineStop, std::string("the simulation stopped (") + status_name(shot->sim().status()) +
                                       "): " + shot->sim().diagnostic());
      break;
    case ShotEnd::SafetyLimit:
      say(MessageKind::Note, "balls still moving after " + fixed(shot->safety_limit(), 0) +
                                 " s, the safety limit: Run on continues the shot (Playback)");
      break;
    default: break;
  }
}

bool Lab::animating() const {
  const bool tracing = log_job_.valid() && log_job_.wait_for(std::chrono::seconds(0)) != std::future_status::ready;
  return playing || predicting() || tracing || margin.busy() || measured.fit.busy() || checking_pockets();
}

bool Lab::contact_on_screen() const {
  const Model& m = shot ? shot->sim().model() : table_model;
  for (const Contact& c : contacts(m, frame_.state))
    if (c.other_ball >= 0 || (c.collider >= 0 && m.colliders[c.collider].name != "bed")) return true;
  return false;
}

Trails Lab::trails(double until) const {
  Trails out;
  if (!shot) return out;
  const auto& frames = shot->frames();
  out.resize(frames.front().state.ball_count());
  for (const Frame& f : frames) {
    if (f.time > until) break;
    for (size_t i = 0; i < out.size(); ++i) {
      if (!f.state.in_play[i] && !out[i].empty() && out_of_play(out[i].back().motion)) continue;
      const PathPoint p{position(f.state.x, i), f.motion[i]};
      if (out[i].empty() || glm::length(p.position - out[i].back().position) > kTrailSpacing || p.motion != out[i].back().motion)
        out[i].push_back(p);
    }
  }
  return out;
}

std::optional<Prediction> Lab::prediction() const {
  auto p = predictor_.latest();
  if (!p || p->generation != wanted_ || !p->complete) return std::nullopt;
  return p;
}

void Lab::await_prediction() {
  constexpr double kWait = 4e-3;  // s: a quarter of a frame at 60 Hz
  if (shot || !settings.view.predicted || awaited_ == wanted_) return;
  awaited_ = wanted_;
  predictor_.wait_for(wanted_, kWait);
}

void Lab::report_prediction() {
  if (reported_ == wanted_ || shot) return;  // a shot says for itself why it stopped
  const auto p = predictor_.latest();
  if (!p || p->generation != wanted_ || !p->complete) return;
  reported_ = wanted_;
  if (!p->problem.empty()) say(MessageKind::Refused, "no predicted paths: " + p->problem);
}

const ContactLog* Lab::contact_log() {
  if (!shot) return nullptr;
  if (log_job_.valid() && log_job_.wait_for(std::chrono::seconds(0)) == std::future_status::ready) {
    tracer_ = log_job_.get();
    tracer_shot_ = log_shot_ = job_shot_;
    log_ = tracer_->log();
  }
  const std::vector<Event>& events = shot->sim().events();
  const bool stale = log_shot_ != shot_id_ || log_.events != events.size();
  // While the shot plays new events come every frame; the tracer follows them a few times a second, each time from
  // where it stopped (ContactTracer), on a worker thread.
  const auto now = std::chrono::steady_clock::now();
  const bool due = !playing || log_shot_ != shot_id_ || now - job_started_ >= std::chrono::milliseconds(250);
  if (stale && due && !log_job_.valid()) {
    if (!tracer_ || tracer_shot_ != shot_id_) tracer_ = std::make_unique<ContactTracer>(shot->start());
    job_started_ = now;
    job_shot_ = shot_id_;
    auto extend = [tracer = std::move(tracer_), events, until = shot->sim().time()]() mutable {
      tracer->extend(events, until);
      return std::move(tracer);
    };
    log_job_ = std::async(std::launch::async, std::move(extend));
  }
  return log_shot_ == shot_id_ ? &log_ : nullptr;
}

}  // namespace shotlab
