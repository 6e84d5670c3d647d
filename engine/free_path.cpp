#include "free_path.hpp"

#include <cmath>
#include <limits>

#include "dynamics.hpp"
#include "numerics.hpp"
#include "polynomial.hpp"
#include "regimes.hpp"

namespace shotlab {

std::optional<FreePath> free_path(const Model& model, const State& state, const double* x, int i,
                                  const ModelIndex& index, double horizon) {
  if (!state.in_play[i]) return std::nullopt;
  constexpr double kForever = std::numeric_limits<double>::infinity();
  if (state.sleeping(i)) return FreePath{position(x, i), Vec3{0.0}, 0.0, 0.0, 0.0, kForever, Vec3{0.0}, kForever};
  if (!state.rolling(i) && !state.sliding(i)) return std::nullopt;
  // The velocity jumps a path may take, summed: the rolling entry removes a slip under entry_slip, 2/7 of it
  // from the velocity (update_rolling); the stop cut (settle_rolling); falling asleep zeroes a velocity under
  // rest_speed (update_sleep).
  const double rest = model.options.sleep_time > 0 ? model.options.rest_speed : 0.0;
  const double jump = 2.0 / 7.0 * entry_slip(model) + kStopSpeed + rest;
  // Up to free_for the ball may come contact_margin into a collider (collider_contact_time), which pushes it back by
  // at most that much.
  const double accel = free_acceleration(state, index, i);
  FreePath path{position(x, i), velocity(x, i), accel, jump, model.options.contact_margin,
                std::min(horizon, collider_contact_time(model, index, state, x, i, horizon, accel))};
  // The regime's acceleration, as the island's closed-form step takes it, and how long it holds.
  double dxdt[kBallDofs];
  (state.rolling(i) ? rolling_derivative : sliding_derivative)(model, index, state, x, i, dxdt);
  path.a = Vec3{dxdt[3], dxdt[4], dxdt[5]};
  path.steady_for = std::min(steady_for(model, index, state, x, i, path.a), path.free_for);
  return path;
}

double path_meeting_time(const FreePath& a, const FreePath& b, double reach, double closing) {
  const double h = std::min(a.free_for, b.free_for), acc = a.accel + b.accel;
  Vec3 d0 = a.p - b.p, v = a.v - b.v;
  if (!std::isfinite(h)) return straight_line_contact_time(d0, v, reach);  // two sleepers
  // While both are steady their centres' offset is d0 + v t + da t^2 / 2 (within the colliders' slack): the first
  // time it comes within reach is a root of a quartic, looked for only where the plain bound (the offset straying from
  // d0 + v t by |da| t^2 / 2) says it may come.
  const double steady = std::min({a.steady_for, b.steady_for, h}), near = reach + a.slack + b.slack;
  if (steady > 0) {
    const Vec3 da = a.a - b.a;
    if (glm::length(d0) <= near) return 0.0;
    if (pair_contact_time(d0, v, near, glm::length(da), steady) < steady) {
      const double t = first_entry(squared_gap(d0, v, da, near), steady);
      if (t <= steady) return t;
    }
    d0 += steady * v + 0.5 * steady * steady * da;
    v += steady * da;
  }
  // From there to h the velocity jumps move the balls by at most (jumps) (h - steady) more: a wider reach.
  const double rest = h - steady, wide = near + (a.jump + b.jump) * rest;
  const double t = pair_contact_time(d0, v, wide, acc, rest);
  if (t < rest) return steady + std::max(t, 0.0);
  const double gap = glm::length(d0 + rest * v) - wide - 0.5 * acc * rest * rest;  // apart until h, at least this far
  return closing > 0 ? h + std::max(gap, 0.0) / closing : std::numeric_limits<double>::infinity();
}

}  // namespace shotlab
