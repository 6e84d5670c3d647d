// The contact law's forms and the error control's units: the bed's component form (UpNormal) against the generic
// law, what counts as a friction switch (friction_switched, band_edges_only) and where a trial's switches are located
// (EventDetector::first_law_change), and a spin held to the tolerance as a surface speed (BallErrorChecker).
#include <algorithm>
#include <random>
#include <string>

#include "engine/contact_force.hpp"
#include "engine/dynamics.hpp"
#include "engine/events.hpp"
#include "engine/stepper.hpp"

#include "support.hpp"

namespace shotlab::test {
namespace {

// The bed's component form must be the same law: for random states of a ball on the cloth, sliding, rolling, spinning
// or nearly at rest (inside every band), the same forces to the last bit (a zero's sign aside, which == ignores).
TEST(ContactLaw, BedComponentFormIsTheGenericLaw) {
  const ContactMaterial cloth = empty_model().material(kBallCloth);
  const Smoothing smoothing{1000.0, 2e5};
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> speed(-2.0, 2.0), slow(-2e-3, 2e-3), depth(1e-7, 2e-4);
  for (int n = 0; n < 2000; ++n) {
    auto draw = [&] { return n % 2 ? speed(rng) : slow(rng); };
    const Vec3 v{draw(), draw(), draw()}, w{draw() / kR, draw() / kR, draw() / kR};
    const double d = depth(rng), inv_m = 1 / kM, inv_i = kR * kR / (0.4 * kM * kR * kR);
    const Kinematics<Vec3> generic{kUp, d, v, v + kR * glm::cross(kUp, w), glm::dot(w, kUp), kR, inv_m + inv_i, inv_m, inv_i};
    const Kinematics<UpNormal> up{UpNormal{}, d, v, v + kR * normal_cross(UpNormal{}, w), normal_component(w, UpNormal{}),
                                  kR, inv_m + inv_i, inv_m, inv_i};
    for (bool clamp : {true, false}) {
      const ContactForce a = contact_force(cloth, generic, smoothing, clamp), b = contact_force(cloth, up, smoothing, clamp);
      ASSERT_EQ(a.normal, b.normal);
      ASSERT_EQ(a.force, b.force) << n;
      ASSERT_EQ(a.friction, b.friction) << n;
      ASSERT_EQ(a.rolling, b.rolling) << n;
      ASSERT_EQ(a.spin_torque, b.spin_torque) << n;
      ASSERT_EQ(a.bands, b.bands) << n;
    }
    ASSERT_EQ(generic.slip, up.slip);
    ASSERT_EQ(generic.spin_rel, up.spin_rel);
  }
}

// A switch is a term entering or leaving its band, or a saturated term turned around; inside the band a term runs
// smoothly through zero (a resting contact's round-off turns it every which way), and a stronger or weaker force in
// the same law is no switch.
TEST(ContactLaw, FrictionSwitches) {
  ContactForce sliding;
  sliding.friction = {-0.3, 0.0, 0.0};
  ContactForce reversed = sliding, stronger = sliding, in_band = sliding;
  reversed.friction = {0.3, 0.0, 0.0};
  stronger.friction = {-0.5, 0.0, 0.1};
  in_band.friction = {-0.1, 0.0, 0.0};
  in_band.bands = kSlipInBand;
  EXPECT_TRUE(friction_switched(FrictionState(sliding), FrictionState(reversed)));
  EXPECT_TRUE(friction_switched(FrictionState(sliding), FrictionState(in_band)));
  EXPECT_FALSE(friction_switched(FrictionState(sliding), FrictionState(stronger)));
  ContactForce in_band_turned = in_band;
  in_band_turned.friction = {1e-17, 0.0, 0.0};
  EXPECT_FALSE(friction_switched(FrictionState(in_band), FrictionState(in_band_turned)));
  ContactForce limited = in_band;
  limited.bands = kSlipInBand | kSlipLimited;
  EXPECT_TRUE(friction_switched(FrictionState(in_band), FrictionState(limited)));  // the rate limit set in: a kink in N
  ContactForce spin_a, spin_b;
  spin_a.spin_torque = 1e-4, spin_b.spin_torque = -1e-4;
  EXPECT_TRUE(friction_switched(FrictionState(spin_a), FrictionState(spin_b)));
}

// Of the switches, band edges alone (a term entering or leaving its band, with or without the rate limit's widening)
// keep the force's first derivative; the rate limit setting in inside the band and a saturated term turned around do
// not.
TEST(ContactLaw, BandEdgesOnly) {
  ContactForce sliding, in_band, limited, reversed, rolling_in, spin_a, spin_b;
  sliding.friction = {-0.3, 0.0, 0.0};
  in_band = limited = reversed = rolling_in = sliding;
  in_band.friction = {-0.1, 0.0, 0.0};
  in_band.bands = kSlipInBand;
  limited.bands = kSlipInBand | kSlipLimited;
  reversed.friction = {0.3, 0.0, 0.0};
  rolling_in.bands = kRollInBand;
  EXPECT_TRUE(band_edges_only(FrictionState(sliding), FrictionState(in_band)));
  EXPECT_TRUE(band_edges_only(FrictionState(in_band), FrictionState(sliding)));
  EXPECT_TRUE(band_edges_only(FrictionState(sliding), FrictionState(limited)));  // into a band the limit widened
  EXPECT_TRUE(band_edges_only(FrictionState(in_band), FrictionState(rolling_in)));
  EXPECT_FALSE(band_edges_only(FrictionState(in_band), FrictionState(limited)));  // the limit set in: a kink in N
  EXPECT_FALSE(band_edges_only(FrictionState(sliding), FrictionState(reversed)));
  spin_a.spin_torque = 1e-4, spin_b.spin_torque = -1e-4;
  spin_b.bands = kSlipInBand;
  EXPECT_FALSE(band_edges_only(FrictionState(spin_a), FrictionState(spin_b)));
}

// The law changes first_law_change finds on a trial of h seconds in which balls slide apart on the cloth, without
// spin, at the speeds u (m/s), integrated by `method`: saturated friction mu m g takes slip off at mu g (the centre)
// plus 5/2 mu g (the spin it builds), so each slip enters its band (1/k = 1 mm/s) at (u - 1e-3) / (3.5 mu g). The
// trial is that constant deceleration, a quadratic, which the span's cubic interpolant holds exactly; its end is
// evaluated by the law (the slips there may have turned around).
EventDetector::LawChanges sliding_apart(const std::vector<double>& u, double h, const std::string& method) {
  nlohmann::json balls = nlohmann::json::array();
  for (size_t i = 0; i < u.size(); ++i)
    balls.push_back({{"id", std::to_string(i)}, {"position", {0.5 * i, kR, 0}}, {"velocity", {0, 0, u[i]}}});
  nlohmann::json doc = cloth_scene(balls);
  doc["integrator"]["method"] = method;
  Prepared p = prepare(scene(doc));
  const ModelIndex index(p.model);
  Dynamics f(p.model, index, p.state);
  StepSpan span;
  span.t1 = h;
  span.x0 = span.x1 = p.state.x;
  f(span.x0, span.f0, 0.0);
  std::vector<ContactRecord> start = f.recorded(), end;
  span.f1 = span.f0;
  for (size_t i = 0; i < u.size(); ++i) {
    // The rest on the bed stays as it is (its vertical force balances the weight to round-off).
    span.f0[kBallDofs * i + 1] = span.f0[kBallDofs * i + 4] = 0.0;
    const Vec3 v = velocity(span.x0, i), a = velocity(span.f0, i), alpha = spin(span.f0, i);
    set_position(span.x1, i, position(span.x0, i) + v * h + 0.5 * h * h * a);
    set_velocity(span.x1, i, v + a * h);
    set_spin(span.x1, i, spin(span.x0, i) + alpha * h);
    set_position(span.f1, i, v + a * h);
    set_velocity(span.f1, i, a);
    set_spin(span.f1, i, alpha);
  }
  StateVector f1;
  f(span.x1, f1, h);
  end = f.recorded();
  auto by_key = [](const ContactRecord& x, const ContactRecord& y) { return x.key < y.key; };
  std::sort(start.begin(), start.end(), by_key);
  std::sort(end.begin(), end.end(), by_key);
  return EventDetector(p.model, index).first_law_change(span, start, end);
}

// A trial across friction switches of several contacts reports the first as the one to cut at and the second as
// `next`, where the step after the cut ends (Island::integrate); a third is not looked for. Three balls slide apart at
// 3, 2 and 1 cm/s (sliding_apart): their slips enter their bands at 4.22, 2.77 and 1.31 ms of a 5 ms trial, in the
// order of the contacts' keys (each one found is earlier than the last).
TEST(ContactLaw, TrialReportsTheNextSwitchAfterTheFirst) {
  const double u[] = {0.03, 0.02, 0.01}, rate = 3.5 * 0.2 * kG, h = 5e-3;
  const EventDetector::LawChanges law = sliding_apart({u[0], u[1], u[2]}, h, "dopri5");
  // Each located just past the switch, to the resolution of a switch on a span this long.
  EXPECT_NEAR(law.friction, (u[2] - 1e-3) / rate, switch_resolution(h));
  EXPECT_NEAR(law.next, (u[1] - 1e-3) / rate, switch_resolution(h));
  EXPECT_EQ(law.release, std::numeric_limits<double>::infinity());
}

// Band edges within the first 1 % of a Runge-Kutta trial are crossed. The slip enters its band at 0.2 % of the trial
// and the centre's speed, falling at mu g, enters the rolling resistance's at 0.7 %; the switch reported is where the
// slip leaves its band on the other side, (u + 1e-3) / (3.5 mu g), at 6 %. Bulirsch-Stoer, whose extrapolation wants
// a smooth right-hand side, cuts at the first entry however early.
TEST(ContactLaw, BandEdgesNearTheStartAreCrossedByRungeKutta) {
  const double rate = 3.5 * 0.2 * kG, h = 5e-3, entry = 0.002 * h, u = 1e-3 + rate * entry;
  for (const char* method : {"dopri5", "cash_karp54"}) {
    const EventDetector::LawChanges law = sliding_apart({u}, h, method);
    EXPECT_NEAR(law.friction, (u + 1e-3) / rate, switch_resolution(h)) << method;
  }
  EXPECT_NEAR(sliding_apart({u}, h, "bulirsch_stoer").friction, entry, switch_resolution(h));
}

// abs_tol holds a position in m, a velocity in m/s and a spin w as the surface speed R w in m/s: on a ball of radius
// 0.03 m an error of 1e-7 / 0.03 rad/s is one tolerance, as is 1e-7 m/s of velocity; the relative share counts the
// component's size and its change over the step, as odeint's default checker does.
TEST(ErrorControl, SpinIsHeldAsASurfaceSpeed) {
  const BallErrorChecker check(1e-7, 1e-7, {0.03});
  const StateVector at_rest(kBallDofs, 0.0);
  auto ratio = [&](int component, double error, const StateVector& x = StateVector(kBallDofs, 0.0)) {
    StateVector err(kBallDofs, 0.0);
    err[component] = error;
    return check.error(x, at_rest, err, 1e-3);
  };
  EXPECT_NEAR(ratio(0, 1e-7), 1.0, 1e-12);         // position, m
  EXPECT_NEAR(ratio(4, 1e-7), 1.0, 1e-12);         // velocity, m/s
  EXPECT_NEAR(ratio(7, 1e-7 / 0.03), 1.0, 1e-12);  // spin, rad/s: R w = 1e-7 m/s
  EXPECT_NEAR(ratio(7, 1e-7), 0.03, 1e-12);
  StateVector spinning(kBallDofs, 0.0);
  spinning[7] = 100.0;  // rad/s: a relative share of 1e-7 x 100 rad/s besides the absolute 1e-7 / 0.03
  EXPECT_NEAR(ratio(7, 1e-5, spinning), 1e-5 / (1e-7 / 0.03 + 1e-5), 1e-12);
}

}  // namespace
}  // namespace shotlab::test
