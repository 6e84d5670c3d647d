// Each command of the program registers its own subcommand (Box2D-samples style registry): main.cpp only lists
// them. A command reports failure by throwing CLI::RuntimeError(exit_code).
#pragma once
#include <CLI/CLI.hpp>
#include <string>

namespace shotlab {

void add_run_command(CLI::App& app);    // run_command.cpp
void add_bench_command(CLI::App& app);  // bench_command.cpp

// Options of the GUI, the program's default mode (no subcommand).
struct GuiOptions {
  std::string scene;   // scene file to open, empty: the default preset
  std::string script;  // file of UI actions to replay (tests, demos), empty: interactive
  int width = 1280, height = 720;
};
void add_gui_options(CLI::App& app, GuiOptions& options);
int run_gui(const GuiOptions& options);  // ui/, or no_gui.cpp in builds without a GUI

}  // namespace shotlab
