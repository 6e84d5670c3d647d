// Static colliders (docs/model.md#shapes). Each answers one question about a ball of radius R at centre p:
// how deep is it in (penetration depth, > 0 when touching) and along which unit normal is it pushed out.
#pragma once
#include <limits>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "shotlab/vec.hpp"

namespace shotlab {

struct Penetration {
  double depth;  // m, > 0 means overlap
  Vec3 normal;   // unit, from the collider towards the ball centre
};

// A circular opening in a plane (a pocket): a ball whose centre is over it touches only the opening's rim.
struct Hole {
  Vec3 center;    // on the plane
  double radius;  // m
};

// Infinite plane through `point` with unit `normal` pointing to the free side (eq. 4.8). Optional holes. One-sided:
// a ball whose centre is behind the plane (fell through a hole) does not touch it.
struct Plane {
  Vec3 point;
  Vec3 normal;
  std::vector<Hole> holes;
};

// Parallelogram spanned by u and v at origin; normal = u^ x v^ (eq. 4.9). Contact only while the centre projects
// inside it. Optional holes. The constructor derives the unit normal and |u|^2, |v|^2 once (the bed is probed for
// every ball in every right-hand side); build a new shape to change one.
struct BoundedPlane {
  BoundedPlane(const Vec3& origin, const Vec3& u, const Vec3& v, std::vector<Hole> holes = {});
  Vec3 origin, u, v;
  std::vector<Hole> holes;
  Vec3 normal;    // unit, u^ x v^
  double uu, vv;  // m^2: |u|^2, |v|^2
};

// Fixed sphere (eq. 4.10).
struct StaticSphere {
  Vec3 center;
  double radius;
};

// Sphere of radius `radius` swept from a to b (eq. 4.11): cushions and pocket jaws.
struct Capsule {
  Vec3 a, b;
  double radius;
};

// A wall standing on an arc around a vertical axis (y up): the solid between the radii `radius` and
// `radius + thickness` from the axis through `center`, within `half_angle` of the horizontal unit direction `toward`,
// from height `bottom` to `top`. A table puts one around the back of each pocket's hole (docs/model.md#pockets): its
// inner face stops a ball that crosses the hole, its outer face one that comes from behind.
struct ArcWall {
  ArcWall(const Vec3& center, double radius, double thickness, const Vec3& toward, double half_angle, double bottom,
          double top);
  Vec3 center;          // a point of the axis (its height is not used)
  double radius;        // m, of the inner face
  double thickness;     // m
  Vec3 toward;          // unit, horizontal: the middle of the arc
  double half_angle;    // rad, in (0, pi]
  double bottom, top;   // m, heights (y)
  double cos_half, sin_half;  // of half_angle, which every probe wants
};

using Shape = std::variant<Plane, BoundedPlane, StaticSphere, Capsule, ArcWall>;

struct Collider {
  std::string name;      // "bed", "cushion-3", ... used in events and diagnostics
  Shape shape;
  std::string material;  // key into Model::materials
};

// Depth and normal for a ball (centre p, radius r); nullopt when the collider cannot touch it at all (outside a
// bounded plane, over a hole). A returned depth may be negative: the gap to contact, used to bound steps. Callers that
// only care about gaps up to `within` metres get nullopt sooner for farther colliders: a capsule's bounding box
// rejects most of a table's cushions at the cost of six comparisons, which matters because this is the engine's
// innermost loop.
std::optional<Penetration> penetration(const Shape& shape, const Vec3& p, double r,
                                       double within = std::numeric_limits<double>::infinity());

// Axis-aligned bounds of a shape (infinite for a plane): a ball whose centre is more than its radius outside them
// cannot touch it.
struct Bounds {
  Vec3 lo, hi;
  bool may_touch(const Vec3& p, double r) const {
    return p.x + r > lo.x && p.x - r < hi.x && p.y + r > lo.y && p.y - r < hi.y && p.z + r > lo.z && p.z - r < hi.z;
  }
};
Bounds bounds(const Shape& shape);

// Distance (m) from the projection of p onto a plane-like shape to the nearest edge of a hole it is outside of;
// +inf for shapes without holes, 0 when over a hole.
double hole_gap(const Shape& shape, const Vec3& p);
// The hole of a plane-like shape that the projection of p lies over, if any.
const Hole* hole_over(const Shape& shape, const Vec3& p);


}  // namespace shotlab
