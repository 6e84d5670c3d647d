#include "ui/history.hpp"

namespace shotlab {

void History::record(const std::string& label, const Scene& before, const std::string& merge) {
  redo_.clear();
  if (!merge.empty() && merge == open_merge_ && !undo_.empty()) return;
  open_merge_ = merge;
  push({label, before, std::nullopt});
}

void History::push(HistoryStep step) {
  undo_.push_back(std::move(step));
  if (undo_.size() > kLimit) undo_.erase(undo_.begin());
}

void History::record_load(const std::string& label, const Scene& before, SceneFile file, bool same_table) {
  seal();
  redo_.clear();
  push({label, before, std::move(file), same_table});
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
                          const FileOf& current_file) {
  HistoryStep e = std::move(from.back());
  from.pop_back();
  to.push_back({e.label, current, e.file ? std::optional<SceneFile>(current_file()) : std::nullopt, e.same_table});
  return e;
}

HistoryStep History::undo(const Scene& current, const FileOf& current_file) {
  open_merge_.clear();
  return take(undo_, redo_, current, current_file);
}

HistoryStep History::redo(const Scene& current, const FileOf& current_file) {
  open_merge_.clear();
  return take(redo_, undo_, current, current_file);
}

void History::clear() {
  undo_.clear();
  redo_.clear();
  open_merge_.clear();
}

}  // namespace shotlab
