// What the 3D view frames: the table with its rails, or, for a scene without a table, its balls, rods' swings and
// the colliders around them; and the camera fitted to it while it auto-fits (camera.hpp).
#pragma once
#include <vector>

#include "shotlab/scene.hpp"
#include "ui/camera.hpp"
#include "ui/layout.hpp"

namespace shotlab {

// Points (m) that every frame of the scene should show: the table's outer corners; without a table, each ball's
// extent, each rod's whole swing and, with `colliders`, the corners of every collider's bounds but a floor's (an
// unbounded or level plane, which would frame the room instead of the balls on it).
std::vector<Vec3> framed_points(const Scene& scene, bool colliders = true);

// The view a scene opens with and Home brings back: the default over a table, a low side view without one, fitted
// (fit_camera) from then on.
void home_view(Camera& camera, const Scene& scene);
// A scene opened (or a load undone): its home view, or the top view again where the user had it and it has a table.
void scene_opened(Camera& camera, const Scene& scene);

// While the camera auto-fits, what is framed fills the 3D view (the rectangle between the panels) at its size. Without
// a table the view centres on it; colliders too far to fit leave the balls and rods framed alone.
void fit_camera(Camera& camera, const Scene& scene, const Rect& view);

}  // namespace shotlab
