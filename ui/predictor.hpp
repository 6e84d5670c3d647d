// Predicted paths before the shot: a background thread runs its own Simulation of the scene as it would be shot,
// until its balls rest, and hands back each ball's path. A newer request supersedes a running one (the thread checks
// between chunks), so dragging the aim never queues work. A long prediction (a break) hands out its paths so far as
// it goes: every kShowEvery of computing, and at every chunk while the window waits for it (wait_for). Finished
// predictions are kept for a while, and while nothing else waits the thread predicts the scenes a request names as
// likely next (the aim a key press away): a request for one of those is answered at once.
#pragma once
#include <atomic>
#include <condition_variable>
#include <deque>
#include <functional>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "shotlab/event.hpp"
#include "shotlab/scene.hpp"

namespace shotlab {

struct PathPoint {
  Vec3 position;
  Motion motion;
};

struct Prediction {
  long generation = -1;                     // which request it answers
  std::vector<std::vector<PathPoint>> paths;  // per ball, in scene order
  double simulated = 0;                     // s covered
  double wall_seconds = 0;                  // spent computing it (scene preparation and simulation)
  bool complete = false;                    // false: the paths so far of a prediction still running
  std::string problem;                      // why it stopped early (engine status, invalid scene), empty if none
};

class Predictor {
 public:
  Predictor();
  ~Predictor();
  Predictor(const Predictor&) = delete;
  Predictor& operator=(const Predictor&) = delete;

  // Starts predicting `scene` until its balls rest or `limit` s (abandoning any older request), or answers at once
  // from a kept prediction of the same scene and limit; returns the request's generation. `next`: scenes likely asked
  // for next, likeliest first, predicted and kept once this one is finished and no newer request waits.
  long request(const Scene& scene, double limit, std::vector<Scene> next = {});
  // Whether a finished prediction of `scene` to `limit` is kept (a request for it is answered at once).
  bool kept(const Scene& scene, double limit) const;
  // Called on the worker thread when a prediction, or more of one, is out (the window's event loop wakes up to draw).
  void set_notify(std::function<void()> notify);
  // The latest prediction handed out, finished or so far (Prediction::complete), of whichever request.
  std::optional<Prediction> latest() const;
  // Waits at most `seconds` until request `generation` is finished; true if it is. Meanwhile the worker hands out its
  // paths so far at every chunk, so that latest() has them when the time is up.
  bool wait_for(long generation, double seconds) const;
  // s: the latest finished prediction's compute time, if it answers request `generation` (its paths not copied).
  std::optional<double> wall_seconds(long generation) const;
  bool busy() const { return busy_; }

 private:
  void run();
  // Runs the scene; nullopt when request `generation` was superseded meanwhile. A guess (a scene from `next`) hands
  // nothing out on the way.
  std::optional<Prediction> predict(const Scene& scene, double limit, long generation, bool guess);
  void publish(Prediction p);  // hands it out unless a newer request came meanwhile
  void keep(std::string key, const Prediction& p);  // among the kept ones, the oldest dropped past kKept
  const Prediction* find(const std::string& key) const;  // with mutex_ held

  mutable std::mutex mutex_;
  std::condition_variable wake_;
  mutable std::condition_variable published_;
  mutable std::atomic<int> waiting_{0};  // calls of wait_for blocked now: the worker hands out what it has
  struct Pending {
    Scene scene;
    std::string key;  // its key among the kept ones, worked out by request()
  };
  std::optional<Pending> pending_;
  std::vector<Scene> next_;  // guesses still to predict, likeliest first (request)
  double limit_ = 0;
  std::deque<std::pair<std::string, Prediction>> kept_;  // finished predictions by key (scene and limit), oldest first
  std::function<void()> notify_;
  std::optional<Prediction> done_;
  long generation_ = 0;
  std::atomic<long> wanted_{0};
  std::atomic<bool> busy_{false};
  bool quit_ = false;
  std::thread thread_;
};

}  // namespace shotlab
