// One bench run: a case simulated with one integrator setting, and what it cost; and the errors of a run against
// the reference run of the same case.
#pragma once
#include <string>
#include <vector>

#include "app/bench/cases.hpp"
#include "shotlab/simulation.hpp"

namespace shotlab {

struct RunResult {
  Status status = Status::Ok;
  double end_time = 0;     // s
  StateVector x;           // final state
  std::vector<double> radius;
  Stats stats;
  int contacts = 0;             // contacts that began during the run, ball-ball and ball-cushion (the cloth excluded)
  double steps_per_contact = 0; // mean number of steps overlapping each of them
  double energy0 = 0, energy1 = 0;  // J, total at start and end
  Vec3 momentum0{0.0}, momentum1{0.0};
  StateVector x0;               // initial state (S1's exact answer is built from it)
  StateVector scale;            // each component's largest |x| over the run (at the start and at every step's end)
  double speed_scale = 0;       // m/s, max initial ball speed (velocity errors are relative to it)
};

// Loads the case's scene from `data_root`, applies the setting, simulates. Throws InputError on a bad scene file.
// `reference`: also keep each component's size over the run (RunResult::scale), which the timed runs leave out.
RunResult run_case(const std::string& data_root, const BenchCase& c, const MethodSetting& setting, bool reference = false);

struct Errors {
  double position = 0;   // max over balls |p - p_ref| / R
  double velocity = 0;   // max over balls |v - v_ref| / speed scale
  int missed = 0;        // contacts of the reference that did not happen
  double energy = -1;    // |E1 - E0| / E0 when the case is conservative, else -1 (not applicable)
  double momentum = -1;  // |P1 - P0| / |P0| when the case is in free space, else -1
  // The end state in the stepper's own terms, for a run at tolerance tol (abs_tol = rel_tol = tol; -1 for fixed
  // steps): the largest |x_i - x_ref,i| / (tol + tol s_i) over the position and velocity components (m, m/s), and
  // apart over the spins, each as the surface speed R w it gives its ball (m/s, as the stepper holds it, stepper.hpp).
  // s_i is the size of the reference's component over the run (RunResult::scale): each step held the error it made to
  // tol + tol |x_i| at the size x_i had then, and a quantity that ends small (the speed of a ball that stopped
  // another, a spin friction wore down) was not asked for more than that. At most 1: within the requested tolerance.
  double tolerance_pv = -1, tolerance_spin = -1;
  // The same with s_i = |x_ref,i| at the end, the stricter reading of earlier reports.
  double tolerance_pv_end = -1, tolerance_spin_end = -1;
  double worst() const { return std::max(position, velocity); }
};

// Errors of `run` against `ref`; for swap_exact cases the velocities are compared with the exact swap instead.
// `tolerance` > 0: the run's tolerance, for the tolerance ratios.
Errors errors(const BenchCase& c, const RunResult& run, const RunResult& ref, double tolerance = 0);

}  // namespace shotlab
