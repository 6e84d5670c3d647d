// Files the shot lab writes and browses. Everything it writes is written atomically (engine/include/shotlab/io/atomic_file.hpp).
#pragma once
#include <string>
#include <vector>

#include "shotlab/io/atomic_file.hpp"

namespace shotlab {


// "<dir>/<stem>-<n>.<ext>" with the smallest n >= 1 not taken; `stem` is reduced to letters, digits, '-' and '_'.
std::string unique_path(const std::string& dir, const std::string& stem, const std::string& ext);

struct DirEntry {
  std::string name;  // file or folder name
  bool folder;
};
// Folders, then .json (scenes) and .csv (measured shots) files, by name; hidden entries left out. Empty when the
// folder cannot be read.
std::vector<DirEntry> list_scene_dir(const std::string& dir);

// The folder a file dialog starts in: the folder of the newest of `recent` outside `presets_dir` that still exists,
// else the home folder, else the working folder.
std::string user_folder(const std::vector<std::string>& recent, const std::string& presets_dir);

// The user's home folder: $HOME, else the account's (HOME unset); "" when neither is known.
std::string home_folder();

// A path the user typed in a file dialog showing folder `dir`: a relative one is taken inside `dir` (not the working
// folder, which the user does not see), "~" is the home folder; surrounding spaces are dropped.
std::string typed_path(const std::string& typed, const std::string& dir);

// The scene file Save as writes for a typed path (typed_path): ".json" added to a name without an extension, so that
// the file browser, which lists .json scenes, shows it.
std::string scene_file_path(const std::string& typed, const std::string& dir);

// Whether `path` lies inside folder `dir` (after resolving both): shipped presets are not overwritten by Save.
bool inside(const std::string& path, const std::string& dir);

}  // namespace shotlab
