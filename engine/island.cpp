#include "island.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <sstream>

#include "check.hpp"
#include "shotlab/diagnostics.hpp"
#include "partition.hpp"

namespace shotlab {

void StepView::state_at(double t, StateVector& x) const { span_.interpolate(t, x); }

const char* status_name(Status s) {
  static constexpr const char* names[] = {"ok", "step_limit", "non_finite", "step_too_small", "unstable"};
  return names[static_cast<int>(s)];
}

Stats& Stats::operator+=(const Stats& o) {
  steps += o.steps;
  rejected_steps += o.rejected_steps;
  redone_steps += o.redone_steps;
  rhs_evaluations += o.rhs_evaluations;
  return *this;
}

namespace {

// The world's model with only the given balls (and the rods that hold them, renumbered).
Model sub_model(const Model& world, const std::vector<int>& balls) {
  Model m;
  m.colliders = world.colliders;
  m.pockets = world.pockets;
  m.balls_leave_below_bed = world.balls_leave_below_bed;
  m.materials = world.materials;
  m.options = world.options;
  m.integrator = world.integrator;
  for (int i : balls) m.balls.push_back(world.balls[i]);
  for (const Rod& rod : world.rods) {
    const auto at = std::lower_bound(balls.begin(), balls.end(), rod.ball);
    if (at != balls.end() && *at == rod.ball) m.rods.push_back({static_cast<int>(at - balls.begin()), rod.anchor, rod.length});
  }
  return m;
}

std::vector<double> radii(const Model& model) {
  std::vector<double> out;
  for (const BallSpec& b : model.balls) out.push_back(b.radius);
  return out;
}

State sub_state(const State& world, const std::vector<int>& balls) {
  const size_t n = balls.size();
  State s{world.time,          StateVector(kBallDofs * n), std::vector<uint8_t>(n), std::vector<uint8_t>(n),
          std::vector<int>(n), std::vector<int>(n),        std::vector<double>(n)};
  for (size_t k = 0; k < n; ++k) copy_ball(world, balls[k], s, static_cast<int>(k));
  return s;
}

}  // namespace

Island::Island(const Model& world, const ModelIndex& world_index, const State& world_state, std::vector<int> balls,
               double first_step, double energy_bound, double onset_factor)
    : balls_(std::move(balls)),
      model_(sub_model(world, balls_)),
      index_(world_index, model_),
      integ_(sub_state(world_state, balls_)),
      dynamics_(model_, index_, integ_),
      onset_growth_(std::pow(onset_factor, 0.2)),
      stepper_(make_stepper(model_.integrator, onset_factor, radii(model_))),
      detector_(model_, index_),
      regimes_(model_, index_),
      dt_next_(is_adaptive(model_.integrator.method) ? first_step : model_.integrator.fixed_step),
      energy_bound_(energy_bound) {
  span_.t0 = span_.t1 = integ_.time;
  span_.x1 = integ_.x;
  restart();
  start_ = integ_;
  energy_ref_ = energy();
}

double Island::energy() {
  if (energy_steps_ != stats_.steps) {
    energy_state_ = integ_;
    span_.interpolate(span_.t1, energy_state_.x);
    energy_ = shotlab::energy(model_, index_, energy_state_, cap_broad_, true).total();
    energy_steps_ = stats_.steps;
  }
  return energy_;
}

void Island::restart() {
  end_record_is_start_ = false;
  aim_ = std::numeric_limits<double>::infinity();
  dynamics_.sweep_again();
  span_.f1.resize(span_.x1.size());
  dynamics_(span_.x1, span_.f1, span_.t1);
  span_.x0 = span_.x1;
  span_.f0 = span_.f1;
  span_.t0 = span_.t1;
  span_.exits.clear();
  stepper_->reset();
  integ_.x = span_.x1;
  integ_.time = span_.t1;
  detector_.reset(integ_);
}

void Island::write(double t, State& world) {
  span_.interpolate(t, scratch_);  // at t = time() exactly the step's end: the Hermite weights are 0, 0, 1, 0
  const State& flags = flags_at(t);
  for (size_t k = 0; k < balls_.size(); ++k) {
    std::copy_n(scratch_.begin() + kBallDofs * k, kBallDofs, world.x.begin() + kBallDofs * balls_[k]);
    copy_ball(flags, static_cast<int>(k), world, balls_[k], false);
  }
  for (const StepSpan::Exit& e : span_.exits)  // out of play from the moment it left, not from the step's end
    if (t >= e.time) world.in_play[balls_[e.ball]] = 0;
}

std::optional<FreePath> Island::free_path(double t, double horizon) {
  if (balls_.size() != 1) return std::nullopt;
  span_.interpolate(t, scratch_);
  return shotlab::free_path(model_, flags_at(t), scratch_.data(), 0, index_, horizon);
}

bool Island::rewind(double t) {
  if (t >= span_.t1) return true;
  span_.x1 = span_.x0;  // a ball that left play in the step is back where it started it, in play (start_)
  span_.f1 = span_.f0;
  span_.t1 = span_.t0;
  span_.exits.clear();
  copy_flags(start_, integ_);
  integ_.x = span_.x1;
  integ_.time = span_.t1;
  stepper_->reset();
  detector_.reset(integ_);
  dynamics_(span_.x1, scratch_, span_.t1);  // for its contact record there (integrate), the step's f0 kept as it was
  end_record_is_start_ = false;
  aim_ = std::numeric_limits<double>::infinity();
  const auto undone = std::find_if(events_.begin(), events_.end(), [&](const Event& e) { return e.time > span_.t0; });
  events_.erase(undone, events_.end());
  while (span_.t1 < t)
    if (!step(t)) return false;
  const auto again = std::find_if(events_.begin(), events_.end(), [&](const Event& e) { return e.time > handed_until_; });
  events_.erase(events_.begin(), again);
  return true;
}

void Island::take_events(double t, std::vector<Event>& out) {
  handed_until_ = std::max(handed_until_, t);
  const auto end = std::find_if(events_.begin(), events_.end(), [t](const Event& e) { return e.time > t; });
  out.insert(out.end(), std::make_move_iterator(events_.begin()), std::make_move_iterator(end));
  events_.erase(events_.begin(), end);
}

// A step as a list of stages: plan its length, freeze its contact laws, integrate (or move in closed form), check,
// commit, then events and regimes at its end (docs/model.md#step-control).
bool Island::step(double limit) {
  bool constant = false;
  double dt = plan(limit, constant);
  freeze_laws();
  const bool to_limit = dt >= limit - span_.t1;  // the synchronisation time ends the step exactly
  if (to_limit) dt = limit - span_.t1;
  // Each step runs in trial_ (its end in x1, f1), whose buffers outlive the step: no allocation per step.
  trial_.t0 = span_.t1;
  trial_.x0 = span_.x1;
  trial_.f0 = f_start_;
  double t;
  if (constant) t = closed_form_to(to_limit ? limit : span_.t1 + dt);
  else if (!integrate(dt, to_limit ? limit : std::numeric_limits<double>::quiet_NaN(), t)) return false;
  ++stats_.steps;
  stats_.rhs_evaluations = dynamics_.evaluations();
  if (!finite_or_stop(t)) return false;
  commit(t);
  settle(t, !constant && is_adaptive(model_.integrator.method));
  return true;
}

// s: the step's length before any trial. An island whose right-hand side stays constant (every ball asleep, or rolling
// or sliding outside its friction bands or inside them where band_tail.hpp has the closed form), or whose other balls
// swing alone on their rods (swing.hpp), moves in closed form (`constant`): as long as the caps allow, no longer than
// a lone ball's horizon. The caps: a friction band's edge, a possible contact (its lists go to plan_).
double Island::plan(double limit, bool& constant) {
  // Compared bit for bit, so that a state gone non-finite (stopped by finite_or_stop) still compares equal.
  SHOTLAB_ASSERT(integ_.time == span_.t1 && integ_.x.size() == span_.x1.size() &&
                     std::memcmp(integ_.x.data(), span_.x1.data(), integ_.x.size() * sizeof(double)) == 0,
                 "a step starts from the last step's end, never from an interpolated state");
  const bool adaptive = is_adaptive(model_.integrator.method);
  double dt = adaptive ? dt_next_ : model_.integrator.fixed_step;
  constant = false;
  trial_.tails.clear();
  trial_.swings.clear();
  trial_.bounces.clear();
  if (!adaptive) return dt;
  continuing_ = span_.swings;
  for (Swing& s : continuing_) s.phase += s.omega * (span_.t1 - span_.t0);  // as apply() reached the step's end
  bouncing_ = span_.bounces;
  for (BedBounce& b : bouncing_) b.from += span_.t1 - span_.t0;  // as apply() reached the step's end
  const double longest = std::min(limit - span_.t1, kLoneHorizon);
  BounceWork bounces{trial_.bounces, bouncing_, longest};
  const double band = time_to_band_edge(model_, integ_, index_, span_.x1.data(), &constant, &trial_.tails,
                                        &trial_.swings, &continuing_, &bounces);
  if (!constant) trial_.tails.clear(), trial_.swings.clear(), trial_.bounces.clear();
  const double horizon = constant ? longest : dt;
  const double touch = time_to_possible_contact(model_, index_, integ_, span_.x1.data(), horizon, cap_broad_, &plan_,
                                                constant && model_.options.flight_regime, &trial_.bounces);
  return std::min({horizon, band, touch});
}

// The changing contacts keep their law through the step (StepContacts). A contact left out has no force at the step's
// start, nor has an unclamped one a different force there, so f there stays as it was, unless a contact left out of
// the last step touches now or one unclamped in it has stopped pushing (it was cut there).
void Island::freeze_laws() {
  dynamics_.swap_plan(plan_);  // plan_ now holds the last step's lists
  const StepContacts &now = dynamics_.plan(), &last = plan_;
  const bool changed = !std::includes(now.separated.begin(), now.separated.end(), last.separated.begin(), last.separated.end()) ||
                       !std::includes(now.pushing.begin(), now.pushing.end(), last.pushing.begin(), last.pushing.end());
  f_start_ = span_.f1;
  if (changed) {
    dynamics_(span_.x1, f_start_, span_.t1);
    end_record_is_start_ = false;
  }
}

// The closed-form step to t, ended where a contact begins if one does first: the caps let a pair come contact_margin
// into touching within the step, and on the closed-form path the interpolant is the motion itself. Returns its end.
double Island::closed_form_to(double t) {
  aim_ = std::numeric_limits<double>::infinity();
  closed_form_step(t);
  const double touch = std::min(detector_.first_contact_change(trial_, integ_, dynamics_.plan(), nullptr).begin,
                                detector_.first_touch(trial_, dynamics_.plan().separated));
  if (touch < t - kOnsetResolution) {
    t = touch;
    closed_form_step(t);
    ++stats_.redone_steps;
  }
  return t;
}

// False, with a diagnostic naming the balls, when the trial's end is not finite.
bool Island::finite_or_stop(double t) {
  const StateVector& x = trial_.x1;
  if (std::all_of(x.begin(), x.end(), [](double v) { return std::isfinite(v); })) return true;
  std::ostringstream msg;
  msg << "non-finite state in the step from t = " << span_.t1 << " s to " << t << " s; balls: ";
  for (int i = 0; i < integ_.ball_count(); ++i)
    for (int k = 0; k < kBallDofs; ++k)
      if (!std::isfinite(x[kBallDofs * i + k])) {
        msg << model_.balls[i].id << " ";
        break;
      }
  msg << ". Last finite state: " << describe_balls(span_.x1);
  stop(Status::NonFinite, msg.str());
  return false;
}

// The trial becomes the accepted step: span_ and the integrator state move to its end at t.
void Island::commit(double t) {
  SHOTLAB_ASSERT(t >= span_.t1, "spans are ordered: a step ends at or after its start");
  span_.x0.swap(span_.x1);
  span_.f0.swap(f_start_);
  span_.t0 = span_.t1;
  span_.exits.clear();
  span_.x1.swap(trial_.x1);
  span_.f1.swap(trial_.f1);
  span_.tails.swap(trial_.tails);
  span_.swings.swap(trial_.swings);
  span_.bounces.swap(trial_.bounces);
  span_.t1 = t;
  integ_.x = span_.x1;
  integ_.time = t;
  ++call_steps_;
  copy_flags(integ_, start_);  // the flags the step ran with (a rewind to inside it needs them)
}

// At the step's end: events located on it, balls that left play frozen where they left, regimes entered or left.
// `recorded`: an integrated step's last evaluation recorded the contacts at its end (end_record_, sorted).
void Island::settle(double t, bool recorded) {
  std::vector<Exit> exits;
  detector_.scan(span_, integ_, dynamics_.plan(), recorded ? &end_record_ : nullptr, events_, exits);
  StateVector at;
  std::vector<StepSpan::Exit> left;
  for (const Exit& e : exits) {
    span_.interpolate(e.time, at);
    StepSpan::Exit& kept = left.emplace_back(StepSpan::Exit{e.ball, e.time, {}, {}});
    std::copy_n(span_.x1.begin() + kBallDofs * e.ball, kBallDofs, kept.x1);
    std::copy_n(span_.f1.begin() + kBallDofs * e.ball, kBallDofs, kept.f1);
    std::erase_if(span_.tails, [&](const BandTail& tail) { return tail.ball == e.ball; });
    std::erase_if(span_.swings, [&](const Swing& swing) { return swing.ball == e.ball; });
    std::erase_if(span_.bounces, [&](const BedBounce& bounce) { return bounce.ball == e.ball; });
    integ_.in_play[e.ball] = 0;
    set_position(span_.x1, e.ball, position(at, e.ball));
    set_velocity(span_.x1, e.ball, Vec3{0.0});
    set_spin(span_.x1, e.ball, Vec3{0.0});
  }
  const bool regime_changed = regimes_.update(integ_, span_.x1, t - span_.t0);
  if (exits.empty() && !regime_changed) return;
  // The system lost or froze bodies, or woke them: the integrator starts afresh from the step's end. The finished
  // step's interpolant stays for the caller's clock, an exited ball on its path until it left, frozen from then on.
  const StepSpan finished = span_;
  restart();
  span_.x0 = finished.x0;
  span_.f0 = finished.f0;
  span_.t0 = finished.t0;
  span_.exits = std::move(left);
}

// Constant acceleration over the step to t1 (the island's right-hand side does not change, time_to_band_edge):
// x(t0 + h) = x0 + h f0 + h^2 / 2 (the acceleration slots of f0 added to the positions), exact, and so is the step's
// Hermite interpolant (cubic) of a motion that is quadratic in time. What decays inside a friction band follows its
// own closed form instead (band_tail.hpp), and so does a swinging ball (swing.hpp: its rod and gravity are all of its
// right-hand side), in the interpolant too. The step size suggestion is left alone: a closed form estimates no error
// to base one on.
void Island::closed_form_step(double t1) {
  end_record_is_start_ = false;
  StateVector &x = trial_.x1, &f = trial_.f1;
  const StateVector& f0 = trial_.f0;
  const double h = t1 - trial_.t0;
  x = trial_.x0;
  for (size_t k = 0; k < x.size(); ++k) x[k] += h * f0[k];
  for (size_t b = 0; b < x.size(); b += kBallDofs)
    for (size_t c = 0; c < 3; ++c) x[b + c] += 0.5 * h * h * f0[b + 3 + c];
  for (const BandTail& tail : trial_.tails) tail.apply(h, x.data() + kBallDofs * tail.ball);
  for (const Swing& swing : trial_.swings) swing.apply(h, x.data() + kBallDofs * swing.ball);
  for (const BedBounce& bounce : trial_.bounces) bounce.apply(h, x.data() + kBallDofs * bounce.ball);
  f.resize(x.size());
  dynamics_(x, f, t1);
  trial_.t1 = t1;
  stats_.last_step = h;
}

void Island::stop(Status why, std::string message) {
  status_ = why;
  diagnostic_ = std::move(message);
}

// The balls worth naming in a diagnostic: those in contact at x with depth and force, or else the pair closest to
// touching (a failing step usually runs into the contact that this pair is about to make).
std::string Island::describe_balls(const StateVector& x) const {
  State s = integ_;
  s.x = x;
  std::ostringstream out;
  const auto list = shotlab::contacts(model_, s);
  for (const Contact& c : list)
    out << (&c == &list.front() ? "Contacts:" : "") << " [" << model_.balls[c.ball].id << " - "
        << (c.other_ball >= 0 ? model_.balls[c.other_ball].id : model_.colliders[c.collider].name)
        << ": depth " << c.depth << " m, force " << c.force.normal << " N]";
  if (!list.empty()) return out.str();
  double best = std::numeric_limits<double>::infinity();
  std::string pair = "none";
  for (int i = 0; i < s.ball_count(); ++i)
    for (int j = i + 1; j < s.ball_count(); ++j) {
      if (!s.in_play[i] || !s.in_play[j]) continue;
      const double gap = glm::length(position(x, i) - position(x, j)) - model_.balls[i].radius - model_.balls[j].radius;
      if (gap < best) best = gap, pair = model_.balls[i].id + " - " + model_.balls[j].id;
    }
  // Without contacts, name the balls themselves (the fastest few: a lone ball has no pair to name).
  std::vector<int> balls;
  for (int i = 0; i < s.ball_count(); ++i)
    if (s.in_play[i]) balls.push_back(i);
  std::sort(balls.begin(), balls.end(), [&](int a, int b) {
    return glm::length(velocity(x, a)) > glm::length(velocity(x, b));
  });
  out << "No contacts.";
  for (size_t k = 0; k < balls.size() && k < 3; ++k) {
    const Vec3 p = position(x, balls[k]);
    out << " Ball " << model_.balls[balls[k]].id << " at (" << p.x << ", " << p.y << ", " << p.z << ") m, "
        << glm::length(velocity(x, balls[k])) << " m/s.";
  }
  if (std::isfinite(best)) out << " Closest pair: " << pair << " (gap " << best << " m).";
  return out.str();
}

}  // namespace shotlab
