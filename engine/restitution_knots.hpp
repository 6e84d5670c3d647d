// The layout of the rigid model's restitution table (restitution_table.cpp): knots of the scaled impact's restitution
// over log10 of its damping parameter g, for Hertz contacts (exponent 1.5) under each damping law, worked out at build
// time by tools/restitution_knots.cpp with scaled_impact itself. Other exponents and g outside the range are worked out
// when first met.
#pragma once

namespace shotlab {

inline constexpr double kKnotsPerDecade = 20;
inline constexpr double kKnotExponent = 1.5;
inline constexpr long kFirstKnot = -6 * 20;  // g = 1e-6 (linear damping of a few N s/m at ten metres a second)
inline constexpr long kLastKnot = 2 * 20;    // g = 100 (overdamped: e is 0 well before)
inline constexpr long kKnotCount = kLastKnot - kFirstKnot + 1;

}  // namespace shotlab
