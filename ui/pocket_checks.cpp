#include "ui/pocket_checks.hpp"

#include <chrono>

#include "shotlab/io/scene_json.hpp"

namespace shotlab {

std::string PocketChecks::key_of(const Scene& scene, int object) {
  Scene s = scene;
  if (s.cue) s.cue->aim = 0;
  return scene_to_json(s).dump() + "|" + std::to_string(object);
}

void PocketChecks::request(const std::string& key, const Scene& scene, const std::vector<Pocket>& pockets, int cue,
                           int object) {
  collect();
  if (kept(key) || (running_.valid() && running_key_ == key)) return;
  Job job{key, scene, pockets, cue, object};
  if (running_.valid()) queued_ = std::move(job);
  else start(std::move(job));
}

void PocketChecks::start(Job job) {
  running_key_ = job.key;
  running_ = std::async(std::launch::async, [job = std::move(job)] {
    std::vector<PocketAim> aims = pocket_aims(job.scene, job.pockets, job.cue, job.object);
    try {
      check_drops(job.scene, job.object, aims);
    } catch (const std::exception&) {  // no thread for a pocket's shot, no memory: the answer says none drops
      for (PocketAim& a : aims) a.drops = false;
    }
    return aims;
  });
}

void PocketChecks::collect() {
  if (!running_.valid() || running_.wait_for(std::chrono::seconds(0)) != std::future_status::ready) return;
  kept_.emplace_back(running_key_, running_.get());
  if (kept_.size() > kKept) kept_.erase(kept_.begin());
  running_key_.clear();
  if (queued_) {
    Job next = std::move(*queued_);
    queued_.reset();
    if (!kept(next.key)) start(std::move(next));
  }
}

const std::vector<PocketAim>* PocketChecks::kept(const std::string& key) const {
  for (const auto& [k, aims] : kept_)
    if (k == key) return &aims;
  return nullptr;
}

std::optional<std::vector<PocketAim>> PocketChecks::answer(const std::string& key) {
  collect();
  if (const auto* aims = kept(key)) return *aims;
  return std::nullopt;
}

bool PocketChecks::wait(const std::string& key, double seconds) {
  const auto until = std::chrono::steady_clock::now() + std::chrono::duration<double>(std::max(seconds, 0.0));
  for (;;) {
    if (answer(key)) return true;
    if (!running_.valid()) return false;  // nothing under way can bring it
    if (seconds < 0) running_.wait();
    else if (running_.wait_until(until) != std::future_status::ready) return false;
  }
}

void PocketChecks::poll() { collect(); }

}  // namespace shotlab
