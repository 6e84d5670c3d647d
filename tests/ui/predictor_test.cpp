// The predicted paths' worker (ui/predictor.hpp): a finished prediction runs to rest; a long one hands out its paths
// so far while the window waits, each a beginning of the finished paths; a superseded request never shows; a scene
// named as likely next is predicted meanwhile, and asking for it is answered at once with what a fresh run gives.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <thread>

#include "shotlab/io/scene_json.hpp"
#include "tests/engine/support.hpp"
#include "ui/predictor.hpp"

namespace shotlab {
namespace {

constexpr double kLimit = 60;     // s simulated, the shot lab's default safety limit
constexpr double kPatience = 30;  // s of wall time any wait here may take (a slow or sanitized build)

// Waits for request `generation` to finish, in waits of `slice` seconds as the window's frames make them; every
// prediction seen on the way (finished or not) goes to `seen`.
Prediction finish(const Predictor& p, long generation, double slice, std::vector<Prediction>* seen = nullptr) {
  const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(kPatience);
  while (!p.wait_for(generation, slice) && std::chrono::steady_clock::now() < end)
    if (const auto now = p.latest(); seen && now) seen->push_back(*now);
  const auto done = p.latest();
  EXPECT_TRUE(done && done->complete && done->generation == generation) << "request " << generation << " finished";
  return done ? *done : Prediction{};
}

// The cut preset's cue ball stops: its finished path ends where it rests, and the prediction says it is finished.
TEST(Predictor, AFinishedPredictionRunsToRest) {
  Predictor p;
  const long g = p.request(load_scene(test::preset("cut.json")), kLimit);
  const Prediction done = finish(p, g, kPatience);
  EXPECT_TRUE(done.problem.empty()) << done.problem;
  EXPECT_GT(done.simulated, 1.0);
  EXPECT_LT(done.simulated, kLimit);
  ASSERT_FALSE(done.paths.empty());
  EXPECT_GT(done.paths[0].size(), 10u);
  EXPECT_FALSE(p.busy());
  EXPECT_EQ(p.wall_seconds(g), done.wall_seconds);
}

// While the window waits a millisecond at a time, the break hands out its paths so far: not finished, some covering part
// of the shot, and each ball's path so far is the start of its finished path, point for point.
TEST(Predictor, ABreakHandsOutItsPathsSoFarWhileTheWindowWaits) {
  Predictor p;
  const long g = p.request(load_scene(test::preset("break.json")), kLimit);
  std::vector<Prediction> seen;
  const Prediction done = finish(p, g, 1e-3, &seen);
  size_t partial = 0;
  for (const Prediction& s : seen) {
    ASSERT_EQ(s.generation, g);
    if (s.complete) continue;
    // A snapshot taken after the last step, before the worker marks it finished, already covers the whole shot.
    EXPECT_LE(s.simulated, done.simulated);
    if (s.simulated < done.simulated) ++partial;
    ASSERT_EQ(s.paths.size(), done.paths.size());
    for (size_t b = 0; b < s.paths.size(); ++b) {
      ASSERT_LE(s.paths[b].size(), done.paths[b].size());
      for (size_t k = 0; k < s.paths[b].size(); ++k) ASSERT_EQ(s.paths[b][k].position, done.paths[b][k].position);
    }
  }
  EXPECT_GT(partial, 0u) << "paths so far seen while the break was predicted";
}

// A request made while another runs supersedes it: the older one's paths, finished or so far, never come out after it.
TEST(Predictor, ASupersededRequestNeverShows) {
  Predictor p;
  const long first = p.request(load_scene(test::preset("break.json")), kLimit);
  const long second = p.request(load_scene(test::preset("cut.json")), kLimit);
  ASSERT_GT(second, first);
  finish(p, second, kPatience);
  std::this_thread::sleep_for(std::chrono::milliseconds(50));  // time for the break's worker to hand anything out
  EXPECT_EQ(p.latest()->generation, second);
}

// The break with the aim turned by an aim key press (0.1 degree) is named as likely next: once the break is finished the
// worker predicts it unasked, and the request for it is answered before it returns, finished, point for point what a
// worker of its own predicts. The break's own prediction stays kept too: turning back is answered at once as well.
TEST(Predictor, ALikelyNextAimIsPredictedBeforeItIsAskedFor) {
  const Scene now = load_scene(test::preset("break.json"));
  Scene next = now;
  next.cue->aim += 0.1 * M_PI / 180;
  Predictor p;
  finish(p, p.request(now, kLimit, {next}), kPatience);
  const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(kPatience);
  while (!p.kept(next, kLimit) && std::chrono::steady_clock::now() < end)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  ASSERT_TRUE(p.kept(next, kLimit)) << "the likely next aim predicted while nothing else waited";
  const long asked = p.request(next, kLimit);
  EXPECT_FALSE(p.busy());
  const auto answer = p.latest();
  ASSERT_TRUE(answer && answer->generation == asked && answer->complete);

  Predictor fresh;
  const Prediction alone = finish(fresh, fresh.request(next, kLimit), kPatience);
  ASSERT_EQ(answer->paths.size(), alone.paths.size());
  for (size_t b = 0; b < alone.paths.size(); ++b) {
    ASSERT_EQ(answer->paths[b].size(), alone.paths[b].size());
    for (size_t k = 0; k < alone.paths[b].size(); ++k) ASSERT_EQ(answer->paths[b][k].position, alone.paths[b][k].position);
  }
  EXPECT_NE(answer->paths[0].back().position, finish(fresh, fresh.request(now, kLimit), kPatience).paths[0].back().position)
      << "the turned aim sends the cue ball elsewhere";
  EXPECT_TRUE(p.kept(now, kLimit));
  const long back = p.request(now, kLimit);
  EXPECT_TRUE(p.wait_for(back, 0.0));
}

}  // namespace
}  // namespace shotlab
