// The shot lab's state and the actions on it (what the panels, the mouse, the keys and scripts all call):
//  - `scene` is the position and aim of the next shot: what the user edits, predicts and saves;
//  - `shot` is the shot being watched (simulated from a copy of the scene taken when it was shot);
//  - `history` holds the scene before every shot, for undo.
#pragma once
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "engine/scene.hpp"
#include "ui/predictor.hpp"
#include "ui/settings.hpp"
#include "ui/shot.hpp"

namespace shotlab {

// Index of the ball with this id in scene.balls, -1 when absent (the scene's model gets its balls only when
// prepared, so Model::ball_index does not apply).
int scene_ball(const Scene& s, const std::string& id);

using Trails = std::vector<std::vector<PathPoint>>;  // per ball

class Lab {
 public:
  explicit Lab(Settings& settings) : settings(settings) {}

  Settings& settings;
  Scene scene;
  std::string scene_path;
  Model table_model;            // prepared model of `scene` (table colliders added): drawing and picking
  std::vector<Scene> history;
  std::unique_ptr<Shot> shot;
  Trails ghost;                 // the previous shot's trails
  double view_time = 0;         // s, the simulated time on screen
  bool playing = false;
  double achieved_speed = 1;    // fraction of the requested clock speed the physics kept up with (smoothed)
  int selected = 0;             // ball index
  std::string error;            // shown until dismissed: a bad file, an invalid edit, an engine stop
  std::string note;             // one line of feedback (saved, screenshot written, ...)
  std::string screenshot_request;  // PNG path: written after the next frame is drawn (gui.cpp)
  std::function<void(const Scene&)> on_load;  // after a scene file loaded (gui.cpp frames the camera)

  bool load(const std::string& path);  // false (and `error` set) when the file is bad; nothing is lost
  void set_scene(Scene s);
  void scene_changed();    // after editing `scene`'s balls or aim: re-predict
  void physics_changed();  // after editing `scene.model`: re-predict, and re-simulate the current shot from its start

  void shoot();
  void replay();
  void undo();
  void continue_from_rest();  // the next shot starts where the balls stopped
  void step();                // one display frame of simulated time while paused
  void seek(double t);        // pause at simulated time t (simulating up to it if needed: scripts, demos)
  void update(double real_dt);  // advances the clock while playing, on the settings' wall-time budget

  // The balls as on screen: the shot at view_time, or the scene's start position.
  const Frame& frame() const { return frame_; }
  Trails trails(double until) const;  // of the current shot, up to `until`
  std::optional<Prediction> prediction() const;  // the current scene's, when ready
  bool predicting() const { return predictor_.busy(); }

  void aim_at(const Vec3& point);  // turns the cue towards a point on the table (before the shot)

  // Ball editing (only while no shot is shown); each refuses an overlap unless the scene allows it.
  bool move_ball(int i, const Vec3& to);
  void add_ball(const Vec3& at);
  void remove_ball(int i);
  void rack();  // a 15-ball triangle at the foot spot, keeping the cue ball

 private:
  bool fits(int i, const Vec3& p) const;
  void show(double t);
  void start_shot(const Scene& start);

  Predictor predictor_;
  long wanted_ = -1;
  Frame frame_;
};

}  // namespace shotlab
