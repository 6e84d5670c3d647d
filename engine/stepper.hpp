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
  // advance and dt becomes the suggested next step; on rejection x, t, dxdt are unchanged and dt shrinks.
  virtual bool try_step(Dynamics& f, StateVector& x, StateVector& dxdt, double& t, double& dt) = 0;
  // Forget history (FSAL derivative, extrapolation tables) after the system changed discontinuously.
  virtual void reset() {}
};

std::unique_ptr<Stepper> make_stepper(const IntegratorOptions& options);
std::unique_ptr<Stepper> make_rosenbrock_stepper(double atol, double rtol);  // stepper_rosenbrock.cpp

}  // namespace shotlab
