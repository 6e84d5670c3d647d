#include "stepper.hpp"

// At the engine's inlining limit (engine/CMakeLists.txt) GCC 12 sees odeint's Bulirsch-Stoer read m_dt_last before
// setting it: its first step compares the step size with it, where a reset or none starts the same fresh state.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#include <boost/numeric/odeint.hpp>
#pragma GCC diagnostic pop
#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

namespace shotlab {
namespace odeint = boost::numeric::odeint;
BallErrorChecker::BallErrorChecker(double abs_tol, double rel_tol, const std::vector<double>& radii) : rel_tol_(rel_tol) {
  abs_tol_.reserve(kBallDofs * radii.size());
  for (double r : radii)
    for (int k = 0; k < kBallDofs; ++k) abs_tol_.push_back(k < kSpinDof ? abs_tol : abs_tol / r);
}

double BallErrorChecker::error(const StateVector& x, const StateVector& dxdt, const StateVector& err, double dt) const {
  // The largest ratio, divided out only where it grows: a division or two a step, not one a component.
  double worst = 0;
  for (size_t i = 0; i < abs_tol_.size(); ++i) {
    const double allowed = abs_tol_[i] + rel_tol_ * (std::abs(x[i]) + dt * std::abs(dxdt[i]));
    if (std::abs(err[i]) > worst * allowed) worst = std::abs(err[i]) / allowed;
  }
  return worst;
}

namespace {

// An error-controlled explicit pair (Cash-Karp 54, Dormand-Prince 5) with that checker.
template <class Pair>
using Controlled = odeint::controlled_runge_kutta<Pair, BallErrorChecker>;
template <class Pair>
Controlled<Pair> make_controlled(double abs_tol, double rel_tol, const std::vector<double>& radii) {
  return Controlled<Pair>(BallErrorChecker(abs_tol, rel_tol, radii));
}

// Euler and RK4: always accept, never change dt (the caller passes the fixed step).
template <class S>
class FixedStepper final : public Stepper {
 public:
  bool try_step(Dynamics& f, StateVector& x, StateVector& dxdt, double& t, double& dt, bool) override {
    f.set_recording(false);
    stepper_.do_step(std::ref(f), x, dxdt, t, dt);
    f.set_recording(true);
    t += dt;
    f(x, dxdt, t);
    return true;
  }

 private:
  S stepper_;
};

// Controlled explicit methods (Cash-Karp 54, Bulirsch-Stoer) that take f(x, t) from the caller. A step that starts at
// a contact onset goes to `strict`, the same method held to a tolerance smaller by the onset factor, where there is
// one (Cash-Karp: the two share no history; Bulirsch-Stoer has none and keeps its one stepper).
template <class S>
class ControlledStepper final : public Stepper {
 public:
  ControlledStepper(S stepper, std::optional<S> strict) : stepper_(std::move(stepper)), strict_(std::move(strict)) {}
  bool try_step(Dynamics& f, StateVector& x, StateVector& dxdt, double& t, double& dt, bool onset) override {
    S& s = onset && strict_ ? *strict_ : stepper_;
    f.set_recording(false);
    const bool accepted = s.try_step(std::ref(f), x, dxdt, t, dt) == odeint::success;
    f.set_recording(true);
    if (!accepted) return false;
    f(x, dxdt, t);
    return true;
  }
  void reset() override {
    if constexpr (requires(S s) { s.reset(); }) {
      stepper_.reset();
      if (strict_) strict_->reset();
    }
  }

 private:
  S stepper_;
  std::optional<S> strict_;
};

// Dormand-Prince 5 is first-same-as-last: a successful step hands back f at its end for free, its last stage, which
// is therefore recorded like every stage (Dynamics::recorded). The caller passes f at the start, so the strict twin
// (see above) needs none of the other's history.
class DormandPrinceStepper final : public Stepper {
  using Pair = odeint::runge_kutta_dopri5<StateVector>;

 public:
  DormandPrinceStepper(double atol, double rtol, double onset_factor, const std::vector<double>& radii)
      : stepper_(make_controlled<Pair>(atol, rtol, radii)),
        strict_(make_controlled<Pair>(atol / onset_factor, rtol / onset_factor, radii)) {}
  bool try_step(Dynamics& f, StateVector& x, StateVector& dxdt, double& t, double& dt, bool onset) override {
    return (onset ? strict_ : stepper_).try_step(std::ref(f), x, dxdt, t, dt) == odeint::success;
  }
  void reset() override { stepper_.reset(), strict_.reset(); }

 private:
  Controlled<Pair> stepper_, strict_;
};

// An explicit pair's weights: nodes c, the higher order's weights b, the embedded one's bhat.
struct Tableau {
  std::vector<double> c, b, bhat;
};

// Cash and Karp (1990) and Dormand and Prince (1980), as odeint implements them.
const Tableau kCashKarp{{0, 1.0 / 5, 3.0 / 10, 3.0 / 5, 1, 7.0 / 8},
                        {37.0 / 378, 0, 250.0 / 621, 125.0 / 594, 0, 512.0 / 1771},
                        {2825.0 / 27648, 0, 18575.0 / 48384, 13525.0 / 55296, 277.0 / 14336, 1.0 / 4}};
const Tableau kDormandPrince{{0, 1.0 / 5, 3.0 / 10, 4.0 / 5, 8.0 / 9, 1, 1},
                             {35.0 / 384, 0, 500.0 / 1113, 125.0 / 192, -2187.0 / 6784, 11.0 / 84, 0},
                             {5179.0 / 57600, 0, 7571.0 / 16695, 393.0 / 640, -92097.0 / 339200, 187.0 / 2100, 1.0 / 40}};

// A contact that begins at the step's start (depth 0, closing at v) pushes with C (v t)^e: an acceleration k t^e,
// k = C v^e / m, that no polynomial follows. Over a step of h its exact velocity change is k h^(e+1) / (e+1), and the
// step adds h sum_i b_i k (c_i h)^e (taking the depth at stage i as v c_i h, as it is while the contact has barely
// slowed the bodies: k h^(e+1) << v), so it is off by k h^(e+1) |sum_i b_i c_i^e - 1/(e+1)|; the estimate (higher
// order minus embedded) sees k h^(e+1) |sum_i (b_i - bhat_i) c_i^e|. Their ratio depends on the weights and e alone,
// not on h, v or the material; the error control compares each component with its own tolerance, and the body the
// contact accelerates most is the one this speaks of. Steps that start later, clear of the onset, are smooth again:
// there the true error is 0.6 of the estimate (measured on a head-on hit).
struct OnsetSums {
  double error = 0, estimate = 0;  // the two sums above, as absolute values
};

OnsetSums onset_sums(Method m, double e) {
  const Tableau* w = m == Method::CashKarp54 ? &kCashKarp : m == Method::DormandPrince5 ? &kDormandPrince : nullptr;
  OnsetSums out;
  if (!w) return out;
  double step = 0;
  for (size_t i = 0; i < w->c.size(); ++i) {
    const double ce = w->c[i] > 0 ? std::pow(w->c[i], e) : 0.0;
    step += w->b[i] * ce;
    out.estimate += (w->b[i] - w->bhat[i]) * ce;
  }
  out.error = std::abs(step - 1.0 / (e + 1.0));
  out.estimate = std::abs(out.estimate);
  return out;
}

}  // namespace

double onset_error_coefficient(Method m, double exponent) {
  const double error = onset_sums(m, exponent).error;
  return error > 1e-14 ? error : 0.0;  // whole exponents below the order are integrated exactly: round-off
}

double onset_underestimate(Method m, double exponent) {
  const OnsetSums s = onset_sums(m, exponent);
  // Whole exponents below the order are integrated exactly: nothing to make up for.
  return s.estimate > 1e-14 ? std::max(1.0, s.error / s.estimate) : 1.0;
}

double onset_factor(const Model& model) {
  double factor = 1.0;
  for (const auto& [name, material] : model.materials)
    factor = std::max(factor, onset_underestimate(model.integrator.method, material.exponent));
  return factor;
}

std::unique_ptr<Stepper> make_stepper(const IntegratorOptions& o, double onset_factor, const std::vector<double>& radii) {
  switch (o.method) {
    case Method::Euler: return std::make_unique<FixedStepper<odeint::euler<StateVector>>>();
    case Method::RK4: return std::make_unique<FixedStepper<odeint::runge_kutta4<StateVector>>>();
    case Method::CashKarp54: {
      using Pair = odeint::runge_kutta_cash_karp54<StateVector>;
      auto make = [&](double scale) { return make_controlled<Pair>(o.abs_tol / scale, o.rel_tol / scale, radii); };
      return std::make_unique<ControlledStepper<Controlled<Pair>>>(make(1.0), make(onset_factor));
    }
    case Method::DormandPrince5: return std::make_unique<DormandPrinceStepper>(o.abs_tol, o.rel_tol, onset_factor, radii);
    case Method::BulirschStoer: {
      using BS = odeint::bulirsch_stoer<StateVector>;
      return std::make_unique<ControlledStepper<BS>>(BS(o.abs_tol, o.rel_tol), std::nullopt);
    }
    case Method::Rosenbrock4: return make_rosenbrock_stepper(o.abs_tol, o.rel_tol);
  }
  return nullptr;
}

}  // namespace shotlab
