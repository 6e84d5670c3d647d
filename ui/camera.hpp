// Orbit camera around a target point on the table: drag to orbit, pan the target, zoom the distance; a top view.
// While auto_fit holds, the frame loop sets the distance each frame so that the table fits the 3D view at any window
// size; orbiting keeps it, zooming or panning ends it, and a reset or the top view brings it back.
#pragma once
#include <glm/glm.hpp>
#include <optional>
#include <vector>

namespace shotlab {

struct Camera {
  glm::dvec3 target{0.0};
  double yaw = 1.5708;   // rad, around the vertical axis: from the front, the table's length across the screen
  double pitch = 1.0;    // rad above the table plane
  double distance = 3.8; // m
  double fov = 0.8;      // rad, vertical
  bool auto_fit = true;  // the distance follows the view's size so that what is framed fits (until the user zooms)

  glm::dvec3 eye() const;
  glm::dmat4 view() const;
  glm::dmat4 projection(double aspect) const;

  void orbit(double dx_pixels, double dy_pixels);
  void pan(double dx_pixels, double dy_pixels, double viewport_height);
  // Towards `toward` when given (the point under the pointer stays under it), else towards the target.
  void zoom(double wheel_steps, const std::optional<glm::dvec3>& toward = std::nullopt);
  void top_view();
  bool looks_down() const;  // straight down on the table, as the top view puts it
  void reset();
  // The distance (m) at which every point lies inside the view of the given aspect (width / height), a margin left;
  // nullopt when they do not fit within 40 m.
  std::optional<double> fit_distance(const std::vector<glm::dvec3>& points, double aspect) const;
};

// A camera fixed to one viewport for the frame: world <-> screen. The viewport is the part of the window between
// the side panels (left edge x0), so that the table is centred where it can be seen.
struct Viewport {
  glm::dmat4 view_proj;
  glm::dvec3 eye;
  double x0, width, height;

  Viewport(const Camera& camera, double x0, double width, double height);
  // Window position in pixels (origin top-left), nullopt when the point is behind the camera.
  std::optional<glm::dvec2> project(const glm::dvec3& p) const;
  // Where the ray under the pixel meets the horizontal plane y = height_above_bed (nullopt: it does not).
  std::optional<glm::dvec3> pick_plane(const glm::dvec2& pixel, double height_above_bed) const;
  // Radius on screen of a sphere of radius r at p (pixels).
  double screen_radius(const glm::dvec3& p, double r) const;
};

}  // namespace shotlab
