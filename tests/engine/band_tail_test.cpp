// The band tails (engine/band_tail.hpp): inside its smoothing band a regime ball's spin about the normal, and a
// rolling ball's speed, decay in closed form over long closed-form steps. The reference is the full model (every
// regime off, smoothed cloth friction integrated by odeint at 1e-13), which knows nothing of the closed forms; the
// fast path is read off its dense output at times inside those steps.
#include <cstdio>
#include <vector>

#include "engine/band_tail.hpp"

#include "support.hpp"

namespace shotlab::test {
namespace {

struct Track {
  std::vector<StateVector> x;  // at each time asked for
  long steps, rhs;
};

Track track(const nlohmann::json& doc, bool fast, const std::vector<double>& times, double reference_tol = 1e-13) {
  nlohmann::json d = doc;
  d["model"] = fast ? nlohmann::json{{"sleep_time", 0}}
                    : nlohmann::json{{"rolling_regime", false}, {"sliding_regime", false}, {"sleep_time", 0}};
  d["integrator"]["abs_tol"] = d["integrator"]["rel_tol"] = fast ? 1e-7 : reference_tol;
  auto sim = simulate(scene(d));
  Track out;
  for (double t : times) {
    advance_to(*sim, t);
    out.x.push_back(sim->state().x);
  }
  out.steps = sim->stats().steps;
  out.rhs = sim->stats().rhs_evaluations;
  return out;
}

// The closed form against its own differential equation, q' = -A fricstep(k q), by finite differences, and its
// integral and stop time against the formula's own pieces.
TEST(BandTail, DecayObeysItsEquation) {
  const BandDecay d{0.8e-3, 1000.0, 0.0981};
  for (double h : {0.0, 1e-3, 1e-2, 5e-2}) {
    const double e = 1e-7, dq = (d.at(h + e) - d.at(h - e)) / (2 * e);
    EXPECT_NEAR(dq, -d.rate * fricstep(d.sharpness * d.at(h)), 1e-9 * d.rate) << h;
    const double di = (d.integral(h + e) - d.integral(h - e)) / (2 * e);
    EXPECT_NEAR(di, d.at(h), 1e-9 * d.q0) << h;
  }
  EXPECT_EQ(d.integral(0.0), 0.0);
  EXPECT_NEAR(d.at(d.time_to(1e-7)), 1e-7, 1e-15);
  EXPECT_EQ(d.at(1e3), 0.0);  // the exponential overflows: stopped, not NaN
  EXPECT_TRUE(std::isfinite(d.integral(1e3)));
  // Far past the band the decay is linear in q, at 1.5 A k: the distance still to go from q is q / (1.5 A k).
  const double late = 0.04;
  EXPECT_NEAR(d.integral(1e3) - d.integral(late), d.at(late) / (1.5 * d.rate * d.sharpness), 1e-3 * d.at(late) / 147);
}

// A ball rolling at 0.8 mm/s with 0.6 mm/s of contact-patch speed about the vertical: both inside their 1 mm/s bands
// on the cloth (mu_r = 0.01, mu_sp = 0.0117, k = 1000 s/m), so both decay exponentially, at about 150 and 430 1/s.
// The fast path follows both in closed form until the speed stop cut at 5e-8 m/s (67 ms): 3 steps to 60 ms where
// integrating the tails took 27 (measured), and on its dense output as close to the full model at every time looked at
// as the full model's own error at 1e-13 (a few 1e-13 m/s at most, measured; at 1e-12, which holds a spin to
// 1e-12 m/s of surface speed, the full model itself is 4e-11 m/s off at 1 ms).
TEST(BandTail, RollingTailsFollowTheFullModel) {
  const double v0 = 0.8e-3, wn0 = 0.6e-3 / kR;
  const nlohmann::json doc = cloth_scene({{{"id", "cue"}, {"position", {0, kR, 0}}, {"velocity", {v0, 0, 0}},
                                           {"angular_velocity", {0, wn0, -v0 / kR}}}});
  const std::vector<double> times{1e-3, 4e-3, 1.5e-2, 4e-2, 6e-2};
  const Track fast = track(doc, true, times), full = track(doc, false, times);
  for (size_t k = 0; k < times.size(); ++k) {
    const StateVector &a = fast.x[k], &b = full.x[k];
    const double dx = glm::length(position(a, 0) - position(b, 0)), dv = glm::length(velocity(a, 0) - velocity(b, 0));
    const double dw = kR * glm::length(spin(a, 0) - spin(b, 0));
    std::printf("[ tails    ] t = %5.1f ms: |v| %.3e m/s, R w_n %.3e m/s; fast path off by %.1e m, %.1e m/s, R |dw| "
                "%.1e m/s\n", 1e3 * times[k], glm::length(velocity(b, 0)), kR * spin(b, 0).y, dx, dv, dw);
    EXPECT_LT(dx, 1e-12);
    EXPECT_LT(dv, 1e-11);
    EXPECT_LT(dw, 1e-11);
  }
  std::printf("[ tails    ] %ld steps and %ld right-hand sides on the fast path, %ld and %ld on the full model\n",
              fast.steps, fast.rhs, full.steps, full.rhs);
  EXPECT_LE(fast.steps, 12);
}

// A ball sliding at 1 m/s with 0.5 mm/s of patch speed about the vertical (inside its band): the sliding regime's
// spin tail keeps the slide in closed form (its slip reaches the band's edge only at 0.145 s): 5 steps to 0.1 s where
// integrating the tail took 30 (measured), with the full model's spin and the slide's parabola at every time looked at.
TEST(BandTail, SlidingSpinTailFollowsTheFullModel) {
  const nlohmann::json doc = cloth_scene({{{"id", "cue"}, {"position", {0, kR, 0}}, {"velocity", {1.0, 0, 0}},
                                           {"angular_velocity", {0, 0.5e-3 / kR, 0}}}});
  const std::vector<double> times{5e-3, 3e-2, 0.1};
  const Track fast = track(doc, true, times), full = track(doc, false, times);
  for (size_t k = 0; k < times.size(); ++k) {
    const StateVector &a = fast.x[k], &b = full.x[k];
    const double dx = glm::length(position(a, 0) - position(b, 0)), dv = glm::length(velocity(a, 0) - velocity(b, 0));
    const double dwn = kR * std::abs(spin(a, 0).y - spin(b, 0).y);
    std::printf("[ tails    ] sliding, t = %5.1f ms: R w_n %.3e m/s; fast path off by %.1e m, %.1e m/s, R |dw_n| "
                "%.1e m/s\n", 1e3 * times[k], kR * spin(b, 0).y, dx, dv, dwn);
    EXPECT_LT(dx, 1e-12);
    EXPECT_LT(dv, 1e-11);
    EXPECT_LT(dwn, 1e-11);
  }
  std::printf("[ tails    ] sliding: %ld steps on the fast path, %ld on the full model\n", fast.steps, full.steps);
  EXPECT_LE(fast.steps, 6);
}

// A ball sliding at 1 m/s with 10 rad/s of spin about its direction of motion: its slip (1.04 m/s, a third of it
// sideways) falls along a fixed line and the path curves, until the slip enters its band at 0.1513 s. From there the
// slip tail carries it in closed form to the rolling entry (at 1e-12 m/s of slip, 2 ms later), rolling resistance
// growing in as the friction fades, where the full model integrates the stiff tail. Against the full model at 1e-14,
// inside the tail and on the roll after it, the fast path at 1e-7 is off by 3e-11 m and 1e-11 m/s at most (the full
// model at 1e-12 by 4e-12, measured): what the closed form leaves out, the turn of rolling resistance's direction in
// the position (a_r t^2 / 2 times the turn, band_tail.hpp), which the sliding regime bounds at 3 % of abs_tol.
TEST(BandTail, SlipTailFollowsTheFullModel) {
  const nlohmann::json doc = cloth_scene({{{"id", "cue"}, {"position", {0, kR, 0}}, {"velocity", {1.0, 0, 0}},
                                           {"angular_velocity", {10.0, 0, 0}}}});
  const double edge = (std::hypot(1.0, 10 * kR) - 1e-3) / (3.5 * 0.2 * kG);  // s: the slip at its band's edge
  const std::vector<double> times{edge + 1e-4, edge + 4e-4, edge + 1.5e-3, 0.3, 1.0};
  const Track fast = track(doc, true, times), full = track(doc, false, times, 1e-14);
  for (size_t k = 0; k < times.size(); ++k) {
    const StateVector &a = fast.x[k], &b = full.x[k];
    const double dx = glm::length(position(a, 0) - position(b, 0)), dv = glm::length(velocity(a, 0) - velocity(b, 0));
    const double dw = kR * glm::length(spin(a, 0) - spin(b, 0));
    const Vec3 u = velocity(b, 0) + kR * glm::cross(kUp, spin(b, 0));
    std::printf("[ tails    ] slip, t = %.4f s: slip %.3e m/s; fast path off by %.1e m, %.1e m/s, R |dw| %.1e m/s\n",
                times[k], std::hypot(u.x, u.z), dx, dv, dw);
    EXPECT_LT(dx, 1e-10);
    EXPECT_LT(dv, 1e-10);
    EXPECT_LT(dw, 1e-10);
  }
  std::printf("[ tails    ] slip: %ld steps on the fast path to 1 s, %ld on the full model at 1e-14\n", fast.steps,
              full.steps);
  EXPECT_LT(fast.steps * 20, full.steps);
}

}  // namespace
}  // namespace shotlab::test
