// How long the frames took while a shot played (the time from one frame's start to the next's, which the status line
// shows as fps): what the GUI tests report for the frame rate of a whole shot, every frame of it rather than the few
// a state dump happens to sample.
#pragma once
#include <algorithm>
#include <cstddef>
#include <vector>

namespace shotlab {

class FrameTimes {
 public:
  // Once a frame: whether a shot played in the last frame, which one (any number that names a shot run: a new run of
  // it is a new shot), and how long that frame took (s). A record is a shot's: it goes on after a pause, and the
  // first frame another shot plays in starts a new one.
  void add(bool played, long shot, double seconds) {
    if (!played) return;
    if (shot != shot_) ms_.clear(), shot_ = shot;
    if (ms_.size() < kMaxFrames) ms_.push_back(seconds * 1e3);
  }

  struct Summary {
    size_t frames = 0;
    double median_ms = 0, p95_ms = 0, worst_ms = 0;  // p95: 95 % of the frames took this long or less
    size_t over_budget = 0;                          // frames longer than the budget
  };
  Summary summary(double budget_ms) const {
    Summary s;
    s.frames = ms_.size();
    if (ms_.empty()) return s;
    std::vector<double> sorted = ms_;
    std::sort(sorted.begin(), sorted.end());
    auto at = [&](double share) { return sorted[static_cast<size_t>(share * static_cast<double>(sorted.size() - 1))]; };
    s.median_ms = at(0.5), s.p95_ms = at(0.95), s.worst_ms = sorted.back();
    s.over_budget = static_cast<size_t>(sorted.end() - std::upper_bound(sorted.begin(), sorted.end(), budget_ms));
    return s;
  }

 private:
  static constexpr size_t kMaxFrames = 1 << 20;  // an hour of play at 300 fps
  std::vector<double> ms_;
  long shot_ = -1;  // whose frames ms_ holds
};

}  // namespace shotlab
