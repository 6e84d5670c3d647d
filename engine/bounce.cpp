#include "bounce.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#include <boost/numeric/odeint.hpp>
#pragma GCC diagnostic pop
#include <algorithm>
#include <array>
#include <cmath>

#include "contact_force.hpp"
#include "contacts.hpp"
#include "model_index.hpp"
#include "numerics.hpp"
#include "regimes.hpp"

namespace shotlab {

namespace odeint = boost::numeric::odeint;

namespace {

using Push = std::array<double, 4>;  // [d, d', P, Q] (BounceTrack)

// The scalar ODE of the bed's contact: m d'' = -m g.n - F(d, d'), F the law's normal force, clamped, while the ball
// presses in (d >= 0); with `touching` false none (the ball is above the surface: a parabola).
struct BedPush {
  const ContactMaterial& mat;
  double inv_mass, g_in;  // 1/kg; m/s^2: gravity's part into the bed, -g.n
  bool touching;
  double force(const Push& y) const {
    return touching && y[0] >= 0 ? std::max(normal_force(mat, y[0], y[1]), 0.0) : 0.0;
  }
  void operator()(const Push& y, Push& f, double) const {
    const double fn = force(y);
    f = {y[1], g_in - fn * inv_mass, fn, y[2]};
  }
  // y'' from y and y' = f: the force's rate where it pushes (none where the clamp holds it at zero).
  void second(const Push& y, const Push& f, double g[4]) const {
    const double rate = f[2] > 0 ? normal_force_rate(mat, y[0], y[1], f[1]) : 0.0;
    g[0] = f[1], g[1] = -rate * inv_mass, g[2] = rate, g[3] = f[2];
  }
  BounceTrack::Knot knot(double t, const Push& y, const Push& f) const {
    BounceTrack::Knot k{t, {y[0], y[1], y[2], y[3]}, {f[0], f[1], f[2], f[3]}, {}};
    second(y, f, k.g);
    return k;
  }
  // m/s: the speed of the vertical motion's amplitude (the elastic energy's share counted as speed).
  double swing(const Push& y) const {
    const double stored = y[0] > 0 && touching ? 2.0 * elastic_energy(mat, y[0]) * inv_mass : 0.0;
    return std::sqrt(y[1] * y[1] + stored);
  }
};

// Quintic Hermite interpolation between knots a and b from their values and first and second derivatives.
void hermite(const BounceTrack::Knot& a, const BounceTrack::Knot& b, double t, double out[4]) {
  const double h = b.t - a.t;
  if (h <= 0) {
    std::copy_n(b.y, 4, out);
    return;
  }
  const double s = (t - a.t) / h, s2 = s * s, s3 = s2 * s, s4 = s3 * s, s5 = s4 * s;
  const double h0 = 1 - 10 * s3 + 15 * s4 - 6 * s5, h5 = 10 * s3 - 15 * s4 + 6 * s5;
  const double h1 = (s - 6 * s3 + 8 * s4 - 3 * s5) * h, h4 = (-4 * s3 + 7 * s4 - 3 * s5) * h;
  const double h2 = 0.5 * (s2 - 3 * s3 + 3 * s4 - s5) * h * h, h3 = 0.5 * (s3 - 2 * s4 + s5) * h * h;
  for (int k = 0; k < 4; ++k)
    out[k] = h0 * a.y[k] + h1 * a.f[k] + h2 * a.g[k] + h3 * b.g[k] + h4 * b.f[k] + h5 * b.y[k];
}

// rad/s: the fastest rate of the contact at depth d: the Hertz stiffness's frequency there, the linearised bed's at
// the static sink, the linear damper's rate.
double contact_rate(const ContactMaterial& mat, double inv_mass, double d, double rest_rate) {
  const double slope = d <= 0 ? 0.0 : mat.exponent == 1.5 ? std::sqrt(d) : std::pow(d, mat.exponent - 1.0);
  const double damper = mat.damping_law == DampingLaw::Linear ? mat.damping * inv_mass : 0.0;
  return std::max({std::sqrt(mat.exponent * mat.stiffness * slope * inv_mass), rest_rate, damper});
}

// Whether a friction term of `per_newton` strength (N per N of normal force) acting on q (m/s) at mobility M stays
// saturated at normal force fn: |q| beyond its band's edge with a quarter to spare. A q of exactly zero holds (its
// term is zero and nothing else moves it).
bool saturated(const Smoothing& s, double q, double per_newton, double mobility, double fn) {
  if (q == 0 || per_newton == 0) return true;
  return std::abs(q) >= 1.25 / sharpness_for(s, per_newton * std::max(fn, 1e-300), mobility);
}

// The ball alone within contact_margin of one flat, level bed, and pressed against no other part of it (over a
// pocket the rim holds the ball): that bed (its penetration in `depth`, m), or -1.
int lone_bed(const Model& model, const ModelIndex& index, const State& state, const double* x, int i, double& depth) {
  const double margin = model.options.contact_margin, r = model.balls[i].radius;
  const Vec3 p = position(x, i);
  for (int j = 0; j < state.ball_count(); ++j)
    if (j != i && state.in_play[j] && glm::length(p - position(x, j)) - r - model.balls[j].radius < margin) return -1;
  int bed = -1;
  bool other = false;
  near_colliders(model, index, p, r, margin, [&](int c, const Penetration& pen) {
    if (other || pen.depth <= -margin) return;
    const Vec3& n = index.plane_normal[c];
    Vec3 point;
    other = bed >= 0 || !flat_bed(model.colliders[c], n, model.options.gravity, point) ||
            glm::dot(pen.normal, n) < 1.0 - 1e-12;
    bed = c;
    depth = pen.depth;
  });
  return other ? -1 : bed;
}

// follow()'s work: the scalar ODE stepped by Dormand-Prince 5 at a hundredth of the tolerance, its knots no further
// apart than the quintic interpolant holds to a tenth of it, and the checks that end the bounce.
class Follower {
 public:
  Follower(const Model& model, const ModelIndex& index, BedBounce& b)
      : model_(model), index_(index), b_(b), mat_(index.collider_material(b.bed)),
        smooth_{model.options.friction_sharpness, model.options.friction_rate_limit},
        push_{mat_, index.inv_mass[b.ball], -glm::dot(model.options.gravity, b.normal), b.touching} {
    const BallSpec& ball = model.balls[b.ball];
    const double r = ball.radius;
    u0_ = b.v0 + r * glm::cross(b.normal, b.w0), du_ = b.dv + r * glm::cross(b.normal, b.dw);
    q0_ = r * glm::dot(b.w0, b.normal), dq_ = r * glm::dot(b.dw, b.normal);
    sink_ = static_sink(ball, mat_, index.gravity);
    rest_rate_ = std::sqrt(mat_.exponent * index.gravity / sink_);
  }
  bool run(double horizon);

 private:
  bool fly(double horizon);
  // The slip and the spin saturated at this impulse and load.
  bool holds(const double y[4], double fn) const {
    const int i = b_.ball;
    Vec3 u = u0_ + y[2] * du_;
    u -= glm::dot(u, b_.normal) * b_.normal;
    const double slip = glm::length(u);
    return saturated(smooth_, slip, mat_.friction_at(slip), index_.inv_mass[i] + index_.inv_inertia_r2[i], fn) &&
           saturated(smooth_, q0_ + y[2] * dq_, mat_.spin_friction, index_.inv_inertia_r2[i], fn);
  }
  // Settled enough for the sliding regime: twice the hop must settle, so that the regimes' own test at this end
  // passes with room for round-off.
  bool settled(double t, const double y[4]) const {
    if (!push_.touching || !model_.options.sliding_regime) return false;
    const double offset = sink_ - y[0], hop2 = y[1] * y[1] + rest_rate_ * rest_rate_ * offset * offset;
    if (4.0 * hop2 >= model_.options.rest_speed * model_.options.rest_speed) return false;  // cheap first
    double at[kBallDofs];
    b_.apply(t, at);
    return settles_on_bed(model_, index_, at, b_.ball, b_.bed, b_.normal, -2.0 * y[1], 2.0 * (sink_ - y[0]), sink_);
  }
  // The depth's crossing of `target` between the last two knots, from t0 (where it was on the far side): the first
  // time on the interpolant past it.
  double crossing(double t0, double t1, double target) const {
    double lo = t0, hi = t1, at[4];
    b_.track->at(lo, at);
    double f_lo = at[0] - target;
    b_.track->at(hi, at);
    double f_hi = at[0] - target;
    // Regula falsi with the Illinois rule (the stale end's value halved), bisection once it stalls.
    int side = 0;
    for (int it = 0; it < 2 * kMaxRootIterations && hi - lo > 1e-2 * kOnsetResolution; ++it) {
      double mid = it < kMaxRootIterations ? (lo * f_hi - hi * f_lo) / (f_hi - f_lo) : 0.5 * (lo + hi);
      if (!(mid > lo && mid < hi)) mid = 0.5 * (lo + hi);
      b_.track->at(mid, at);
      const double f_mid = at[0] - target;
      if ((f_mid > 0) == (f_lo > 0)) {
        lo = mid, f_lo = f_mid;
        if (side == -1) f_hi *= 0.5;
        side = -1;
      } else {
        hi = mid, f_hi = f_mid;
        if (side == 1) f_lo *= 0.5;
        side = 1;
      }
    }
    return hi;
  }
  // s: the longest knot spacing at y for which the interpolant's error stays under a tenth of abs_tol.
  double longest(const Push& y) const {
    const double v = std::max(push_.swing(y), 1e-300), tol = 0.1 * model_.integrator.abs_tol;
    const double share = std::min(0.6, std::pow(46080.0 * tol / v, 1.0 / 6.0));
    return share / contact_rate(mat_, push_.inv_mass, y[0], rest_rate_);
  }

  const Model& model_;
  const ModelIndex& index_;
  BedBounce& b_;
  const ContactMaterial& mat_;
  Smoothing smooth_;
  BedPush push_;
  Vec3 u0_, du_;
  double q0_, dq_, sink_, rest_rate_;
  BounceTrack* track_ = nullptr;
};

// Above the surface the depth is a parabola, d = d0 + d0' t + g_in t^2 / 2, which the interpolant holds exactly: the
// bounce ends where the ball rises out of the margin and off its support (kSupportGap, a millionth past it: airborne,
// an event located on this step, and clear for the flight that follows) or comes down onto the bed, kLanded deep: the
// contact has begun at the step's end, where its onset is recorded (EventDetector::scan), as after a flight.
bool Follower::fly(double horizon) {
  constexpr double kLanded = 1e-15;  // m: past the surface by far more than the round-off of the centre's height
  const double d0 = b_.depth0, r0 = -glm::dot(b_.v0, b_.normal), g = push_.g_in;
  const double out = -std::max(model_.options.contact_margin, kSupportGap) * (1.0 + 1e-6);
  auto depth = [&](double t) { return d0 + r0 * t + 0.5 * g * t * t; };
  const bool leaves = r0 < 0 && (g <= 0 || d0 - r0 * r0 / (2.0 * g) < out);  // its apex above the margin
  double t;
  if (leaves) {  // the smaller root of g t^2 / 2 + r0 t + (d0 - out), written without cancellation
    const double c = d0 - out;
    t = 2.0 * c / (-r0 + std::sqrt(std::max(0.0, r0 * r0 - 2.0 * g * c)));
  } else {  // the root after the apex of depth = kLanded (with r0 > 0 and c <= 0: the only positive one)
    const double c = d0 - kLanded, root = std::sqrt(std::max(0.0, r0 * r0 - 2.0 * g * c));
    t = r0 > 0 && c <= 0 ? -2.0 * c / (r0 + root) : (root - r0) / g;
  }
  if (!(t < horizon)) t = horizon;
  else
    for (int k = 0; k < 64 && (leaves ? depth(t) > out : depth(t) <= 0); ++k) t = std::nextafter(t, horizon);
  auto track = std::make_shared<BounceTrack>();
  for (double at : {0.0, t}) {
    const Push y{depth(at), r0 + g * at, 0.0, 0.0}, f{y[1], g, 0.0, 0.0};
    track->knots.push_back(push_.knot(at, y, f));
  }
  b_.track = track;
  b_.end = t;
  b_.across = glm::length(b_.along);
  b_.accel = index_.gravity;
  return t > 0;
}

bool Follower::run(double horizon) {
  if (!push_.touching) return fly(horizon);
  auto track = std::make_shared<BounceTrack>();
  b_.track = track;
  Push y{b_.depth0, -glm::dot(b_.v0, b_.normal), 0.0, 0.0}, f;
  push_(y, f, 0.0);
  track->knots.push_back(push_.knot(0.0, y, f));
  double fmax = push_.force(y);
  if (!holds(y.data(), fmax)) return false;
  auto stepper = odeint::make_controlled<odeint::runge_kutta_dopri5<Push>>(1e-2 * model_.integrator.abs_tol,
                                                                            1e-2 * model_.integrator.rel_tol);
  double t = 0, dt = std::min(horizon, longest(y));
  b_.end = -1;
  for (int steps = 0; t < horizon && b_.end < 0; ++steps) {
    if (steps == kMaxBounceSteps) break;
    dt = std::min({dt, longest(y), horizon - t});
    Push y1 = y, f1 = f;
    double t1 = t;
    if (stepper.try_step(push_, y1, f1, t1, dt) != odeint::success) continue;
    track->knots.push_back(push_.knot(t1, y1, f1));
    const double fn = push_.force(y1);
    if (y1[0] <= 0) {  // the contact's end: where the depth crosses zero
      b_.end = crossing(t, t1, 0.0);
    } else if (!holds(y1.data(), fn)) {  // ends at the last knot where it held
      track->knots.pop_back();
      b_.end = t;
      break;
    } else if (settled(t1, y1.data())) {
      b_.end = t1;
    }
    fmax = std::max(fmax, fn);
    t = t1, y = y1, f = f1;
  }
  if (b_.end < 0) b_.end = t;  // the horizon
  fmax *= 1.1;                 // (a peak between knots)
  b_.across = fmax * glm::length(b_.dv) + glm::length(b_.along);
  b_.accel = fmax * (push_.inv_mass + glm::length(b_.dv)) + index_.gravity;
  return b_.end > 0;
}

}  // namespace

void BounceTrack::at(double t, double out[4]) const {
  if (knots.size() == 1) {
    std::copy_n(knots.front().y, 4, out);
    return;
  }
  const auto after = std::upper_bound(knots.begin() + 1, knots.end() - 1, t,
                                      [](double s, const Knot& k) { return s < k.t; });
  hermite(*(after - 1), *after, t, out);
}

void BedBounce::apply(double step_h, double* b) const {
  const double h = from + step_h;
  double y[4];
  track->at(h, y);
  const Vec3 vt = v0 - glm::dot(v0, normal) * normal;
  const Vec3 p = p0 + h * vt + 0.5 * h * h * along + y[3] * dv - (y[0] - depth0) * normal;
  const Vec3 v = vt + h * along + y[2] * dv - y[1] * normal;
  const Vec3 w = w0 + y[2] * dw;
  for (int c = 0; c < 3; ++c) b[c] = p[c], b[3 + c] = v[c], b[6 + c] = w[c];
}

std::optional<BedBounce> bed_bounce_of(const Model& model, const State& state, const ModelIndex& index, const double* x,
                                       int i) {
  if (!model.options.bounce_regime || !is_adaptive(model.integrator.method) || !state.active(i) || state.rolling(i) ||
      state.sliding(i) || index.rods_on[i] > 0)
    return std::nullopt;
  BedBounce b;
  b.ball = i;
  b.bed = lone_bed(model, index, state, x, i, b.depth0);
  if (b.bed < 0) return std::nullopt;
  const BallSpec& ball = model.balls[i];
  const ContactMaterial& mat = index.collider_material(b.bed);
  const Vec3& n = b.normal = index.plane_normal[b.bed];
  b.p0 = position(x, i), b.v0 = velocity(x, i), b.w0 = spin(x, i);
  const Vec3 g = model.options.gravity;
  b.along = g - glm::dot(g, n) * n;
  // In contact or above the surface: where the ball is kOnsetResolution from now (a contact that begins or ends
  // sooner is taken as begun or ended, so that no bounce ends within round-off of its start).
  b.touching = b.depth0 - glm::dot(b.v0, n) * kOnsetResolution > 0;
  if (b.touching) b.depth0 = std::max(b.depth0, 0.0);
  // The tangential terms per newton of normal force: the law is linear in it where they saturate. Rolling resistance
  // acts only without slip, where it would not be (a ball with no slip but a velocity along the bed is no bounce).
  const auto k = collider_kinematics(index, i, ball.radius, b.v0, b.w0, n, 0.0);
  const Vec3 u = k.slip - glm::dot(k.slip, n) * n, vt = b.v0 - glm::dot(b.v0, n) * n;
  if (glm::length(u) == 0 && glm::length(vt) != 0 && mat.rolling_resistance > 0) return std::nullopt;
  ContactForce unit;
  unit.normal = 1.0;
  add_friction(mat, k, {model.options.friction_sharpness, model.options.friction_rate_limit}, unit);
  const Vec3 a = unit.force * index.inv_mass[i];
  b.dv = a - glm::dot(a, n) * n;
  b.dw = contact_torque(unit, n, ball.radius) * index.inv_inertia[i];
  return b;
}

bool follow(const Model& model, const ModelIndex& index, BedBounce& bounce, double horizon) {
  return horizon > 0 && Follower(model, index, bounce).run(horizon);
}

bool goes_on(const BedBounce& last, const double* x, BedBounce& bounce) {
  // Not for the last few steps of round-off before its end (a step cut at a touch a hair before it).
  if (last.ball != bounce.ball || last.bed != bounce.bed || !(last.left() > kOnsetResolution)) return false;
  double y[4];
  last.track->at(last.from, y);
  if (!last.touching && y[0] > 0) return false;  // landed a hair before the end (the step was cut at the onset)
  double at[kBallDofs];
  last.apply(0.0, at);
  if (!std::equal(at, at + kBallDofs, x + kBallDofs * last.ball)) return false;
  bounce = last;
  return true;
}

}  // namespace shotlab
