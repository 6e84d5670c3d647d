// Sweeps (shotlab/io/sweep.hpp): plans from --vary options, rows that match single runs, row order whatever the
// threads, failures as rows. Runs under the sanitizers with the rest of the engine tests (the pool's threads included).
#include <algorithm>
#include <fstream>
#include <sstream>

#include "shotlab/io/run.hpp"
#include "shotlab/io/sweep.hpp"
#include "support.hpp"

namespace shotlab::test {
namespace {

std::string text_of(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// The row's fields, quotes removed (no field in these tests holds a quote itself).
std::vector<std::string> fields(const std::string& line) {
  std::vector<std::string> out(1);
  bool quoted = false;
  for (char c : line)
    if (c == '"') quoted = !quoted;
    else if (c == ',' && !quoted) out.emplace_back();
    else if (c != '\n') out.back() += c;
  return out;
}

SweepPlan plan(const std::vector<std::string>& vary, size_t samples = 0, uint64_t seed = 1) {
  std::vector<SweepAxis> axes;
  for (const std::string& v : vary) axes.push_back(parse_sweep_axis(v));
  return plan_sweep(axes, samples, seed);
}

std::vector<std::string> run_all(const Sweep& sweep, int jobs) {
  std::vector<std::string> rows;
  sweep.run(0, sweep.size(), jobs, [&](size_t i, const std::string& line) {
    EXPECT_EQ(i, rows.size());  // handed on in row order
    rows.push_back(line);
  });
  return rows;
}

TEST(SweepPlan, GridVariesTheFirstPathSlowestAndKeepsRangeEnds) {
  const SweepPlan p = plan({"cue.speed=0.1:0.3:3", "balls.cue.velocity=[1,0,0],[0,0,1]"});
  ASSERT_EQ(p.rows.size(), 6u);
  EXPECT_EQ(p.rows[0], (std::vector<std::string>{"0.1", "[1,0,0]"}));
  EXPECT_EQ(p.rows[1], (std::vector<std::string>{"0.1", "[0,0,1]"}));
  EXPECT_EQ(p.rows[2][0], "0.2");
  EXPECT_EQ(p.rows[5][0], "0.3");  // the end exactly, not 0.1 + 2 * 0.1
  EXPECT_EQ(plan({"a=[1,2,3]"}).rows.size(), 3u);  // one JSON array: its elements
  EXPECT_EQ(plan({"integrator.method=rk4,dopri5"}).rows[1][0], "dopri5");
  // The values a developer typed the range for, not their arithmetic's (0.3 / 6 = 0.049999999999999996).
  const SweepPlan fine = plan({"f=0:0.3:7"});
  EXPECT_EQ(fine.rows[1][0], "0.05");
  EXPECT_EQ(fine.rows[2][0], "0.1");
  EXPECT_EQ(fine.rows[4][0], "0.2");
  EXPECT_EQ(plan({"f=-0.2:0.4:4"}).rows[1][0], "0");  // not the 2.8e-17 of the arithmetic
  EXPECT_EQ(plan({"f=-0.1:0.5:7"}).rows[1][0], "0");
  EXPECT_EQ(plan({"f=0.1234567890123456:1:3"}).rows[0][0], "0.1234567890123456");  // the ends as typed
  EXPECT_EQ(plan({"f=0.1:0.1:1"}).rows.size(), 1u);  // one value where lo is hi
}

// A run to rest without a duration of its own goes past a scene's shorter one: the cut preset's 4 s end with the cue
// ball still rolling; it rests at 5.8 s.
TEST(RunDuration, ToRestItGoesPastAShortSceneDuration) {
  const Scene cut = load_scene(preset("cut.json"));
  ASSERT_LT(cut.duration, 5.0);
  EXPECT_EQ(run_duration(cut, std::nullopt, false), cut.duration);
  EXPECT_EQ(run_duration(cut, 2.5, true), 2.5);
  HeadlessRun run = start_run(cut);
  advance_run(*run.sim, run_duration(cut, std::nullopt, true), 60, true);
  EXPECT_TRUE(run.sim->at_rest());
  EXPECT_GT(run.sim->time(), cut.duration);
  EXPECT_LT(run.sim->time(), 10.0);
}

TEST(SweepPlan, RandomSamplesAreFixedBySeedAndInsideTheirRanges) {
  const SweepPlan a = plan({"x=2:3", "y=p,q"}, 200, 42), b = plan({"x=2:3", "y=p,q"}, 200, 42);
  EXPECT_EQ(a.rows, b.rows);
  EXPECT_NE(a.rows, plan({"x=2:3", "y=p,q"}, 200, 43).rows);
  int p = 0;
  for (const auto& r : a.rows) {
    const double x = std::stod(r[0]);
    EXPECT_TRUE(x >= 2 && x < 3) << x;
    p += r[1] == "p";
  }
  EXPECT_GT(p, 70);  // both values drawn (binomial(200, 1/2): 70 is 4 sigma below)
  EXPECT_LT(p, 130);
}

TEST(SweepPlan, BadOptionsNameTheOptionAndTheProblem) {
  auto message = [](const std::vector<std::string>& vary, size_t samples = 0) {
    try {
      plan(vary, samples);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message({"cue.speed"}).find("expected PATH=VALUES"), std::string::npos);
  EXPECT_NE(message({"cue.speed="}).find("no values"), std::string::npos);
  EXPECT_NE(message({"cue.speed=1,,2"}).find("empty value"), std::string::npos);
  EXPECT_NE(message({"cue.speed=1:x:3"}).find("numbers lo and hi"), std::string::npos);
  EXPECT_NE(message({"cue.speed=1:2:0"}).find("count n"), std::string::npos);
  EXPECT_NE(message({"cue.speed=1:2"}).find("lo:hi:n"), std::string::npos);
  EXPECT_NE(message({"cue.speed=0.1:0.3:1"}).find("one value"), std::string::npos);
  EXPECT_NE(message({"a=0:1:10000", "b=0:1:10000"}).find("more than"), std::string::npos);
  EXPECT_NE(message({}).find("no path"), std::string::npos);
  EXPECT_EQ(message({"cue.speed=1:2"}, 5), "no error");
}

// A row holds what a single run of the same scene with the same overrides ends with.
TEST(Sweep, RowsMatchSingleRunsAndDoNotDependOnThreads) {
  const Sweep sweep(text_of(preset("cut.json")), "cut.json", plan({"cue.speed=1.5,2,2.5", "cue.aim_deg=-75.5,-75"}), {});
  const std::vector<std::string> one = run_all(sweep, 1), three = run_all(sweep, 3);
  ASSERT_EQ(one.size(), 6u);
  const std::vector<std::string> head = fields(sweep.header());
  const auto col = [&](const std::string& name) { return std::find(head.begin(), head.end(), name) - head.begin(); };
  for (size_t i = 0; i < one.size(); ++i) {
    std::vector<std::string> a = fields(one[i]), b = fields(three[i]);
    ASSERT_EQ(a.size(), head.size());
    a[col("wall_seconds")] = b[col("wall_seconds")] = "";
    EXPECT_EQ(a, b);
  }
  const std::vector<std::string> pot = fields(one[3]);  // 2 m/s at -75 degrees: the preset's shot
  EXPECT_EQ(pot[col("status")], "ok");
  EXPECT_EQ(pot[col("pocketed")], "1@pocket-right-front");
  EXPECT_EQ(pot[col("first_ball")], "1");
  EXPECT_EQ(pot[col("1.motion")], "pocketed");

  HeadlessRun single = start_run(load_scene(preset("cut.json"), {"cue.speed=2", "cue.aim_deg=-75"}));
  advance_run(*single.sim, kRestLimit, 60, true);  // to rest past the preset's 4 s, at the sweep's sampling
  EXPECT_TRUE(single.sim->at_rest());
  const Vec3 cue = position(single.sim->state().x, 0);
  EXPECT_EQ(std::stod(pot[col("cue.x")]), cue.x);
  EXPECT_EQ(std::stod(pot[col("cue.z")]), cue.z);
  EXPECT_EQ(std::stod(pot[col("time")]), single.sim->time());
  EXPECT_EQ(std::stoul(pot[col("events")]), single.sim->events().size());
}

TEST(Sweep, AFailedRunIsARowAndTheSweepGoesOn) {
  SweepSettings bounded;
  bounded.limits = {60, 30, {}};
  const Sweep sweep(text_of(preset("cut.json")), "cut.json", plan({"cue.speed=2,-1,zz"}), {});
  const std::vector<std::string> rows = run_all(sweep, 2);
  EXPECT_EQ(fields(rows[0])[2], "ok");
  EXPECT_EQ(fields(rows[1])[2], "error");
  EXPECT_NE(rows[1].find("cue.speed: must be positive"), std::string::npos) << rows[1];
  EXPECT_EQ(fields(rows[1]).size(), fields(sweep.header()).size());
  EXPECT_EQ(sweep.status(rows[2]), "error");
  const Sweep capped(text_of(preset("break.json")), "break.json", plan({"cue.speed=8"}), bounded);
  const std::string row = capped.row(0);
  EXPECT_EQ(capped.status(row), "limit");
  EXPECT_NE(row.find("more than 30 events"), std::string::npos) << row;
}

TEST(Sweep, ABrokenSceneOrAFailingWriterStopsWithAMessage) {
  EXPECT_THROW(Sweep("{\"balls\": 3}", "bad.json", plan({"cue.speed=1"}), {}), InputError);
  SweepSettings too_long;
  too_long.duration = 1e9;
  EXPECT_THROW(Sweep(text_of(preset("cut.json")), "cut.json", plan({"cue.speed=1"}), too_long), InputError);
  // A misspelt path would fail every row alike: refused before the first run, naming the option and the field.
  try {
    Sweep(text_of(preset("cut.json")), "cut.json", plan({"cue.speed=1", "materials.ball_ball.fricton=0:0.3:2"}), {});
    ADD_FAILURE() << "a misspelt path was taken";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("--vary materials.ball_ball.fricton: cut.json: materials.ball_ball.fricton: "
                                         "unknown field (did you mean 'friction'?)"), std::string::npos) << e.what();
  }
  // A value that brings its own unknown field is that row's error, not the path's.
  const Sweep odd(text_of(preset("cut.json")), "cut.json", plan({R"(materials.ball_ball=[{"sped":2}])"}), {});
  EXPECT_EQ(odd.status(odd.row(0)), "error");
  const Sweep sweep(text_of(preset("cut.json")), "cut.json", plan({"cue.speed=1:2:6"}), {});
  EXPECT_THROW(sweep.run(0, 6, 2, [](size_t i, const std::string&) {
    if (i == 2) throw InputError("out.csv: disk full");
  }), InputError);
  std::atomic<bool> cancel{true};
  size_t rows = 0;
  sweep.run(0, 6, 2, [&](size_t, const std::string&) { ++rows; }, {}, &cancel);
  EXPECT_EQ(rows, 0u);
}

}  // namespace
}  // namespace shotlab::test
