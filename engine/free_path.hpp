// A ball's free path: where a lone ball in the rolling or sliding regime, or a sleeper, can be over the next moments,
// so that the partitioner can keep islands apart for longer than a speed bound alone allows (partition.hpp).
#pragma once
#include <optional>

#include "contacts.hpp"
#include "shotlab/model.hpp"
#include "shotlab/state.hpp"

namespace shotlab {

// Where a ball can be while it touches nothing but its bed: for the first `steady_for` seconds within `slack` of
// p + v t + a t^2 / 2, and from there up to `free_for` within accel s^2 / 2 + jump s + slack of where that parabola's
// tangent takes it (s: the time since). That holds for a lone ball in the rolling or sliding regime: it leaves its
// regime only when something comes within contact_margin (or its bed ends at a pocket); until its speed or slip falls
// to its band's edge (regimes.hpp, steady_for) its acceleration is the regime's constant a, and after that it stays
// under free_acceleration (contacts.hpp); its velocity jumps only at the rolling entry's snap, the stop cut and falling
// asleep (at rest_speed), all later than that, by at most `jump` in all; a collider may push it back by `slack` before
// free_for. A sleeper does not move at all until something touches it.
struct FreePath {
  Vec3 p, v;        // m, m/s
  double accel;     // m/s^2
  double jump;      // m/s
  double slack;     // m
  double free_for;  // s; +inf for a sleeper
  Vec3 a{0.0};      // m/s^2: the regime's acceleration, constant for steady_for
  double steady_for = 0;  // s; +inf for a sleeper
};

// The free path of ball i at (state, x), if it is asleep or in the rolling or sliding regime (the caller makes sure
// that nothing else in its island can touch it), looked at for `horizon` seconds at most: free_for <= horizon.
std::optional<FreePath> free_path(const Model& model, const State& state, const double* x, int i,
                                  const ModelIndex& index, double horizon);

// s: a lower bound on when two balls on free paths come within `reach` (m) of each other, given that neither can
// close in faster than `closing` (m/s, the sum of their speed bounds) once its path ends: the paths are followed to
// the earlier of their ends (exactly while both are steady), and from there on the gap closes at most at `closing`.
double path_meeting_time(const FreePath& a, const FreePath& b, double reach, double closing);

}  // namespace shotlab
