#include "shotlab/restitution.hpp"

#include <cmath>
#include <string>

namespace shotlab {

namespace {

constexpr double kStep = 1e-3;       // in units of T: the undamped Hertz impact lasts 3.2 of them
constexpr double kLongest = 200.0;   // in units of T: an impact still going on by then never parts (overdamped)

// x'' of the scaled impact at depth x > 0 and rate v = x', the force clamped at zero.
double accel(DampingLaw law, double n, double g, double x, double v) {
  const double spring = std::pow(x, n);
  const double f = law == DampingLaw::Linear ? spring + g * v : spring * (1 + g * v);
  return -std::max(f, 0.0);
}

}  // namespace

ScaledImpact scaled_impact(DampingLaw law, double exponent, double g) {
  // Classic Runge-Kutta on (x, v) from touching at unit speed until the depth returns to zero (found on the last
  // step's linear interpolant) or the clamped force lets go while they separate (then nothing changes their speed).
  double x = 0, v = 1, t = 0;
  auto a = [&](double xx, double vv) { return xx > 0 ? accel(law, exponent, g, xx, vv) : 0.0; };
  while (t < kLongest) {
    const double h = kStep;
    const double k1x = v, k1v = a(x, v);
    const double k2x = v + 0.5 * h * k1v, k2v = a(x + 0.5 * h * k1x, v + 0.5 * h * k1v);
    const double k3x = v + 0.5 * h * k2v, k3v = a(x + 0.5 * h * k2x, v + 0.5 * h * k2v);
    const double k4x = v + h * k3v, k4v = a(x + h * k3x, v + h * k3v);
    const double x1 = x + h / 6 * (k1x + 2 * k2x + 2 * k3x + k4x);
    const double v1 = v + h / 6 * (k1v + 2 * k2v + 2 * k3v + k4v);
    if (x1 <= 0) return {-v1, t + h * x / (x - x1)};
    x = x1, v = v1, t += h;
    if (v < 0 && a(x, v) == 0) return {-v, t + x / -v};  // the force let go: the bodies part at this speed
  }
  return {0.0, kLongest};
}

double effective_mass(bool ball_ball, double ball_mass) { return ball_ball ? ball_mass / 2 : ball_mass; }

std::string apply_restitution(ContactMaterial& m, double m_eff) {
  const double e = m.restitution, v = m.restitution_speed, n = m.exponent;
  if (!(e > 0 && e <= 1)) return "restitution must be above 0 and at most 1";
  if (!(v > 0) || !std::isfinite(v)) return "restitution_speed must be a positive speed";
  if (!(m.contact_time >= 0) || !std::isfinite(m.contact_time)) return "contact_time must be a positive time";
  if (!(m_eff > 0) || !(m.stiffness > 0)) return "needs a positive mass and stiffness";
  // e falls as g grows under both laws: bisect on log g between no damping and far overdamped.
  double lo = -9, hi = 4, g = 0;
  if (e < 1) {
    for (int k = 0; k < 60; ++k) {
      const double mid = 0.5 * (lo + hi);
      (scaled_impact(m.damping_law, n, std::pow(10.0, mid)).restitution > e ? lo : hi) = mid;
    }
    g = std::pow(10.0, 0.5 * (lo + hi));
  }
  if (m.contact_time > 0) {  // T from the scaled duration, then C_s from T = (m_eff v^2 / C_s)^(1/(n+1)) / v
    const double T = m.contact_time / scaled_impact(m.damping_law, n, g).duration;
    m.stiffness = m_eff * v * v / std::pow(v * T, n + 1);
  }
  const double T = std::pow(m_eff * v * v / m.stiffness, 1 / (n + 1)) / v;
  m.damping = m.damping_law == DampingLaw::Linear ? g * m_eff / T : g / v;
  return "";
}

double damping_for_restitution(const ContactMaterial& material, double m_eff, double v, double e) {
  ContactMaterial m = material;
  m.restitution = e, m.restitution_speed = v, m.contact_time = 0;
  return apply_restitution(m, m_eff).empty() ? m.damping : material.damping;
}

}  // namespace shotlab
