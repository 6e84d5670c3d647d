// What the 3D view frames: the table with its rails, or, for a scene without a table, its balls, rods' swings and
// bounded colliders; and the camera fitted to it while it auto-fits (camera.hpp).
#pragma once
#include <vector>

#include "shotlab/scene.hpp"
#include "ui/camera.hpp"
#include "ui/layout.hpp"

namespace shotlab {

// Points (m) that every frame of the scene should show: the table's outer corners; without a table, each ball's
// extent, each rod's whole swing and the corners of every collider's bounds (an unbounded plane frames nothing).
std::vector<Vec3> framed_points(const Scene& scene);

// A newly loaded scene's camera: the default for a table, a low side view without one (fit_camera centres it).
void on_scene_loaded(Camera& camera, const Scene& scene);

// While the camera auto-fits, what is framed fills the 3D view (the rectangle between the panels) at its size.
void fit_camera(Camera& camera, const Scene& scene, const Rect& view);

}  // namespace shotlab
