// The rigid model's root finder (engine/polynomial.hpp) on gaps whose roots are known by construction: products of
// chosen factors, near-grazing paths, touching at the start, roots across scales.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "engine/polynomial.hpp"

namespace shotlab {
namespace {

// The coefficients of k (s - r1)(s - r2)(s - r3)(s - r4).
Quartic from_roots(double k, double r1, double r2, double r3, double r4) {
  Quartic c{k, 0, 0, 0, 0};
  for (double r : {r1, r2, r3, r4}) {
    Quartic next{};
    for (int i = 0; i < 4; ++i) next[i + 1] += c[i], next[i] -= r * c[i];
    c = next;
  }
  return c;
}

constexpr double kNever = std::numeric_limits<double>::infinity();

TEST(Polynomial, FindsTheFirstEntryAmongFourRoots) {
  // Positive before 0.1, negative between 0.1 and 0.2, positive to 0.7, negative to 0.9.
  const Quartic c = from_roots(1, 0.1, 0.2, 0.7, 0.9);
  EXPECT_NEAR(first_entry(c, 1.0), 0.1, 1e-15);
  EXPECT_NEAR(first_entry(c, 0.15), 0.1, 1e-15);
  EXPECT_EQ(first_entry(c, 0.05), kNever);
}

TEST(Polynomial, SkipsAnExitAndFindsTheNextEntry) {
  // Negative before 0.1 (inside), leaving at 0.1, entering again at 0.6: starting inside and opening, the entry is 0.6.
  const Quartic c = from_roots(-1, 0.1, 0.6, 2.0, 3.0);
  ASSERT_LT(evaluate(c, 0), 0);
  EXPECT_NEAR(first_entry(c, 1.0), 0.6, 1e-15);
}

TEST(Polynomial, ClosingAtZeroGapIsAnEntryAtOnce) {
  // Touching and closing at s = 0 (a rack's frozen balls): enters at 0; touching and opening: not.
  EXPECT_EQ(first_entry({0.0, -1.0, 0.0, 0.0, 0.0}, 1.0), 0.0);
  EXPECT_EQ(first_entry({0.0, 1.0, 0.0, 0.0, 0.0}, 1.0), kNever);
  EXPECT_EQ(first_entry({-1e-20, 1.0, 0.0, 0.0, 0.0}, 1.0), kNever);  // overlapping by round-off, parting
  // Touching with no closing speed but accelerating together: a contact at once (a ball spun into a touching one).
  EXPECT_EQ(first_entry({0.0, 0.0, -1.0, 0.0, 0.0}, 1.0), 0.0);
  EXPECT_EQ(first_entry({-1e-20, 0.0, -1.0, 0.0, 0.0}, 1.0), 0.0);
  EXPECT_EQ(first_entry({0.0, 0.0, 1.0, 0.0, 0.0}, 1.0), kNever);  // touching, accelerating apart
  // Overlapping, parting, then closing again before they are clear: a contact where they start to close.
  EXPECT_NEAR(first_entry({-1.0, 1.0, -1.0, 0.0, 0.0}, 2.0), 0.5, 1e-15);
}

TEST(Polynomial, ANearGrazeIsFoundAndAMissIsNot) {
  // (s - 0.3)^2 (s + 1)(s + 2), about 2.99 (s - 0.3)^2 near 0.3: lowered by 1e-6 it dips below zero from
  // about 0.3 - sqrt(1e-6 / 2.99) on; lifted by 1e-6 it never reaches zero.
  Quartic lowered = from_roots(1, 0.3, 0.3, -1, -2), lifted = lowered;
  lowered[0] -= 1e-6, lifted[0] += 1e-6;
  double root = 0.3;  // of (s - 0.3)^2 = 1e-6 / ((s + 1)(s + 2)), by fixed-point steps from 0.3
  for (int k = 0; k < 20; ++k) root = 0.3 - std::sqrt(1e-6 / ((root + 1) * (root + 2)));
  EXPECT_NEAR(first_entry(lowered, 1.0), root, 1e-12);
  EXPECT_EQ(first_entry(lifted, 1.0), kNever);
}

TEST(Polynomial, QuadraticsAndLinesToo) {
  EXPECT_NEAR(first_entry({1.0, -2.0, 0.0, 0.0, 0.0}, 1.0), 0.5, 1e-15);
  EXPECT_NEAR(first_entry({2.0, 0.0, -2.0, 0.0, 0.0}, 5.0), 1.0, 1e-15);
  EXPECT_EQ(first_entry({2.0, 0.0, 0.0, 0.0, 0.0}, 5.0), kNever);
}

TEST(Polynomial, RootsAcrossScalesAreFoundToTheLastBits) {
  for (double r : {1e-9, 1e-6, 1e-3, 0.5, 7.0, 900.0}) {
    const Quartic c = from_roots(1, r, 3 * r, -r, -5 * r);
    EXPECT_NEAR(first_entry(c, 10 * r), r, 4e-16 * std::max(1.0, r) + 1e-12 * r) << "r = " << r;
  }
}

}  // namespace
}  // namespace shotlab
