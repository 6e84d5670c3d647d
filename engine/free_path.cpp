#include "free_path.hpp"

#include <cmath>
#include <limits>

#include "numerics.hpp"
#include "regimes.hpp"

namespace shotlab {

std::optional<FreePath> free_path(const Model& model, const State& state, const double* x, int i,
                                  const ModelIndex& index, double horizon) {
  if (!state.in_play[i]) return std::nullopt;
  if (state.sleeping(i)) return FreePath{position(x, i), Vec3{0.0}, 0.0, 0.0, 0.0, std::numeric_limits<double>::infinity()};
  if (!state.rolling(i) && !state.sliding(i)) return std::nullopt;
  // The velocity jumps a path may take, summed: the rolling entry removes a slip under entry_slip, 2/7 of it
  // from the velocity (update_rolling); the stop cut (settle_rolling); falling asleep zeroes a velocity under
  // rest_speed (update_sleep).
  const double rest = model.options.rest_speed;
  const double jump = 2.0 / 7.0 * entry_slip(model) + kStopSpeed + (model.options.sleep_time > 0 ? rest : 0.0);
  // Up to free_for the ball may come contact_margin into a collider (collider_contact_time), which pushes it back by
  // at most that much.
  return FreePath{position(x, i), velocity(x, i), free_acceleration(state, index, i), jump,
                  model.options.contact_margin, std::min(horizon, collider_contact_time(model, index, state, x, i, horizon, free_acceleration(state, index, i)))};
}

double path_meeting_time(const FreePath& a, const FreePath& b, double reach, double closing) {
  const double h = std::min(a.free_for, b.free_for), acc = a.accel + b.accel;
  const Vec3 d0 = a.p - b.p, v = a.v - b.v;
  if (!std::isfinite(h)) return straight_line_contact_time(d0, v, reach);  // two sleepers
  // Until h the velocity jumps move the balls by at most (jumps) h more, the colliders by their slack: a wider reach.
  const double wide = reach + (a.jump + b.jump) * h + a.slack + b.slack;
  const double t = pair_contact_time(d0, v, wide, acc, h);
  if (t < h) return std::max(t, 0.0);
  const double gap = glm::length(d0 + h * v) - wide - 0.5 * acc * h * h;  // apart until h, at least this far then
  return closing > 0 ? h + std::max(gap, 0.0) / closing : std::numeric_limits<double>::infinity();
}

}  // namespace shotlab
