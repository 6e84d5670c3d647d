#include "island.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "diagnostics.hpp"
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

Island::Island(const Model& world, const State& world_state, std::vector<int> balls, double first_step,
               double energy_bound, double onset_factor)
    : balls_(std::move(balls)),
      model_(sub_model(world, balls_)),
      integ_(sub_state(world_state, balls_)),
      dynamics_(model_, integ_),
      onset_growth_(std::pow(onset_factor, 0.2)),
      stepper_(make_stepper(model_.integrator, onset_factor, radii(model_))),
      detector_(model_),
      regimes_(model_),
      cap_cache_(model_),
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
    energy_ = shotlab::energy(model_, energy_state_, cap_cache_, true).total();
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
}

std::optional<FreePath> Island::free_path(double t, double horizon) {
  if (balls_.size() != 1) return std::nullopt;
  span_.interpolate(t, scratch_);
  return shotlab::free_path(model_, flags_at(t), scratch_.data(), 0, cap_cache_, horizon);
}

bool Island::rewind(double t) {
  if (t >= span_.t1) return true;
  span_.x1 = span_.x0;
  span_.f1 = span_.f0;
  span_.t1 = span_.t0;
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

bool Island::step(double limit) {
  const bool adaptive = is_adaptive(model_.integrator.method);
  double dt = adaptive ? dt_next_ : model_.integrator.fixed_step;
  // An island whose right-hand side stays constant (every ball asleep, or rolling or sliding outside its friction
  // bands, or inside them where band_tail.hpp has the closed form), or whose other balls swing alone on their rods
  // (swing.hpp), moves in closed form: one step as long as the caps allow (and no longer than a lone ball's horizon,
  // where the island's deadline is not finite), with no error to control.
  bool constant = false;
  trial_.tails.clear();
  trial_.swings.clear();
  if (adaptive) {
    continuing_ = span_.swings;
    for (Swing& s : continuing_) s.phase += s.omega * (span_.t1 - span_.t0);  // as apply() reached the step's end
    const double band = time_to_band_edge(model_, integ_, cap_cache_, span_.x1.data(), &constant, &trial_.tails,
                                          &trial_.swings, &continuing_);
    if (!constant) trial_.tails.clear(), trial_.swings.clear();
    const double horizon = constant ? std::min(limit - span_.t1, kLoneHorizon) : dt;
    dt = std::min({horizon, band, time_to_possible_contact(model_, integ_, span_.x1.data(), horizon, cap_cache_, &plan_)});
  }
  // The changing contacts keep their law through the step (StepContacts). A contact left out has no force at the
  // step's start, nor has an unclamped one a different force there, so f there stays as it was, unless a contact
  // left out of the last step touches now or one unclamped in it has stopped pushing (it was cut there).
  dynamics_.swap_step(plan_);
  const StepContacts &now = dynamics_.step(), &last = plan_;
  const bool changed = !std::includes(now.separated.begin(), now.separated.end(), last.separated.begin(), last.separated.end()) ||
                       !std::includes(now.pushing.begin(), now.pushing.end(), last.pushing.begin(), last.pushing.end());
  f_start_ = span_.f1;
  if (changed) {
    dynamics_(span_.x1, f_start_, span_.t1);
    end_record_is_start_ = false;
  }
  // The synchronisation time ends the step exactly (round-off in t1 + (limit - t1) is snapped below).
  const bool to_limit = dt >= limit - span_.t1;
  if (to_limit) dt = limit - span_.t1;
  // Each step runs in trial_ (its end in x1, f1), whose buffers outlive the step: no allocation per step.
  trial_.t0 = span_.t1;
  trial_.x0 = span_.x1;
  trial_.f0 = f_start_;
  double t;
  if (constant) {
    aim_ = std::numeric_limits<double>::infinity();
    t = to_limit ? limit : span_.t1 + dt;
    closed_form_step(t);
    // The caps let a pair come contact_margin into touching within the step: end it where the contact begins,
    // exactly, as on the closed-form path the step's interpolant is the motion itself.
    const double touch = std::min(detector_.first_contact_change(trial_, integ_, dynamics_.step(), nullptr).begin,
                                  detector_.first_touch(trial_, dynamics_.step().separated));
    if (touch < t - kOnsetResolution) {
      t = touch;
      closed_form_step(t);
      ++stats_.redone_steps;
    }
  } else if (!integrate(dt, to_limit ? limit : std::numeric_limits<double>::quiet_NaN(), t)) {
    return false;
  }
  StateVector &x = trial_.x1, &f = trial_.f1;
  ++stats_.steps;
  stats_.rhs_evaluations = dynamics_.evaluations();

  if (!std::all_of(x.begin(), x.end(), [](double v) { return std::isfinite(v); })) {
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

  span_.x0.swap(span_.x1);
  span_.f0.swap(f_start_);
  span_.t0 = span_.t1;
  span_.x1.swap(x);
  span_.f1.swap(f);
  span_.tails.swap(trial_.tails);
  span_.swings.swap(trial_.swings);
  span_.t1 = t;
  integ_.x = span_.x1;
  integ_.time = t;
  ++call_steps_;

  // The flags the step started with (a rewind to inside it needs them); only the flags, not the state vector.
  copy_flags(integ_, start_);
  std::vector<Exit> exits;
  // An integrated step's last evaluation recorded the contacts at its end (end_record_, sorted).
  detector_.scan(span_, integ_, dynamics_.step(), !constant && adaptive ? &end_record_ : nullptr, events_, exits);
  // A ball that left play is frozen where it left.
  StateVector at;
  for (const Exit& e : exits) {
    span_.interpolate(e.time, at);
    std::erase_if(span_.tails, [&](const BandTail& tail) { return tail.ball == e.ball; });
    std::erase_if(span_.swings, [&](const Swing& swing) { return swing.ball == e.ball; });
    integ_.in_play[e.ball] = 0;
    set_position(span_.x1, e.ball, position(at, e.ball));
    set_velocity(span_.x1, e.ball, Vec3{0.0});
    set_spin(span_.x1, e.ball, Vec3{0.0});
  }
  const bool regime_changed = regimes_.update(integ_, span_.x1, t - span_.t0);
  if (!exits.empty() || regime_changed) {
    // The system lost or froze bodies, or woke them: the integrator starts afresh from the step's end. The finished
    // step's interpolant stays for the caller's clock, with the exited balls frozen in it.
    const StepSpan finished = span_;
    restart();
    span_.x0 = finished.x0;
    span_.f0 = finished.f0;
    span_.t0 = finished.t0;
    for (const Exit& e : exits)
      for (int k = 0; k < kBallDofs; ++k) {
        span_.x0[kBallDofs * e.ball + k] = span_.x1[kBallDofs * e.ball + k];
        span_.f0[kBallDofs * e.ball + k] = 0.0;
      }
  }
  return true;
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
  f.resize(x.size());
  dynamics_(x, f, t1);
  trial_.t1 = t1;
  stats_.last_step = h;
}

// s: the step from an onset (StepContacts::onset) over which the part of the error the onset's force alone causes
// comes to `tolerance` (m/s): that error is coefficient k h^(e+1) (stepper.hpp, onset_error_coefficient) with
// k = onset_strength.
double Island::onset_step(double tolerance) {
  const StepContacts& s = dynamics_.step();
  if (s.onset_exponent != onset_exponent_) {
    onset_exponent_ = s.onset_exponent;
    onset_coefficient_ = onset_error_coefficient(model_.integrator.method, onset_exponent_);
  }
  if (onset_coefficient_ <= 0 || s.onset_strength <= 0) return std::numeric_limits<double>::infinity();
  return std::pow(tolerance / (onset_coefficient_ * s.onset_strength), 1.0 / (onset_exponent_ + 1.0));
}

bool Island::integrate(double dt, double limit, double& t) {
  const bool adaptive = is_adaptive(model_.integrator.method);
  const double wanted = dt_next_;
  // A change the last step's trials saw past where they were cut ends this step (aim_): a trial across it would be
  // redone to end there, two trials for one step. Located on a trial that crossed the cut's kink, it is not always
  // close enough (a step that ends short of it is followed by a short one), but on balance it pays: on the break,
  // the rack's trials 790 -> 718 and 5 % fewer instructions in all.
  const double aim = aim_;
  aim_ = std::numeric_limits<double>::infinity();
  if (adaptive && aim > span_.t1 && aim - span_.t1 < dt) dt = aim - span_.t1;
  const bool capped = dt < wanted;
  StepSpan& trial = trial_;
  StateVector &x = trial.x1, &f = trial.f1;
  double tried;
  int retries = 0;
  double passed = 0;     // the first trial the error control accepted, s
  bool at_onset = false;  // the step was cut where a contact begins
  std::optional<ContactKey> aimed;  // the contact left out of the step where it was cut to end (first_touch)
  const long rejected_before = stats_.rejected_steps;
  // The contacts at the step's start, as the last evaluation there recorded them (the step's end before, or the start
  // again where the contact lists changed), to compare each trial's end with.
  auto by_key = [](const ContactRecord& a, const ContactRecord& b) { return a.key < b.key; };
  if (end_record_is_start_) {
    start_record_.swap(end_record_);
  } else if (adaptive) {  // the fixed-step methods cut no step
    start_record_ = dynamics_.recorded();
    std::sort(start_record_.begin(), start_record_.end(), by_key);
  }
  end_record_is_start_ = false;
  // A contact that begins at the step's start (StepContacts::onset) makes an error the estimate understates. The
  // step starts at the length where that error is 0.9 of the tolerance: the strict controller would shrink a longer
  // trial to about there anyway, one rejection (six right-hand sides) at a time, and a step that ends at an onset hands
  // over its own length, which has nothing to do with the contact's. That trial takes the tolerance of a velocity at
  // the closing speed; the controller checks it. The step is held to the strict tolerance where that error can
  // matter, over a tenth of the absolute tolerance (the body struck may have been at rest, where the relative share
  // is nothing); not for the pairs of a resting rack that begin to close at micrometres per second, where the strict
  // tolerance would only tighten the rack's every step (S6 at 1e-7: 5e-7 R -> 9e-8 R, but the break's rack 10 %
  // slower, the same as asking for a tighter tolerance).
  bool from_onset = false;
  if (dynamics_.step().onset) {
    const IntegratorOptions& o = model_.integrator;
    dt = std::min(dt, onset_step(0.9 * (o.abs_tol + o.rel_tol * dynamics_.step().onset_speed)));
    from_onset = dt > onset_step(0.1 * o.abs_tol);
  }
  for (;;) {
    x = trial.x0;
    f = trial.f0;
    t = span_.t1;
    tried = dt;
    if (stepper_->try_step(dynamics_, x, f, t, dt, from_onset)) {
      // A contact that begins or ends inside the step puts a kink (linear damping: a jump) in the force, where every
      // embedded error estimate misjudges a high-order step (MODEL.md, "Numerical facts"), and so does a friction term
      // that enters or leaves its smoothing band (friction_switched): a slip driven through the band by a hard contact
      // crosses it in a fraction of the step, a sign switch the estimate may not see at all (in a breaking rack such
      // steps were 8-13 times the tolerance). Redo the step so that it ends at the change, located on this step's
      // dense output; the next step then starts at the kink. An onset of a contact left out of the step, any release and
      // any friction switch end the step however early they come; other onsets and ends of contacts in the first 1 % of
      // a step are left alone, where a redone step's successor finds them.
      if (!adaptive) break;
      if (retries == 0) passed = tried;
      trial.t1 = t;
      const StepContacts& kept = dynamics_.step();
      end_record_ = dynamics_.recorded();
      std::sort(end_record_.begin(), end_record_.end(), by_key);
      const auto change = detector_.first_contact_change(trial, integ_, kept, &end_record_);
      const double early = span_.t1 + 0.01 * tried;
      constexpr double inf = std::numeric_limits<double>::infinity();
      ContactKey touching;
      const double touch = detector_.first_touch(trial, kept.separated, &touching);
      const double onset = std::min(change.begin > early ? change.begin : inf, touch);
      // Releases and friction switches, however early: a contact whose law the step kept unclamped would pull all
      // through the step, and a friction switch just after the start is a slip driven through its band in a moment,
      // where the step's first stage would see the friction before it turned.
      const auto law = detector_.first_law_change(trial, start_record_, end_record_);
      const double cut = std::min({onset, change.end > early ? change.end : inf, law.release, law.friction});
      if (cut >= t - kOnsetResolution) {
        // A step redone to end where a contact left out of it touches was aimed at a root of the last trial's
        // interpolant, which may fall short of the redone step's own: ended there, the next step would start a few
        // picometres apart, its first stage without the contact's force (with linear damping, c v for all the rest
        // of the step), which the error estimate hardly sees (S5's cradle: three such onsets, each 21x the
        // tolerance, made up nearly all of its error). Such a step goes on by the time the gap takes to close at its
        // closing speed, to half the onset resolution past the touch (within the test above once located again), but
        // never past the first trial the error control passed, which kept to every cap and to `limit`.
        if (!aimed || retries == kMaxRedos) break;
        const double longer = tried + detector_.time_to_touch(trial, *aimed) + 0.5 * kOnsetResolution;
        if (!(longer > tried + 0.5 * kOnsetResolution && longer <= passed)) break;
        dt = longer;
        ++retries;
        ++stats_.redone_steps;
        continue;
      }
      at_onset = cut == onset;
      // The changes each trial of the step saw after its cut: the earliest of them past the step's end ends the next
      // step (integrate's start). Onsets are left to the onset's own step length, and a cut an earlier trial made that
      // this one fell short of is no such change (the trajectory that reached it was not the one redone): aiming at
      // either cost more steps than it saved.
      for (const double later : {change.end, law.release, law.friction, law.next})
        if (later > cut + kTimeResolution) aim_ = std::min(aim_, later);
      aimed.reset();
      if (cut == touch) aimed = touching;
      if (retries == kMaxRedos) {
        if (kept.separated.empty() && kept.pushing.empty()) break;
        // Still a change inside: the step again with the plain law, its kinks left to the error control.
        StepContacts plain;
        dynamics_.swap_step(plain);
        dt = tried;
        continue;
      }
      dt = cut - span_.t1;
      ++retries;
      ++stats_.redone_steps;
      continue;
    } else if (!std::isfinite(dt) || dt < 1e-14) {
      std::ostringstream msg;
      msg << "step too small: the error control shrank the step to " << dt << " s at t = " << span_.t1 << " s. "
          << describe_balls(span_.x1);
      stop(Status::StepTooSmall, msg.str());
      return false;
    }
    ++stats_.rejected_steps;
    aimed.reset();  // a shorter trial than the cut: the next step finds the onset
  }
  if (retries == 0 && tried == limit - span_.t1) t = limit;
  stats_.last_step = tried;
  end_record_is_start_ = adaptive;  // the accepted trial's end, sorted: the next step's start unless restarted
  // After a rejection, do not grow the step at once: odeint's controller would grow it up to 5x and, on a
  // stability-limited problem (the stiff friction switch), be rejected again. A step cut short where a contact begins,
  // ends or releases passed the error control at its first length, so the next one may try that again (in a breaking
  // rack, contacts change every 15 us and each cut would otherwise shrink the steps after it); after an onset, the
  // onset's own step length caps it (onset_step: its force was not in that trial, and a loose setting's error estimate
  // could pass a step across all of it; methods without that estimate, Bulirsch-Stoer and Rosenbrock 4, keep to the cut
  // length, tests/stability/impact_test.cpp). Taking the cut length instead left the contact's first steps to the
  // accident of where the step before it ended: S1 at 0.5 m/s, where islands join 2 us before the contact, ended 1.6e-7
  // v0 off at 1e-7 against the plain path's 8e-9. Where that first length was itself cut by a cap (on the approach to
  // a contact the cap's last trial is a few microseconds), the step the caller wanted stands, as for a capped step
  // that is not redone: S5's fast path, whose last step before the touch ended 0.5 us short of it, began the cradle's
  // chain with 2.2 us steps where the plain path began with 5.7 us ones; now both take the same steps through it. A
  // step that starts at an onset and is held to the strict tolerance (stepper.hpp) had its rejections from that
  // length, not from stiffness. The next one starts clear of the onset, where the estimate holds again, so it may be
  // as long as the plain tolerance allows: these fifth-order controllers size a step as (tolerance / error)^(1/5), so
  // onset_factor^(1/5) longer than the strict one suggests (S1 at 8 m/s: 32 steps through the contact without this, 30
  // with it).
  const bool rejected = stats_.rejected_steps > rejected_before, sized = onset_growth_ > 1;  // sized: has onset_step
  if (from_onset && sized && !(retries > 0 && at_onset))
    dt_next_ = (rejected ? std::min(dt, tried) : dt) * onset_growth_;
  else if (rejected || (retries > 0 && at_onset && !sized)) dt_next_ = std::min(dt, tried);
  else if (retries > 0) dt_next_ = std::max({dt, passed, capped ? wanted : 0.0});
  else dt_next_ = capped ? std::max(dt, wanted) : dt;
  return true;
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
