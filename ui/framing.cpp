#include "ui/framing.hpp"

#include <cmath>
#include <optional>

#include "shotlab/colliders.hpp"

namespace shotlab {

namespace {

// A plane a ball may rest on or run under: unbounded, or level (its normal straight up or down).
bool floor_like(const Shape& shape) {
  if (std::holds_alternative<Plane>(shape)) return true;
  const auto* plane = std::get_if<BoundedPlane>(&shape);
  return plane && std::abs(plane->normal.y) > 0.99;
}

// The camera's target and distance that frame `points` in a view of the given aspect; nullopt if none within reach.
std::optional<std::pair<Vec3, double>> framing(const Camera& camera, const std::vector<Vec3>& points, bool centre,
                                               double aspect) {
  if (points.empty()) return std::nullopt;
  Camera c = camera;
  if (centre) {
    Vec3 lo{points[0]}, hi{points[0]};
    for (const Vec3& p : points) lo = glm::min(lo, p), hi = glm::max(hi, p);
    c.target = (lo + hi) * 0.5;
  }
  const auto distance = c.fit_distance(points, aspect);
  if (!distance) return std::nullopt;
  return std::pair{c.target, *distance};
}

}  // namespace

std::vector<Vec3> framed_points(const Scene& scene, bool colliders) {
  std::vector<Vec3> points;
  if (scene.table) {
    const double rail = scene.table->rail_width;
    const double hx = scene.table->length / 2 + rail, hz = scene.table->width / 2 + rail;
    for (double sx : {-1.0, 1.0})
      for (double sz : {-1.0, 1.0}) points.push_back({sx * hx, 0, sz * hz});
    return points;
  }
  for (const InitialBall& b : scene.balls)
    for (double s : {-1.0, 1.0}) points.push_back(b.position + Vec3{s * b.spec.radius, 0, 0});
  for (const Rod& r : scene.model.rods)  // the whole swing: a rod's length either side of its anchor and below it
    for (const Vec3& d : {Vec3{0, 0, 0}, Vec3{r.length, 0, 0}, Vec3{-r.length, 0, 0}, Vec3{0, -r.length, 0},
                          Vec3{0, 0, r.length}, Vec3{0, 0, -r.length}})
      points.push_back(r.anchor + d);
  // A collider a ball may run into is in view from the start, not only after the user has zoomed far out.
  for (const Collider& c : scene.model.colliders) {
    if (!colliders || floor_like(c.shape)) continue;
    const Bounds b = bounds(c.shape);
    if (!std::isfinite(glm::length(b.hi - b.lo))) continue;
    for (double x : {b.lo.x, b.hi.x})
      for (double y : {b.lo.y, b.hi.y})
        for (double z : {b.lo.z, b.hi.z}) points.push_back({x, y, z});
  }
  return points;
}

void home_view(Camera& camera, const Scene& scene) {
  camera.reset();
  if (scene.table) return;
  camera.yaw = M_PI / 2;
  camera.pitch = 0.25;
}

void scene_opened(Camera& camera, const Scene& scene) {
  const bool top = camera.looks_down();
  home_view(camera, scene);
  if (top && scene.table) camera.top_view();
}

void fit_camera(Camera& camera, const Scene& scene, const Rect& view) {
  if (!camera.auto_fit || view.w < 1 || view.h < 1) return;
  const double aspect = view.w / view.h;
  const bool centre = !scene.table;
  auto fit = framing(camera, framed_points(scene), centre, aspect);
  if (!fit && centre) fit = framing(camera, framed_points(scene, false), centre, aspect);
  if (!fit) return;
  camera.target = fit->first;
  camera.distance = fit->second;
}

}  // namespace shotlab
