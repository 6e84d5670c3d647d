#include "bounce.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#include <boost/numeric/odeint.hpp>
#pragma GCC diagnostic pop
#include <algorithm>
#include <array>
#include <boost/math/tools/toms748_solve.hpp>
#include <cmath>
#include <cstdint>

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

// rad/s: the fastest rate of the contact at depth d or deeper: the Hertz stiffness's frequency there (rising with the
// depth), the linear damper's rate.
double contact_rate(const ContactMaterial& mat, double inv_mass, double d) {
  const double damper = mat.damping_law == DampingLaw::Linear ? mat.damping * inv_mass : 0.0;
  return std::max(std::sqrt(d > 0 ? hertz_stiffness(mat, d) * inv_mass : 0.0), damper);
}

// Whether a friction term of `per_newton` strength (N per N of normal force), acting at mobility M on a quantity that
// started at `start` and is now `along` its starting direction (m/s), stays saturated at normal force fn: beyond its
// band's edge on the same side, with a quarter to spare. A term that starts at exactly zero holds (nothing moves it).
bool saturated(const Smoothing& s, double start, double along, double per_newton, double mobility, double fn) {
  if (start == 0 || per_newton == 0) return true;
  return along >= 1.25 / sharpness_for(s, per_newton * std::max(fn, 1e-300), mobility);
}

// The root of g in [t0, t1] where g(t0) and g(t1) differ in sign, to 1e-15 s, as the end of the bracket on the far
// side of it (TOMS 748, as the event detector locates its roots); t1 where they do not.
template <class G>
double root_after(double t0, double t1, G&& g) {
  namespace policies = boost::math::policies;
  using NoThrow = policies::policy<policies::evaluation_error<policies::ignore_error>>;
  std::uintmax_t iterations = 4 * kMaxRootIterations;
  const double g0 = g(t0), g1 = g(t1);
  if (g0 == 0 || g1 == 0 || (g0 > 0) == (g1 > 0)) return t1;
  const auto closed = [](double a, double b) { return b - a <= 1e-2 * kOnsetResolution; };
  return boost::math::tools::toms748_solve(g, t0, t1, g0, g1, closed, iterations, NoThrow()).second;
}

// follow()'s work: the scalar ODE stepped by Dormand-Prince 5 at a hundredth of the tolerance, its knots no further
// apart than the quintic interpolant holds the depth's rate to a tenth of it, a knot where the clamp lets go, and the
// checks that end the bounce.
class Follower {
 public:
  Follower(const Model& model, const ModelIndex& index, BedBounce& b)
      : model_(model), index_(index), b_(b), mat_(index.collider_material(b.bed)),
        smooth_{model.options.friction_sharpness, model.options.friction_rate_limit},
        push_{mat_, index.inv_mass[b.ball], -glm::dot(model.options.gravity, b.normal), b.touching} {
    const BallSpec& ball = model.balls[b.ball];
    const double r = ball.radius;
    u0_ = b.v0 + r * glm::cross(b.normal, b.w0), du_ = b.dv + r * glm::cross(b.normal, b.dw);
    u0_ -= glm::dot(u0_, b.normal) * b.normal;
    slip0_ = glm::length(u0_);
    q0_ = r * glm::dot(b.w0, b.normal), dq_ = r * glm::dot(b.dw, b.normal);
    sink_ = static_sink(ball, mat_, index.gravity);
  }
  bool run(double horizon);

 private:
  using Dopri5 = odeint::runge_kutta_dopri5<Push>;
  bool fly(double horizon);
  bool step_to_release(std::vector<BounceTrack::Knot>& knots, double t0, double t1, Push& y, Push& f, double& t,
                       Dopri5& stepper);
  // The slip and the spin saturated at this impulse and load, each on the side it started on: a slip that falls
  // through zero between two knots fails at the second.
  bool holds(const double y[4], double fn) const {
    const int i = b_.ball;
    const double along = slip0_ > 0 ? glm::dot(u0_ + y[2] * du_, u0_) / slip0_ : 0.0;
    const double spin = std::copysign(1.0, q0_) * (q0_ + y[2] * dq_);
    return saturated(smooth_, slip0_, along, mat_.friction_at(slip0_), index_.inv_mass[i] + index_.inv_inertia_r2[i],
                     fn) &&
           saturated(smooth_, q0_, spin, mat_.spin_friction, index_.inv_inertia_r2[i], fn);
  }
  // Settled enough for the sliding regime: twice the hop must settle, so that the regimes' own test at this end
  // passes with room for round-off.
  bool settled(double t, const double y[4]) const {
    if (!push_.touching || !model_.options.sliding_regime) return false;
    if (2.0 * bed_hop(mat_, index_.gravity, sink_, y[1], sink_ - y[0]) >= model_.options.rest_speed) return false;
    double at[kBallDofs];
    b_.apply(t, at);
    return settles_on_bed(model_, index_, at, b_.ball, b_.bed, b_.normal, -2.0 * y[1], 2.0 * (sink_ - y[0]), sink_);
  }
  // The track's depth (m) at t.
  double depth_at(double t) const {
    double at[4];
    b_.track->at(t, at);
    return at[0];
  }
  // The share of a period (h w, for a motion of rate w) by which knots may lie apart where the interpolant is to hold
  // the depth's rate to a tenth of abs_tol: its error is about (h w)^6 V / 46080 (6! 64) for a speed amplitude V, at
  // most the start's swing (damping only takes energy out; gravity's work over the depth, a few um, is the 10 %).
  double share(const Push& y0) const {
    const double v = std::max(1.1 * push_.swing(y0), 1e-300), tol = 0.1 * model_.integrator.abs_tol;
    return std::min(0.6, std::pow(46080.0 * tol / v, 1.0 / 6.0));
  }
  // s: the longest knot spacing at y for that share, at the rate of the depth or of the static sink (the linearised
  // bed's, where the ball settles), whichever is faster.
  double longest(const Push& y, double share) const {
    return share / contact_rate(mat_, push_.inv_mass, std::max(y[0], sink_));
  }

  const Model& model_;
  const ModelIndex& index_;
  BedBounce& b_;
  const ContactMaterial& mat_;
  Smoothing smooth_;
  BedPush push_;
  Vec3 u0_, du_;  // m/s: the slip along the bed at the start; its change per N s of normal impulse
  double slip0_, q0_, dq_, sink_;
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

// Where the clamp takes over inside the step from t0 to t1 (the law's force through zero while the ball is still
// pressed in) the step is done again to end there, at two knots: the force's rate is the law's before, zero after.
// False (the step stands) where no such root is found inside it.
bool Follower::step_to_release(std::vector<BounceTrack::Knot>& knots, double t0, double t1, Push& y, Push& f,
                               double& t, Dopri5& stepper) {
  const double at = root_after(t0, t1, [&](double s) {
    double z[4];
    b_.track->at(s, z);
    return normal_force(mat_, z[0], z[1]);
  });
  if (!(at > t0 && at < t1)) return false;
  knots.pop_back();
  Push y1, f1;
  stepper.do_step(push_, y, f, t0, y1, f1, at - t0);
  f1[1] = push_.g_in, f1[2] = 0.0;  // no force there
  BounceTrack::Knot before = push_.knot(at, y1, f1);
  before.g[2] = normal_force_rate(mat_, y1[0], y1[1], f1[1]);
  before.g[1] = -before.g[2] * push_.inv_mass;
  knots.push_back(before);
  knots.push_back(push_.knot(at, y1, f1));
  y = y1, f = f1, t = at;
  return true;
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
  auto stepper = odeint::make_controlled<Dopri5>(1e-2 * model_.integrator.abs_tol, 1e-2 * model_.integrator.rel_tol);
  const double spacing = share(y);
  double t = 0, dt = std::min(horizon, longest(y, spacing));
  b_.end = -1;
  for (int steps = 0; t < horizon && b_.end < 0; ++steps) {
    if (steps == kMaxBounceSteps) break;
    dt = std::min({dt, longest(y, spacing), horizon - t});
    Push y1 = y, f1 = f;
    double t1 = t;
    if (stepper.try_step(push_, y1, f1, t1, dt) != odeint::success) continue;
    track->knots.push_back(push_.knot(t1, y1, f1));
    if (f[2] > 0 && y1[0] > 0 && push_.force(y1) == 0 &&
        step_to_release(track->knots, t, t1, y, f, t, stepper.stepper()))
      continue;
    // The contact's end (the depth back through zero), else the step's; the slip and spin checked up to there.
    const double end = y1[0] <= 0 ? root_after(t, t1, [&](double s) { return depth_at(s); }) : t1;
    double at[4];
    track->at(end, at);
    if (!holds(at, push_.force({at[0], at[1], at[2], at[3]}))) {  // ends at the last knot where they held
      track->knots.pop_back();
      b_.end = t;
      break;
    }
    fmax = std::max(fmax, push_.force(y1));
    if (end < t1) {  // the step done again to end there: the next phase starts from the equation's state, not the
      track->knots.pop_back();  // interpolant's (near the surface Hertz's force has no bounded higher derivatives)
      stepper.stepper().do_step(push_, y, f, t, y1, f1, end - t);
      track->knots.push_back(push_.knot(end, y1, f1));
    }
    if (end < t1 || y1[0] <= 0) b_.end = end;
    else if (settled(t1, y1.data())) b_.end = t1;
    t = end, y = y1, f = f1;
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
  const BallSpec& ball = model.balls[i];
  const Vec3 p = position(x, i);
  for (int j = 0; j < state.ball_count(); ++j)
    if (j != i && state.in_play[j] &&
        glm::length(p - position(x, j)) - ball.radius - model.balls[j].radius < model.options.contact_margin)
      return std::nullopt;
  BedBounce b;
  b.ball = i;
  Vec3 point;
  b.bed = only_bed_near(model, index, p, ball.radius, point, b.depth0);
  if (b.bed < 0) return std::nullopt;
  const ContactMaterial& mat = index.collider_material(b.bed);
  // The closed forms of the bed assume a constant friction coefficient; without friction, rolling resistance would
  // act on a ball that moves along the bed at a weight that depends on the slip.
  if (mat.friction_law != FrictionLaw::Constant || (mat.friction <= 0 && mat.rolling_resistance > 0)) return std::nullopt;
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
