// The bench's error measure (app/bench/run.cpp): the figures in docs/bench rest on it, so its scales are pinned here
// with hand-made end states, not with runs of the engine.
#include <gtest/gtest.h>

#include "app/bench/run.hpp"

namespace shotlab {
namespace {

// Two balls of radius 0.03 m at the origin and 1 m along x, at rest; velocities set per test.
RunResult two_balls() {
  RunResult r;
  r.radius = {0.03, 0.03};
  r.x.assign(2 * kBallDofs, 0.0);
  set_position(r.x, 1, Vec3{1.0, 0.0, 0.0});
  r.x0 = r.x;
  return r;
}

TEST(BenchErrors, VelocityErrorIsRelativeToTheFastestInitialSpeed) {
  RunResult ref = two_balls();
  ref.speed_scale = 2.0;  // m/s
  set_velocity(ref.x, 0, Vec3{0.5, 0.0, 0.0});
  RunResult run = ref;
  set_velocity(run.x, 0, Vec3{0.5, 1e-3, 0.0});
  set_position(run.x, 1, Vec3{1.0, 0.0, 3e-6});
  const Errors e = errors(BenchCase{}, run, ref);
  EXPECT_NEAR(e.velocity, 1e-3 / 2.0, 1e-15);
  EXPECT_NEAR(e.position, 3e-6 / 0.03, 1e-15);
}

// A scene that starts at rest (the cradle) measures velocities against the fastest ball at the reference's end,
// whichever ball that is: here the second, ten times faster than the first.
TEST(BenchErrors, SceneStartingAtRestUsesTheFastestFinalSpeed) {
  RunResult ref = two_balls();
  set_velocity(ref.x, 0, Vec3{0.1, 0.0, 0.0});
  set_velocity(ref.x, 1, Vec3{0.0, 0.0, -1.0});
  RunResult run = ref;
  set_velocity(run.x, 0, Vec3{0.1 + 1e-4, 0.0, 0.0});
  EXPECT_NEAR(errors(BenchCase{}, run, ref).velocity, 1e-4 / 1.0, 1e-15);
}

// Undamped head-on hits are measured against the exact swap of the initial velocities, not against the reference.
TEST(BenchErrors, SwapCasesCompareWithTheExactSwap) {
  RunResult ref = two_balls();
  set_velocity(ref.x0, 0, Vec3{2.0, 0.0, 0.0});
  ref.speed_scale = 2.0;
  RunResult run = ref;
  set_velocity(run.x, 1, Vec3{2.0 - 4e-6, 0.0, 0.0});
  set_velocity(ref.x, 1, Vec3{1.0, 0.0, 0.0});  // a wrong reference must not matter
  BenchCase swap;
  swap.swap_exact = true;
  EXPECT_NEAR(errors(swap, run, ref).velocity, 4e-6 / 2.0, 1e-15);
}

// The end state in the stepper's terms: each component's error against tol + tol |x_ref| (here 1e-7 + 1e-7 x 1 m for
// ball 1's x, 1e-7 + 1e-7 x 0.5 m/s for ball 0's speed), positions and velocities apart from spins, a spin as the
// surface speed R w (R = 0.03 m); fixed-step runs (no tolerance) get none.
TEST(BenchErrors, ToleranceRatioWeighsEachComponentAsTheStepperDoes) {
  RunResult ref = two_balls();
  ref.speed_scale = 1.0;
  set_velocity(ref.x, 0, Vec3{0.5, 0.0, 0.0});
  RunResult run = ref;
  set_position(run.x, 1, Vec3{1.0 + 1e-7, 0.0, 0.0});    // 1e-7 / 2e-7: half the tolerance
  set_velocity(run.x, 0, Vec3{0.5 + 3e-7, 0.0, 0.0});    // 3e-7 / 1.5e-7: twice
  set_spin(run.x, 1, Vec3{0.0, 5e-6, 0.0});              // R 5e-6 = 1.5e-7 m/s on a spin at rest: 1.5 times
  const Errors e = errors(BenchCase{}, run, ref, 1e-7);
  EXPECT_NEAR(e.tolerance_pv, 2.0, 1e-9);
  EXPECT_NEAR(e.tolerance_spin, 1.5, 1e-9);
  EXPECT_NEAR(e.tolerance_pv_end, 2.0, 1e-9);
  EXPECT_NEAR(e.tolerance_spin_end, 1.5, 1e-9);
  EXPECT_EQ(errors(BenchCase{}, run, ref).tolerance_pv, -1.0);
}

// The relative share at the size a component had over the reference's run: ball 0 was struck to 3 m/s and ends at
// 0.5 m/s; an error of 3e-7 m/s is 3e-7 / (1e-7 + 1e-7 x 3) = 0.75 of the tolerance its steps were held to, twice the
// tolerance at the end value. Its spin reached 100 rad/s (R w = 3 m/s) and ends at rest.
TEST(BenchErrors, ToleranceRatioTakesEachComponentsSizeOverTheRun) {
  RunResult ref = two_balls();
  ref.speed_scale = 3.0;
  set_velocity(ref.x, 0, Vec3{0.5, 0.0, 0.0});
  ref.scale.assign(ref.x.size(), 0.0);
  ref.scale[3] = 3.0;    // ball 0's x velocity, m/s
  ref.scale[7] = 100.0;  // ball 0's spin about y, rad/s
  RunResult run = ref;
  set_velocity(run.x, 0, Vec3{0.5 + 3e-7, 0.0, 0.0});
  set_spin(run.x, 0, Vec3{0.0, 4e-6, 0.0});  // R 4e-6 = 1.2e-7 m/s against 1e-7 + 1e-7 x 3 m/s
  const Errors e = errors(BenchCase{}, run, ref, 1e-7);
  EXPECT_NEAR(e.tolerance_pv, 0.75, 1e-9);
  EXPECT_NEAR(e.tolerance_pv_end, 2.0, 1e-9);
  EXPECT_NEAR(e.tolerance_spin, 0.3, 1e-9);
  EXPECT_NEAR(e.tolerance_spin_end, 1.2, 1e-9);
}

}  // namespace
}  // namespace shotlab
