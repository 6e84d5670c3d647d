// What the 3D view frames when a scene loads (ui/framing.hpp): without a table, the colliders a ball may run into are
// in view from the start, as the table is.
#include <gtest/gtest.h>

#include <string>

#include "shotlab/io/scene_json.hpp"
#include "ui/framing.hpp"

namespace shotlab {
namespace {

// A ball on an unbounded floor between a sphere 1 m off to one side and a capsule 0.8 m off to the other.
Scene far_colliders() {
  const nlohmann::json doc = {
      {"colliders",
       {{{"type", "plane"}, {"point", {0, 0, 0}}, {"normal", {0, 1, 0}}},
        {{"type", "sphere"}, {"center", {1.0, 0.05, 0}}, {"radius", 0.05}},
        {{"type", "capsule"}, {"a", {-0.8, 0.03, -0.3}}, {"b", {-0.8, 0.03, 0.3}}, {"radius", 0.03}}}},
      {"balls", {{{"id", "a"}, {"position", {0, 0.028575, 0}}}}}};
  return parse_scene(doc, "far colliders");
}

// Whether p lies inside the view of the given size (pixels) between the panels.
bool in_view(const Camera& camera, const Rect& view, const Vec3& p) {
  const auto at = Viewport(camera, view.x, view.w, view.h).project(p);
  return at && at->x > view.x && at->x < view.right() && at->y > view.y && at->y < view.bottom();
}

TEST(Framing, ASceneWithoutATableShowsItsColliders) {
  const Scene s = far_colliders();
  for (const Rect& view : {Rect{330, 0, 590, 720}, Rect{300, 0, 400, 600}, Rect{330, 0, 1260, 1080}}) {
    Camera camera;
    home_view(camera, s);
    fit_camera(camera, s, view);
    for (const Vec3& p : {Vec3{0, 0.028575, 0}, Vec3{1.05, 0.05, 0}, Vec3{-0.83, 0.03, 0.33}, Vec3{-0.83, 0.03, -0.33}})
      EXPECT_TRUE(in_view(camera, view, p)) << "(" << p.x << ", " << p.y << ", " << p.z << ") in a " << view.w << "x"
                                            << view.h << " view";
  }
}

// A floor frames nothing, unbounded or a level 200 m square: a ball on it alone fills the view.
TEST(Framing, AFloorFramesNothing) {
  Scene s = far_colliders();
  s.model.colliders.resize(1);
  s.model.colliders.push_back({"floor", BoundedPlane({-100, 0, -100}, {200, 0, 0}, {0, 0, 200}), kBallCloth});
  const std::vector<Vec3> points = framed_points(s);
  ASSERT_EQ(points.size(), 2u);
  EXPECT_DOUBLE_EQ(points[1].x - points[0].x, 2 * 0.028575);
}

// Colliders too far to frame (a sphere 60 m off) leave the ball framed alone, centred, instead of a view of neither.
TEST(Framing, TooFarToFrameFallsBackToTheBalls) {
  Scene s = far_colliders();
  std::get<StaticSphere>(s.model.colliders[1].shape).center = {60, 0.05, 0};
  const Rect view{330, 0, 590, 720};
  Camera camera;
  home_view(camera, s);
  fit_camera(camera, s, view);
  EXPECT_TRUE(in_view(camera, view, {0, 0.028575, 0}));
  EXPECT_LT(camera.distance, 1.0);
}

// A top view the user chose stays when another table opens; a scene without a table opens in its own view.
TEST(Framing, ATopViewStaysForTheNextTable) {
  const Scene table = load_scene(std::string(SHOTLAB_SOURCE_DIR) + "/presets/cut.json");
  Camera camera;
  camera.top_view();
  scene_opened(camera, table);
  EXPECT_TRUE(camera.looks_down());
  scene_opened(camera, far_colliders());
  EXPECT_FALSE(camera.looks_down());
  scene_opened(camera, table);
  EXPECT_FALSE(camera.looks_down()) << "the default view over a table otherwise";
}

// The first wheel notch out after a fit beyond the zoom's own limit does not jump closer.
TEST(Framing, ZoomingOutNeverJumpsIn) {
  Camera camera;
  camera.distance = 20;
  camera.zoom(-1);
  EXPECT_GE(camera.distance, 20);
  camera.zoom(+1);
  EXPECT_LT(camera.distance, 20);
}

// From a teacher's trial: the wheel zoomed on the view's centre. It now zooms towards the cloth under the pointer,
// which keeps its place on the screen, in and out.
TEST(Framing, TheWheelZoomsTowardsThePointer) {
  Camera camera;
  const Vec3 spot{0.9, 0.0, -0.3};
  for (const double notches : {+3.0, -2.0}) {
    const Viewport before(camera, 0, 1000, 700);
    const auto pixel = before.project(spot);
    ASSERT_TRUE(pixel);
    const double distance = camera.distance;
    camera.zoom(notches, spot);
    EXPECT_NE(camera.distance, distance);
    const auto after = Viewport(camera, 0, 1000, 700).project(spot);
    ASSERT_TRUE(after);
    EXPECT_NEAR(after->x, pixel->x, 1e-6);
    EXPECT_NEAR(after->y, pixel->y, 1e-6);
  }
}

// A table frames its rails' outer corners, whatever else the scene holds.
TEST(Framing, ATableFramesItsRails) {
  const Scene s = load_scene(std::string(SHOTLAB_SOURCE_DIR) + "/presets/cut.json");
  ASSERT_TRUE(s.table);
  const std::vector<Vec3> points = framed_points(s);
  ASSERT_EQ(points.size(), 4u);
  EXPECT_DOUBLE_EQ(points[3].x, s.table->length / 2 + s.table->rail_width);
}

}  // namespace
}  // namespace shotlab
