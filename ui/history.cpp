#include "ui/history.hpp"

namespace shotlab {

namespace {
HistoryStep entry(const std::string& label, const Scene& scene) {
  HistoryStep e;
  e.label = label;
  e.scene = scene;
  return e;
}
}  // namespace

void History::record(const std::string& label, const Scene& before, const std::string& merge) {
  redo_.clear();
  if (!merge.empty() && merge == open_merge_ && !undo_.empty()) return;
  open_merge_ = merge;
  push(entry(label, before));
}

void History::push(HistoryStep step) {
  undo_.push_back(std::move(step));
  if (undo_.size() > kLimit) undo_.erase(undo_.begin());
}

void History::record_load(const std::string& label, const Scene& before, SceneFile file, bool same_table) {
  seal();
  redo_.clear();
  HistoryStep e = entry(label, before);
  e.file = std::move(file);
  e.same_table = same_table;
  push(std::move(e));
}

void History::record_target(const std::string& label, const Scene& current, const std::optional<Vec3>& before) {
  seal();
  redo_.clear();
  HistoryStep e = entry(label, current);
  e.target = before;
  push(std::move(e));
}

void History::record_kept(const std::string& label, const Scene& current, std::vector<KeptShot> before) {
  seal();
  redo_.clear();
  HistoryStep e = entry(label, current);
  e.kept = std::move(before);
  push(std::move(e));
}

const std::string& History::undo_label() const {
  static const std::string none;
  return undo_.empty() ? none : undo_.back().label;
}

const std::string& History::redo_label() const {
  static const std::string none;
  return redo_.empty() ? none : redo_.back().label;
}

HistoryStep History::take(std::vector<HistoryStep>& from, std::vector<HistoryStep>& to, const Scene& current,
                          const FileOf& current_file, const std::optional<Vec3>& current_target) {
  HistoryStep e = std::move(from.back());
  from.pop_back();
  HistoryStep back = entry(e.label, current);  // the way back: what is on screen now
  if (e.file) back.file = current_file();
  back.same_table = e.same_table;
  if (e.target) back.target = current_target;
  if (e.kept) back.kept = current_file().bench.kept;
  to.push_back(std::move(back));
  return e;
}

HistoryStep History::undo(const Scene& current, const FileOf& current_file, const std::optional<Vec3>& current_target) {
  open_merge_.clear();
  return take(undo_, redo_, current, current_file, current_target);
}

HistoryStep History::redo(const Scene& current, const FileOf& current_file, const std::optional<Vec3>& current_target) {
  open_merge_.clear();
  return take(redo_, undo_, current, current_file, current_target);
}

void History::clear() {
  undo_.clear();
  redo_.clear();
  open_merge_.clear();
}

}  // namespace shotlab
