#include <iostream>

#include "app/commands.hpp"

int shotlab::run_gui(const GuiOptions&) {
  std::cerr << "shotlab: this build has no GUI (configured with -DSHOTLAB_GUI=OFF); use 'shotlab run SCENE.json'\n";
  return 1;
}
