// One undo stack for everything the user does to the table: ball moves, adds and removals, aim and cue changes, a
// break set up, and shots. Each entry is the scene as it was before the action, with a label for the menu. A run of
// edits of the same kind (dragging the aim, nudging the speed) merges into one entry, so that one undo takes back
// the whole gesture. Tuned physics is not part of it (the tuning panel has its own reset).
#pragma once
#include <string>
#include <vector>

#include "shotlab/scene.hpp"

namespace shotlab {

class History {
 public:
  // Records `before` (the scene as it was) under `label`. With a non-empty `merge`, a call whose merge key equals
  // the previous call's adds nothing: the entry already holds the scene from before the gesture began.
  void record(const std::string& label, const Scene& before, const std::string& merge = "");
  // Ends the current gesture: the next record() opens a new entry even with the same merge key.
  void seal() { open_merge_.clear(); }

  bool can_undo() const { return !undo_.empty(); }
  bool can_redo() const { return !redo_.empty(); }
  const std::string& undo_label() const;  // "" when there is nothing to undo
  const std::string& redo_label() const;
  size_t size() const { return undo_.size(); }

  // The scene to go back to; `current` is kept for redo. Call only when can_undo() / can_redo().
  Scene undo(const Scene& current);
  Scene redo(const Scene& current);
  void clear();

 private:
  struct Entry {
    std::string label;
    Scene scene;
  };
  std::vector<Entry> undo_, redo_;
  std::string open_merge_;
  static constexpr size_t kLimit = 200;  // entries kept; the oldest go first
};

}  // namespace shotlab
