#include "regimes.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <utility>

#include "dynamics.hpp"
#include "events.hpp"

namespace shotlab {

// A ball in the sliding regime gets to the entry slip without stiff steps: its slip tail is followed in closed form
// (band_tail.hpp) down to kDeadTail, leaving nothing to snap.
double entry_slip(const Model& model) {
  return std::min(kEntrySlip * model.options.rest_speed, kEntrySlipPerTolerance * model.integrator.abs_tol);
}

double static_sink(const BallSpec& b, const ContactMaterial& m, double g) {
  const double q = b.mass * g / m.stiffness;
  return m.exponent == 1.5 ? std::cbrt(q * q) : std::pow(q, 1.0 / m.exponent);  // cbrt: a third of pow's cost
}

bool flat_bed(const Collider& c, const Vec3& normal, const Vec3& gravity, Vec3& point) {
  if (const auto* s = std::get_if<Plane>(&c.shape)) point = s->point;
  else if (const auto* s = std::get_if<BoundedPlane>(&c.shape)) point = s->origin;
  else return false;
  const double g = glm::length(gravity);
  return g > 0 && glm::dot(normal, -gravity / g) > 1.0 - 1e-12;
}

int only_bed_near(const Model& model, const ModelIndex& index, const Vec3& p, double r, Vec3& point, double& depth) {
  const double margin = model.options.contact_margin;
  int support = -1;
  bool other = false;  // something other than one flat bed is within the margin
  near_colliders(model, index, p, r, margin, [&](int c, const Penetration& pen) {
    if (other || pen.depth <= -margin) return;
    const Vec3& normal = index.plane_normal[c];
    if (support >= 0 || !flat_bed(model.colliders[c], normal, model.options.gravity, point) ||
        glm::dot(pen.normal, normal) < 1.0 - 1e-12) {  // over a pocket the rim, not the bed, holds the ball
      other = true;
      return;
    }
    support = c;
    depth = pen.depth;
  });
  return other ? -1 : support;
}

namespace {

// s: how long a quantity q (a slip, speed or contact-patch speed, m/s) that a friction term of the given strength (N)
// relaxes at strength times mobility (1/kg: m/s^2, contact_force.hpp) takes to fall to its smoothing band's edge
// 1/k, or to `floor` (m/s) where that is higher; not positive once there.
double time_to_edge(const Smoothing& s, double q, double strength, double mobility, double floor = 0.0) {
  return (q - std::max(floor, 1.0 / sharpness_for(s, strength, mobility))) / (strength * mobility);
}
// A sliding ball's slip u inside its band (|u| = q0 > 0, unit direction u^) as a Slip tail (band_tail.hpp), and how long
// its step may run: to where the slip is round-off (kDeadTail), so that the rolling entry comes at the step's end with
// nothing left to snap (the closed form costs the same however far it is followed). None where
// that closed form would not hold to well under the tolerance: the rolling regime off (nothing ends the tail), the
// slip already at the entry, rolling resistance inside its own band before the end, or v turning so far (by
// s q0 |u^ x d| / |v| at most) that what the closed form leaves out, a_r T times the turn squared in the velocity and
// a_r T^2 / 2 times the turn in the position, comes over kSnapShare abs_tol.
std::optional<std::pair<BandTail, double>> slip_tail(const Model& model, const ModelIndex& index, const Smoothing& smooth,
                                                     const ContactMaterial& m, int i, const Vec3& n, const Vec3& p,
                                                     const Vec3& v, const Vec3& u) {
  const double q0 = glm::length(u), entry = entry_slip(model);
  if (!model.options.rolling_regime || q0 <= entry) return std::nullopt;
  const double weight = model.balls[i].mass * glm::length(model.options.gravity);
  const double mobility = index.inv_mass[i] + index.inv_inertia_r2[i], share = index.inv_mass[i] / mobility;
  const BandDecay decay{q0, sharpness_for(smooth, m.friction * weight, mobility), m.friction * weight * mobility};
  const double until = decay.time_to(kDeadTail);
  const double a_r = m.rolling_resistance * weight * index.inv_mass[i], speed = glm::length(v) - share * q0;
  const Vec3 dir = u / q0;
  if (a_r > 0) {
    const double band = 1.0 / sharpness_for(smooth, m.rolling_resistance * weight, index.inv_mass[i]);
    if (!(speed - a_r * until > band)) return std::nullopt;
    const double turn = share * q0 * glm::length(glm::cross(dir, v / glm::length(v))) / speed;
    if (a_r * until * std::max(turn * turn, 0.5 * until * turn) > kSnapShare * model.integrator.abs_tol) return std::nullopt;
  }
  return std::pair{BandTail{BandTail::Kind::Slip, i, n, dir, p, model.balls[i].radius, decay, v, a_r, share}, until};
}

// What the rest of a hop does through the bed's friction (update_sliding derives it), added to ball i as it enters a
// regime whose accelerations are dxdt: times -v_n / g on the velocity and spin, times -offset / g on the position.
void add_hop_rest(StateVector& x, int i, double vn, double offset, double g, const double* dxdt) {
  for (int c = 0; c < 3; ++c) {
    x[kBallDofs * i + c] -= offset / g * dxdt[3 + c];
    x[kBallDofs * i + 3 + c] -= vn / g * dxdt[3 + c];
    x[kBallDofs * i + 6 + c] -= vn / g * dxdt[6 + c];
  }
}

// s: how long a ball on its regime's path keeps to it, by its regime's own floors (steady_for).
double regime_steady_for(const Model& model, const ModelIndex& index, const State& state, const double* x, int i) {
  const int bed = state.rolling(i) ? state.rolling_on[i] : state.sliding(i) ? state.sliding_on[i] : -1;
  if (bed < 0) return 0.0;
  const ContactMaterial& m = index.collider_material(bed);
  const Smoothing smooth{model.options.friction_sharpness, model.options.friction_rate_limit};
  const double weight = model.balls[i].mass * index.gravity, r = model.balls[i].radius;
  const Vec3 v = velocity(x, i), &n = index.plane_normal[bed];
  if (state.rolling(i)) {  // the speed, to the stop cut (settle_rolling) at the latest
    const double speed = glm::length(v);
    if (m.rolling_resistance <= 0) return speed >= kStopSpeed ? std::numeric_limits<double>::infinity() : 0.0;
    return std::max(0.0, time_to_edge(smooth, speed, m.rolling_resistance * weight, index.inv_mass[i], kStopSpeed));
  }
  if (m.friction <= 0 || m.friction_law != FrictionLaw::Constant) return 0.0;
  Vec3 u = v + r * glm::cross(n, spin(x, i));  // the slip, to the rolling entry's snap (update_rolling) at the latest
  u -= glm::dot(u, n) * n;
  return std::max(0.0, time_to_edge(smooth, glm::length(u), m.friction * weight,
                                    index.inv_mass[i] + index.inv_inertia_r2[i], entry_slip(model)));
}

}  // namespace

double steady_for(const Model& model, const ModelIndex& index, const State& state, const double* x, int i,
                  const Vec3& a) {
  const double steady = regime_steady_for(model, index, state, x, i);
  if (model.options.sleep_time <= 0) return steady;
  // Falling asleep zeroes a velocity under rest_speed (update_sleep): the speed, falling at most at |a|, stays
  // over it for (speed - rest_speed) / |a| at least.
  const double speed = glm::length(velocity(x, i)), slowing = glm::length(a), rest = model.options.rest_speed;
  if (speed <= rest) return 0.0;
  return slowing > 0 ? std::min(steady, (speed - rest) / slowing) : steady;
}

Regimes::Regimes(const Model& model, const ModelIndex& index) : model_(model), index_(index) {
  const double g = glm::length(model.options.gravity);
  for (const BallSpec& b : model.balls)
    for (int c : index_.plane_like) sink_.push_back(static_sink(b, index_.collider_material(c), g));
}

namespace {

// time_to_band_edge's scan of the balls in the rolling or sliding regime: the earliest band edge (best), and whether
// every term is outside its band or follows a tail's closed form (outside).
struct BandScan {
  const Model& model;
  const ModelIndex& index;
  const double* x;
  std::vector<BandTail>* tails;
  Smoothing smooth;
  double g;  // m/s^2
  double best = std::numeric_limits<double>::infinity();
  bool outside = true;

  // A quantity q falling at `rate` (each friction term of strength F relaxes the motion it opposes at F times its
  // mobility, contact_force.hpp) reaches its band's edge 1/k after (q - 1/k) / rate. Where fricstep is 0 (q = 0 and
  // `zero_holds`: nothing else moves q) or 1 (beyond the edge), the term is constant. Whether q is inside the band.
  bool edge(double q, double strength, double mobility, bool zero_holds) {
    const double t = time_to_edge(smooth, q, strength, mobility);
    if (t > kKinkTooClose) best = std::min(best, t);
    else if (q != 0 || !zero_holds) return true;
    return false;
  }
  void ball(const State& state, int i, int bed);
};

// Inside its band the spin about the normal, and a rolling ball's speed, follow their tails' closed forms where the
// caller takes tails (band_tail.hpp). A speed tail lasts until the stop cut (settle_rolling).
void BandScan::ball(const State& state, int i, int bed) {
  const ContactMaterial& m = index.collider_material(bed);
  const Vec3& n = index.plane_normal[bed];
  const double weight = model.balls[i].mass * g, r = model.balls[i].radius;
  const Vec3 v = velocity(x, i), w = spin(x, i);
  const double spin_strength = m.spin_friction * weight, wn = glm::dot(w, n);
  if (m.spin_friction > 0 && edge(r * std::abs(wn), spin_strength, index.inv_inertia_r2[i], true)) {
    if (tails)
      tails->push_back({BandTail::Kind::Spin, i, n, Vec3{0.0}, Vec3{0.0}, r,
                        {r * wn, sharpness_for(smooth, spin_strength, index.inv_inertia_r2[i]),
                         spin_strength * index.inv_inertia_r2[i]}});
    else
      outside = false;
  }
  if (state.rolling(i)) {  // the speed, against rolling resistance
    const double strength = m.rolling_resistance * weight, speed = glm::length(v);
    if (m.rolling_resistance > 0 && edge(speed, strength, index.inv_mass[i], true)) {
      if (tails && speed > kStopSpeed) {
        const BandDecay decay{speed, sharpness_for(smooth, strength, index.inv_mass[i]), strength * index.inv_mass[i]};
        tails->push_back({BandTail::Kind::Speed, i, n, v / speed, position(x, i), r, decay});
        best = std::min(best, decay.time_to(0.5 * kStopSpeed));
      } else {
        outside = false;
      }
    }
  } else if (m.friction > 0) {  // the slip, against sliding friction (rolling resistance acts only inside its band)
    Vec3 u = v + r * glm::cross(n, w);
    u -= glm::dot(u, n) * n;
    if (edge(glm::length(u), m.friction * weight, index.inv_mass[i] + index.inv_inertia_r2[i], false)) {
      const auto tail = tails ? slip_tail(model, index, smooth, m, i, n, position(x, i), v, u) : std::nullopt;
      if (tail) tails->push_back(tail->first), best = std::min(best, tail->second);
      else outside = false;
    }
  } else if (m.rolling_resistance > 0) {
    outside = false;  // frictionless sliding: rolling resistance acts on the centre's speed all along
  }
}

// The balls in the full model that move in closed form: each swinging alone on its rod (listed in `swings`), flying,
// held by no rod and touching nothing, under gravity alone (the constant acceleration of the island's closed-form
// step), or bouncing on the bed alone (listed in `bounces`, followed for at most `horizon` s once every ball moves so,
// their ends lowering `best`); false at the first that does none of these.
bool add_free_motions(const Model& model, const State& state, const ModelIndex& index, const double* x,
                      std::vector<Swing>& swings, const std::vector<Swing>* continuing, BounceWork* bounces,
                      double& best) {
  for (int i = 0; i < state.ball_count(); ++i) {
    if (!state.active(i) || state.rolling(i) || state.sliding(i)) continue;
    if (index.rods_on[i] == 0) {
      if (model.options.flight_regime && clear_of_contacts(model, index, state, x, i)) continue;
      auto bounce = bounces ? bed_bounce_of(model, state, index, x, i) : std::nullopt;
      if (!bounce) return false;
      bounces->list.push_back(std::move(*bounce));
      continue;
    }
    const Swing* last = nullptr;
    if (continuing)
      for (const Swing& s : *continuing)
        if (s.ball == i) last = &s;
    const auto swing = swing_of(model, state, index, x, i, last);
    if (!swing) return false;
    swings.push_back(*swing);
  }
  if (!bounces) return true;
  for (BedBounce& bounce : bounces->list) {
    const auto& last = bounces->last;
    const bool on = std::any_of(last.begin(), last.end(), [&](const BedBounce& b) { return goes_on(b, x, bounce); });
    if (!on && !follow(model, index, bounce, bounces->horizon)) return false;
    best = std::min(best, bounce.left());
  }
  return true;
}

}  // namespace

double time_to_band_edge(const Model& model, const State& state, const ModelIndex& index, const double* x,
                         bool* constant, std::vector<BandTail>* tails, std::vector<Swing>* swings,
                         const std::vector<Swing>* continuing, BounceWork* bounces) {
  BandScan scan{model, index, x, tails, {model.options.friction_sharpness, model.options.friction_rate_limit},
                glm::length(model.options.gravity)};
  if (tails) tails->clear();
  if (swings) swings->clear();
  if (bounces) bounces->list.clear();
  bool full = false;  // a ball in the full model
  for (int i = 0; i < state.ball_count(); ++i) {
    if (!state.active(i)) continue;  // asleep or out of play: frozen
    const int bed = state.rolling(i) ? state.rolling_on[i] : state.sliding(i) ? state.sliding_on[i] : -1;
    if (bed < 0) full = true;  // the full model, unless the ball swings alone on its rod or flies (below)
    else scan.ball(state, i, bed);
  }
  // The swings, flights and bounces last: worked out only where nothing else keeps the island from its closed form.
  bool outside = scan.outside;
  if (full && !swings) outside = false;
  double best = scan.best;
  if (full && outside) outside = add_free_motions(model, state, index, x, *swings, continuing, bounces, best);
  if (constant) *constant = outside;
  return best;
}

bool Regimes::slip_below(const StateVector& x, int i, const Vec3& n, double limit) const {
  Vec3 u = velocity(x, i) + model_.balls[i].radius * glm::cross(n, spin(x, i));
  u -= glm::dot(u, n) * n;
  return glm::length(u) < limit;
}

int Regimes::only_on_bed(const StateVector& x, int i, Vec3& normal, double& height) const {
  const double margin = model_.options.contact_margin, r = model_.balls[i].radius;
  const Vec3 p = position(x, i);
  // Other balls and rods first: they are cheap to check and rule out most balls of a rack.
  for (int j : touching_[i])
    if (glm::length(p - position(x, j)) - r - model_.balls[j].radius < margin) return -1;
  if (index_.rods_on[i] > 0) return -1;
  Vec3 point;
  double depth;
  const int support = only_bed_near(model_, index_, p, r, point, depth);
  if (support < 0) return -1;
  normal = index_.plane_normal[support];
  height = glm::dot(point, normal) + r - sink(i, support);
  return support;
}

// The snap (update_sliding) adds the rest of the hop's friction at once, as if the friction per newton f stayed what it
// is now. That is exact while the bed's sliding friction stays saturated (outside its band: constant in size and
// direction, as a sliding ball's slip falls along a fixed line, and rolling resistance does not act) and not at all
// inside the band, where the slip relaxes within 0.1 ms and the hop's force no longer matters: there the snap is off
// by up to mu v_n in velocity until the slip has relaxed, and by about mu v_n / sigma in position for good (mu: the
// friction and rolling resistance per newton, sigma: the slowest decay rate of the bed's vertical mode). So the hop
// that is left when the slip reaches its band's edge must be under kSnapShare abs_tol sigma / mu (1e-5 m/s at abs_tol
// 1e-7 on the cloth: sigma = c / 2m = 720 1/s, mu = 0.21), and the hop now under rest_speed, the normal speed the
// rolling entry allows. A ball that slides on after a hop of 1e-2 m/s then settles 3 ms later instead of 16 ms.
// m/s: the bed's vertical motion of ball i (normal speed vn, height offset from the static sink) as the speed of its
// amplitude in the linearised bed contact (stiffness e m g / sink, so omega^2 = e g / sink).
double Regimes::hop(int i, int bed, double vn, double offset) const {
  return bed_hop(index_.collider_material(bed), glm::length(model_.options.gravity), sink(i, bed), vn, offset);
}

double bed_hop(const ContactMaterial& m, double g, double sink, double vn, double offset) {
  return std::hypot(vn, std::sqrt(m.exponent * g / sink) * offset);
}

bool settles_on_bed(const Model& model, const ModelIndex& index, const double* b, int i, int bed, const Vec3& n,
                    double vn, double offset, double sink) {
  const BallSpec& ball = model.balls[i];
  const ContactMaterial& m = index.collider_material(bed);
  const double g = glm::length(model.options.gravity);
  const double omega2 = m.exponent * g / sink;
  const double hop = bed_hop(m, g, sink, vn, offset);
  if (hop >= model.options.rest_speed) return false;
  const double mu = m.friction + m.rolling_resistance;
  if (mu <= 0) return true;  // nothing tangential depends on the normal force
  const double sigma = m.damping_law == DampingLaw::Linear ? m.damping / (2 * ball.mass) : 0.5 * g * m.damping;
  const double slowest = sigma * sigma > omega2 ? sigma - std::sqrt(sigma * sigma - omega2) : sigma;  // overdamped
  // The slip's time to its band's edge, falling at the regime's rate mu m g (1/m + R^2/I) (time_to_band_edge).
  Vec3 u = velocity(b, 0) + ball.radius * glm::cross(n, spin(b, 0));
  u -= glm::dot(u, n) * n;
  const Smoothing smooth{model.options.friction_sharpness, model.options.friction_rate_limit};
  const double saturated_for =
      m.friction > 0 ? std::max(0.0, time_to_edge(smooth, glm::length(u), m.friction * (ball.mass * g),
                                                  index.inv_mass[i] + index.inv_inertia_r2[i]))
                     : 0.0;
  return hop * std::exp(-slowest * saturated_for) < kSnapShare * model.integrator.abs_tol * slowest / mu;
}

double Regimes::sink(int i, int plane) const {
  const auto& planes = index_.plane_like;
  return sink_[i * planes.size() + (std::find(planes.begin(), planes.end(), plane) - planes.begin())];
}

bool Regimes::update(State& state, StateVector& x, double dt) {
  const int n = state.ball_count();
  if (n == 0) return false;
  if (state.asleep.size() != static_cast<size_t>(n)) state.asleep.assign(n, 0);
  if (state.rolling_on.size() != static_cast<size_t>(n)) state.rolling_on.assign(n, -1);
  if (state.sliding_on.size() != static_cast<size_t>(n)) state.sliding_on.assign(n, -1);
  if (state.still_for.size() != static_cast<size_t>(n)) state.still_for.assign(n, 0.0);
  // Neighbour lists within contact_margin (sleep groups use only the frozen-touching ones).
  touching_.resize(n);
  for (auto& list : touching_) list.clear();  // keeps each list's buffer: this runs after every step
  overlapping_pairs(model_, index_, state, x.data(), broad_, std::max(model_.options.contact_margin, kTouch));
  for (const auto& [i, j] : broad_.pairs) {
    touching_[i].push_back(j);
    touching_[j].push_back(i);
  }
  const bool slept = update_sleep(state, x, dt);
  // Each awake ball's bed, once for both regimes: a ball that enters rolling below moves by its snap, but it touches
  // nothing else within contact_margin, so no other ball's answer changes. Only adaptive methods: they end a step
  // where a contact begins, so a ball in a regime never meets a force its closed form ignores for longer than that;
  // a fixed step would let it ignore an impact for a whole step.
  bed_.assign(n, Support{});
  const bool regimes = (model_.options.rolling_regime || model_.options.sliding_regime) && is_adaptive(model_.integrator.method);
  for (int i = 0; i < n && regimes; ++i)
    if (state.active(i)) bed_[i].collider = only_on_bed(x, i, bed_[i].normal, bed_[i].height);
  const bool rolled = update_rolling(state, x);
  const bool slid = update_sliding(state, x);
  return slept || rolled || slid;
}

bool Regimes::update_rolling(State& state, StateVector& x) {
  bool changed = false;
  for (int i = 0; i < state.ball_count(); ++i) {
    const int bed = model_.options.rolling_regime ? bed_[i].collider : -1;
    const Vec3& n = bed_[i].normal;
    const double height = bed_[i].height;
    const bool eligible = bed >= 0;
    if (state.rolling(i) && !eligible) {
      state.rolling_on[i] = -1;
      changed = true;
    } else if (state.rolling(i)) {
      changed = settle_rolling(x, i, n) || changed;
    } else if (!state.rolling(i) && eligible && slip_below(x, i, n, entry_slip(model_)) &&
               hop(i, bed, glm::dot(velocity(x, i), n), glm::dot(position(x, i), n) - height) <
                   model_.options.rest_speed) {  // settled: a ball pressed deep into the bed is not snapped out
      // Snap onto the constraint: height at the sink depth, no normal velocity, and the remaining slip u (under
      // entry_slip by the entry condition) removed the way cloth friction removes it: by a tangential impulse J at
      // the contact point r = -R n. Then du = J/m + R n x ((r x J)/I) = J/m (1 + m R^2/I) = 3.5 J/m, so
      // J = -m u / 3.5: the velocity takes 2/7 of the correction, the spin the rest, as in a real stun-to-roll. What
      // is left of a hop goes into the rolling resistance and spin friction as at the sliding entry (update_sliding):
      // the regime's equations are linear in the normal force too.
      const double r = model_.balls[i].radius, mass = model_.balls[i].mass;
      const Vec3 p = position(x, i), v = velocity(x, i), w = spin(x, i);
      const double vn = glm::dot(v, n), offset = glm::dot(p, n) - height;
      const Vec3 vt = v - glm::dot(v, n) * n;
      Vec3 u = vt + r * glm::cross(n, w);
      u -= glm::dot(u, n) * n;
      const Vec3 j = -(mass / 3.5) * u;
      set_position(x, i, p + (height - glm::dot(p, n)) * n);
      set_velocity(x, i, vt + j / mass);
      set_spin(x, i, w + glm::cross(-r * n, j) / model_.balls[i].inertia());
      state.rolling_on[i] = bed;
      state.sliding_on[i] = -1;
      double dxdt[kBallDofs];
      rolling_derivative(model_, index_, state, x.data(), i, dxdt);
      add_hop_rest(x, i, vn, offset, glm::length(model_.options.gravity), dxdt);
      changed = true;
    }
  }
  return changed;
}

bool Regimes::update_sliding(State& state, StateVector& x) {
  bool changed = false;
  const double g = glm::length(model_.options.gravity);
  for (int i = 0; i < state.ball_count(); ++i) {
    if (state.rolling(i)) continue;  // rolling supersedes sliding (update_rolling cleared the flag)
    const int bed = model_.options.sliding_regime ? bed_[i].collider : -1;
    const Vec3& n = bed_[i].normal;
    const double height = bed_[i].height;
    if (state.sliding(i)) {
      if (bed != state.sliding_on[i]) {
        state.sliding_on[i] = -1;  // the full model takes over at the sink, with no normal motion: its equilibrium
        changed = true;
      }
      continue;
    }
    if (bed < 0) continue;
    // Settled: the normal speed and the height's offset from the sink small enough (settles). The snap removes that
    // motion and adds what the normal force still to come would have done through the friction. While the ball
    // touches only the bed, m dv_n/dt = N - m g, so over the rest of the hop N brings m (0 - v_n) more impulse than
    // the weight, and every friction term, linear in N at the bed's load, that much more too: the regime (N = m g
    // from here on) adds its accelerations times -v_n / g. That impulse comes over the hop, not at once: its first
    // moment, the integral of t (N - m g) dt = -m (integral of v_n dt) = m offset, moves the ball by the regime's
    // acceleration times -offset / g for good. Both hold for any N(t), a bounce off the bed included.
    const Vec3 p = position(x, i), v = velocity(x, i);
    const double vn = glm::dot(v, n), offset = glm::dot(p, n) - height;
    if (!settles_on_bed(model_, index_, x.data() + kBallDofs * i, i, bed, n, vn, offset, sink(i, bed))) continue;
    set_position(x, i, p - offset * n);
    set_velocity(x, i, v - vn * n);
    state.sliding_on[i] = bed;
    double dxdt[kBallDofs];
    sliding_derivative(model_, index_, state, x.data(), i, dxdt);
    add_hop_rest(x, i, vn, offset, g, dxdt);
    changed = true;
  }
  return changed;
}

// A rolling ball's speed decays to zero the way the slip does at the rolling entry: linearly down to the fricstep
// band, then exponentially, at 1.5 k mu_r g ~ 150 1/s. Inside the band it follows its closed form (band_tail.hpp),
// which never quite reaches zero: below 1e-7 m/s the ball stops (the distance still to roll, v / (150 1/s), is under
// 1 nm). Its spin about the normal goes on decaying in closed form on its own.
bool Regimes::settle_rolling(StateVector& x, int i, const Vec3& n) const {
  const Vec3 v = velocity(x, i), w = spin(x, i);
  const double speed = glm::length(v);
  // A speed already at round-off (1e-12 m/s and below) is left alone: cutting it changes nothing but would restart
  // the integrator after every step.
  if (!(speed > kDeadTail && speed < kStopSpeed)) return false;
  set_velocity(x, i, Vec3{0.0});
  set_spin(x, i, glm::dot(w, n) * n);  // no rolling spin at zero speed (v + R n x w = 0)
  return true;
}

}  // namespace shotlab
