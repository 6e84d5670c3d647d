// The bounce: a ball that touches nothing but a flat, level bed within contact_margin and slides on it (its slip and
// its spin about the normal outside their friction bands, or exactly zero, for the whole stretch) moves in reduced
// form. The bed's normal force then depends on the depth and its rate alone, so the height follows a scalar ODE, solved
// here to a hundredth of the tolerance; every friction term is linear in that force, so the tangential motion and the
// spin follow from its impulse. This covers a landing, the hops after it and the settling onto the cloth, where an
// island would otherwise integrate all nine numbers of the ball through a stiff contact (docs/model.md#bounce).
#pragma once
#include <memory>
#include <optional>
#include <vector>

#include "shotlab/state.hpp"

namespace shotlab {

struct Model;
struct ModelIndex;

// The bed's contact over a bounce, at the steps of its scalar ODE: per knot the time since the bounce began (s),
// y = [depth d (m), its rate d' (m/s, positive while pressing in), normal impulse P (N s), its integral Q (N s^2)],
// and y' and y'' for quintic Hermite interpolation between knots.
struct BounceTrack {
  struct Knot {
    double t;
    double y[4], f[4], g[4];
  };
  std::vector<Knot> knots;
  // y at time t (0 <= t <= the last knot's time), written to out.
  void at(double t, double out[4]) const;
};

struct BedBounce {
  int ball;          // in the state vector
  int bed;           // the collider
  Vec3 normal;       // the bed's unit normal
  Vec3 p0, v0, w0;   // the ball at the start (m, m/s, rad/s)
  Vec3 dv;           // m/s per N s of normal impulse: the friction's change of the velocity (along the bed)
  Vec3 dw;           // rad/s per N s: its change of the spin (friction at the contact point, spin friction)
  Vec3 along;        // m/s^2: gravity's part along the bed (none on a level table)
  double depth0;     // m: the bed's penetration at the start
  bool touching;     // in contact over the bounce (else above the surface, within contact_margin, until it lands)
  double from = 0;    // s along the track where this step starts (a bounce that goes on over the next step)
  // Set by follow(), along the track:
  double end = 0;     // s after the start: where the reduced form stops holding, or the horizon asked for
  double accel = 0;   // m/s^2: a bound on the ball's acceleration until `end`
  double across = 0;  // m/s^2: the same for its part along the bed
  std::shared_ptr<const BounceTrack> track;  // shared: a span's copies keep the same track

  // Writes the ball's 9 numbers h seconds into this step (0 <= from + h <= end) at b.
  void apply(double h, double* b) const;
  double left() const { return end - from; }  // s: how long this step may follow it
};

// An island's bounces for its next step (time_to_band_edge): the list to fill, the last step's bounces moved on to
// its end (`last`, their `from` advanced), and how far to follow a new one (s).
struct BounceWork {
  std::vector<BedBounce>& list;
  const std::vector<BedBounce>& last;
  double horizon;
};

// Whether ball i at x (an island's state vector) may bounce: the model asks for it (Options::bounce_regime, adaptive
// methods only), the ball is in the full model, held by no rod, and within contact_margin of one flat, level bed and
// of nothing else, and its slip (and spin about the normal) is saturated or zero. Cheap: the bounce's frame, not yet
// followed.
std::optional<BedBounce> bed_bounce_of(const Model& model, const State& state, const ModelIndex& index, const double* x,
                                       int i);

// Follows the bounce for at most `horizon` (s), to the first of: the contact's end (the ball leaves the bed's
// surface), its beginning (from above), the ball rising past kSupportGap (airborne), the slip or the spin coming
// within a quarter of its band's edge on its side, the ball settling enough for the sliding regime (regimes.hpp).
// False where it does not hold even at the start.
bool follow(const Model& model, const ModelIndex& index, BedBounce& bounce, double horizon);

// The bounce `last` followed over the step that ended at x, going on from there: where the ball is exactly where it
// led (nothing snapped it at the step's end), more than kOnsetResolution before its end and, above the surface, not
// yet down on it, the same track, sparing follow(); else false.
bool goes_on(const BedBounce& last, const double* x, BedBounce& bounce);

}  // namespace shotlab
