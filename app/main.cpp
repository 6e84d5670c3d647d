// shotlab: the desktop shot lab (no subcommand), or a headless command.
#include <cstdlib>
#include <iostream>

#include "app/commands.hpp"
#include "app/paths.hpp"
#include "app/run_command.hpp"

int main(int argc, char** argv) {
  CLI::App app{"shotlab: billiard-ball physics shot lab"};
  app.require_subcommand(0, 1);
  shotlab::add_run_command(app);
  shotlab::add_bench_command(app);
  shotlab::GuiOptions gui;
  shotlab::add_gui_options(app, gui);
  CLI11_PARSE(app, argc, argv);
  if (!app.get_subcommands().empty()) return 0;

  // No subcommand: the GUI when there is a display, else a headless run of the break preset.
  if (!std::getenv("DISPLAY") && !std::getenv("WAYLAND_DISPLAY")) {
    std::cout << "shotlab: no display; running the break preset headless instead of the GUI\n";
    shotlab::RunOptions preset;
    preset.scene = shotlab::preset_path("break.json");
    preset.until_rest = true;
    return shotlab::run_scene(preset);
  }
  gui.data_root = shotlab::data_root();
  return shotlab::run_gui(gui);
}
