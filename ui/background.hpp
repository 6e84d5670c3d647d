// One job at a time on its own thread, for work the window must not wait for (shot margins): a newer job cancels
// the running one, whose result is dropped. The job reports progress and checks the cancel flag between its runs.
// The thread runs at a lower priority (nice 10, inherited by the threads a job starts), so that a job on every core
// leaves the window its frames.
#pragma once
#include <sys/resource.h>
#include <unistd.h>

#include <atomic>
#include <condition_variable>
#include <functional>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

namespace shotlab {

template <class Result>
class Background {
 public:
  using Progress = std::function<void(size_t, size_t)>;
  using Job = std::function<Result(const Progress&, const std::atomic<bool>& cancel)>;

  Background() : thread_([this] { loop(); }) {}
  ~Background() {
    {
      std::lock_guard lock(mutex_);
      quit_ = true;
      cancel_ = true;
    }
    wake_.notify_one();
    thread_.join();
  }
  Background(const Background&) = delete;
  Background& operator=(const Background&) = delete;

  void start(Job job) {  // cancels the running job; this one runs next
    std::lock_guard lock(mutex_);
    pending_ = std::move(job);
    cancel_ = true;
    busy_ = true;
    wake_.notify_one();
  }
  void cancel() {
    std::lock_guard lock(mutex_);
    pending_.reset();
    cancel_ = true;
  }
  bool busy() const { return busy_; }
  double progress() const { return total_ ? static_cast<double>(done_) / static_cast<double>(total_) : 0.0; }
  std::optional<Result> result() const {  // the last job that finished uncancelled
    std::lock_guard lock(mutex_);
    return result_;
  }
  size_t finished() const { return finished_; }  // jobs that finished uncancelled: a new result when it grows
  std::string error() const {  // why the last job failed (an exception's message), empty if it did not
    std::lock_guard lock(mutex_);
    return error_;
  }
  void clear() {
    std::lock_guard lock(mutex_);
    result_.reset();
    error_.clear();
  }

 private:
  void loop() {
    setpriority(PRIO_PROCESS, static_cast<id_t>(gettid()), 10);  // Linux: per thread; a refusal only costs frames
    for (;;) {
      Job job;
      {
        std::unique_lock lock(mutex_);
        wake_.wait(lock, [&] { return quit_ || pending_; });
        if (quit_) return;
        job = std::move(*pending_);
        pending_.reset();
        cancel_ = false;
        done_ = 0, total_ = 0;
      }
      std::optional<Result> r;
      std::string error;
      try {
        r = job([this](size_t done, size_t total) { done_ = done, total_ = total; }, cancel_);
      } catch (const std::exception& e) {
        error = e.what();
      }
      std::lock_guard lock(mutex_);
      if (!cancel_) result_ = std::move(r), error_ = error, ++finished_;
      busy_ = pending_.has_value();
    }
  }

  mutable std::mutex mutex_;
  std::condition_variable wake_;
  std::optional<Job> pending_;
  std::optional<Result> result_;
  std::string error_;
  std::atomic<bool> cancel_{false}, busy_{false};
  std::atomic<size_t> done_{0}, total_{0}, finished_{0};
  bool quit_ = false;
  std::thread thread_;  // last: started once everything above is built
};

}  // namespace shotlab
