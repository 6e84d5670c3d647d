// Step control of an island's integrated step: the error-controlled trials, the cuts at contact and friction changes
// located on a trial's dense output, the redos, and the next step's length (docs/model.md#step-control).
#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "check.hpp"
#include "island.hpp"

namespace shotlab {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

bool by_key(const ContactRecord& a, const ContactRecord& b) { return a.key < b.key; }

}  // namespace

// s: the step from an onset (StepContacts::onset) over which the part of the error the onset's force alone causes
// comes to `tolerance` (m/s): that error is coefficient k h^(e+1) (stepper.hpp, onset_error_coefficient) with
// k = onset_strength.
double Island::onset_step(double tolerance) {
  const StepContacts& s = dynamics_.plan();
  if (s.onset_exponent != onset_exponent_) {
    onset_exponent_ = s.onset_exponent;
    onset_coefficient_ = onset_error_coefficient(model_.integrator.method, onset_exponent_);
  }
  if (s.onset_strength <= 0) return kInf;
  if (onset_coefficient_ <= 0) {
    // A whole exponent: Cash-Karp and Dormand-Prince integrate the onset's polynomial force exactly, so no error
    // bounds the step, and one may pass through the contact. A quarter of the contact's own time scale,
    // (v / strength)^(1/(e+1)) (it lasts about three, docs/model.md#restitution), holds it.
    const bool tableau = model_.integrator.method == Method::CashKarp54 || model_.integrator.method == Method::DormandPrince5;
    return tableau ? 0.25 * std::pow(s.onset_speed / s.onset_strength, 1.0 / (onset_exponent_ + 1.0)) : kInf;
  }
  return std::pow(tolerance / (onset_coefficient_ * s.onset_strength), 1.0 / (onset_exponent_ + 1.0));
}

// The contacts at the step's start as the last evaluation there recorded them (the last step's accepted end, or the
// start again where the contact lists changed), to compare each trial's end with.
void Island::load_start_record(bool adaptive) {
  if (end_record_is_start_) {
    start_record_.swap(end_record_);
  } else if (adaptive) {  // the fixed-step methods cut no step
    start_record_ = dynamics_.recorded();
    std::sort(start_record_.begin(), start_record_.end(), by_key);
  }
  end_record_is_start_ = false;
}

bool Island::integrate(double dt, double limit, double& t) {
  const bool adaptive = is_adaptive(model_.integrator.method);
  const double wanted = dt_next_;
  // A change the last step's trials saw past where they were cut ends this step: a trial across it would be redone.
  const double aim = aim_;
  aim_ = kInf;
  if (adaptive && aim > span_.t1 && aim - span_.t1 < dt) dt = aim - span_.t1;
  const bool capped = dt < wanted;
  load_start_record(adaptive);
  // A step from an onset starts where the onset's own error is 0.9 of the tolerance at the closing speed, and is held
  // to the strict tolerance where that error can matter, over a tenth of abs_tol (stepper.hpp).
  bool from_onset = false;
  if (dynamics_.plan().onset) {
    const IntegratorOptions& o = model_.integrator;
    dt = std::min(dt, onset_step(0.9 * (o.abs_tol + o.rel_tol * dynamics_.plan().onset_speed)));
    from_onset = dt > onset_step(0.1 * o.abs_tol);
  }
  Trials trials;
  const long rejected_before = stats_.rejected_steps;
  [[maybe_unused]] const long laws = dynamics_.plan_swaps();
  for (;;) {
    trial_.x1 = trial_.x0;
    trial_.f1 = trial_.f0;
    t = span_.t1;
    trials.tried = dt;
    if (stepper_->try_step(dynamics_, trial_.x1, trial_.f1, t, dt, from_onset)) {
      SHOTLAB_ASSERT(dynamics_.plan_swaps() == laws + trials.plain, "a contact law stays frozen within its step");
      if (!adaptive || !cut_at_change(trials, t, dt)) break;
      continue;
    }
    if (!std::isfinite(dt) || dt < 1e-14) {
      std::ostringstream msg;
      msg << "step too small: the error control shrank the step to " << dt << " s at t = " << span_.t1 << " s. "
          << describe_balls(span_.x1);
      stop(Status::StepTooSmall, msg.str());
      return false;
    }
    ++stats_.rejected_steps;
    trials.aimed.reset();  // a shorter trial than the cut: the next step finds the onset
  }
  if (trials.retries == 0 && trials.tried == limit - span_.t1) t = limit;
  stats_.last_step = trials.tried;
  end_record_is_start_ = adaptive;  // the accepted trial's end, sorted: the next step's start unless restarted
  size_next_step(dt, wanted, capped, from_onset, trials, stats_.rejected_steps > rejected_before);
  return true;
}

// After a trial the error control passed (ending at t): a contact that begins or ends inside it, a release or a
// friction switch puts a kink in the force, where every embedded error estimate misjudges a high-order step
// (docs/model.md#step-control). Returns true with the new trial length in dt when the step is to be redone to end at
// the first such change; false when the trial stands. Onsets and ends in the first 1 % of a step are left to the next.
bool Island::cut_at_change(Trials& tr, double t, double& dt) {
  if (tr.retries == 0) tr.passed = tr.tried;
  trial_.t1 = t;
  const StepContacts& kept = dynamics_.plan();
  end_record_ = dynamics_.recorded();
  std::sort(end_record_.begin(), end_record_.end(), by_key);
  const auto change = detector_.first_contact_change(trial_, integ_, kept, &end_record_, &start_record_);
  const double early = span_.t1 + kEarlyShare * tr.tried;
  ContactKey touching;
  const double touch = detector_.first_touch(trial_, kept.separated, &touching);
  const double onset = std::min(change.begin > early ? change.begin : kInf, touch);
  // Releases and friction switches end the step however early they come (bar the band edges first_law_change crosses).
  const auto law = detector_.first_law_change(trial_, start_record_, end_record_);
  const double cut = std::min({onset, change.end > early ? change.end : kInf, law.release, law.friction});
  if (cut >= t - kOnsetResolution) return go_on_to_touch(tr, dt);
  tr.at_onset = cut == onset;
  // The changes this trial saw after its cut: the earliest past the step's end ends the next step.
  for (const double later : {change.end, law.release, law.friction, law.next})
    if (later > cut + kTimeResolution) aim_ = std::min(aim_, later);
  tr.aimed.reset();
  if (cut == touch) tr.aimed = touching;
  if (tr.retries == kMaxRedos) {
    if (kept.separated.empty() && kept.pushing.empty()) return false;
    StepContacts plain;  // still a change inside: the step again with the plain law, its kinks left to the control
    dynamics_.swap_plan(plain);
    tr.plain = true;
    dt = tr.tried;
    return true;
  }
  dt = cut - span_.t1;
  ++tr.retries;
  ++stats_.redone_steps;
  return true;
}

// A trial with no change inside. One redone to end where a contact left out of it touches was aimed at a root of the
// last trial's interpolant, which may fall short of its own: it goes on by the time the gap takes to close, to half
// the onset resolution past the touch, never past the first trial the error control passed. True with dt when so.
bool Island::go_on_to_touch(Trials& tr, double& dt) {
  if (!tr.aimed || tr.retries == kMaxRedos) return false;
  const double longer = tr.tried + detector_.time_to_touch(trial_, *tr.aimed) + 0.5 * kOnsetResolution;
  if (!(longer > tr.tried + 0.5 * kOnsetResolution && longer <= tr.passed)) return false;
  dt = longer;
  ++tr.retries;
  ++stats_.redone_steps;
  return true;
}

// The next step's trial length (dt: what the stepper suggests after the accepted trial). After a rejection, do not grow
// the step at once (a stability-limited stiff switch would be rejected again), but a step then cut at a change within
// 1 % of the length that passed (a few ns on: the next steps would only grow it back) goes on at that length; a step
// cut at a change passed the control at its first length and may try it again; after an onset the onset's own length
// caps it, and the step after one that started at an onset may be onset_factor^(1/5) longer
// (docs/model.md#step-control).
void Island::size_next_step(double dt, double wanted, bool capped, bool from_onset, const Trials& tr, bool rejected) {
  const bool sized = onset_growth_ > 1;  // the method has onset_step
  if (from_onset && sized && !(tr.retries > 0 && tr.at_onset))
    dt_next_ = (rejected ? std::min(dt, tr.tried) : dt) * onset_growth_;
  else if (rejected && tr.retries > 0 && !tr.at_onset && tr.tried < 0.01 * tr.passed) dt_next_ = tr.passed;
  else if (rejected || (tr.retries > 0 && tr.at_onset && !sized)) dt_next_ = std::min(dt, tr.tried);
  else if (tr.retries > 0) dt_next_ = std::max({dt, tr.passed, capped ? wanted : 0.0});
  else dt_next_ = capped ? std::max(dt, wanted) : dt;
}

}  // namespace shotlab
