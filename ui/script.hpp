// Scripted UI actions (tests, demos, screenshots): one command a line, documented in docs/gui-script.md. The
// script runs once per frame after the frame is drawn, so `screenshot` captures what the previous commands led to.
#pragma once
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include "ui/camera.hpp"
#include "ui/lab.hpp"
#include "ui/state_dump.hpp"

namespace shotlab {

struct ScriptHost {
  Lab& lab;
  Camera& camera;
  std::function<bool(const std::string&)> screenshot;  // writes the frame just drawn as PNG
  const ScreenInfo* screen = nullptr;  // the frame just drawn: where things are, for `dump`
  double fps = 0;              // frames per second over the last second of wall time
  bool real_clock = false;     // false: each frame advances the clock by exactly 1/60 s of real time
};

class Script {
 public:
  // Throws std::runtime_error when the file cannot be read; `preset NAME` reads data_root/presets/NAME.json.
  Script(const std::string& path, std::string data_root);

  // Runs commands until one asks to let frames pass (frames, wait-*) or the script ends.
  void run(ScriptHost& host);
  bool done() const { return next_ >= lines_.size() && wait_frames_ == 0; }
  int failures() const { return failures_; }

 private:
  bool execute(ScriptHost& host, const std::string& line);  // false: wait (come back next frame)
  bool edit(ScriptHost& host, const std::string& cmd, std::istringstream& in);  // table edits; false: not one
  bool view(ScriptHost& host, const std::string& cmd, std::istringstream& in);  // view and camera; false: not one
  void fail(const std::string& line, const std::string& why);

  std::string data_root_;
  std::string line_;  // being executed

  std::vector<std::string> lines_;
  size_t next_ = 0;
  int wait_frames_ = 0;
  int waited_ = 0;  // frames spent in the current wait-* command
  int failures_ = 0;
  int frame_ = 0;
};

}  // namespace shotlab
