#include "shotlab/colliders.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace shotlab {
namespace {

const Hole* hole_under(const std::vector<Hole>& holes, const Vec3& p, const Vec3& n, double height) {
  for (const Hole& h : holes) {
    Vec3 d = p - h.center;
    // Cheap reject: an in-plane offset within the radius needs every coordinate within radius + height.
    const double reach = h.radius + std::abs(height);
    if (std::abs(d.x) > reach || std::abs(d.y) > reach || std::abs(d.z) > reach) continue;
    d -= glm::dot(d, n) * n;  // in-plane offset
    if (glm::dot(d, d) < h.radius * h.radius) return &h;
  }
  return nullptr;
}

// Ball centre p against the point q nearest to it on a convex core of radius rc (sphere, capsule axis).
Penetration from_point(const Vec3& p, double r, const Vec3& q, double rc) {
  const Vec3 d = p - q;
  const double dist = glm::length(d);
  // A centre exactly on the core has no defined normal; any direction is as good, up is the least surprising.
  const Vec3 n = dist > 0 ? d / dist : kUp;
  return {r + rc - dist, n};
}

// The horizontal unit direction of an arc wall's end: its middle turned by the half angle, towards the side
// (-toward.z, 0, toward.x) when sign is +1.
Vec3 arc_end(const ArcWall& s, double sign) {
  return s.cos_half * s.toward + sign * s.sin_half * Vec3{-s.toward.z, 0.0, s.toward.x};
}

struct Probe {
  const Vec3& p;
  double r;
  double within;

  // Plane surface with holes. The plane is one-sided: a centre behind it (it fell through a hole) touches nothing.
  // A centre over a hole can only touch the hole's rim: the point of the rim circle nearest to it.
  std::optional<Penetration> surface(const Vec3& point, const Vec3& n, const std::vector<Hole>& holes) const {
    const double height = glm::dot(p - point, n);
    if (height < 0) return std::nullopt;
    if (const Hole* h = hole_under(holes, p, n, height)) {
      const Vec3 in_plane = p - height * n - h->center;
      const double len = glm::length(in_plane);
      const Vec3 e = len > 0 ? in_plane / len : glm::normalize(glm::cross(n, Vec3{1.0, 0.0, 0.0}) + glm::cross(n, kUp));
      return from_point(p, r, h->center + h->radius * e, 0.0);
    }
    return Penetration{r - height, n};
  }

  std::optional<Penetration> operator()(const Plane& s) const { return surface(s.point, s.normal, s.holes); }
  std::optional<Penetration> operator()(const BoundedPlane& s) const {
    const Vec3 d = p - s.origin;
    const double du = glm::dot(d, s.u), dv = glm::dot(d, s.v);
    if (du <= 0 || du >= s.uu || dv <= 0 || dv >= s.vv) return std::nullopt;
    return surface(s.origin, s.normal, s.holes);
  }
  std::optional<Penetration> operator()(const StaticSphere& s) const { return from_point(p, r, s.center, s.radius); }
  std::optional<Penetration> operator()(const Capsule& s) const {
    const double reach = r + s.radius + within;
    for (int k = 0; k < 3; ++k)
      if (p[k] < std::min(s.a[k], s.b[k]) - reach || p[k] > std::max(s.a[k], s.b[k]) + reach) return std::nullopt;
    // Nearest point of segment a-b: clamp the projection parameter to [0, 1].
    const Vec3 ab = s.b - s.a;
    const double len2 = glm::dot(ab, ab);
    const double t = len2 > 0 ? std::clamp(glm::dot(p - s.a, ab) / len2, 0.0, 1.0) : 0.0;
    return from_point(p, r, s.a + t * ab, s.radius);
  }
  // The wall's point nearest the centre: along the radius within the arc, else on the end face nearer the centre
  // (the arcs' nearest points are the ends then). A centre inside the solid goes out through the nearest of its inner,
  // outer, top and bottom faces.
  std::optional<Penetration> operator()(const ArcWall& s) const {
    const double reach = r + within, outer = s.radius + s.thickness;
    const Vec3 d{p.x - s.center.x, 0.0, p.z - s.center.z};
    const double rho = glm::length(d);
    if (rho > outer + reach || p.y < s.bottom - reach || p.y > s.top + reach) return std::nullopt;
    const Vec3 e = rho > 0 ? d / rho : s.toward;
    const double y = std::clamp(p.y, s.bottom, s.top);
    const Vec3 axis{s.center.x, y, s.center.z};
    if (glm::dot(e, s.toward) >= s.cos_half) {
      const double q = std::clamp(rho, s.radius, outer);
      if (q != rho || y != p.y) return from_point(p, r, axis + q * e, 0.0);
      const double faces[4] = {rho - s.radius, outer - rho, s.top - p.y, p.y - s.bottom};
      const Vec3 normals[4] = {-e, e, kUp, -kUp};
      const auto k = std::min_element(faces, faces + 4) - faces;
      return Penetration{r + faces[k], normals[k]};
    }
    const Vec3 end = arc_end(s, glm::dot(e, Vec3{-s.toward.z, 0.0, s.toward.x}) < 0 ? -1.0 : 1.0);
    return from_point(p, r, axis + std::clamp(glm::dot(d, end), s.radius, outer) * end, 0.0);
  }
};

}  // namespace

BoundedPlane::BoundedPlane(const Vec3& origin, const Vec3& u, const Vec3& v, std::vector<Hole> holes)
    : origin(origin), u(u), v(v), holes(std::move(holes)), normal(glm::normalize(glm::cross(u, v))),
      uu(glm::dot(u, u)), vv(glm::dot(v, v)) {}

ArcWall::ArcWall(const Vec3& center, double radius, double thickness, const Vec3& toward, double half_angle,
                 double bottom, double top)
    : center(center), radius(radius), thickness(thickness), toward(toward), half_angle(half_angle), bottom(bottom),
      top(top), cos_half(std::cos(half_angle)), sin_half(std::sin(half_angle)) {}

std::optional<Penetration> penetration(const Shape& shape, const Vec3& p, double r, double within) {
  return std::visit(Probe{p, r, within}, shape);
}

Bounds bounds(const Shape& shape) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  if (const auto* s = std::get_if<StaticSphere>(&shape)) return {s->center - s->radius, s->center + s->radius};
  if (const auto* s = std::get_if<Capsule>(&shape))
    return {glm::min(s->a, s->b) - s->radius, glm::max(s->a, s->b) + s->radius};
  if (const auto* s = std::get_if<BoundedPlane>(&shape)) {
    // The parallelogram's corners; a ball touches the plane only while its centre projects inside.
    const Vec3 c[4] = {s->origin, s->origin + s->u, s->origin + s->v, s->origin + s->u + s->v};
    Bounds b{c[0], c[0]};
    for (const Vec3& q : c) b.lo = glm::min(b.lo, q), b.hi = glm::max(b.hi, q);
    return b;
  }
  if (const auto* s = std::get_if<ArcWall>(&shape)) {
    // The ends' corners, and the outer face's farthest points along x and z where the arc takes them in.
    Bounds b{Vec3{inf}, Vec3{-inf}};
    auto take = [&](const Vec3& dir, double radius) {
      const Vec3 q = s->center + radius * dir;
      b.lo = glm::min(b.lo, q), b.hi = glm::max(b.hi, q);
    };
    const double outer = s->radius + s->thickness;
    for (const double sign : {-1.0, 1.0}) take(arc_end(*s, sign), s->radius), take(arc_end(*s, sign), outer);
    for (const Vec3& dir : {Vec3{1, 0, 0}, Vec3{-1, 0, 0}, Vec3{0, 0, 1}, Vec3{0, 0, -1}})
      if (glm::dot(dir, s->toward) >= s->cos_half) take(dir, outer);
    b.lo.y = s->bottom, b.hi.y = s->top;
    return b;
  }
  return {Vec3{-inf}, Vec3{inf}};
}

namespace {

// A plane-like shape's holes, its normal and a point on it; no holes for the other shapes.
struct HoledPlane {
  const std::vector<Hole>* holes = nullptr;
  Vec3 normal{0.0}, point{0.0};
};

HoledPlane holed_plane(const Shape& shape) {
  if (const auto* s = std::get_if<Plane>(&shape)) return {&s->holes, s->normal, s->point};
  if (const auto* s = std::get_if<BoundedPlane>(&shape)) return {&s->holes, s->normal, s->origin};
  return {};
}

}  // namespace

const Hole* hole_over(const Shape& shape, const Vec3& p) {
  const HoledPlane h = holed_plane(shape);
  return h.holes ? hole_under(*h.holes, p, h.normal, glm::dot(p - h.point, h.normal)) : nullptr;
}

double hole_gap(const Shape& shape, const Vec3& p) {
  const HoledPlane h = holed_plane(shape);
  double gap = std::numeric_limits<double>::infinity();
  if (!h.holes) return gap;
  for (const Hole& hole : *h.holes) {
    Vec3 d = p - hole.center;
    d -= glm::dot(d, h.normal) * h.normal;
    gap = std::min(gap, std::max(0.0, glm::length(d) - hole.radius));
  }
  return gap;
}
}  // namespace shotlab
