// Polynomials of degree 4 at most, in time: gaps (a squared distance minus a squared reach) along paths of constant
// acceleration, the rigid model's and the free paths' (free_path.hpp). Roots are isolated between the derivative's
// roots and bisected, so a double or a grazing root is neither missed nor found twice.
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "shotlab/vec.hpp"

namespace shotlab {

// c[0] + c[1] s + ... + c[4] s^4.
using Quartic = std::array<double, 5>;

inline double evaluate(const Quartic& c, double s) {
  return (((c[4] * s + c[3]) * s + c[2]) * s + c[1]) * s + c[0];
}

inline Quartic derivative(const Quartic& c) { return {c[1], 2 * c[2], 3 * c[3], 4 * c[4], 0.0}; }

// The root of c in [a, b], where c(a) and c(b) have opposite signs or c(b) = 0, to about the last bit: Newton steps
// while they stay inside the shrinking bracket, halving where they would leave it.
inline double bisect_root(const Quartic& c, double a, double b) {
  const bool rising = evaluate(c, a) < 0;
  const Quartic d = derivative(c);
  double x = 0.5 * (a + b);
  for (int k = 0; k < 200; ++k) {
    const double f = evaluate(c, x);
    if (f == 0) return x;
    ((f < 0) == rising ? a : b) = x;
    const double slope = evaluate(d, x), newton = slope != 0 ? x - f / slope : a;
    const double next = newton > a && newton < b ? newton : 0.5 * (a + b);
    if (!(next > a && next < b)) return b;
    if (std::abs(next - x) <= 1e-15 * std::max(1.0, std::abs(x))) return next;
    x = next;
  }
  return x;
}

// The points in (lo, hi) where c changes sign, ascending, at most `degree` of them (count returned). c's degree must
// be at most `degree`.
inline int sign_changes(const Quartic& c, int degree, double lo, double hi, std::array<double, 4>& out) {
  if (degree <= 0) return 0;
  std::array<double, 6> edges{lo};
  int n_edges = 1;
  if (degree > 1) {
    std::array<double, 4> turns{};
    const int n = sign_changes(derivative(c), degree - 1, lo, hi, turns);
    for (int k = 0; k < n; ++k) edges[n_edges++] = turns[k];
  }
  edges[n_edges++] = hi;
  int count = 0;
  for (int k = 0; k + 1 < n_edges; ++k) {
    const double fa = evaluate(c, edges[k]), fb = evaluate(c, edges[k + 1]);
    if ((fa < 0 && fb > 0) || (fa > 0 && fb < 0)) out[count++] = bisect_root(c, edges[k], edges[k + 1]);
  }
  return count;
}

// The times s in [0, h] at which the gap c begins a contact, ascending (count returned): where it goes from positive to
// zero or below, and where, at zero or below, it starts to fall (a touching pair that closes, however slowly, from
// rest or from parting; not one that parts). Between two of c's turns it is monotone, so there are at most 2.
inline int entries(const Quartic& c, double h, std::array<double, 4>& out) {
  const Quartic d = derivative(c);
  std::array<double, 6> edges{0.0};
  std::array<double, 4> turns{};
  int n_edges = 1, count = 0;
  const int n = sign_changes(d, 3, 0.0, h, turns);
  for (int k = 0; k < n; ++k) edges[n_edges++] = turns[k];
  edges[n_edges++] = h;
  for (int k = 0; k + 1 < n_edges; ++k) {
    const double from = evaluate(c, edges[k]), to = evaluate(c, edges[k + 1]);
    if (from > 0 && to <= 0) out[count++] = bisect_root(c, edges[k], edges[k + 1]);
    else if (from <= 0 && evaluate(d, 0.5 * (edges[k] + edges[k + 1])) < 0) out[count++] = edges[k];
  }
  return count;
}

// The squared distance between two points, dp + dv s + da s^2 / 2 apart at time s, minus reach^2: a polynomial in s
// (two balls' centres on parabolas; a gap for entries).
inline Quartic squared_gap(const Vec3& dp, const Vec3& dv, const Vec3& da, double reach) {
  return {glm::dot(dp, dp) - reach * reach, 2 * glm::dot(dp, dv), glm::dot(dv, dv) + glm::dot(dp, da),
          glm::dot(dv, da), 0.25 * glm::dot(da, da)};
}

// s: the earliest of entries(c, h); +inf when there is none.
inline double first_entry(const Quartic& c, double h) {
  std::array<double, 4> out{};
  return entries(c, h, out) > 0 ? out[0] : std::numeric_limits<double>::infinity();
}

}  // namespace shotlab
