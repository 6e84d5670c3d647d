// The C API's cost over the engine called directly (issue 32): the break to rest as a game runs it, one frame of 1/60 s
// at a time with every ball's state read after each frame, through libshotlab.so and through the engine's C++ headers,
// in alternated rounds. Prints the median time of each and their ratio. Run pinned to one core (scripts/throughput.py
// does): capi_overhead SCENE [ROUNDS]; capi_overhead --advance-calls SCENE CALLS DT times single advance calls.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "shotlab.h"
#include "shotlab/io/scene_json.hpp"
#include "shotlab/simulation.hpp"

namespace {

constexpr double kFrame = 1.0 / 60;  // s
constexpr int kFrames = 420;         // 7 s: the break comes to rest

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

// Through the C API; returns the wall time, or -1 on a failure (printed).
double through_c_api(const char* scene, std::vector<double>& buffer) {
  const auto t0 = Clock::now();
  shotlab_sim* sim = nullptr;
  if (shotlab_create_from_file(scene, &sim) != SHOTLAB_OK) {
    std::fprintf(stderr, "capi_overhead: %s\n", shotlab_last_error(sim));
    return -1;
  }
  int n = 0;
  shotlab_ball_count(sim, &n);
  buffer.resize(9 * static_cast<size_t>(n));
  for (int f = 0; f < kFrames; ++f) {
    if (shotlab_advance(sim, kFrame) != SHOTLAB_OK) break;
    shotlab_balls(sim, buffer.data(), buffer.data() + 3 * n, buffer.data() + 6 * n, nullptr, n);
  }
  shotlab_destroy(sim);
  return seconds_since(t0);
}

// The same through the engine's headers.
double direct(const char* scene, std::vector<double>& buffer) {
  const auto t0 = Clock::now();
  shotlab::Prepared p = shotlab::prepare(shotlab::load_scene(scene));
  shotlab::Simulation sim(std::move(p.model), std::move(p.state));
  const int n = sim.state().ball_count();
  buffer.resize(9 * static_cast<size_t>(n));
  for (int f = 0; f < kFrames; ++f) {
    if (sim.advance(kFrame) != shotlab::Status::Ok) break;
    const shotlab::State& s = sim.state();
    for (int i = 0; i < n; ++i)
      for (int k = 0; k < 3; ++k) {
        buffer[3 * i + k] = s.x[shotlab::kBallDofs * i + k];
        buffer[3 * (n + i) + k] = s.x[shotlab::kBallDofs * i + 3 + k];
        buffer[3 * (2 * n + i) + k] = s.x[shotlab::kBallDofs * i + shotlab::kSpinDof + k];
      }
  }
  return seconds_since(t0);
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

}  // namespace

// The cost of one shotlab_advance call on a scene whose balls sleep (the engine has nothing to do): the reference
// for the Python module's per-call overhead.
int advance_calls(const char* scene, long calls, double dt) {
  shotlab_sim* sim = nullptr;
  if (shotlab_create_from_file(scene, &sim) != SHOTLAB_OK) {
    std::fprintf(stderr, "capi_overhead: %s\n", shotlab_last_error(sim));
    return 1;
  }
  shotlab_advance(sim, 1.0);  // to sleep
  const auto t0 = Clock::now();
  for (long k = 0; k < calls; ++k) shotlab_advance(sim, dt);
  std::printf("advance_us %.4f\n", 1e6 * seconds_since(t0) / static_cast<double>(calls));
  shotlab_destroy(sim);
  return 0;
}

int main(int argc, char** argv) {
  if (argc == 5 && std::string(argv[1]) == "--advance-calls") return advance_calls(argv[2], std::atol(argv[3]), std::atof(argv[4]));
  if (argc < 2) {
    std::fprintf(stderr, "usage: capi_overhead SCENE [ROUNDS] | capi_overhead --advance-calls SCENE CALLS DT\n");
    return 1;
  }
  const int rounds = argc > 2 ? std::max(1, std::atoi(argv[2])) : 30;
  std::vector<double> buffer, c_api, engine, ratios;
  through_c_api(argv[1], buffer);  // warm both paths up
  direct(argv[1], buffer);
  for (int r = 0; r < rounds; ++r) {  // alternated, so that a change of clock speed hits both alike
    const double a = r % 2 ? through_c_api(argv[1], buffer) : direct(argv[1], buffer);
    const double b = r % 2 ? direct(argv[1], buffer) : through_c_api(argv[1], buffer);
    if (a < 0 || b < 0) return 1;
    (r % 2 ? c_api : engine).push_back(a);
    (r % 2 ? engine : c_api).push_back(b);
    ratios.push_back(c_api.back() / engine.back());
  }
  std::printf("c_api_ms %.4f\nengine_ms %.4f\nratio %.4f\nrounds %d\n", 1e3 * median(c_api), 1e3 * median(engine),
              median(ratios), rounds);  // ratio: the median of the rounds' ratios
  return 0;
}
