// Files the shot lab writes and browses. Everything it writes goes to a temporary file beside the target (a unique
// name), is flushed to disk, then renamed over the target: a crash or a full disk never leaves half a file, and a
// user's file is only replaced by a complete one.
#pragma once
#include <string>
#include <vector>

namespace shotlab {

// Throws std::runtime_error naming the path and the problem.
void write_file_atomic(const std::string& path, const std::string& content);

// "<dir>/<stem>-<n>.<ext>" with the smallest n >= 1 not taken; `stem` is reduced to letters, digits, '-' and '_'.
std::string unique_path(const std::string& dir, const std::string& stem, const std::string& ext);

struct DirEntry {
  std::string name;  // file or folder name
  bool folder;
};
// Folders, then .json files, by name; hidden entries left out. Empty when the folder cannot be read.
std::vector<DirEntry> list_scene_dir(const std::string& dir);

// Whether `path` lies inside folder `dir` (after resolving both): shipped presets are not overwritten by Save.
bool inside(const std::string& path, const std::string& dir);

}  // namespace shotlab
