// One shot being simulated and recorded. In the shot lab a shot runs until every ball rests, or until a long safety
// limit (a Newton's cradle swings for minutes), which is reported, never silent; the scene's `duration` is for
// headless runs only. The simulation runs ahead of the view clock on a wall-time budget per frame, and every advance
// is recorded as a Frame, so the view can pause, slow down and draw trails without re-running physics. Frames are
// 1/240 s apart; a collision (a fraction of a millisecond) falls between them, so a paused view asks for the exact
// state instead (exact_frame), which a second simulation of the same shot computes: results do not depend on how the
// clock is sliced, so it is the state of the shot that was watched, bit for bit.
#pragma once
#include <glm/gtc/quaternion.hpp>
#include <memory>
#include <vector>

#include "shotlab/diagnostics.hpp"
#include "shotlab/scene.hpp"
#include "shotlab/simulation.hpp"

namespace shotlab {

struct Frame {
  double time = 0;
  State state;
  std::vector<glm::dquat> orientation;  // integrated from the spin: the engine does not need it, the eye does
  std::vector<Motion> motion;
  Energy energy;  // J (kept per frame: the energy plot would otherwise evaluate every contact again)
};

struct Sample {
  double time, value;
};

enum class ShotEnd { Running, Rest, SafetyLimit, EngineStop };

inline constexpr double kDefaultSafetyLimit = 60.0;  // s of simulated time before a shot still moving is stopped

class Shot {
 public:
  // Throws std::invalid_argument (validate) or what the engine throws.
  Shot(const Scene& start, double safety_limit = kDefaultSafetyLimit);

  // Simulates towards `target` s of simulated time, stopping early after `budget` s of wall time. Returns the
  // simulated time reached (< target when the budget ran out or the shot ended).
  double advance(double target, double budget);

  ShotEnd end() const;
  bool finished() const { return end() != ShotEnd::Running; }
  double safety_limit() const { return limit_; }
  void extend_limit(double seconds) { limit_ += seconds; }  // run on past the safety limit

  const Simulation& sim() const { return *sim_; }
  const Scene& start() const { return start_; }
  const std::vector<Frame>& frames() const { return frames_; }
  // The recorded frame at or just before t, with positions interpolated to t (for playback).
  Frame frame_at(double t) const;
  // The exact state at t <= sim().time() (for a paused view), orientations from the recorded frames.
  Frame exact_frame(double t);

  const std::vector<Sample>& step_sizes() const { return step_sizes_; }
  // Integrator work and wall time of the most recent advance() call, and the real-time factor over the whole shot.
  long last_steps() const { return last_steps_; }
  long last_rhs() const { return last_rhs_; }
  double last_wall() const { return last_wall_; }  // s
  double realtime_factor() const;

 private:
  void record();
  Frame frame_from(const Simulation& sim, double t) const;

  Scene start_;
  std::unique_ptr<Simulation> sim_;
  std::unique_ptr<Simulation> scrub_;  // the same shot again, for exact_frame
  std::vector<Frame> frames_;
  std::vector<Sample> step_sizes_;
  double limit_;
  double window_end_ = -1;  // s: where the step limit's current window ends (advance)
  long last_steps_ = 0, last_rhs_ = 0;
  double last_wall_ = 0;
};

}  // namespace shotlab
