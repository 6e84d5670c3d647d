// Issue 5's accuracy target, measured as the bench measures it (app/bench/run.cpp, Errors::tolerance_pv and
// tolerance_spin): on the bench scenes S1-S6 the fast path at the default tolerance ends within that tolerance of the
// bench's reference (Dormand-Prince 5 on the plain path at 1e-13), in the stepper's own terms. Not a timing: the runs
// take about half a second.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>

#include "app/bench/run.hpp"

namespace shotlab {
namespace {

const std::string kRoot = SHOTLAB_SOURCE_DIR;

Errors against_reference(const BenchCase& c, double tolerance) {
  const RunResult ref = run_case(kRoot, c, {Method::DormandPrince5, 1e-13, true}, true);
  const RunResult run = run_case(kRoot, c, {Method::CashKarp54, tolerance});
  const Errors e = errors(c, run, ref, tolerance);
  std::printf("[ within   ] %s at %.0e: positions and velocities %.2f, spins %.2f of the tolerance (%.2f, %.2f against "
              "the end values)\n", c.id.c_str(), tolerance, e.tolerance_pv, e.tolerance_spin, e.tolerance_pv_end,
              e.tolerance_spin_end);
  return e;
}

// Every case of S1-S6 at the default 1e-7. Before friction switches and releases of every contact ended steps
// (engine/events.hpp, first_law_change), steps the error control passed in the breaking rack of S6 were 8 to 13 times
// the tolerance, and S6 ended 1.5 times it off (2.5 times against the end values).
TEST(WithinTolerance, BenchScenesAtTheDefaultTolerance) {
  const double tolerance = IntegratorOptions{}.abs_tol;
  for (const BenchCase& c : bench_cases()) {
    if (c.until_rest) continue;  // S7, S8: chaotic breaks to rest, timed only
    const Errors e = against_reference(c, tolerance);
    EXPECT_LE(e.tolerance_pv, 1.0) << c.id;
    EXPECT_LE(e.tolerance_spin, 1.0) << c.id;
  }
}

// A glancing cut (0.99 of a diameter) at 1e-6: the damped contact lets go while its balls still overlap, and the clamp
// of its normal force at zero is a kink; a step across it went 7.5 times the tolerance off before the release of any
// contact, not only of one the step kept unclamped, ended the step (0.3 now).
TEST(WithinTolerance, GlancingCutLetsGoAtItsRelease) {
  const std::vector<BenchCase> cases = bench_cases();
  const auto c = std::find_if(cases.begin(), cases.end(), [](const BenchCase& b) { return b.id == "S2-0.99"; });
  ASSERT_NE(c, cases.end());
  const Errors e = against_reference(*c, 1e-6);
  EXPECT_LE(e.tolerance_pv, 1.0);
  EXPECT_LE(e.tolerance_spin, 1.0);
}

}  // namespace
}  // namespace shotlab
