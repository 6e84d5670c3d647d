#include "simulation.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace shotlab {

const char* status_name(Status s) {
  static constexpr const char* names[] = {"ok", "step_limit", "non_finite", "step_too_small", "unstable"};
  return names[static_cast<int>(s)];
}

Simulation::Simulation(Model model, State initial)
    : model_(std::move(model)),
      integ_(std::move(initial)),
      state_(integ_),
      dynamics_(model_, integ_),
      stepper_(make_stepper(model_.integrator)),
      detector_(model_),
      regimes_(model_),
      cap_cache_(model_),
      dt_next_(is_adaptive(model_.integrator.method) ? model_.integrator.initial_step : model_.integrator.fixed_step) {
  span_.t0 = span_.t1 = integ_.time;
  span_.x1 = integ_.x;
  restart();
  // Balls that start at rest (in their static sink on the bed, nothing moving against them) sleep from the start
  // instead of after sleep_time of integrating a contact that cannot move.
  if (regimes_.update(integ_, span_.x1, model_.options.sleep_time)) restart();
  state_ = integ_;
  const Energy e = energy();
  energy_start_ = e.total();
  energy_scale_ = e.kinetic + e.elastic + 1.0;
}

void Simulation::restart() {
  span_.f1.resize(span_.x1.size());
  dynamics_(span_.x1, span_.f1, span_.t1);
  span_.x0 = span_.x1;
  span_.f0 = span_.f1;
  span_.t0 = span_.t1;
  stepper_->reset();
  integ_.x = span_.x1;
  integ_.time = span_.t1;
  detector_.reset(integ_);
  energy_frozen_ = shotlab::energy(model_, integ_, cap_cache_, true).total() -
                   shotlab::energy(model_, integ_, cap_cache_, false).total();
}

bool Simulation::at_rest() const {
  for (int i = 0; i < state_.ball_count(); ++i) {
    if (state_.sleeping(i)) continue;  // frozen at rest
    const Motion m = motion(i);
    if (m != Motion::Stationary && m != Motion::Pocketed) return false;
  }
  return true;
}

Status Simulation::advance(double dt) {
  // The clock only runs forward: the dense output of the last step cannot go back past its start.
  if (!(dt >= 0)) throw std::invalid_argument("Simulation::advance: dt must be >= 0 s, got " + std::to_string(dt));
  if (status_ != Status::Ok) return status_;
  const auto wall0 = std::chrono::steady_clock::now();
  const double target = state_.time + dt;
  int steps = 0;
  while (span_.t1 < target && status_ == Status::Ok) {
    if (steps++ >= model_.integrator.max_steps_per_call) {
      std::ostringstream msg;
      msg << "step limit: " << model_.integrator.max_steps_per_call << " steps in one advance() did not reach t = "
          << target << " s; stopped at t = " << span_.t1 << " s with step " << stats_.last_step << " s. "
          << describe_balls(span_.x1);
      stop(Status::StepLimit, msg.str());
      break;
    }
    step();
  }
  if (status_ == Status::Ok) {
    span_.interpolate(target, state_.x);
    state_.time = target;
  } else {  // stay at the last good point
    state_.x = span_.x1;
    state_.time = span_.t1;
  }
  state_.in_play = integ_.in_play;
  state_.asleep = integ_.asleep;
  state_.rolling_on = integ_.rolling_on;
  if (status_ == Status::Ok) {
    const double e = shotlab::energy(model_, state_, cap_cache_, false).total() + energy_frozen_;
    if (e - energy_start_ > energy_scale_) {
      std::ostringstream msg;
      msg << "unstable: the total energy grew from " << energy_start_ << " J to " << e << " J by t = " << state_.time
          << " s, which a passive system cannot do: the step is too large for the contact stiffness (use an adaptive "
             "method, a smaller fixed step or a softer material). "
          << describe_balls(state_.x);
      stop(Status::Unstable, msg.str());
    }
  }
  stats_.rhs_evaluations = dynamics_.evaluations();
  stats_.wall_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  return status_;
}

bool Simulation::step() {
  const bool adaptive = is_adaptive(model_.integrator.method);
  double dt = adaptive ? dt_next_ : model_.integrator.fixed_step;
  const double wanted = dt;
  if (adaptive) dt = std::min(dt, time_to_possible_contact(model_, integ_, span_.x1.data(), dt, cap_cache_));
  const bool capped = dt < wanted;
  StateVector x, f;
  double t, tried;
  int retries = 0;
  const long rejected_before = stats_.rejected_steps;
  for (;;) {
    x = span_.x1;
    f = span_.f1;
    t = span_.t1;
    tried = dt;
    if (stepper_->try_step(dynamics_, x, f, t, dt)) {
      // A contact that begins or ends inside the step puts a kink (linear damping: a jump) in the force, where every
      // embedded error estimate misjudges a high-order step (MODEL.md, "Numerical facts"). Redo the step so that it
      // ends at the change, located on this step's dense output; the next step then starts at the kink. Changes in
      // the first 1 % of a step are left alone: that is where a redone step's successor finds them.
      if (!adaptive || retries == 3) break;
      const StepSpan trial{span_.t1, t, span_.x1, span_.f1, x, f};
      const double onset = detector_.first_contact_change(trial, integ_);
      if (onset <= span_.t1 + 0.01 * tried || onset >= t) break;
      dt = onset - span_.t1;
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
  }
  stats_.last_step = tried;
  ++stats_.steps;
  // After a rejection, do not grow the step at once: odeint's controller would grow it up to 5x and, on a
  // stability-limited problem (the stiff friction switch), be rejected again.
  dt_next_ = retries > 0 || stats_.rejected_steps > rejected_before ? std::min(dt, tried) : capped ? std::max(dt, wanted) : dt;

  if (!std::all_of(x.begin(), x.end(), [](double v) { return std::isfinite(v); })) {
    std::ostringstream msg;
    msg << "non-finite state in the step from t = " << span_.t1 << " s to " << t << " s; balls: ";
    for (int i = 0; i < integ_.ball_count(); ++i)
      for (int k = 0; k < kBallDofs; ++k)
        if (!std::isfinite(x[9 * i + k])) {
          msg << model_.balls[i].id << " ";
          break;
        }
    msg << ". Last finite state: " << describe_balls(span_.x1);
    stop(Status::NonFinite, msg.str());
    return false;
  }

  span_.x0.swap(span_.x1);
  span_.f0.swap(span_.f1);
  span_.t0 = span_.t1;
  span_.x1 = std::move(x);
  span_.f1 = std::move(f);
  span_.t1 = t;
  integ_.x = span_.x1;
  integ_.time = t;

  std::vector<Exit> exits;
  detector_.scan(span_, integ_, events_, exits);
  if (observer_) observer_(span_);
  // A ball that left play is frozen where it left.
  StateVector at;
  for (const Exit& e : exits) {
    span_.interpolate(e.time, at);
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
        span_.x0[9 * e.ball + k] = span_.x1[9 * e.ball + k];
        span_.f0[9 * e.ball + k] = 0.0;
      }
  }
  return true;
}

void Simulation::stop(Status why, std::string message) {
  status_ = why;
  diagnostic_ = std::move(message);
}

// The balls worth naming in a diagnostic: those in contact at x with depth and force, or else the pair closest to
// touching (a failing step usually runs into the contact that this pair is about to make).
std::string Simulation::describe_balls(const StateVector& x) const {
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
  out << "No contacts; closest pair: " << pair << " (gap " << best << " m).";
  return out.str();
}

}  // namespace shotlab
