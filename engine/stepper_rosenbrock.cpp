// Rosenbrock 4 lives in its own file: odeint's implementation uses Boost.uBLAS, whose Boost 1.74 version calls
// std::allocator::construct, removed in C++20. CMake compiles this one file as C++17.
#include <boost/numeric/odeint.hpp>
#include <cmath>

#include "stepper.hpp"

namespace shotlab {
namespace odeint = boost::numeric::odeint;
namespace {

// Rosenbrock 4 (L-stable, for very stiff contacts) on odeint's ublas types, with a finite-difference Jacobian:
// column k is (f(x + h e_k) - f(x)) / h, h = sqrt(machine epsilon) * max(|x_k|, 1e-3). The system is autonomous,
// so df/dt = 0. Cost: 9n + 1 evaluations of f per step, affordable for the few-ball scenes that need it.
class RosenbrockStepper final : public Stepper {
  using Vector = boost::numeric::ublas::vector<double>;
  using Matrix = boost::numeric::ublas::matrix<double>;

 public:
  RosenbrockStepper(double atol, double rtol) : atol_(atol), rtol_(rtol), controller_(std::make_unique<Controller>(atol, rtol)) {}
  bool try_step(Dynamics& f, StateVector& x, StateVector& dxdt, double& t, double& dt, bool) override {
    Vector xu(x.size());
    std::copy(x.begin(), x.end(), xu.begin());
    auto system = [&](const Vector& in, Vector& out, double time) {
      in_.assign(in.begin(), in.end());
      f(in_, out_, time);
      out.resize(out_.size());
      std::copy(out_.begin(), out_.end(), out.begin());
    };
    auto jacobian = [&](const Vector& in, Matrix& jac, double time, Vector& dfdt) {
      const size_t n = in.size();
      in_.assign(in.begin(), in.end());
      f(in_, base_, time);
      for (size_t k = 0; k < n; ++k) {
        const double h = 1.49e-8 * std::max(std::abs(in_[k]), 1e-3);
        const double saved = in_[k];
        in_[k] = saved + h;
        f(in_, out_, time);
        in_[k] = saved;
        for (size_t r = 0; r < n; ++r) jac(r, k) = (out_[r] - base_[r]) / h;
      }
      dfdt.resize(n);
      std::fill(dfdt.begin(), dfdt.end(), 0.0);
    };
    f.set_recording(false);
    const bool accepted = controller_->try_step(std::make_pair(system, jacobian), xu, t, dt) == odeint::success;
    f.set_recording(true);
    if (!accepted) return false;
    std::copy(xu.begin(), xu.end(), x.begin());
    f(x, dxdt, t);
    return true;
  }
  // The controller remembers the last error for its step prediction; a fresh one forgets it.
  void reset() override { controller_ = std::make_unique<Controller>(atol_, rtol_); }

 private:
  using Controller = odeint::rosenbrock4_controller<odeint::rosenbrock4<double>>;
  double atol_, rtol_;
  std::unique_ptr<Controller> controller_;
  StateVector in_, out_, base_;
};

}  // namespace

std::unique_ptr<Stepper> make_rosenbrock_stepper(double atol, double rtol) {
  return std::make_unique<RosenbrockStepper>(atol, rtol);
}

}  // namespace shotlab
