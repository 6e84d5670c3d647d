#include "app/commands.hpp"

namespace shotlab {

void add_gui_options(CLI::App& app, GuiOptions& o) {
  app.add_option("--scene", o.scene, "GUI: scene file to open");
  app.add_option("--script", o.script, "GUI: replay a file of UI actions (see docs/gui-script.md)");
  app.add_option("--dump-state", o.dump_state, "GUI: on SIGUSR1 write the state as JSON here (tests)");
  app.add_option("--width", o.width, "GUI: window width in pixels")->check(CLI::Range(kMinWindow, kMaxWindow));
  app.add_option("--height", o.height, "GUI: window height in pixels")->check(CLI::Range(kMinWindow, kMaxWindow));
}

}  // namespace shotlab
