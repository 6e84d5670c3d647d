#include "ui/history.hpp"

namespace shotlab {

void History::record(const std::string& label, const Scene& before, const std::string& merge) {
  redo_.clear();
  if (!merge.empty() && merge == open_merge_ && !undo_.empty()) return;
  open_merge_ = merge;
  undo_.push_back({label, before});
  if (undo_.size() > kLimit) undo_.erase(undo_.begin());
}

const std::string& History::undo_label() const {
  static const std::string none;
  return undo_.empty() ? none : undo_.back().label;
}

const std::string& History::redo_label() const {
  static const std::string none;
  return redo_.empty() ? none : redo_.back().label;
}

Scene History::undo(const Scene& current) {
  Entry e = std::move(undo_.back());
  undo_.pop_back();
  redo_.push_back({e.label, current});
  open_merge_.clear();
  return std::move(e.scene);
}

Scene History::redo(const Scene& current) {
  Entry e = std::move(redo_.back());
  redo_.pop_back();
  undo_.push_back({e.label, current});
  open_merge_.clear();
  return std::move(e.scene);
}

void History::clear() {
  undo_.clear();
  redo_.clear();
  open_merge_.clear();
}

}  // namespace shotlab
