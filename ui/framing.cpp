#include "ui/framing.hpp"

#include <cmath>

#include "shotlab/colliders.hpp"

namespace shotlab {

std::vector<Vec3> framed_points(const Scene& scene) {
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
    const Bounds b = bounds(c.shape);
    if (!std::isfinite(glm::length(b.hi - b.lo))) continue;
    for (double x : {b.lo.x, b.hi.x})
      for (double y : {b.lo.y, b.hi.y})
        for (double z : {b.lo.z, b.hi.z}) points.push_back({x, y, z});
  }
  return points;
}

void on_scene_loaded(Camera& camera, const Scene& scene) {
  camera.reset();
  if (scene.table) return;
  camera.yaw = M_PI / 2;
  camera.pitch = 0.25;
}

void fit_camera(Camera& camera, const Scene& scene, const Rect& view) {
  if (!camera.auto_fit || view.w < 1 || view.h < 1) return;
  const std::vector<Vec3> points = framed_points(scene);
  if (points.empty()) return;
  if (!scene.table) {
    Vec3 lo{1e9}, hi{-1e9};
    for (const Vec3& p : points) lo = glm::min(lo, p), hi = glm::max(hi, p);
    camera.target = (lo + hi) * 0.5;
  }
  camera.distance = camera.fit_distance(points, view.w / view.h);
}

}  // namespace shotlab
