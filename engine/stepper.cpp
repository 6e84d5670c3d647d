#include "stepper.hpp"

#include <boost/numeric/odeint.hpp>
#include <cmath>

namespace shotlab {
namespace odeint = boost::numeric::odeint;
namespace {

// Euler and RK4: always accept, never change dt (the caller passes the fixed step).
template <class S>
class FixedStepper final : public Stepper {
 public:
  bool try_step(Dynamics& f, StateVector& x, StateVector& dxdt, double& t, double& dt) override {
    stepper_.do_step(std::ref(f), x, dxdt, t, dt);
    t += dt;
    f(x, dxdt, t);
    return true;
  }

 private:
  S stepper_;
};

// Controlled explicit methods (Cash-Karp 54, Bulirsch-Stoer) that take f(x, t) from the caller.
template <class S>
class ControlledStepper final : public Stepper {
 public:
  explicit ControlledStepper(S stepper) : stepper_(std::move(stepper)) {}
  bool try_step(Dynamics& f, StateVector& x, StateVector& dxdt, double& t, double& dt) override {
    if (stepper_.try_step(std::ref(f), x, dxdt, t, dt) != odeint::success) return false;
    f(x, dxdt, t);
    return true;
  }
  void reset() override {
    if constexpr (requires(S s) { s.reset(); }) stepper_.reset();
  }

 private:
  S stepper_;
};

// Dormand-Prince 5 is first-same-as-last: a successful step hands back f at its end for free.
class DormandPrinceStepper final : public Stepper {
 public:
  DormandPrinceStepper(double atol, double rtol)
      : stepper_(odeint::make_controlled(atol, rtol, odeint::runge_kutta_dopri5<StateVector>())) {}
  bool try_step(Dynamics& f, StateVector& x, StateVector& dxdt, double& t, double& dt) override {
    return stepper_.try_step(std::ref(f), x, dxdt, t, dt) == odeint::success;
  }
  void reset() override { stepper_.reset(); }

 private:
  odeint::result_of::make_controlled<odeint::runge_kutta_dopri5<StateVector>>::type stepper_;
};

}  // namespace

std::unique_ptr<Stepper> make_stepper(const IntegratorOptions& o) {
  switch (o.method) {
    case Method::Euler: return std::make_unique<FixedStepper<odeint::euler<StateVector>>>();
    case Method::RK4: return std::make_unique<FixedStepper<odeint::runge_kutta4<StateVector>>>();
    case Method::CashKarp54: {
      auto s = odeint::make_controlled(o.abs_tol, o.rel_tol, odeint::runge_kutta_cash_karp54<StateVector>());
      return std::make_unique<ControlledStepper<decltype(s)>>(std::move(s));
    }
    case Method::DormandPrince5: return std::make_unique<DormandPrinceStepper>(o.abs_tol, o.rel_tol);
    case Method::BulirschStoer:
      return std::make_unique<ControlledStepper<odeint::bulirsch_stoer<StateVector>>>(
          odeint::bulirsch_stoer<StateVector>(o.abs_tol, o.rel_tol));
    case Method::Rosenbrock4: return make_rosenbrock_stepper(o.abs_tol, o.rel_tol);
  }
  return nullptr;
}

}  // namespace shotlab
