// The program's state as JSON, for tests that drive the GUI: what the lab holds (scene, shot, playback, history,
// message, settings) and where things are on screen (the 3D view, each ball, each named widget), so that a test
// clicks where the program says a thing is and asserts on what happened. Written on the script's `dump` command and,
// in an interactive run started with --dump-state PATH, on SIGUSR1.
#pragma once
#include <map>
#include <nlohmann/json.hpp>
#include <string>

#include "ui/camera.hpp"
#include "ui/frame_times.hpp"
#include "ui/lab.hpp"
#include "ui/layout.hpp"

namespace shotlab {

struct ScreenInfo {
  int window_w = 0, window_h = 0;
  Rect view;                               // the 3D view between the panels
  const Viewport* viewport = nullptr;      // for the balls' and the table's screen positions
  const std::map<std::string, Rect>* widgets = nullptr;  // named widget rectangles of the last frame
  const std::map<std::string, double>* readouts = nullptr;  // values the panels showed in the last frame
  float mouse_x = 0, mouse_y = 0;  // where the GUI sees the pointer (pixels; very negative: not over the window)
  double fps = 0;
  double frame_ms = 0;
  long frame = 0;
  const FrameTimes* play_frames = nullptr;  // the frames the last shot played in
};

nlohmann::json state_json(const Lab& lab, const ScreenInfo& screen);
// Writes it atomically (a reader never sees half a file); false when it cannot.
bool write_state(const Lab& lab, const ScreenInfo& screen, const std::string& path);

}  // namespace shotlab
