// Each collider's penetration depth and normal (MODEL.md eq. 4.8-4.11), checked against hand-computed geometry.
#include <gtest/gtest.h>

#include <algorithm>

#include "shotlab/colliders.hpp"
#include "engine/contacts.hpp"
#include "shotlab/table.hpp"

namespace shotlab {
namespace {

constexpr double r = 0.03;

void expect_vec(const Vec3& a, const Vec3& b, double tol = 1e-12) {
  EXPECT_NEAR(a.x, b.x, tol);
  EXPECT_NEAR(a.y, b.y, tol);
  EXPECT_NEAR(a.z, b.z, tol);
}

TEST(Colliders, PlaneDepthAndNormal) {
  const Plane p{{0, 1, 0}, {0, 1, 0}, {}};
  const auto pen = penetration(p, {5, 1.01, -3}, r);
  ASSERT_TRUE(pen);
  EXPECT_NEAR(pen->depth, 0.02, 1e-12);  // R - (p - r).m = 0.03 - 0.01
  expect_vec(pen->normal, {0, 1, 0});
  EXPECT_NEAR(penetration(p, {0, 1.5, 0}, r)->depth, -0.47, 1e-12);  // a gap is a negative depth
}

TEST(Colliders, PlaneIsOneSided) {
  const Plane p{{0, 0, 0}, {0, 1, 0}, {}};
  EXPECT_FALSE(penetration(p, {0, -0.001, 0}, r));
}

TEST(Colliders, TiltedPlane) {
  const Vec3 n = glm::normalize(Vec3{1, 1, 0});
  const auto pen = penetration(Plane{{0, 0, 0}, n, {}}, {0.01, 0.01, 0}, r);
  EXPECT_NEAR(pen->depth, r - 0.02 / std::sqrt(2.0), 1e-12);
  expect_vec(pen->normal, n);
}

TEST(Colliders, HoleRimIsTheOnlyContactOverAHole) {
  const Plane p{{0, 0, 0}, {0, 1, 0}, {{{0, 0, 0}, 0.05}}};
  EXPECT_TRUE(penetration(p, {0.06, 0.02, 0}, r));  // centre beside the hole: the plane carries the ball
  EXPECT_NEAR(penetration(p, {0.06, 0.02, 0}, r)->depth, 0.01, 1e-12);
  // Centre over the hole, 1 cm inside its edge and 2 cm up: the rim point (0.05, 0, 0) is sqrt(0.01^2 + 0.02^2) away.
  const auto rim = penetration(p, {0.04, 0.02, 0}, r);
  ASSERT_TRUE(rim);
  EXPECT_NEAR(rim->depth, r - std::sqrt(0.0005), 1e-12);
  expect_vec(rim->normal, glm::normalize(Vec3{-0.01, 0.02, 0}));
}

TEST(Colliders, BoundedPlaneOnlyInsideItsParallelogram) {
  const BoundedPlane b{{0, 0, 0}, {2, 0, 0}, {0, 0, -1}, {}};  // normal u^ x v^ = +y
  const auto in = penetration(b, {1, 0.01, -0.5}, r);
  ASSERT_TRUE(in);
  EXPECT_NEAR(in->depth, 0.02, 1e-12);
  expect_vec(in->normal, {0, 1, 0});
  EXPECT_FALSE(penetration(b, {2.1, 0.01, -0.5}, r));
  EXPECT_FALSE(penetration(b, {1, 0.01, 0.1}, r));
}

TEST(Colliders, StaticSphere) {
  const auto pen = penetration(StaticSphere{{1, 1, 1}, 0.1}, {1, 1, 1.12}, r);
  EXPECT_NEAR(pen->depth, 0.13 - 0.12, 1e-12);
  expect_vec(pen->normal, {0, 0, 1});
}

TEST(Colliders, CapsuleMiddleAndEnds) {
  const Capsule c{{0, 0, 0}, {1, 0, 0}, 0.01};
  const auto mid = penetration(c, {0.5, 0.035, 0}, r);  // nearest axis point (0.5, 0, 0)
  EXPECT_NEAR(mid->depth, 0.04 - 0.035, 1e-12);
  expect_vec(mid->normal, {0, 1, 0});
  const auto end = penetration(c, {1.03, 0, 0.0}, r);  // beyond b: nearest point is b itself
  EXPECT_NEAR(end->depth, 0.01, 1e-12);
  expect_vec(end->normal, {1, 0, 0});
  const auto before = penetration(c, {-0.02, 0.02, 0}, r);  // before a
  EXPECT_NEAR(before->depth, 0.04 - std::sqrt(0.0008), 1e-12);
}


// An arc wall around the y axis: inner radius 0.065, outer 0.085, within 120 degrees of +x, from y = -0.09 to 0.05.
const ArcWall kWall{{0, 0, 0}, 0.065, 0.02, {1, 0, 0}, 120 * M_PI / 180, -0.09, 0.05};

TEST(Colliders, ArcWallFaces) {
  const auto inner = penetration(kWall, {0.05, 0.02, 0}, r);  // in the hole: the inner face, 0.015 away
  EXPECT_NEAR(inner->depth, r - 0.015, 1e-12);
  expect_vec(inner->normal, {-1, 0, 0});
  const auto outer = penetration(kWall, {0.1, 0, 0}, r);  // behind it: the outer face
  EXPECT_NEAR(outer->depth, r - 0.015, 1e-12);
  expect_vec(outer->normal, {1, 0, 0});
  const auto top = penetration(kWall, {0.075, 0.07, 0}, r);  // over it: the top, 0.02 below
  EXPECT_NEAR(top->depth, r - 0.02, 1e-12);
  expect_vec(top->normal, {0, 1, 0});
  // 10 degrees past the end at +120 degrees (towards +z), 0.075 from the axis: the end face, 0.075 sin 10 deg away.
  const double a = 130 * M_PI / 180;
  const auto end = penetration(kWall, {0.075 * std::cos(a), 0, 0.075 * std::sin(a)}, r);
  EXPECT_NEAR(end->depth, r - 0.075 * std::sin(10 * M_PI / 180), 1e-12);
  expect_vec(end->normal, {std::cos(a + M_PI / 2 - 10 * M_PI / 180), 0, std::sin(a + M_PI / 2 - 10 * M_PI / 180)});
  const auto within = penetration(kWall, {0.07, 0, 0}, r);  // inside the solid: out through the inner face, 5 mm off
  EXPECT_NEAR(within->depth, r + 0.005, 1e-12);
  expect_vec(within->normal, {-1, 0, 0});
  EXPECT_FALSE(penetration(kWall, {0.3, 0, 0}, r, 0.01));  // farther than asked about
}

TEST(Colliders, ArcWallBounds) {
  const Bounds b = bounds(kWall);  // the ends at +-120 degrees, and +x, +z, -z on the outer face
  expect_vec(b.lo, {-0.5 * 0.085, -0.09, -0.085});
  expect_vec(b.hi, {0.085, 0.05, 0.085});
}

// The depth is r less the distance to the nearest point of the wall's surface, found by brute force over its six
// faces sampled every 0.25 mm and 0.25 degrees across (exactly up and down the tall ones), for points all around it:
// in the hole, behind, above, below, past the ends, in the open arc.
TEST(Colliders, ArcWallDepthIsTheDistanceToItsSurface) {
  std::vector<Vec3> surface;
  const double ri = kWall.radius, ro = ri + kWall.thickness, h = kWall.half_angle, step = 0.00025;
  auto at = [&](double rho, double angle, double y) { return Vec3{rho * std::cos(angle), y, rho * std::sin(angle)}; };
  const int angles = static_cast<int>(2 * h / (0.25 * M_PI / 180));
  for (int k = 0; k <= angles; ++k) {
    const double angle = -h + 2 * h * k / angles;
    for (double y = kWall.bottom; y <= kWall.top + 1e-12; y += 0.002)
      surface.push_back(at(ri, angle, y)), surface.push_back(at(ro, angle, y));
    for (double rho = ri; rho <= ro + 1e-12; rho += step)
      surface.push_back(at(rho, angle, kWall.top)), surface.push_back(at(rho, angle, kWall.bottom));
  }
  for (const double angle : {-h, h})
    for (double rho = ri; rho <= ro + 1e-12; rho += step)
      for (double y = kWall.bottom; y <= kWall.top + 1e-12; y += 0.002) surface.push_back(at(rho, angle, y));
  int checked = 0;
  for (const double rho : {0.0, 0.02, 0.05, 0.07, 0.1, 0.12})
    for (int k = 0; k < 24; ++k)
      for (const double y : {-0.12, 0.0, 0.04, 0.08}) {
        const Vec3 p = at(rho, k * M_PI / 12 + 0.1, y);
        const auto pen = penetration(kWall, p, r);
        double nearest = 1e9;
        for (const Vec3& q : surface) {
          // The vertical sampling is coarse on the tall faces: measure across them exactly at p's clamped height.
          Vec3 d = p - q;
          if (q.y > kWall.bottom && q.y < kWall.top) d.y = p.y - std::clamp(p.y, kWall.bottom, kWall.top);
          nearest = std::min(nearest, glm::length(d));
        }
        const bool inside = rho > ri && rho < ro && y > kWall.bottom && y < kWall.top &&
                            std::cos(k * M_PI / 12 + 0.1) > std::cos(h);
        if (inside) continue;  // in the solid: out through the nearest face, checked in ArcWallFaces
        ++checked;
        EXPECT_NEAR(r - pen->depth, nearest, 4e-4) << "rho " << rho << ", angle step " << k << ", y " << y;
        EXPECT_LE(r - pen->depth, nearest + 1e-12) << "rho " << rho << ", angle step " << k << ", y " << y;
      }
  EXPECT_GT(checked, 500);
}

// ModelIndex's clear column (model_index.hpp): a ball inside it is probed against the plane-like colliders only. On a
// pool table, near_colliders must still find every collider the plain probe of each finds, wherever the ball is:
// mid-table, at a cushion's nose, in a pocket's jaws, over a hole, off the table. Where the bed is probed as a level
// floor, it gives exactly what the plain probe gives.
TEST(Colliders, ClearColumnHidesNoCollider) {
  Model model = empty_model();
  add_table(model, pool_table());
  const ModelIndex index(model);
  ASSERT_LT(index.clear.lo_x, index.clear.hi_x);
  ASSERT_LT(index.clear.lo_z, index.clear.hi_z);
  const double ball = 0.028575;
  int column = 0, near_edge = 0, level = 0;
  for (double x = -1.45; x <= 1.45; x += 0.0061)
    for (double z = -0.8; z <= 0.8; z += 0.0059)
      for (double within : {0.0, 1e-3}) {
        const Vec3 p{x, ball - 1e-5, z};
        std::vector<int> found, expected;
        near_colliders(model, index, p, ball, within, [&](int c, const Penetration& pen) {
          found.push_back(c);
          // Over the level floor (contacts.hpp) the bed's depth and normal are the plain probe's, to the bit.
          const auto plain = penetration(model.colliders[c].shape, p, ball, within);
          ASSERT_TRUE(plain.has_value()) << model.colliders[c].name << " at x = " << x << ", z = " << z;
          EXPECT_EQ(pen.depth, plain->depth);
          EXPECT_EQ(pen.normal, plain->normal);
        });
        for (size_t c = 0; c < model.colliders.size(); ++c)
          if (penetration(model.colliders[c].shape, p, ball, within) && index.collider_bounds[c].may_touch(p, ball + within))
            expected.push_back(static_cast<int>(c));
        // Every collider the plain probe reports as within reach (depth > -within) is found.
        for (int c : expected) {
          const auto pen = penetration(model.colliders[c].shape, p, ball, within);
          if (pen->depth > -within) {
            EXPECT_NE(std::find(found.begin(), found.end(), c), found.end())
                << model.colliders[c].name << " hidden at x = " << x << ", z = " << z;
          }
        }
        (found.size() == 1 && expected.size() == 1 ? column : near_edge)++;
        level += index.floor[0].holds(p, 0.0);
      }
  EXPECT_GT(column, 0);
  EXPECT_GT(near_edge, 0);
  // The bed is a level floor over most of the column: all of it but the strips the corner pockets reach into.
  EXPECT_GT(level, column * 9 / 10);
}

}  // namespace
}  // namespace shotlab
