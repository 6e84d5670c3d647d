// The changing side of a simulation (MuJoCo's mjData): the ODE state vector and which balls are still in play.
#pragma once
#include <algorithm>
#include <cstdint>
#include <vector>

#include "shotlab/vec.hpp"

namespace shotlab {

// ODE state layout (docs/model.md#state): 9 numbers a ball, [p (m), v (m/s), w (rad/s)], balls in model order.
inline constexpr int kBallDofs = 9;
inline constexpr int kSpinDof = 6;  // where a ball's spin starts among its 9 numbers
using StateVector = std::vector<double>;

template <class X> Vec3 position(const X& x, int i) { return {x[9 * i], x[9 * i + 1], x[9 * i + 2]}; }
template <class X> Vec3 velocity(const X& x, int i) { return {x[9 * i + 3], x[9 * i + 4], x[9 * i + 5]}; }
template <class X> Vec3 spin(const X& x, int i) { return {x[9 * i + 6], x[9 * i + 7], x[9 * i + 8]}; }
template <class X> void set_vec(X& x, int index, const Vec3& v) {
  x[index] = v.x;
  x[index + 1] = v.y;
  x[index + 2] = v.z;
}
template <class X> void set_position(X& x, int i, const Vec3& v) { set_vec(x, 9 * i, v); }
template <class X> void set_velocity(X& x, int i, const Vec3& v) { set_vec(x, 9 * i + 3, v); }
template <class X> void set_spin(X& x, int i, const Vec3& v) { set_vec(x, 9 * i + 6, v); }

struct State {
  double time = 0;              // s
  StateVector x;                // 9 * balls
  std::vector<uint8_t> in_play; // 0 once a ball is pocketed or has left the table: frozen, touches nothing
  std::vector<uint8_t> asleep;  // 1 while a ball rests and nothing moving touches it (regimes.hpp); empty: none
  std::vector<int> rolling_on;  // the collider a ball rolls on in the rolling regime (regimes.hpp), else -1; empty: none
  std::vector<int> sliding_on;  // the collider a ball slides on in the sliding regime (regimes.hpp), else -1; empty: none
  std::vector<double> still_for;  // s each ball has been at rest, towards sleep_time (regimes.hpp); empty: none

  int ball_count() const { return static_cast<int>(in_play.size()); }
  bool sleeping(int i) const { return static_cast<size_t>(i) < asleep.size() && asleep[i]; }
  bool rolling(int i) const { return static_cast<size_t>(i) < rolling_on.size() && rolling_on[i] >= 0; }
  bool sliding(int i) const { return static_cast<size_t>(i) < sliding_on.size() && sliding_on[i] >= 0; }
  // In play and awake: its equations are integrated.
  bool active(int i) const { return in_play[i] && !sleeping(i); }
};

// Every ball's regime flags (everything but the time and the state vector) from one state to another.
inline void copy_flags(const State& from, State& to) {
  to.in_play = from.in_play;
  to.asleep = from.asleep;
  to.rolling_on = from.rolling_on;
  to.sliding_on = from.sliding_on;
  to.still_for = from.still_for;
}

// Ball i of `from` (its flags and, with `with_x`, its 9 numbers) into ball j of `to`, whose flags are sized: between
// a scene and the sub-state of one of its islands (island.hpp).
inline void copy_ball(const State& from, int i, State& to, int j, bool with_x = true) {
  if (with_x) std::copy_n(from.x.begin() + kBallDofs * i, kBallDofs, to.x.begin() + kBallDofs * j);
  to.in_play[j] = from.in_play[i];
  to.asleep[j] = from.sleeping(i);
  to.rolling_on[j] = from.rolling(i) ? from.rolling_on[i] : -1;
  to.sliding_on[j] = from.sliding(i) ? from.sliding_on[i] : -1;
  to.still_for[j] = static_cast<size_t>(i) < from.still_for.size() ? from.still_for[i] : 0.0;
}

}  // namespace shotlab
