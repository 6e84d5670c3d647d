// What `shotlab bench` measures: the scene variants (S1-S8, scene files in presets/bench/ and presets/ with
// PATH=VALUE overrides) and the integrator settings swept over each of them.
#pragma once
#include <string>
#include <vector>

#include "shotlab/model.hpp"

namespace shotlab {

struct BenchCase {
  std::string id;                      // "S1-2-undamped": unique, used in the CSV
  std::string scene;                   // "S1": the --scenes selector
  std::string label;                   // for plots and tables
  std::string file;                    // presets/bench/...json, relative to the data root
  std::vector<std::string> overrides;  // PATH=VALUE applied to the file
  bool swap_exact = false;    // head-on, equal masses, undamped: the balls swap velocities exactly
  bool conservative = false;  // nothing dissipates: report the energy drift
  bool free_space = false;    // no external force: report the momentum error
  bool until_rest = false;    // timed only (S7, S8): run until every ball is at rest, no error measured
  bool coarse = false;        // expensive (S6): sweep whole decades only, as --quick does
};

// Every case, in report order.
std::vector<BenchCase> bench_cases();

// One integrator configuration: an adaptive method at a tolerance (abs_tol = rel_tol = tol), or a fixed-step
// method at a step, on the engine's default fast path or on the plain all-ODE path (SolverPath, model.hpp), which the
// references use.
struct MethodSetting {
  Method method;
  double value;        // tolerance (adaptive) or step in s (fixed)
  bool plain = false;  // the plain all-ODE path
  bool rigid = false;  // the rigid contact model instead (docs/model.md#rigid-model): no integrator, method ignored
};
IntegratorOptions integrator_options(const MethodSetting& setting);
// The setting's line in plots and tables: "cash_karp54", "cash_karp54 plain", or "rigid".
// What the CSV's method column says: the method's name, or "rigid".
std::string method_column(const MethodSetting& setting);
std::string line_name(const MethodSetting& setting);

// The sweep: Euler and RK4 over fixed steps, each adaptive method over tolerances, loosest first (the runner stops
// a method once it gets too slow, and tighter settings are only slower). `coarse` takes whole decades only and
// fewer steps; S7 and S8 get a short list of practical settings. Cash-Karp and Dormand-Prince also run on the plain
// path, so that the fast path's gain (issue 5) shows next to them. Each list ends with the rigid model, once.
std::vector<MethodSetting> sweep(bool coarse);
std::vector<MethodSetting> sweep_timed_only(bool quick);

// The reference solution: the first of these methods that finishes, checked by the next one that finishes and
// agrees with it to kReferenceAgreement, at the first of these tolerances where such a pair exists. At 1e-13 the
// error control of some methods cannot pass a damped contact onset, where the linear damping force jumps (they stop
// with step_too_small), and Bulirsch-Stoer can disagree outright (docs/bench/README.md): hence the fallbacks.
// References run on the plain path: the fast path's regime switches (at rest_speed) are a model difference of their
// own, which the bench measures instead of building into the reference.
inline constexpr Method kReferenceMethods[] = {Method::DormandPrince5, Method::CashKarp54, Method::BulirschStoer};
inline constexpr double kReferenceTols[] = {1e-13, 1e-12};
inline constexpr double kReferenceAgreement = 1e-9;

}  // namespace shotlab
