// The pool every many-run program uses (sweeps, shot margins): work(i) for each index on a few threads, then
// done(i) in index order, so that results come out the same whatever the number of threads.
#pragma once
#include <atomic>
#include <cstddef>
#include <functional>

namespace shotlab {

// Calls work(i) for every i in [begin, end) on `jobs` threads (0: one per core; work must only touch what belongs to
// i), and done(i) (may be empty) in index order under a lock as soon as i and every index before it are worked.
// progress(finished, total) after each index. No index starts once *cancel is set. An exception from work or done
// stops the pool and is rethrown here.
void parallel_in_order(size_t begin, size_t end, int jobs, const std::function<void(size_t)>& work,
                       const std::function<void(size_t)>& done = {},
                       const std::function<void(size_t, size_t)>& progress = {},
                       const std::atomic<bool>* cancel = nullptr);

}  // namespace shotlab
