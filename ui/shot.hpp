// One shot being simulated and recorded. The simulation runs ahead of the view clock on a wall-time budget per frame;
// every advance is recorded as a Frame, so the view can pause, slow down, scrub backwards and draw trails without
// re-running physics. The observer keeps the integrator's step sizes and the ball-ball contact force of the last
// collision (both at step resolution: a collision lasts a fraction of a millisecond, far less than a frame).
#pragma once
#include <glm/gtc/quaternion.hpp>
#include <memory>
#include <vector>

#include "engine/scene.hpp"
#include "engine/simulation.hpp"

namespace shotlab {

struct Frame {
  double time;
  State state;
  std::vector<glm::dquat> orientation;  // integrated from the spin: the engine does not need it, the eye does
  std::vector<Motion> motion;
  double energy = 0;  // J, total (kept per frame: the energy plot would otherwise recompute every contact)
};

struct Sample {
  double time, value;
};

class Shot {
 public:
  explicit Shot(const Scene& start);  // throws std::invalid_argument (validate) or what the engine throws

  // Simulates towards `target` s of simulated time, stopping early after `budget` s of wall time. Returns the
  // simulated time reached (< target when the budget ran out or the simulation stopped).
  double advance(double target, double budget);

  bool finished() const;  // at rest, past the scene's duration, or stopped by the engine (step limit, blow-up)
  const Simulation& sim() const { return *sim_; }
  const Scene& start() const { return start_; }
  const std::vector<Frame>& frames() const { return frames_; }
  // The recorded frame at or just before t, with positions interpolated to t.
  Frame frame_at(double t) const;

  const std::vector<Sample>& step_sizes() const { return step_sizes_; }
  const std::vector<Sample>& collision_force() const { return collision_force_; }
  // Integrator work of the most recent advance() call, and the real-time factor over the whole shot.
  long last_steps() const { return last_steps_; }
  long last_rhs() const { return last_rhs_; }
  double realtime_factor() const;

 private:
  void record();
  void observe(const Island& island);

  Scene start_;
  std::unique_ptr<Simulation> sim_;
  std::vector<Frame> frames_;
  std::vector<Sample> step_sizes_, collision_force_;
  double last_contact_time_ = -1;
  double chunk_;  // s of simulated time a single advance() call covers: shrinks while the integrator crawls
  long last_steps_ = 0, last_rhs_ = 0;
};

}  // namespace shotlab
