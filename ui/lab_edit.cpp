// Aiming and editing the table: every change records an undo entry (one per gesture), and none is made while a shot
// is shown (the note says what to do instead).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

#include "ui/aim.hpp"
#include "ui/lab.hpp"

namespace shotlab {

namespace {
constexpr double kMaxCueSpeed = 15.0;  // m/s
constexpr double kMinCueSpeed = 0.05;  // m/s
// A target change while the cue ball is in hand: the next undo (Esc) is the pick-up's.
constexpr const char* kPutDownFirst =
    "the cue ball is in hand: a click puts it down (Esc puts it back), then the target";

// Where a practice target may go: on the bed, inside the cushions.
bool on_the_cloth(const Scene& s, const Vec3& at) {
  return !s.table || (std::abs(at.x) <= s.table->length / 2 && std::abs(at.z) <= s.table->width / 2);
}

std::string deg(double rad) {
  char text[32];
  std::snprintf(text, sizeof text, "%.2f", rad * 180 / M_PI);
  return text;
}
}  // namespace

bool Lab::editable(const char* what) {
  if (!shot) return true;
  say(MessageKind::Refused, std::string("A shot is shown, so ") + what +
                                " would change nothing: U (Undo) retries from the position before it, N (Next) plays "
                                "on from where the balls stopped.");
  return false;
}

void Lab::set_cue(const CueStrike& cue, const std::string& what) {
  if (!scene.cue || !editable("aiming")) return;
  history.record(what, scene, "cue:" + what);
  scene.cue = cue;
  // P's note names the aim, cut and speed it chose: another change of the cue makes it stale.
  if (what != kPocketAim && pocket_aimed_ && message == pocket_aimed_->note) say(MessageKind::None, "");
  scene_changed();
}

void Lab::aim_at(const Vec3& point) {
  if (!scene.cue) return;
  const int c = scene_ball(scene, scene.cue->ball);
  if (c < 0) return;
  const Vec3 from = scene.balls[c].position;
  if (std::hypot(point.x - from.x, point.z - from.z) < 1e-4) return;
  CueStrike cue = *scene.cue;
  cue.aim = heading(from, point) - squirt_of(scene);  // the aim line (the ball's launch heading) through the point
  set_cue(cue, "aim");
}

void Lab::aim_at_ball(int i) {
  if (i < 0 || i >= static_cast<int>(scene.balls.size())) return;
  aim_at(scene.balls[i].position);
}

// Cycles through the pockets the aimed-at ball (or the one nearest the aim) can be cut into: those the shot drops it
// in at the current speed and spin (each checked by simulating it), else all of them; and says which it is. The
// check runs off the UI thread (pocket_checks.hpp): a quick one (a cut) is waited for, a long one (a full rack) lands
// in a later frame (finish_pocket_aim), presses meanwhile adding up.
void Lab::aim_for_pocket(int step) {
  if (!scene.cue) return say(MessageKind::Refused, "tick the cue strike first: the pockets are aimed with it");
  if (!editable("aiming at a pocket")) return;  // not a note claiming an aim that set_cue refused
  const int cue = scene_ball(scene, scene.cue->ball);
  int object = pocket_object(scene);
  // While the aim is the one P set, P goes on with that ball: its line to a pocket may meet another ball first.
  if (pocket_aimed_ && scene.cue->aim == pocket_aimed_->aim)
    if (const int kept = scene_ball(scene, pocket_aimed_->ball); kept >= 0 && kept != cue) object = kept;
  if (object < 0) return say(MessageKind::Refused, "no object ball to aim at a pocket");
  if (pocket_aims(scene, table_model.pockets, cue, object).empty())
    return say(MessageKind::Refused, "no pocket can be reached from here with a cut under 85 degrees");
  std::string key = PocketChecks::key_of(scene, object);
  if (!pocket_wait_ || pocket_wait_->key != key) pocket_wait_ = PocketWait{std::move(key), object, 0, step};
  pocket_wait_->steps += step;
  pocket_wait_->aim = scene.cue->aim;
  pocket_checks_.request(pocket_wait_->key, scene, table_model.pockets, cue, object);
  if (pocket_checks_.wait(pocket_wait_->key, pocket_wait_seconds)) return finish_pocket_aim();
  say(MessageKind::Note, "checking which pockets drop the " + scene.balls[object].spec.id + " ...");
}

void Lab::finish_pocket_aim(bool block) {
  pocket_checks_.poll();
  if (!pocket_wait_) return;
  // A shot started, or balls moved, the speed, spin or aim changed meanwhile: that answer is not for this shot.
  if (shot || !scene.cue || scene.cue->aim != pocket_wait_->aim ||
      PocketChecks::key_of(scene, pocket_wait_->object) != pocket_wait_->key) {
    pocket_wait_.reset();
    return;
  }
  if (block) pocket_checks_.wait(pocket_wait_->key, -1);
  auto aims = pocket_checks_.answer(pocket_wait_->key);
  if (!aims) return;
  const PocketWait done = *pocket_wait_;
  pocket_wait_.reset();
  choose_pocket(std::move(*aims), done.object, done.steps, done.first);
}

// P's note on the aim it took: the cut of the aim line as it is now (the window's middle is off the ghost-ball line
// that PocketAim::cut_deg measures), whether it drops and how far the aim may turn.
std::string Lab::pocket_note(const PocketAim& a, int object, bool only) const {
  const auto line = aim_line(scene);
  const double cut = line && line->hit == object ? line->cut_deg : a.cut_deg;
  char speed[32], window[64] = "";
  std::snprintf(speed, sizeof speed, "%.2f m/s", scene.cue->speed);
  if (a.window_deg > 0)
    std::snprintf(window, sizeof window, ", the middle of an aim window of +-%.2f deg", a.window_deg);
  const std::string head = "aimed " + scene.balls[object].spec.id + " at " + pocket_label(a.pocket) + " (cut " +
                           deg(cut * M_PI / 180) + " deg; ";
  if (!a.drops) return head + "does not drop at " + speed + ": try another speed or pocket)";
  return head + "drops at " + speed + window + ")" + (only ? "; no other pocket in reach drops it" : "");
}

// P's choice once the drops are known: `step` pockets on from the one aimed at now, among those that drop when any
// does; off every pocket, the first press (`first`) snaps to the nearest one and the others step on from there.
void Lab::choose_pocket(std::vector<PocketAim> aims, int object, int step, int first) {
  if (aims.empty()) return;
  if (aims.front().drops)  // only those that drop are offered, when any does
    aims.erase(std::find_if(aims.begin(), aims.end(), [](const PocketAim& a) { return !a.drops; }), aims.end());
  // The pocket after the one aimed at now (the closest heading), easiest cut first.
  size_t now = 0;
  for (size_t k = 1; k < aims.size(); ++k)
    if (std::abs(std::remainder(aims[k].aim - scene.cue->aim, 2 * M_PI)) <
        std::abs(std::remainder(aims[now].aim - scene.cue->aim, 2 * M_PI)))
      now = k;
  const bool on_one = std::abs(std::remainder(aims[now].aim - scene.cue->aim, 2 * M_PI)) < 1e-9;
  const long n = static_cast<long>(aims.size()), by = on_one ? step : step - first;
  const size_t next = static_cast<size_t>(((static_cast<long>(now) + by) % n + n) % n);
  CueStrike cue = *scene.cue;
  cue.aim = aims[next].aim;
  set_cue(cue, kPocketAim);
  say(MessageKind::Note, pocket_note(aims[next], object, aims.size() == 1));
  pocket_aimed_ = PocketAimed{scene.balls[object].spec.id, scene.cue->aim, message};
}

bool Lab::set_target(const Vec3& at) {
  if (in_hand) return say(MessageKind::Refused, kPutDownFirst), false;  // its undo is the pick-up's
  if (!on_the_cloth(scene, at))
    return say(MessageKind::Refused, "the target goes on the cloth, inside the cushions"), false;
  history.record_target(target ? "move target" : "set target", scene, target);
  target = Vec3{at.x, 0, at.z};
  return true;
}

void Lab::drag_target(const Vec3& at) {
  if (target && !in_hand && on_the_cloth(scene, at)) target = Vec3{at.x, 0, at.z};  // past the cushions it stays
}

void Lab::clear_target() {
  if (!target) return;
  if (in_hand) return say(MessageKind::Refused, kPutDownFirst);
  history.record_target("clear target", scene, target);
  target.reset();
}

CueStrike turned(const CueStrike& cue, double degrees) {
  CueStrike out = cue;
  out.aim = std::remainder(cue.aim + degrees * M_PI / 180, 2 * M_PI);
  return out;
}

void Lab::nudge_aim(double degrees) {
  if (!scene.cue) return;
  if (std::abs(degrees) == kAimStepDeg) last_turn_deg_ = degrees;
  set_cue(turned(*scene.cue, degrees), "aim");
}

void Lab::nudge_speed(double mps) {
  if (!scene.cue) return;
  CueStrike cue = *scene.cue;
  cue.speed = std::clamp(std::round((cue.speed + mps) * 100) / 100, kMinCueSpeed, kMaxCueSpeed);
  set_cue(cue, "speed");
}

bool Lab::fits(int i, const Vec3& p) const {
  if (scene.allow_overlap) return true;
  for (int j = 0; j < static_cast<int>(scene.balls.size()); ++j)
    if (j != i && glm::length(scene.balls[j].position - p) < scene.balls[j].spec.radius + scene.balls[i].spec.radius)
      return false;
  return true;
}

bool Lab::begin_move(int i) {
  if (i < 0 || i >= static_cast<int>(scene.balls.size()) || !editable("moving a ball")) return false;
  history.seal();
  history.record("move " + scene.balls[i].spec.id, scene, "move");
  selected = i;
  return true;
}

bool Lab::move_ball(int i, const Vec3& to) {
  if (shot || i < 0 || i >= static_cast<int>(scene.balls.size())) return false;
  Vec3 p{to.x, scene.balls[i].position.y, to.z};
  // On a table a ball stays on the cloth: dragged past a cushion it slides along it, touching it (past the nose line
  // it would start off the bed, and the scene would not simulate; short of it, pressed into the rubber).
  if (scene.table) p = hand_zone(*scene.table, scene.balls[i].spec.radius, false).clamp(p);
  if (!fits(i, p)) return false;
  history.record("move " + scene.balls[i].spec.id, scene, "move");  // merged into the gesture's entry
  scene.balls[i].position = p;
  scene_changed();
  return true;
}

void Lab::add_ball(const Vec3& at) {
  if (!editable("adding a ball")) return;
  InitialBall b;
  b.spec = scene.balls.empty() ? BallSpec{"", kPoolBall.mass, kPoolBall.radius} : scene.balls.back().spec;
  for (int n = 1;; ++n)  // the smallest free number
    if (scene_ball(scene, std::to_string(n)) < 0) {
      b.spec.id = std::to_string(n);
      break;
    }
  b.position = {at.x, b.spec.radius, at.z};
  if (scene.table) b.position = hand_zone(*scene.table, b.spec.radius, false).clamp(b.position);
  scene.balls.push_back(b);
  const bool room = fits(static_cast<int>(scene.balls.size()) - 1, b.position);
  scene.balls.pop_back();
  if (!room) return say(MessageKind::Refused, "no room for a ball there");
  history.seal();
  history.record("add " + b.spec.id, scene);
  scene.balls.push_back(b);
  selected = static_cast<int>(scene.balls.size()) - 1;
  scene_changed();
}

void Lab::remove_ball(int i) {
  if (i < 0 || i >= static_cast<int>(scene.balls.size()) || !editable("removing a ball")) return;
  if (!scene.model.rods.empty()) return say(MessageKind::Refused, "this scene's rods hold its balls: they cannot be removed");
  if (scene.cue && scene.cue->ball == scene.balls[i].spec.id)
    return say(MessageKind::Refused, "the cue ball is not removed: untick 'cue strike' first, or select another ball");
  history.seal();
  history.record("remove " + scene.balls[i].spec.id, scene);
  scene.balls.erase(scene.balls.begin() + i);
  scene_changed();
}

void Lab::pick_up_cue_ball() {
  if (!scene.cue || scene_ball(scene, scene.cue->ball) < 0)
    return say(MessageKind::Refused, "this scene has no cue ball to take in hand");
  if (!scene.table) return say(MessageKind::Refused, "ball in hand needs a table");
  // B again while in hand: the note again, no second step (Esc would then only undo the second).
  if (!in_hand) {
    if (!editable("ball in hand")) return;
    history.seal();
    history.record("ball in hand", scene);
    in_hand = true;
  }
  say(MessageKind::Note, break_position(scene) ? "ball in hand behind the head string: click to put it down"
                                               : "ball in hand: click to put it down, Esc puts it back");
}

void Lab::place_cue_ball(const Vec3& at, bool drop) {
  if (!in_hand || !scene.cue || !scene.table) return;
  const int c = scene_ball(scene, scene.cue->ball);
  if (c < 0) return;
  // The ball follows the pointer over the cloth only: off the table (on a panel's way, or below it) it stays where it
  // was, so that S does not shoot from the rail the pointer was nearest to (a coach's trial broke from there).
  if (!drop && (std::abs(at.x) > scene.table->length / 2 || std::abs(at.z) > scene.table->width / 2)) return;
  const Zone zone = hand_zone(*scene.table, scene.balls[c].spec.radius, break_position(scene));
  const Vec3 p = zone.clamp({at.x, scene.balls[c].position.y, at.z});
  // A full-ball aim (a break's at the apex) stays on its ball while the cue ball moves; any other keeps its heading.
  const auto line = aim_line(scene);
  const int full_on = line && line->hit >= 0 && line->cut_deg < 0.01 ? line->hit : -1;
  if (fits(c, p) && glm::length(p - scene.balls[c].position) > 0) {
    scene.balls[c].position = p;
    if (full_on >= 0) scene.cue->aim = heading(p, scene.balls[full_on].position) - squirt_of(scene);
    scene_changed();
  }
  if (drop) {
    in_hand = false;
    history.seal();
    say(MessageKind::None, "");
  }
}

void Lab::setup_break() {
  if (scene.table && scene.table->kind != TableKind::Pool)
    return say(MessageKind::Refused, "a break needs a pool table (this scene's table has no pockets to rack for)");
  // From another position the shots kept to compare, the A/B overlay and the last shot's ghost belong to that one
  // (a player's trial saw a cut's kept lines over the rack): they go, and one undo brings them back as a load's does.
  // A break after a break keeps them to compare.
  const bool fresh = !break_position(scene);
  history.seal();
  if (fresh) history.record_load("set up break", scene, current_file(), true);
  else history.record("set up break", scene);
  if (shot) {  // a new position: the shot shown goes (its trails stay as the ghost, unless `fresh`)
    ghost = trails(shot->sim().time());
    shot.reset();
    playing = false;
    view_time = 0;
  }
  if (fresh) restore(Workbench{}), ghost.clear();
  Scene s = break_scene(scene);
  s.model = scene.model;
  scene = std::move(s);
  selected = 0;  // the target stays over a break (where the cue ball should end); a fresh set-up cleared it above
  tool = Tool::Aim;  // a click on the apex aims there (the Target tool left on moved the target to it)
  scene_changed();
  pick_up_cue_ball();
  history.seal();
}

std::optional<double> Lab::target_miss() const {
  if (!target || !scene.cue) return std::nullopt;
  const int c = scene_ball(scene, scene.cue->ball);
  if (c < 0) return std::nullopt;
  if (shot) {
    if (!shot->finished() || !shot->sim().state().in_play[c]) return std::nullopt;
    const Vec3 p = position(shot->sim().state().x, c);
    return std::hypot(p.x - target->x, p.z - target->z);
  }
  const auto p = prediction();
  if (!p || c >= static_cast<int>(p->paths.size()) || p->paths[c].empty()) return std::nullopt;
  const Vec3 end = p->paths[c].back().position;
  return std::hypot(end.x - target->x, end.z - target->z);
}

void Lab::keep_shot() {
  if (!shot) return say(MessageKind::Refused, "shoot first: a kept shot is one that has been played");
  const bool full = kept.size() >= kMaxKeptShots;
  if (full) kept.erase(kept.begin());
  KeptShot k;
  k.trails = trails(shot->sim().time());
  k.colour = kept.empty() ? 0 : kept.back().colour + 1;
  if (const auto& c = shot->start().cue) {
    // The tip first, as a coach names the shot (a narrow panel cuts the end off); 0.005 R is where the tip widget
    // reads 0.00.
    char tip[64], side[32] = "", rest[64];
    if (std::abs(c->height) < 0.005) std::snprintf(tip, sizeof tip, "centre");
    else std::snprintf(tip, sizeof tip, "%s %.2f R", c->height > 0 ? "follow" : "draw", std::abs(c->height));
    if (std::abs(c->side) >= 0.005)
      std::snprintf(side, sizeof side, ", %s %.2f R", c->side > 0 ? "right" : "left", std::abs(c->side));
    std::snprintf(rest, sizeof rest, ", %.2f m/s, aim %.1f deg", c->speed, c->aim * 180 / M_PI);
    k.label = std::string(tip) + side + rest;
  } else {
    k.label = "shot " + std::to_string(k.colour + 1);
  }
  say(MessageKind::Note,
      "kept: " + k.label + (full ? " (the oldest kept shot made room)" : " (listed under Practice)"));
  kept.push_back(std::move(k));
}

void Lab::set_cue_strike(bool on) {
  if (on == scene.cue.has_value()) return;
  history.record(on ? "add cue strike" : "remove cue strike", scene);
  if (on) {
    scene.cue = spare_cue();
  } else {
    removed_cue_ = scene.cue;
    scene.cue.reset();
  }
  scene_changed();
}

CueStrike Lab::spare_cue() const {
  CueStrike c = removed_cue_.value_or(CueStrike{});
  if (!removed_cue_ || scene_ball(scene, c.ball) < 0) c.ball = scene.balls.at(selected).spec.id;
  return c;
}

void Lab::clear_kept() {
  if (kept.empty()) return;
  const size_t n = kept.size();
  history.record_kept("clear kept shots", scene, std::exchange(kept, {}));
  say(MessageKind::Note,
      "cleared " + std::to_string(n) + " kept shot" + (n == 1 ? "" : "s") + " (Undo brings them back)");
}

}  // namespace shotlab
