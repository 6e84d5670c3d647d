// The odeint methods behind one interface, so the simulation loop (simulation.cpp) is written once.
#pragma once
#include <memory>
#include <vector>

#include "dynamics.hpp"
#include "shotlab/model.hpp"
#include "shotlab/state.hpp"

namespace shotlab {

class Stepper {
 public:
  virtual ~Stepper() = default;
  // One attempt from (x, t) with step dt. On entry dxdt = f(x, t). On success x, t and dxdt (= f at the new point)
  // advance and dt becomes the suggested next step, and f's last evaluation, whose contacts it recorded
  // (Dynamics::recorded), is the one at the new point; on rejection x, t, dxdt are unchanged and dt shrinks. `onset`:
  // the step starts where a contact begins, and an error-controlled method holds its estimate to the share of the
  // tolerance that makes up for what the estimate misses there (onset_underestimate).
  virtual bool try_step(Dynamics& f, StateVector& x, StateVector& dxdt, double& t, double& dt, bool onset) = 0;
  // Forget history (FSAL derivative, extrapolation tables) after the system changed discontinuously.
  virtual void reset() {}
};

// The error control of Cash-Karp 54 and Dormand-Prince 5 (odeint's error checker for their controlled steppers): a
// step passes when the largest |err_i| / (atol_i + rel_tol (|x_i| + dt |dxdt_i|)) over the components is at most 1,
// as in odeint's default checker, but with atol_i in the unit of its component. The tolerance is a length for the
// positions and a speed for the velocities, and a spin w is held to it as the speed R |w| at which it moves the
// ball's surface, what it adds to the slip at a contact (docs/model.md#slip): abs_tol / R rad/s. odeint's one scalar for
// every component held a pool ball's spin 1/R = 35 times tighter than its velocity, and the spins then set the steps
// wherever friction acts (it moves 5/(2R) rad/s of spin for every m/s it takes from the centre): the break took 14 %
// more steps for it.
class BallErrorChecker {
 public:
  using value_type = double;
  // radii: each ball's radius (m), in the state's order.
  BallErrorChecker(double abs_tol, double rel_tol, const std::vector<double>& radii);
  double error(const StateVector& x, const StateVector& dxdt, const StateVector& err, double dt) const;
  // The form odeint's controlled steppers call.
  template <class Algebra>
  double error(Algebra&, const StateVector& x, const StateVector& dxdt, const StateVector& err, double dt) const {
    return error(x, dxdt, err, dt);
  }

 private:
  std::vector<double> abs_tol_;  // per component: m, m/s, rad/s
  double rel_tol_;
};

// How many times the embedded error estimate of method m understates the true error of a step that starts where a
// contact whose force grows as depth^exponent begins: 4.69 for Cash-Karp 54 and 11.3 for Dormand-Prince 5 at Hertz's
// 1.5; 1 for the fixed-step methods and those not analysed (Bulirsch-Stoer, Rosenbrock 4).
double onset_underestimate(Method m, double exponent);
// The error of method m's step of length h from such an onset, per unit of k h^(e+1), where k = C v^e / m is the
// coefficient of the contact's acceleration k t^e (e: the exponent, C: the stiffness, v: the closing speed): 5.8e-4
// for Cash-Karp 54, 4.5e-4 for Dormand-Prince 5 at e = 1.5; 0 for the methods not analysed.
double onset_error_coefficient(Method m, double exponent);

// The largest onset_underestimate over the model's contact materials, for its integrator.
double onset_factor(const Model& model);

// `onset_factor`: the largest onset_underestimate of the contacts the stepper will meet (see above). `radii`: each
// ball's radius (m), in the state's order. Cash-Karp 54 and Dormand-Prince 5 control their error with
// BallErrorChecker; Bulirsch-Stoer and Rosenbrock 4 keep odeint's own control, abs_tol for every component alike.
std::unique_ptr<Stepper> make_stepper(const IntegratorOptions& options, double onset_factor,
                                      const std::vector<double>& radii);
std::unique_ptr<Stepper> make_rosenbrock_stepper(double atol, double rtol);  // stepper_rosenbrock.cpp

}  // namespace shotlab
