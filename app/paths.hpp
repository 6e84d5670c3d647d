// Where the program finds its presets and assets: next to the source tree it was built from, or as given by
// SHOTLAB_HOME.
#pragma once
#include <cstdlib>
#include <string>

namespace shotlab {

inline std::string data_root() {
  if (const char* home = std::getenv("SHOTLAB_HOME")) return home;
  return SHOTLAB_SOURCE_DIR;
}
inline std::string preset_path(const std::string& name) { return data_root() + "/presets/" + name; }
inline std::string asset_path(const std::string& name) { return data_root() + "/assets/" + name; }

}  // namespace shotlab
