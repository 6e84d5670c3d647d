// Each command of the program registers its own subcommand (Box2D-samples style registry): main.cpp only lists
// them. A command reports failure by throwing CLI::RuntimeError(exit_code).
#pragma once
#include <CLI/CLI.hpp>
#include <string>

#include "ui/gui.hpp"

namespace shotlab {

void add_run_command(CLI::App& app);    // run_command.cpp
void add_sweep_command(CLI::App& app);  // sweep_command.cpp
void add_margin_command(CLI::App& app); // margin_command.cpp
void add_fit_command(CLI::App& app);    // fit_command.cpp
void add_bench_command(CLI::App& app);  // bench/command.cpp

// A count or seed given as a whole number >= 0: CLI11 would read "-5" into an unsigned number as a huge one.
inline const CLI::Validator kNotNegative(
    [](std::string& text) { return text.find('-') != std::string::npos ? std::string("must be 0 or more") : std::string(); },
    "NOT NEGATIVE");

// The GUI's options (ui/gui.hpp) on the command line; run_gui is ui/'s, or no_gui.cpp's in builds without a GUI.
void add_gui_options(CLI::App& app, GuiOptions& options);

}  // namespace shotlab
