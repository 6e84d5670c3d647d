#include <iostream>

#include "app/paths.hpp"

int shotlab::run_gui(int, char**) {
  std::cerr << "shotlab: this build has no GUI (configured with -DSHOTLAB_GUI=OFF); use 'shotlab run SCENE.json'\n";
  return 1;
}
