// shotlab: the desktop shot lab (no subcommand), or a headless command.
#include <cstdlib>
#include <iostream>

#include "app/commands.hpp"
#include "app/paths.hpp"
#include "app/run_command.hpp"
#include "shotlab/io/scene_json.hpp"

namespace {

// No display: the README's run command still does something useful (the break preset headless); a scene or a script
// asked for is checked and the reason the window cannot open is given.
int without_display(const shotlab::GuiOptions& gui) {
  if (gui.scene.empty() && gui.script.empty()) {
    std::cout << "shotlab: no display; running the break preset headless instead of the GUI\n";
    shotlab::RunOptions preset;
    preset.scene = shotlab::preset_path("break.json");
    preset.until_rest = true;
    return shotlab::run_scene(preset);
  }
  if (!gui.scene.empty()) {
    try {
      shotlab::load_scene(gui.scene);
    } catch (const std::exception& e) {
      std::cerr << "shotlab: " << e.what() << "\n";
      return 1;
    }
  }
  std::cerr << "shotlab: cannot open the shot lab window: no display (DISPLAY and WAYLAND_DISPLAY are not set)"
            << (gui.scene.empty() ? "" : "; to simulate the scene headless: shotlab run " + gui.scene) << "\n";
  return 1;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"shotlab: billiard-ball physics shot lab"};
  app.require_subcommand(0, 1);
  shotlab::add_run_command(app);
  shotlab::add_sweep_command(app);
  shotlab::add_margin_command(app);
  shotlab::add_fit_command(app);
  shotlab::add_bench_command(app);
  shotlab::GuiOptions gui;
  shotlab::add_gui_options(app, gui);
  try {
    app.parse(argc, argv);
  } catch (const CLI::RuntimeError& e) {  // a command's own failure, with its exit status (docs: 1 or 3)
    return e.get_exit_code();
  } catch (const CLI::ParseError& e) {    // --help prints and succeeds; any bad argument is bad input: 1
    return app.exit(e) == 0 ? 0 : 1;
  } catch (const std::exception& e) {     // a failure no command caught: say it, never abort
    std::cerr << "shotlab: " << e.what() << "\n";
    return 1;
  }
  if (!app.get_subcommands().empty()) return 0;
  auto set = [](const char* name) { const char* v = std::getenv(name); return v && *v; };
  if (!set("DISPLAY") && !set("WAYLAND_DISPLAY")) return without_display(gui);
  gui.data_root = shotlab::data_root();
  try {
    return shotlab::run_gui(gui);
  } catch (const std::exception& e) {
    std::cerr << "shotlab: " << e.what() << "\n";
    return 1;
  }
}
