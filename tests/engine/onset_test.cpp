// Steps from a contact onset (stepper.hpp, onset_underestimate and onset_error_coefficient). Where a contact begins,
// its force grows as depth^1.5 from zero, and an explicit Runge-Kutta pair's error estimate understates the error of
// the step that starts there. The engine works out by how much from the method's weights; these tests take real
// steps of odeint's steppers across a real Hertz onset and measure it, and check the outcome of whole collisions
// against the exact answer of an undamped head-on hit (the balls swap velocities).
#include <boost/numeric/odeint.hpp>
#include <cstdio>
#include <type_traits>

#include "engine/dynamics.hpp"
#include "engine/stepper.hpp"

#include "support.hpp"

namespace shotlab::test {
namespace {

namespace odeint = boost::numeric::odeint;

// Two balls in free space, touching at 1e-14 m of depth (so that the force is on from the start, as after an onset
// located at zero depth), ball a closing on b at v; no damping, no friction.
Prepared touching_pair(double v) {
  const nlohmann::json doc = {{"gravity", {0, 0, 0}},
                              {"materials", {{"ball_ball", {{"friction", 0}, {"damping", 0}}}}},
                              {"balls",
                               {{{"id", "a"}, {"position", {-2 * kR + 1e-14, 0, 0}}, {"velocity", {v, 0, 0}}},
                                {{"id", "b"}, {"position", {0, 0, 0}}}}}};
  return prepare(scene(doc));
}

// One step of length h from the onset with `stepper` (odeint's error stepper: result and error estimate), against a
// reference integration of the same step at 1e-16: ball a's velocity error, true and estimated.
template <class ErrorStepper>
std::pair<double, double> onset_step_errors(ErrorStepper stepper, Prepared& p, double h) {
  const ModelIndex index(p.model);
  Dynamics f(p.model, index, p.state);
  const StateVector& x0 = p.state.x;
  StateVector dxdt(x0.size()), out(x0.size()), err(x0.size()), dxdt_out(x0.size());
  f(x0, dxdt, 0.0);
  if constexpr (std::is_same_v<ErrorStepper, odeint::runge_kutta_dopri5<StateVector>>)
    stepper.do_step(std::ref(f), x0, dxdt, 0.0, out, dxdt_out, h, err);  // first same as last: f at the end too
  else
    stepper.do_step(std::ref(f), x0, dxdt, 0.0, out, h, err);
  StateVector ref = x0;
  auto reference = odeint::make_controlled(1e-16, 1e-16, odeint::runge_kutta_dopri5<StateVector>());
  odeint::integrate_adaptive(reference, std::ref(f), ref, 0.0, h, h / 1000);
  return {std::abs(velocity(out, 0).x - velocity(ref, 0).x), std::abs(velocity(err, 0).x)};
}

// The error of a step of h from an onset at closing speed v is coefficient x k h^2.5 with k = C v^1.5 / m, and its
// estimate understates it by onset_underestimate, for every h and v (MODEL.md: C = 5e8 N/m^1.5, m = 0.17 kg).
TEST(Onset, StepErrorIsWhatTheWeightsSay) {
  const double stiffness = 5e8, mass = kM;
  for (double v : {0.5, 8.0})
    for (double h : {1e-7, 1e-6}) {
      Prepared p = touching_pair(v);
      const double k = stiffness * std::pow(v, 1.5) / mass;
      const auto [ck_true, ck_estimate] = onset_step_errors(odeint::runge_kutta_cash_karp54<StateVector>(), p, h);
      const auto [dp_true, dp_estimate] = onset_step_errors(odeint::runge_kutta_dopri5<StateVector>(), p, h);
      std::printf("[ onset    ] v %.1f m/s, h %.0e s: Cash-Karp true %.3e estimate %.3e, Dormand-Prince true %.3e "
                  "estimate %.3e (m/s)\n", v, h, ck_true, ck_estimate, dp_true, dp_estimate);
      const double scale = k * std::pow(h, 2.5);
      EXPECT_NEAR(ck_true / scale, onset_error_coefficient(Method::CashKarp54, 1.5), 0.02 * 5.8e-4);
      EXPECT_NEAR(dp_true / scale, onset_error_coefficient(Method::DormandPrince5, 1.5), 0.02 * 4.5e-4);
      EXPECT_NEAR(ck_true / ck_estimate, onset_underestimate(Method::CashKarp54, 1.5), 0.02 * 4.69);
      EXPECT_NEAR(dp_true / dp_estimate, onset_underestimate(Method::DormandPrince5, 1.5), 0.02 * 11.34);
    }
  EXPECT_EQ(onset_underestimate(Method::CashKarp54, 2.0), 1.0);  // a whole power: integrated exactly
  EXPECT_EQ(onset_underestimate(Method::RK4, 1.5), 1.0);
}

// An undamped head-on hit of equal balls swaps their velocities exactly. At the default tolerance (1e-7, relative to
// the speed) the engine must deliver that swap to within the tolerance at 0.5, 2 and 8 m/s. Before steps from an
// onset were held to the stricter tolerance, 2 m/s ended 1.4e-7 v0 off; before the step after an onset cut stopped
// taking the cut's length, 0.5 m/s ended 1.6e-7 v0 off (its islands join 2 us before the contact).
TEST(Onset, HeadOnHitSwapsVelocitiesWithinTheTolerance) {
  for (double v0 : {0.5, 2.0, 8.0}) {
    const nlohmann::json doc = {{"gravity", {0, 0, 0}},
                                {"materials", {{"ball_ball", {{"friction", 0}, {"damping", 0}}}}},
                                {"balls",
                                 {{{"id", "a"}, {"position", {-2 * kR - 1e-3, 0, 0}}, {"velocity", {v0, 0, 0}}},
                                  {{"id", "b"}, {"position", {0, 0, 0}}}}}};
    auto sim = simulate(scene(doc));
    ASSERT_EQ(sim->advance(1e-3 / v0 + 1e-3), Status::Ok);  // the contact lasts under 0.5 ms
    const StateVector& x = sim->state().x;
    const double off = std::max(glm::length(velocity(x, 0)), glm::length(velocity(x, 1) - Vec3(v0, 0, 0)));
    std::printf("[ swap     ] %.1f m/s: swapped to %.2e v0 in %ld steps\n", v0, off / v0, sim->stats().steps);
    EXPECT_LT(off / v0, 1e-7);
  }
}

// Newton's cradle (the bench's S5): each ball is pushed into the next, 10 um away, while still pressed by the one
// before, so three of its four onsets are located on a step's interpolant, whose root may fall a few picometres short
// of the redone step's own. A step that then starts short of the touch takes its first stage without the damped
// contact's force c v, which the error estimate hardly sees (each such step was 21x the tolerance). No step may start
// with a pair closing within kTouch of touching, and at the default tolerance every position and velocity at the end
// must agree with a reference run at 1e-12 to within the tolerance, weighed as odeint's error checker weighs a step
// (abs_tol + rel_tol |x|, leaving out its dt |dx/dt| share): 18.8x the tolerance before, 0.42 after.
TEST(Onset, CradleChainEndsWithinTheTolerance) {
  int short_starts = 0;
  auto run = [&](double tol) {
    Scene s = load_scene(preset("bench/s5_cradle.json"));
    s.model.integrator.abs_tol = s.model.integrator.rel_tol = tol;
    s.model.integrator.max_steps_per_call = 1000000;
    auto sim = simulate(s);
    sim->set_observer([&](const StepView& step) {
      const StateVector& x = step.state.x;  // where the next step starts
      for (size_t a = 0; a + 1 < step.balls.size(); ++a) {
        const Vec3 d = position(x, a + 1) - position(x, a);
        const double gap = glm::length(d) - 2 * kR;
        const double closing = glm::dot(velocity(x, a) - velocity(x, a + 1), d) / glm::length(d);
        if (gap >= 0 && gap < kTouch && closing > 1e-3) ++short_starts;
      }
    });
    [&] { ASSERT_EQ(sim->advance(s.duration), Status::Ok) << sim->diagnostic(); }();
    return sim->state().x;
  };
  const double tol = IntegratorOptions{}.abs_tol;
  const StateVector x = run(tol);
  EXPECT_EQ(short_starts, 0);
  const StateVector ref = run(1e-12);
  double worst = 0;
  for (size_t i = 0; i < x.size(); ++i)
    if (i % kBallDofs < 6) worst = std::max(worst, std::abs(x[i] - ref[i]) / (tol + tol * std::abs(ref[i])));
  std::printf("[ cradle   ] positions and velocities within %.2f of the tolerance\n", worst);
  EXPECT_LT(worst, 1.0);
}

}  // namespace
}  // namespace shotlab::test
