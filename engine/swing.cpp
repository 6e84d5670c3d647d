#include "swing.hpp"

#include <boost/math/special_functions/ellint_1.hpp>
#include <cmath>

#include "contacts.hpp"
#include "numerics.hpp"

namespace shotlab {

namespace {

// In double precision: Boost's default policy computes a double's elliptic integral in long double, at several times
// the cost.
using Double = boost::math::policies::policy<boost::math::policies::promote_double<false>>;

// Jacobi's sn and cn of (u, k), 0 <= k < 1, by descending Gauss transformations (DLMF 22.7.i): with
// k1 = (1 - k') / (1 + k') = k^2 / (1 + k')^2 and v = u / (1 + k1),
//   sn(u, k) = (1 + k1) sn(v, k1) / (1 + k1 sn^2(v, k1)),   cn(u, k) = cn(v, k1) dn(v, k1) / (1 + k1 sn^2(v, k1)),
//   dn(v, k1) = sqrt(1 - k1^2 sn^2(v, k1)).
// k falls quadratically (a 90-degree swing's 0.71 to 0.17, 7e-3, 1e-5, 3e-11): once k^2 is under round-off of 1,
// sn = sin and cn = cos. Three or four square roots and one sine and cosine, where Boost's Jacobi functions (an
// arithmetic-geometric mean with an arcsine a level) cost several times as much, and its dn, a ratio of two cosines
// that both vanish at the turning points, could be anything there.
void sn_cn(double u, double k, double& sn, double& cn) {
  if (k * k < 1e-17) {
    sn = std::sin(u);
    cn = std::cos(u);
    return;
  }
  const double kp = std::sqrt((1.0 - k) * (1.0 + k)), k1 = k * k / ((1.0 + kp) * (1.0 + kp));
  double s, c;
  sn_cn(u / (1.0 + k1), k1, s, c);
  const double d = std::sqrt(1.0 - k1 * k1 * s * s), q = 1.0 + k1 * s * s;
  sn = (1.0 + k1) * s / q;
  cn = c * d / q;
}

}  // namespace

void Swing::apply(double h, double* b) const {
  double sn, cn;
  sn_cn(phase + omega * h, modulus, sn, cn);
  // cos θ and sin θ from sin(θ/2) = k sn and cos(θ/2) = dn = sqrt(1 - k^2 sn^2), with no further sine or cosine.
  const double half = modulus * sn, c = 1.0 - 2.0 * half * half, s = 2.0 * half * std::sqrt(1.0 - half * half);
  set_position(b, 0, anchor + length * (c * down + s * across));
  set_velocity(b, 0, (length * 2.0 * modulus * omega * cn) * (c * across - s * down));
}

std::optional<Swing> swing_of(const Model& model, const State& state, const ModelIndex& index, const double* x, int i,
                              const Swing* last) {
  if (!model.options.swing_regime || index.gravity <= 0) return std::nullopt;
  const Rod* rod = nullptr;
  for (const Rod& r : model.rods)
    if (r.ball == i) {
      if (rod) return std::nullopt;  // two rods: no plane pendulum
      rod = &r;
    }
  if (!rod || rod->length <= 0) return std::nullopt;
  // Touching nothing, now: the step caps and the closed-form step's cut at the first touch (island.cpp) see to the
  // rest of the step.
  if (!clear_of_contacts(model, index, state, x, i)) return std::nullopt;
  const Vec3 p = position(x, i), v = velocity(x, i);
  if (last) {  // bit for bit where the last step's closed form put it (closed_form_step): nothing changed it since
    double b[kBallDofs];
    last->apply(0.0, b);
    if (position(b, 0) == p && velocity(b, 0) == v) return *last;
  }
  // On the rod, moving across it and in the plane through it and ĝ, to within what a snap may move it (the
  // out-of-plane speed over the longest closed-form step, kLoneHorizon).
  const double snap = kSnapShare * model.integrator.abs_tol;
  const Vec3 d = p - rod->anchor, g = model.options.gravity / index.gravity;
  const double len = glm::length(d);
  if (len <= 0 || std::abs(len - rod->length) > snap) return std::nullopt;
  const Vec3 dh = d / len;
  if (std::abs(glm::dot(v, dh)) > snap) return std::nullopt;
  Vec3 e = dh - glm::dot(dh, g) * g;
  if (glm::length(e) == 0) e = v - glm::dot(v, g) * g;  // straight below (or above) the anchor: the plane of v
  if (glm::length(e) == 0) e = std::abs(g.x) < 0.9 ? glm::cross(g, Vec3{1, 0, 0}) : glm::cross(g, Vec3{0, 1, 0});
  e = glm::normalize(e);
  if (std::abs(glm::dot(v, glm::cross(g, e))) * kLoneHorizon > snap) return std::nullopt;
  // θ from the vertical: cos θ = d^.ĝ, sin θ = d^.ê; sin(θ/2) = sin θ / (2 cos(θ/2)) with
  // cos(θ/2) = sqrt((1 + cos θ) / 2), accurate at small angles where 1 - cos θ would not be.
  const double cos_t = glm::dot(dh, g), sin_t = glm::dot(dh, e);
  if (cos_t <= 0) return std::nullopt;  // level with the anchor or above it
  const double omega = std::sqrt(index.gravity / rod->length);
  const double rate = glm::dot(v, cos_t * e - sin_t * g) / rod->length;  // θ', rad/s
  const double s0 = sin_t / std::sqrt(2.0 * (1.0 + cos_t)), c0 = rate / (2.0 * omega);
  const double k = std::sqrt(s0 * s0 + c0 * c0);
  if (k > std::sqrt(0.5)) return std::nullopt;  // above the anchor's height
  const double phase = k > 0 ? boost::math::ellint_1(k, std::atan2(s0 / k, c0 / k), Double()) : 0.0;
  return Swing{i, rod->anchor, g, e, rod->length, omega, k, phase};
}

}  // namespace shotlab
