// Scripted UI actions (tests, demos, screenshots): one command a line, documented in docs/gui-script.md. The
// script runs once per frame after the frame is drawn, so `screenshot` captures what the previous commands led to.
#pragma once
#include <functional>
#include <string>
#include <vector>

#include "ui/camera.hpp"
#include "ui/lab.hpp"

namespace shotlab {

struct ScriptHost {
  Lab& lab;
  Camera& camera;
  std::function<bool(const std::string&)> screenshot;  // writes the frame just drawn as PNG
  double fps = 0;              // frames per second over the last second of wall time
  bool real_clock = false;     // false: each frame advances the clock by exactly 1/60 s of real time
};

class Script {
 public:
  explicit Script(const std::string& path);  // throws std::runtime_error when the file cannot be read

  // Runs commands until one asks to let frames pass (frames, wait-*) or the script ends.
  void run(ScriptHost& host);
  bool done() const { return next_ >= lines_.size() && wait_frames_ == 0; }
  int failures() const { return failures_; }

 private:
  bool execute(ScriptHost& host, const std::string& line);  // false: wait (come back next frame)
  void dump(const ScriptHost& host, const std::string& path) const;

  std::vector<std::string> lines_;
  size_t next_ = 0;
  int wait_frames_ = 0;
  int waited_ = 0;  // frames spent in the current wait-* command
  int failures_ = 0;
  int frame_ = 0;
};

}  // namespace shotlab
