#include "cases.hpp"

#include <cmath>

namespace shotlab {
namespace {

std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.9g", v);
  return buf;
}

// S1: ball a starts 1 mm from b. It reaches b after 1e-3/v s; the contact lasts under 0.5 ms at these speeds
// (VALIDATION R5: 448 us at 0.5 m/s), and the run ends 2e-3/v + 1 ms after the start, well after separation.
BenchCase head_on(double speed, bool damped) {
  const std::string s = num(speed);
  BenchCase c{"S1-" + s + (damped ? "-damped" : "-undamped"), "S1",
              "S1 head-on " + s + " m/s, " + (damped ? "damped" : "undamped"), "presets/bench/s1_head_on.json",
              {"balls.a.velocity=[" + s + ",0,0]", "duration=" + num(2e-3 / speed + 1e-3)}};
  if (!damped) {
    c.overrides.push_back("materials.ball_ball.damping=0");
    c.swap_exact = c.conservative = true;
  }
  c.free_space = true;
  return c;
}

// S2: the cue ball's line passes the object ball's centre at `offset` diameters.
BenchCase glancing(double offset) {
  const double diameter = 2 * 0.028575;
  BenchCase c{"S2-" + num(offset), "S2", "S2 glancing cut, offset " + num(offset), "presets/bench/s2_glancing.json",
              {"balls.cue.position=[-0.06,0," + num(offset * diameter) + "]"}};
  c.free_space = true;
  return c;
}

BenchCase whole_file(const std::string& id, const std::string& label, const std::string& file) {
  return {id, id, label, file, {}};
}

// Half decades from 10^from down to 10^to: 1e-3, 3.16e-4, 1e-4, ...
std::vector<double> half_decades(double from, double to, bool whole_only) {
  std::vector<double> out;
  for (double e = from; e >= to - 1e-9; e -= whole_only ? 1.0 : 0.5) out.push_back(std::pow(10.0, e));
  return out;
}

}  // namespace

std::vector<BenchCase> bench_cases() {
  std::vector<BenchCase> cases;
  for (bool damped : {false, true})
    for (double v : {0.5, 2.0, 8.0}) cases.push_back(head_on(v, damped));
  for (double offset : {0.9, 0.99, 0.999}) cases.push_back(glancing(offset));
  cases.push_back(whole_file("S3", "S3 stun shot, slide to roll", "presets/bench/s3_stun.json"));
  cases.push_back(whole_file("S4", "S4 cushion rebound", "presets/bench/s4_cushion.json"));
  cases.push_back(whole_file("S5", "S5 Newton's cradle, 5 balls", "presets/bench/s5_cradle.json"));
  BenchCase rack = whole_file("S6", "S6 break, first 60 ms", "presets/bench/s6_break.json");
  rack.coarse = true;
  cases.push_back(rack);
  BenchCase full = whole_file("S7", "S7 full break to rest", "presets/bench/s7_break_full.json");
  full.until_rest = true;
  cases.push_back(full);
  // Issue 5's target scene: the break preset (11 m/s from the head spot, frozen rack) to rest.
  BenchCase target = whole_file("S8", "S8 break preset at 11 m/s to rest", "presets/bench/s8_break.json");
  target.until_rest = true;
  cases.push_back(target);
  return cases;
}

IntegratorOptions integrator_options(const MethodSetting& s) {
  IntegratorOptions o;
  o.method = s.method;
  if (is_adaptive(s.method)) o.abs_tol = o.rel_tol = s.value;
  else o.fixed_step = s.value;
  o.max_steps_per_call = 1 << 30;  // the bench advances a whole run in one call
  return o;
}

std::string method_column(const MethodSetting& s) { return s.rigid ? "rigid" : method_name(s.method); }

std::string line_name(const MethodSetting& s) { return method_column(s) + (s.plain ? " plain" : ""); }

namespace {
const MethodSetting kRigid{Method::CashKarp54, 0.0, false, true};
}

std::vector<MethodSetting> sweep(bool coarse) {
  std::vector<MethodSetting> out;
  // Fixed steps from 1e-4 s (about the explicit stability limit of the cloth friction, docs/model.md#fricstep) to 1e-6 s (coarse)
  // or 1e-7 s.
  for (Method m : {Method::Euler, Method::RK4})
    for (double h : half_decades(-4, coarse ? -6 : -7, coarse)) out.push_back({m, h});
  for (Method m : {Method::CashKarp54, Method::DormandPrince5, Method::BulirschStoer, Method::Rosenbrock4})
    for (double tol : half_decades(-3, -11, coarse)) out.push_back({m, tol});
  for (Method m : {Method::CashKarp54, Method::DormandPrince5})
    for (double tol : half_decades(-3, -11, coarse)) out.push_back({m, tol, true});
  out.push_back(kRigid);
  return out;
}

std::vector<MethodSetting> sweep_timed_only(bool quick) {
  // --quick: the default setting on both paths only.
  if (quick) return {{Method::CashKarp54, 1e-7}, {Method::CashKarp54, 1e-7, true}, kRigid};
  std::vector<MethodSetting> out;
  for (Method m : {Method::CashKarp54, Method::DormandPrince5, Method::BulirschStoer})
    for (double tol : {1e-4, 1e-6, 1e-7, 1e-8}) out.push_back({m, tol});
  for (Method m : {Method::CashKarp54, Method::DormandPrince5}) out.push_back({m, 1e-7, true});
  out.push_back(kRigid);
  return out;
}

}  // namespace shotlab
