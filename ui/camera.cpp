#include "ui/camera.hpp"

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

namespace shotlab {

namespace {
constexpr double kMaxPitch = 1.5707;  // just short of straight down, so the view matrix keeps its up vector
constexpr double kMinDistance = 0.05, kMaxZoom = 12.0, kMaxFit = 40.0;  // m: the camera's distance to its target
}

glm::dvec3 Camera::eye() const {
  return target + distance * glm::dvec3{std::cos(pitch) * std::cos(yaw), std::sin(pitch), std::cos(pitch) * std::sin(yaw)};
}

glm::dmat4 Camera::view() const { return glm::lookAt(eye(), target, glm::dvec3{0, 1, 0}); }

glm::dmat4 Camera::projection(double aspect) const { return glm::perspective(fov, aspect, 0.01, 50.0); }

void Camera::orbit(double dx, double dy) {
  yaw += dx * 0.006;
  pitch = std::clamp(pitch + dy * 0.006, 0.02, kMaxPitch);
}

void Camera::pan(double dx, double dy, double viewport_height) {
  // One pixel moves the target by the size of a pixel at the target's distance.
  const double scale = 2 * distance * std::tan(fov / 2) / std::max(viewport_height, 1.0);
  const glm::dvec3 forward = glm::normalize(target - eye());
  const glm::dvec3 right = glm::normalize(glm::cross(forward, glm::dvec3{0, 1, 0}));
  const glm::dvec3 up = glm::cross(right, forward);
  target += (-dx * right + dy * up) * scale;
  auto_fit = false;
}

void Camera::zoom(double steps, const std::optional<glm::dvec3>& toward) {
  // Out to kMaxZoom, or as far as a fit had put it: the first notch never jumps closer.
  const double before = distance;
  distance = std::clamp(distance * std::pow(0.88, steps), kMinDistance, std::max(kMaxZoom, distance));
  // Eye and target scaled about the point by the same ratio: it keeps its place on the screen. A point far beyond the
  // target (the cloth near the horizon of a low view) would throw the camera off: then towards the target.
  if (toward && glm::length(*toward - target) < 2 * before) target += (*toward - target) * (1 - distance / before);
  auto_fit = false;
}

void Camera::top_view() {
  target = {0, 0, 0};
  yaw = M_PI / 2;  // x (the table's length) runs left to right on screen
  pitch = kMaxPitch;
  distance = 4.1;
  auto_fit = true;
}

bool Camera::looks_down() const { return pitch >= kMaxPitch; }

void Camera::reset() { *this = Camera{}; }

std::optional<double> Camera::fit_distance(const std::vector<glm::dvec3>& points, double aspect) const {
  constexpr double kMargin = 0.94;  // of the half-extent of the view, on each side
  auto fits = [&](double d) {
    Camera c = *this;
    c.distance = d;
    const glm::dmat4 vp = c.projection(aspect) * c.view();
    for (const glm::dvec3& p : points) {
      const glm::dvec4 clip = vp * glm::dvec4(p, 1.0);
      if (clip.w <= 1e-6 || std::abs(clip.x) > kMargin * clip.w || std::abs(clip.y) > kMargin * clip.w) return false;
    }
    return true;
  };
  double lo = kMinDistance, hi = kMaxFit;
  if (!fits(hi)) return std::nullopt;
  for (int k = 0; k < 40; ++k) {  // fitting is monotonic in the distance: bisect to a fraction of a millimetre
    const double mid = 0.5 * (lo + hi);
    (fits(mid) ? hi : lo) = mid;
  }
  return hi;
}

Viewport::Viewport(const Camera& c, double x, double w, double h)
    : view_proj(c.projection(w / std::max(h, 1.0)) * c.view()), eye(c.eye()), x0(x), width(w), height(h) {}

std::optional<glm::dvec2> Viewport::project(const glm::dvec3& p) const {
  const glm::dvec4 clip = view_proj * glm::dvec4(p, 1.0);
  if (clip.w < 1e-4) return std::nullopt;
  const glm::dvec3 ndc = glm::dvec3(clip) / clip.w;
  return glm::dvec2{x0 + (ndc.x * 0.5 + 0.5) * width, (0.5 - ndc.y * 0.5) * height};
}

std::optional<glm::dvec3> Viewport::pick_plane(const glm::dvec2& pixel, double y) const {
  const glm::dmat4 inv = glm::inverse(view_proj);
  const glm::dvec2 ndc{(pixel.x - x0) / width * 2 - 1, 1 - pixel.y / height * 2};
  glm::dvec4 far = inv * glm::dvec4(ndc, 1.0, 1.0);
  const glm::dvec3 dir = glm::normalize(glm::dvec3(far) / far.w - eye);
  if (std::abs(dir.y) < 1e-9) return std::nullopt;
  const double s = (y - eye.y) / dir.y;
  if (s <= 0) return std::nullopt;
  return eye + s * dir;
}

double Viewport::screen_radius(const glm::dvec3& p, double r) const {
  const glm::dvec3 forward = glm::normalize(p - eye);
  const glm::dvec3 side = glm::normalize(glm::cross(forward, glm::dvec3{0, 1, 0}) + glm::dvec3{1e-12, 0, 0});
  const auto a = project(p), b = project(p + r * side);
  return a && b ? glm::length(*a - *b) : 0.0;
}

}  // namespace shotlab
