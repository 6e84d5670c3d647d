// The desktop shot lab's entry point and its options (the command line fills them; app/ only wires them).
#pragma once
#include <string>

namespace shotlab {

struct GuiOptions {
  std::string scene;       // scene file to open, empty: the last one, else the break preset
  std::string script;      // file of UI actions to replay (tests, demos), empty: interactive
  std::string dump_state;  // where SIGUSR1 writes the state as JSON (tests driving real input), empty: off
  std::string data_root;   // folder holding presets/ and assets/
  int width = 1280, height = 720;  // window size, pixels
};

inline constexpr int kMinWindow = 320, kMaxWindow = 16384;  // pixels, each side

// Runs the window until it is closed; returns the exit code (a script's failures give 1).
int run_gui(const GuiOptions& options);

}  // namespace shotlab
