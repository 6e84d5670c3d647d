// The shot lab's state and the actions on it (what the panels, the mouse, the keys and scripts all call):
//  - `scene` is the position and aim of the next shot: what the user edits, predicts and saves;
//  - `shot` is the shot being watched (simulated from a copy of the scene taken when it was shot);
//  - `history` is one undo stack for edits and shots (history.hpp); tuned physics has its own reset.
// The actions live in lab.cpp (files, shots, playback) and lab_edit.cpp (aiming and editing the table).
#pragma once
#include <chrono>
#include <functional>
#include <future>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "shotlab/scene.hpp"
#include "ui/contact_log.hpp"
#include "ui/history.hpp"
#include "ui/layout.hpp"
#include "ui/margin_view.hpp"
#include "ui/measured_view.hpp"
#include "ui/pocket_checks.hpp"
#include "ui/predictor.hpp"
#include "ui/settings.hpp"
#include "ui/shot.hpp"

namespace shotlab {

// Index of the ball with this id in scene.balls, -1 when absent.
int scene_ball(const Scene& s, const std::string& id);

// What a left click or drag on the table does.
enum class Tool { Aim, Move, Target };

// The banner's message and what it offers: a load error is dismissed (the current scene stayed); an engine stop
// offers to undo the shot; a refused edit or a note is a line of feedback.
enum class MessageKind { None, Note, Refused, LoadError, EngineStop };

inline constexpr size_t kMaxKeptShots = 8;
inline constexpr double kAimStepDeg = 0.1;  // the aim keys' plain step (shift 1 degree, ctrl 0.01)
// The cue turned by `degrees` (positive: counter-clockwise seen from above), as the aim keys turn it.
CueStrike turned(const CueStrike& cue, double degrees);

class Lab {
 public:
  Lab(Settings& settings, std::string data_root) : settings(settings), data_root(std::move(data_root)) {}

  Settings& settings;
  const std::string data_root;  // holds presets/ and assets/
  Scene scene;
  std::string scene_path;
  Scene loaded;                 // the scene as loaded: physics reset and the list of changes compare with it
  Model table_model;            // prepared model of `scene` (table colliders added): drawing and picking
  History history;
  std::unique_ptr<Shot> shot;
  Trails ghost;                 // the previous shot's trails
  std::vector<KeptShot> kept;
  Trails compare;               // "A": the shot's trails before the physics was changed
  std::string compare_label;
  std::vector<Frame> compare_frames;  // A's frames: its lines in the plots
  std::optional<Vec3> target;   // where the cue ball should stop (players' position play)
  double target_radius = 0.05;  // m
  Tool tool = Tool::Aim;
  bool in_hand = false;         // the cue ball follows the pointer until placed
  double view_time = 0;         // s, the simulated time on screen
  bool playing = false;
  double achieved_speed = 1;    // fraction of the requested clock speed the physics kept up with (smoothed)
  int selected = 0;             // ball index
  std::string message;
  MessageKind message_kind = MessageKind::None;
  bool scene_kept = true;  // after a LoadError: the scene before it is still open (false: a preset opened instead)
  std::chrono::steady_clock::time_point message_since;  // when the message was set: a note goes after kNoteSeconds
                                                        // of wall time (idle frames come every half second)
  static constexpr double kNoteSeconds = 6;
  std::string screenshot_request;  // PNG path: written after the next frame is drawn
  std::optional<Rect> screenshot_crop;  // only this part of the window (a plot), else all of it
  int screenshot_delay = 0;             // frames drawn before it is taken
  std::string plot_capture;             // the plot (its id) drawn large over the window for that PNG
  bool plot_capture_drawn = false;      // ... in this frame (its panel may have closed since the request)
  std::string strobe_request;      // PNG path: a multiple exposure of the shot, drawn by the next frame
  std::function<void(const Scene&)> on_load;  // after a scene file loaded (gui.cpp frames the camera)
  MarginView margin;            // the shot margin worked out in the background (margin_view.hpp)
  MeasuredView measured;        // a measured shot loaded from CSV and its fit (measured_view.hpp)

  // Files and scenes (lab.cpp).
  bool load(const std::string& path);  // false (and the message set) when the file is bad; nothing is lost
  // A measured shot (CSV, docs/fit.md): the scene becomes its balls where first seen on the current scene's table
  // (the three-cushion preset's when the current table is not a carom table), with the strike the data suggests.
  bool load_measured(const std::string& path);
  void start_fit();        // fits the measured shot's strike (and the chosen values) in the background
  void apply_fit();        // puts a finished fit's strike and values into the scene (one undo entry for the strike)
  void set_scene(Scene s);
  void say(MessageKind kind, std::string text);
  void scene_changed();    // after editing `scene`'s balls or aim: re-predict
  void physics_changed();  // after editing `scene.model`: re-predict, and re-simulate the current shot from its start
  static constexpr double kRetuneSeconds = 0.1;  // wall time physics_changed may spend reaching the moment shown
  std::vector<std::string> physics_changes() const;  // "materials.ball_ball.stiffness: 1e+10 -> 5e+09", ...
  void reset_physics();    // back to the loaded scene's materials, options and integrator
  void pin_compare();      // the current shot's trails (before a shot: the predicted paths) become the A of A/B
  bool can_pin() const { return shot || prediction_seconds(); }  // a finished prediction, not copied

  // Shots and playback (lab.cpp).
  void shoot();
  void replay();
  void undo();
  void redo();
  void continue_from_rest();  // the next shot starts where the balls stopped
  static constexpr const char* kNextLabel = "Next";  // its undo entry's label
  void step(int direction);   // one display frame of simulated time, forward (+1) or back (-1), paused
  void seek(double t);        // pause at simulated time t (simulating up to it if needed)
  void run_on();              // a shot stopped at the safety limit runs on for as long again
  void update(double real_dt);  // advances the clock while playing, on the settings' wall-time budget
  bool shot_over() const { return shot && shot->finished() && view_time >= shot->sim().time(); }
  bool animating() const;     // something changes on screen without input: the frame loop keeps drawing
  int shot_id() const { return shot_id_; }  // counts the shots started (a rerun after a change of physics too)

  const Frame& frame() const { return frame_; }  // the balls as on screen
  bool contact_on_screen() const;  // a ball touches another ball or a cushion in the frame shown
  Trails trails(double until) const;  // of the current shot, up to `until`
  std::optional<Prediction> prediction() const;  // the current scene's, when finished
  // The predicted paths to draw: the current scene's, finished or so far, else the last ones handed out (the aim
  // changed in this frame and its paths are not out yet), so that they never blink off while the aim is dragged.
  std::optional<Prediction> predicted_paths() const { return predictor_.latest(); }
  long prediction_request() const { return wanted_; }  // the current scene's (Prediction::generation)
  // Before a frame is drawn: a new aim's prediction gets a few milliseconds to finish, once, so that a shot that takes
  // no longer to predict (a cut) shows its own paths in the frame that changed the aim.
  void await_prediction();
  // Once a frame: before a shot, a finished prediction that failed (a scene the chosen model refuses) says why, once.
  void report_prediction();
  std::optional<double> prediction_seconds() const { return predictor_.wall_seconds(wanted_); }  // its compute time
  bool predicting() const { return predictor_.busy(); }
  // The contacts of the current shot with their force histories, traced on a worker thread; the latest complete
  // log (possibly older than the shot's events while a new one is being traced).
  const ContactLog* contact_log();

  // Aiming and editing the table (lab_edit.cpp); each refuses, with a note, while a shot is shown.
  void aim_at(const Vec3& point);         // the cue towards a point on the table
  void aim_at_ball(int i);                // full-ball aim at ball i's centre
  void aim_for_pocket(int step);          // cycles through the pockets the aimed-at ball can be cut into
  // Once a frame: P's answer, when its check has finished since (with `block`, waited for: scripts and tests).
  void finish_pocket_aim(bool block = false);
  bool checking_pockets() const { return pocket_wait_.has_value(); }
  double pocket_wait_seconds = 25e-3;  // s: P waits this long for its check within the frame (a cut's takes ~15 ms)
  void nudge_aim(double degrees);
  void nudge_speed(double mps);
  void set_cue(const CueStrike& cue, const std::string& what);  // any other cue change, merged per `what`
  bool begin_move(int i);                 // a drag of ball i starts (one undo entry for the whole drag)
  bool move_ball(int i, const Vec3& to);  // refused on overlap unless the scene allows it
  void end_gesture() { history.seal(); }
  void add_ball(const Vec3& at);
  void remove_ball(int i);                // the cue ball is not removed (untick the cue strike first)
  void pick_up_cue_ball();                // ball in hand
  void place_cue_ball(const Vec3& at, bool drop);  // follows the pointer; `drop` puts it down
  void setup_break();                     // rack, cue ball in hand behind the head string, a cue strike
  bool set_target(const Vec3& at);        // on the bed inside the cushions (refused elsewhere: false); an undo step
  void clear_target();                    // an undo step too
  void drag_target(const Vec3& at);       // carried by a drag after set_target: part of its undo step
  std::optional<double> target_miss() const;  // m from the cue ball's rest position (or predicted one) to the target
  void keep_shot();
  void clear_kept();  // an undo step of its own
  void set_cue_strike(bool on);  // off keeps the stroke aside (spare_cue); on brings it back
  CueStrike spare_cue() const;   // the stroke unticked last, on its ball if still there, else on the selected ball

 private:
  std::optional<CueStrike> removed_cue_;  // set_cue_strike(false) keeps it; a load forgets it
  bool take_compare();  // A of A/B from the shot so far, else the finished prediction; false: neither there
  void adopt(Scene s, const std::string& path, const std::string& what);  // lab.cpp: a loaded scene taken on
  void take_step(HistoryStep step);  // the scene (and file) undo or redo goes back to
  SceneFile current_file() const;    // the scene's file and the workbench, for the history to bring back
  void restore(Workbench bench);     // kept shots, A/B, target and measured shot as a load's undo brings them back
  bool editable(const char* what);
  bool fits(int i, const Vec3& p) const;
  void choose_pocket(std::vector<PocketAim> aims, int object, int step, int first);  // lab_edit.cpp
  std::string pocket_note(const PocketAim& a, int object, bool only) const;  // P's note on the aim it took
  void show(double t);
  void start_shot(const Scene& start);
  void launch();  // the scene's shot starts playing; the last shot's paths stay as the ghost
  void back_before_next();  // undoing Next: the shot before it, shown at its end
  void pause_on_events(double from, double to);
  void finish_playing();

  PocketChecks pocket_checks_;
  struct PocketWait {  // P pressed, its check not back yet
    std::string key;   // PocketChecks::key_of
    int object = -1;
    int steps = 0;     // the presses' steps, added up
    int first = 0;     // the first press's step
    double aim = 0;    // rad, the cue's at the last press: an aim turned since then is the user's, not P's to change
  };
  std::optional<PocketWait> pocket_wait_;
  struct PocketAimed {  // the ball P last aimed at a pocket, the aim it set and the note it gave
    std::string ball;
    double aim = 0;
    std::string note;
  };
  static constexpr const char* kPocketAim = "pocket aim";  // P's entry in the undo list
  std::optional<PocketAimed> pocket_aimed_;
  Predictor predictor_;
  long wanted_ = -1;
  double last_turn_deg_ = kAimStepDeg;  // the last aim key's step: the guessed next aims repeat it first
  long reported_ = -1;  // the last request report_prediction looked at
  long awaited_ = -1;  // the last request a frame waited for (await_prediction)
  Frame frame_;
  double exact_time_ = -1;  // the paused frame's time, so that the exact state is not worked out every frame
  size_t events_seen_ = 0;  // of the shot's events, those playback has passed (pause_on_events)
  int shot_id_ = 0;         // counts shots started: which one the contact log describes
  ContactLog log_;
  int log_shot_ = -1;
  std::unique_ptr<ContactTracer> tracer_;  // the shot tracer_shot_ run on to where log_ ends, while no job holds it
  int tracer_shot_ = -1;
  std::future<std::unique_ptr<ContactTracer>> log_job_;  // the tracer, extended on a worker thread
  int job_shot_ = -1;
  std::chrono::steady_clock::time_point job_started_;  // of the last trace
};

}  // namespace shotlab
