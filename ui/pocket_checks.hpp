// Which pockets the current shot drops its object ball in (aim.hpp, check_drops), worked out off the UI thread and
// kept: with a full rack P plays the shot out once for each pocket, about 20 ms, more than a frame. The answer does
// not depend on the aim, so pressing P again on the same table cycles through kept answers at once.
#pragma once
#include <future>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "shotlab/scene.hpp"
#include "ui/aim.hpp"

namespace shotlab {

class PocketChecks {
 public:
  // What the aims and their drops depend on: the scene without its aim (its table gives the pockets) and the object
  // ball.
  static std::string key_of(const Scene& scene, int object);

  // Starts checking the pockets of `scene` (cue ball `cue`, object ball `object`) under `key` unless its answer is
  // kept or being worked out; a check of another table still running finishes first, then this one starts.
  void request(const std::string& key, const Scene& scene, const std::vector<Pocket>& pockets, int cue, int object);
  // The kept answer for `key`, after moving a finished check into the kept ones: every aim pocket_aims offers, with
  // `drops` set, those that drop first.
  std::optional<std::vector<PocketAim>> answer(const std::string& key);
  // Waits up to `seconds` (< 0: as long as it takes) for the answer for `key`; false if it is not there by then.
  bool wait(const std::string& key, double seconds);
  void poll();  // once a frame: a finished check kept, the queued one started

 private:
  struct Job {
    std::string key;
    Scene scene;
    std::vector<Pocket> pockets;
    int cue = -1, object = -1;
  };
  void start(Job job);
  void collect();  // a finished check into kept_, then the queued one started
  const std::vector<PocketAim>* kept(const std::string& key) const;

  std::future<std::vector<PocketAim>> running_;
  std::string running_key_;
  std::optional<Job> queued_;  // the latest request that came while another ran
  std::vector<std::pair<std::string, std::vector<PocketAim>>> kept_;  // oldest first
  static constexpr size_t kKept = 8;
};

}  // namespace shotlab
