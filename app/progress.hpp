// A progress bar on the terminal for commands that run many simulations: "[#####.....] 340/1000 runs, 12 s left",
// redrawn in place at most ten times a second, on stderr and only when it is a terminal.
#pragma once
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <functional>
#include <memory>
#include <string>

namespace shotlab {

inline std::function<void(size_t, size_t)> progress_bar(bool wanted) {
  using Clock = std::chrono::steady_clock;
  if (!wanted || !isatty(STDERR_FILENO)) return {};
  struct Times { Clock::time_point start = Clock::now(), drawn = start - std::chrono::seconds(1); };
  auto t = std::make_shared<Times>();
  return [t](size_t done, size_t total) {
    const auto now = Clock::now();
    if (done < total && now - t->drawn < std::chrono::milliseconds(100)) return;
    t->drawn = now;
    constexpr int kWidth = 30;
    const int filled = static_cast<int>(kWidth * done / std::max<size_t>(1, total));
    const double elapsed = std::chrono::duration<double>(now - t->start).count();
    const double left = done ? elapsed * static_cast<double>(total - done) / static_cast<double>(done) : 0;
    std::fprintf(stderr, "\r[%s%s] %zu/%zu runs, %.0f s left ", std::string(filled, '#').c_str(),
                 std::string(kWidth - filled, '.').c_str(), done, total, left);
    if (done == total) std::fprintf(stderr, "\n");
  };
}

}  // namespace shotlab
