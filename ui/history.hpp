// One undo stack for everything the user does to the table: ball moves, adds and removals, aim and cue changes, a
// break set up, the practice target, clearing kept shots, shots and Next. Each entry is the scene as it was before
// the action, with a label for the menu. A run of edits of the same kind (dragging the aim, nudging the speed) merges into one entry, so
// that one undo takes back the whole gesture. Tuned physics is not part of it (the tuning panel has its own reset),
// except across a file load: undoing a load brings back the whole scene before it, its file, its tuned physics and
// the lab's workbench.
#pragma once
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "shotlab/scene.hpp"
#include "ui/workbench.hpp"

namespace shotlab {

// The file a scene came from: its path ("" for a scene made in the lab), the scene as it was loaded, and what the
// lab held about it (kept shots, A/B, target, measured shot) when another file replaced it.
struct SceneFile {
  std::string path;
  Scene loaded;
  Workbench bench;
};

// What undo or redo goes back to: the scene, and for a load's entry the file that goes with it.
struct HistoryStep {
  std::string label;
  Scene scene;
  std::optional<SceneFile> file;  // set when the step crosses a file load: physics, path, loaded, bench go back too
  bool same_table = false;        // with `file`: only the position changed (a break set up over another one), so the
                                  // tuned physics and the camera stay
  std::optional<std::optional<Vec3>> target;  // set for a practice target's step: the target then (none: no target)
  std::optional<std::vector<KeptShot>> kept;  // set for a step of the kept shots alone: those kept then
};

class History {
 public:
  // Records `before` (the scene as it was) under `label`. With a non-empty `merge`, a call whose merge key equals
  // the previous call's adds nothing: the entry already holds the scene from before the gesture began.
  void record(const std::string& label, const Scene& before, const std::string& merge = "");
  // Ends the current gesture: the next record() opens a new entry even with the same merge key.
  void seal() { open_merge_.clear(); }
  // Records the scene and file in use before another file was loaded over them.
  void record_load(const std::string& label, const Scene& before, SceneFile file, bool same_table = false);
  // Records the practice target as it was before it was set, moved or cleared (the scene does not change).
  void record_target(const std::string& label, const Scene& current, const std::optional<Vec3>& before);
  // Records the kept shots as they were before they were cleared (the scene does not change).
  void record_kept(const std::string& label, const Scene& current, std::vector<KeptShot> before);

  bool can_undo() const { return !undo_.empty(); }
  bool can_redo() const { return !redo_.empty(); }
  const std::string& undo_label() const;  // "" when there is nothing to undo
  const std::string& redo_label() const;
  size_t size() const { return undo_.size(); }

  // The step to go back to; `current` (and, when the step crosses a load or is one of the kept shots, what
  // `current_file` gives: called only then, since it copies the workbench; for a target's step, `current_target`) is
  // kept for the way back. Call only when
  // can_undo() / can_redo().
  using FileOf = std::function<SceneFile()>;
  HistoryStep undo(const Scene& current, const FileOf& current_file, const std::optional<Vec3>& current_target = {});
  HistoryStep redo(const Scene& current, const FileOf& current_file, const std::optional<Vec3>& current_target = {});
  void clear();
  void drop_redo() { if (!redo_.empty()) redo_.pop_back(); }  // the last undo was a cancel, nothing to redo

 private:
  void push(HistoryStep step);
  static HistoryStep take(std::vector<HistoryStep>& from, std::vector<HistoryStep>& to, const Scene& current,
                          const FileOf& current_file, const std::optional<Vec3>& current_target);
  std::vector<HistoryStep> undo_, redo_;
  std::string open_merge_;
  static constexpr size_t kLimit = 200;  // entries kept; the oldest go first
};

}  // namespace shotlab
