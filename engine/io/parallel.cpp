#include "shotlab/io/parallel.hpp"

#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace shotlab {

void parallel_in_order(size_t begin, size_t end, int jobs, const std::function<void(size_t)>& work,
                       const std::function<void(size_t)>& done, const std::function<void(size_t, size_t)>& progress,
                       const std::atomic<bool>* cancel) {
  if (begin >= end) return;
  const size_t total = end - begin;
  if (jobs <= 0) jobs = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  jobs = static_cast<int>(std::min<size_t>(static_cast<size_t>(jobs), total));
  std::atomic<size_t> next{begin};
  std::atomic<bool> failed{false};
  std::mutex mutex;  // guards what follows
  std::vector<bool> ready(total, false);
  size_t emitted = begin, finished = 0;
  std::exception_ptr error;
  auto stop = [&] {  // under the lock
    if (!error) error = std::current_exception();
    failed = true;
  };
  auto worker = [&] {
    for (size_t i; !failed && !(cancel && *cancel) && (i = next++) < end;) {
      try {
        work(i);
      } catch (...) {
        std::lock_guard lock(mutex);
        stop();
        return;
      }
      std::lock_guard lock(mutex);
      if (failed) return;
      ready[i - begin] = true;
      ++finished;
      try {
        for (; emitted < end && ready[emitted - begin]; ++emitted)
          if (done) done(emitted);
        if (progress) progress(finished, total);
      } catch (...) {
        stop();
      }
    }
  };
  std::vector<std::thread> pool;
  for (int k = 1; k < jobs; ++k) pool.emplace_back(worker);
  worker();
  for (std::thread& t : pool) t.join();
  if (error) std::rethrow_exception(error);
}

}  // namespace shotlab
