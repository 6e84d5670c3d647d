// restitution_at (shotlab/restitution.hpp): the soft law's restitution at an impact speed, for the rigid model's
// impulses, read off a table of scaled_impact (restitution_knots.hpp) instead of integrating an impact each time.
#include <cmath>
#include <map>
#include <mutex>
#include <tuple>

#include "restitution_knots.hpp"
#include "shotlab/restitution.hpp"

namespace shotlab {

namespace {

constexpr double kBuilt[2][kKnotCount] = {
#include "restitution_knots.inc"
};

// The restitution of the scaled impact at g = 10^(k / kKnotsPerDecade): built in, or worked out once per process.
double knot(DampingLaw law, double n, long k) {
  if (n == kKnotExponent && k >= kFirstKnot && k <= kLastKnot) return kBuilt[static_cast<int>(law)][k - kFirstKnot];
  static std::mutex lock;
  static std::map<std::tuple<int, double, long>, double> met;
  const auto key = std::make_tuple(static_cast<int>(law), n, k);
  const std::lock_guard<std::mutex> hold(lock);
  auto found = met.find(key);
  if (found == met.end()) found = met.emplace(key, scaled_impact(law, n, std::pow(10.0, k / kKnotsPerDecade)).restitution).first;
  return found->second;
}

}  // namespace

double restitution_at(const ContactMaterial& m, double m_eff, double v) {
  if (!(v > 0) || !(m.stiffness > 0) || !(m_eff > 0)) return 1;
  const double n = m.exponent;
  const double T = std::pow(m_eff * v * v / m.stiffness, 1 / (n + 1)) / v;  // as apply_restitution's
  const double g = m.damping_law == DampingLaw::Linear ? m.damping * T / m_eff : m.damping * v;
  if (!(g > 0)) return scaled_impact(m.damping_law, n, 0).restitution;
  // e is smooth in log g: the cubic through the four nearest knots, at u = at - lo in [0, 1).
  const double at = std::log10(g) * kKnotsPerDecade, lo = std::floor(at), u = at - lo;
  const long k = static_cast<long>(lo);
  const double a = knot(m.damping_law, n, k - 1), b = knot(m.damping_law, n, k), c = knot(m.damping_law, n, k + 1),
               d = knot(m.damping_law, n, k + 2);
  return -u * (u - 1) * (u - 2) / 6 * a + (u + 1) * (u - 1) * (u - 2) / 2 * b - (u + 1) * u * (u - 2) / 2 * c +
         (u + 1) * u * (u - 1) / 6 * d;
}

bool switch_damping_law(ContactMaterial& material, DampingLaw law, double m_eff, double v) {
  if (material.damping_law == law) return true;
  ContactMaterial next = material;
  next.damping_law = law;
  next.restitution = restitution_at(material, m_eff, v), next.restitution_speed = v, next.contact_time = 0;
  const bool kept = apply_restitution(next, m_eff).empty();
  material.damping_law = law;
  if (kept) material.damping = next.damping;
  return kept;
}

}  // namespace shotlab
