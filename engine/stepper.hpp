// The odeint methods behind one interface, so the simulation loop (simulation.cpp) is written once.
#pragma once
#include <memory>

#include "dynamics.hpp"
#include "model.hpp"
#include "state.hpp"

namespace shotlab {

class Stepper {
 public:
  virtual ~Stepper() = default;
  // One attempt from (x, t) with step dt. On entry dxdt = f(x, t). On success x, t and dxdt (= f at the new point)
  // advance and dt becomes the suggested next step; on rejection x, t, dxdt are unchanged and dt shrinks. `onset`:
  // the step starts where a contact begins, and an error-controlled method holds its estimate to the share of the
  // tolerance that makes up for what the estimate misses there (onset_underestimate).
  virtual bool try_step(Dynamics& f, StateVector& x, StateVector& dxdt, double& t, double& dt, bool onset) = 0;
  // Forget history (FSAL derivative, extrapolation tables) after the system changed discontinuously.
  virtual void reset() {}
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

// `onset_factor`: the largest onset_underestimate of the contacts the stepper will meet (see above).
std::unique_ptr<Stepper> make_stepper(const IntegratorOptions& options, double onset_factor);
std::unique_ptr<Stepper> make_rosenbrock_stepper(double atol, double rtol);  // stepper_rosenbrock.cpp

}  // namespace shotlab
