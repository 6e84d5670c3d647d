// Dense output for every method: the cubic Hermite interpolant of one accepted step, built from the states and
// derivatives at both ends. Between contacts the ball paths on the cloth are polynomials of degree <= 2 (docs/model.md#dense-output:
// parabolic sliding, linear deceleration, linear spin decay), which a cubic reproduces exactly; inside contacts the
// steps are short. Error O(h^4) in general. The exceptions are a closed-form step's band tails (band_tail.hpp),
// swings (swing.hpp) and bounces (bounce.hpp): what they govern follows their own closed form.
#pragma once
#include <algorithm>
#include <vector>

#include "band_tail.hpp"
#include "bounce.hpp"
#include "shotlab/state.hpp"
#include "swing.hpp"

namespace shotlab {

struct StepSpan {
  double t0 = 0, t1 = 0;
  StateVector x0, f0, x1, f1;
  // What decays inside a friction band over the span, the balls that swing on their rods and those that bounce on the
  // bed, in closed form (a closed-form step's; else none).
  std::vector<BandTail> tails;
  std::vector<Swing> swings;
  std::vector<BedBounce> bounces;
  // Balls that left play inside the span (Island::settle). x1 holds each frozen where it left, from `time` on; before
  // then it moves on the step's own end values, kept here, as it did.
  struct Exit {
    int ball;
    double time;  // s
    double x1[kBallDofs], f1[kBallDofs];
  };
  std::vector<Exit> exits;

  // State at t in [t0, t1], written to out (resized).
  void interpolate(double t, StateVector& out) const {
    out.resize(x0.size());
    interpolate(t, out, 0, out.size());
  }
  // Only ball i's numbers (9 from 9 i) at t, written into out (sized for the whole state; the rest left as it is): a
  // bisection on one contact of a 16-ball island needs two balls, not all of them.
  void interpolate_ball(double t, StateVector& out, int i) const {
    out.resize(x0.size());
    interpolate(t, out, 9 * static_cast<size_t>(i), 9 * static_cast<size_t>(i) + 9);
  }

 private:
  void interpolate(double t, StateVector& out, size_t begin, size_t end) const {
    const double h = t1 - t0;
    if (h <= 0) {
      std::copy(x1.begin() + begin, x1.begin() + end, out.begin() + begin);
      return;
    }
    const double s = (t - t0) / h, s2 = s * s, s3 = s2 * s;
    // Hermite basis: h00 = 2s^3 - 3s^2 + 1, h10 = s^3 - 2s^2 + s, h01 = -2s^3 + 3s^2, h11 = s^3 - s^2.
    const double h00 = 2 * s3 - 3 * s2 + 1, h10 = (s3 - 2 * s2 + s) * h, h01 = -2 * s3 + 3 * s2, h11 = (s3 - s2) * h;
    for (size_t k = begin; k < end; ++k) out[k] = h00 * x0[k] + h10 * f0[k] + h01 * x1[k] + h11 * f1[k];
    // A tail's or a swing's components from its closed form instead of the cubic, which would overshoot an exponential
    // or an arc across a long step. At t1 itself x1, as a regime's snap at the step's end may have left it (the stop
    // cut).
    if (s >= 1) return;
    auto in_range = [&](int ball) {
      const size_t b = kBallDofs * static_cast<size_t>(ball);
      return b >= begin && b < end;
    };
    for (const BandTail& tail : tails)
      if (in_range(tail.ball)) tail.apply(t - t0, out.data() + kBallDofs * tail.ball);
    for (const Swing& swing : swings)
      if (in_range(swing.ball)) swing.apply(t - t0, out.data() + kBallDofs * swing.ball);
    for (const BedBounce& bounce : bounces)
      if (in_range(bounce.ball)) bounce.apply(t - t0, out.data() + kBallDofs * bounce.ball);
    for (const Exit& e : exits) {
      if (!in_range(e.ball)) continue;
      for (size_t k = 0, j = kBallDofs * static_cast<size_t>(e.ball); k < kBallDofs; ++k, ++j)
        out[j] = t < e.time ? h00 * x0[j] + h10 * f0[j] + h01 * e.x1[k] + h11 * e.f1[k] : x1[j];
    }
  }
};

}  // namespace shotlab
