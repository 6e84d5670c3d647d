// Every input path refuses what it cannot use with a message naming the file or option, the field and the problem,
// and never crashes, never runs without end and never reports success for a run that did nothing (issue 29).
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "support.hpp"

namespace shotlab::test {
namespace {

namespace fs = std::filesystem;

fs::path scratch() {
  static const fs::path dir = [] {
    fs::path d = fs::temp_directory_path() / ("shotlab_hardening_" + std::to_string(getpid()));
    fs::create_directories(d);
    return d;
  }();
  return dir;
}

std::string write(const std::string& name, const std::string& text) {
  const fs::path p = scratch() / name;
  std::ofstream(p, std::ios::binary) << text;
  return p.string();
}

std::string load_error(const std::string& path, const std::vector<std::string>& overrides = {}) {
  try {
    load_scene(path, overrides);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

// Exit status, stderr. `env` goes before the command (e.g. "DISPLAY= ").
int cli(const std::string& args, std::string& err, const std::string& env = "") {
  const std::string err_file = (scratch() / "err.txt").string();
  const int status = std::system((env + std::string(SHOTLAB_BIN) + " " + args + " > /dev/null 2> " + err_file).c_str());
  std::ifstream in(err_file);
  std::stringstream text;
  text << in.rdbuf();
  err = text.str();
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

std::string nested(int levels, const std::string& inner) {
  return std::string(levels, '[') + inner + std::string(levels, ']');
}

TEST(Hardening, DeepNestingIsRefusedNotCrashed) {
  const std::string deep = "{\"integrator\": {\"max_steps_per_call\": " + nested(60000, "1") + "}}";
  const std::string err = load_error(write("deep.json", deep));
  EXPECT_NE(err.find("nested deeper than 64 levels"), std::string::npos) << err.substr(0, 200);
  std::string rack = "{\"rack\": {\"rows\": ";
  for (int k = 0; k < 100000; ++k) rack += "{\"a\": ";
  rack += "1" + std::string(100000, '}') + "}}";
  EXPECT_NE(load_error(write("deep_rack.json", rack)).find("nested deeper"), std::string::npos);
  EXPECT_NE(load_error(preset("sliding_to_rolling.json"), {"duration=" + nested(60000, "1")}).find("nested deeper"),
            std::string::npos);
}

TEST(Hardening, MessagesQuoteValuesShortly) {
  std::string list = "[";
  for (int k = 0; k < 20000; ++k) {
    if (k) list += ',';
    list += std::to_string(k);
  }
  list += "]";
  const std::string err = load_error(write("long.json", "{\"integrator\": {\"max_steps_per_call\": " + list + "}}"));
  EXPECT_NE(err.find("integrator.max_steps_per_call: must be an integer, got an array of 20000"), std::string::npos)
      << err.substr(0, 300);
  EXPECT_LT(err.size(), 300u);
}

TEST(Hardening, DuplicateKeysAndOversizedFilesAreRefused) {
  EXPECT_NE(load_error(write("dup.json", R"({"duration": -5, "duration": 1})")).find("\"duration\" is given twice"),
            std::string::npos);
  EXPECT_NE(load_error("/dev/zero").find("larger than 16 MiB"), std::string::npos);
  EXPECT_NE(load_error(scratch().string()).find("is a folder"), std::string::npos);
  EXPECT_NE(load_error(write("long_run.json", R"({"duration": 1e9})")).find("duration: must be at most 3600 s"),
            std::string::npos);
}

TEST(Hardening, MessagesBlameTheRightField) {
  const std::string err = load_error(write("overflow.json", R"({"name": "1e400", "duration": 1e400})"));
  EXPECT_NE(err.find(": duration: must be a finite number"), std::string::npos) << err;
  // A rod whose length is left to its default and whose anchor is the ball's centre has no length: refused when
  // read (it used to load, save, and then fail to load again).
  const std::string rod = load_error(write("rod.json", R"({"balls": [{"id": "a", "position": [0, 1, 0]}],
    "rods": [{"ball": "a", "anchor": [0, 1, 0]}]})"));
  EXPECT_NE(rod.find("rods[0].anchor: is at the ball's centre"), std::string::npos) << rod;
}

// A saved scene keeps its rack (seed and jitter) while the racked balls are as racked; a moved ball saves them all.
TEST(Hardening, SavingKeepsTheRack) {
  Scene s = load_scene(preset("break_realistic.json"));
  ASSERT_TRUE(s.rack);
  const std::string path = (scratch() / "rack.json").string();
  save_scene(path, s);
  const nlohmann::json saved = nlohmann::json::parse(std::ifstream(path));
  EXPECT_EQ(saved["rack"]["seed"], s.rack->spec.seed);
  EXPECT_EQ(saved["rack"]["jitter"], s.rack->spec.jitter);
  EXPECT_EQ(saved["balls"].size(), s.rack->first);
  EXPECT_EQ(scene_to_json(load_scene(path)), scene_to_json(s));
  s.balls.back().position.x += 0.01;
  save_scene(path, s);
  const nlohmann::json moved = nlohmann::json::parse(std::ifstream(path));
  EXPECT_FALSE(moved.contains("rack"));
  EXPECT_EQ(moved["balls"].size(), s.balls.size());
}

TEST(Hardening, AnOverlapMadeByTheRackNamesTheRack) {
  const std::string err = load_error(preset("break_realistic.json"), {"rack.jitter=3"});
  EXPECT_NE(err.find("rack: the racked balls"), std::string::npos) << err;
  EXPECT_NE(err.find("rack.jitter"), std::string::npos) << err;
}

// A ball started at rest 8.5 mm deep in an undamped bed holds C d^(e+1) / (e+1) of elastic energy: it must be pushed
// out with that energy (less the little gravity takes on the way out), not put to sleep with it.
TEST(Hardening, PreloadedContactsPushApart) {
  const double d = 0.0085, C = 1e8, e = 1.5;  // depth m, stiffness N/m^1.5, Hertz exponent
  auto doc = cloth_scene({{{"id", "a"}, {"position", {0, kR - d, 0}}}},
                         {{"stiffness", C}, {"exponent", e}, {"damping", 0.0}, {"friction", 0.0}});
  auto sim = simulate(scene(doc));
  EXPECT_FALSE(sim->state().sleeping(0));
  ASSERT_EQ(sim->advance(0.01), Status::Ok) << sim->diagnostic();
  const double stored = C * std::pow(d, e + 1) / (e + 1), lift = kM * kG * d;
  const double v = std::sqrt(2 * (stored - lift) / kM);
  EXPECT_GT(sim->stats().steps, 0);
  EXPECT_NEAR(velocity(sim->state().x, 0).y + kG * sim->time(), v, 0.01 * v);  // it leaves within 0.3 ms
}

// A ball under a table's bed used to run into "unstable ... use an adaptive method" with an adaptive method.
// An aim of 1e308 degrees times pi overflowed to infinity and struck the ball with a NaN velocity: whole turns are
// taken off first, so any finite angle aims somewhere.
TEST(Hardening, AHugeAimAngleStillAims) {
  const Scene s = scene({{"table", {{"type", "pool"}}},
                         {"balls", {{{"id", "cue"}, {"position", {-0.9, kR, 0}}}}},
                         {"cue", {{"ball", "cue"}, {"speed", 1.5}, {"aim_deg", -1e308}}}});
  auto sim = simulate(s);
  EXPECT_EQ(sim->advance(0.05), Status::Ok) << sim->diagnostic();
  EXPECT_TRUE(std::isfinite(velocity(sim->state().x, 0).x));
  EXPECT_GT(glm::length(velocity(sim->state().x, 0)), 1.0);
}

TEST(Hardening, ABallBelowTheTableIsRefused) {
  const std::string err = load_error(preset("sliding_to_rolling.json"), {"balls[0].position=[0,-0.1,0]"});
  EXPECT_NE(err.find("balls[0].position: below the table's bed"), std::string::npos) << err;
}

// A stop with no contact used to say "closest pair: none (gap inf m)" and name no ball.
// A user trial loaded a cue ball at x = 5 m (reported pocketed 0.25 s later) and a cue speed of 1e6 m/s (balls 10 km
// away at the 60 s limit) without a word: both are refused, naming the field and the bound.
TEST(Hardening, BallsOffTheTableAndAbsurdSpeedsAreRefused) {
  const std::string cut = preset("cut.json");
  std::string err = load_error(cut, {"balls[0].position=[5,0.028575,0]"});
  EXPECT_NE(err.find("balls[0].position: (5, 0) m is off the table"), std::string::npos) << err;
  EXPECT_NE(err.find("1.27 and 0.635 m"), std::string::npos) << err;
  err = load_error(cut, {"cue.speed=1e6"});
  EXPECT_NE(err.find("cue.speed: 1e+06 m/s is faster than a cue strikes (at most 30 m/s"), std::string::npos) << err;
  err = load_error(cut, {"balls[1].velocity=[0,0,100]"});
  EXPECT_NE(err.find("balls[1].velocity: 100 m/s"), std::string::npos) << err;
  err = load_error(cut, {"balls[1].angular_velocity=[0,5000,0]"});
  EXPECT_NE(err.find("balls[1].angular_velocity"), std::string::npos) << err;
  EXPECT_EQ(load_error(cut, {"cue.speed=14", "balls[1].position=[1.27,0.028575,-0.635]"}), "");  // at the corner: fine
}

TEST(Hardening, AStopWithoutContactsNamesTheBalls) {
  nlohmann::json doc = {{"balls", {{{"id", "lone"}, {"position", {0, 1, 0}}}}},
                        {"integrator", {{"method", "euler"}, {"fixed_step", 1e-6}, {"max_steps_per_call", 5}}}};
  auto sim = simulate(scene(doc));
  EXPECT_EQ(sim->advance(0.1), Status::StepLimit);
  EXPECT_NE(sim->diagnostic().find("Ball lone at (0, "), std::string::npos) << sim->diagnostic();
  EXPECT_EQ(sim->diagnostic().find("inf"), std::string::npos) << sim->diagnostic();
}

// Each of these threw an exception nobody caught (exit 134) before.
TEST(Hardening, OverridesNeverThrowAnythingButInputError) {
  const std::string numeric_id = write("numeric_id.json", R"({"balls": [{"id": 7, "position": [0, 0.028575, 0]}]})");
  for (const auto& [path, set] : std::vector<std::pair<std::string, std::string>>{
           {preset("sliding_to_rolling.json"), "balls[99999999999999999999999].mass=1"},
           {preset("sliding_to_rolling.json"), "duration=1e400"},
           {numeric_id, "balls.x.mass=1"},
           {preset("sliding_to_rolling.json"), "balls[0].id=\xff"},
           {preset("sliding_to_rolling.json"), ".=1"},
           {preset("sliding_to_rolling.json"), "duration={bad"}}) {
    SCOPED_TRACE(set);
    EXPECT_FALSE(load_error(path, {set}).empty());
    std::string err;
    EXPECT_EQ(cli("run " + path + " --set '" + set + "' --duration 0.1", err), 1) << err;
    EXPECT_NE(err.find("--set"), std::string::npos) << err;
  }
}

TEST(Hardening, RunsThatCouldNotEndOrDoNothingAreRefused) {
  std::string err;
  EXPECT_EQ(cli("run " + preset("cut.json") + " --duration 1e9", err), 1);
  EXPECT_NE(err.find("at most 3600"), std::string::npos) << err;
  for (const char* rate : {"nan", "1e19", "1e-300", "0", "-5"}) {
    EXPECT_EQ(cli("run " + preset("cut.json") + " --sample-rate " + rate, err), 1) << rate;
    EXPECT_NE(err.find("--sample-rate"), std::string::npos) << err;
  }
  EXPECT_EQ(cli("run " + preset("cut.json") + " --duration 3600 --sample-rate 1000", err), 1);
  EXPECT_NE(err.find("--max-samples"), std::string::npos) << err;
}

// The step limit counts per 1/60 s of simulated time, not per sample slice: rk4 on the cut preset used to exit 0
// at 60 Hz and 3 at 1 Hz.
TEST(Hardening, SamplingDoesNotChangeTheOutcome) {
  std::string err;
  for (const char* rate : {"1", "7", "60", "1000"}) {
    const std::string out = (scratch() / (std::string("rate") + rate + ".json")).string();
    EXPECT_EQ(cli("run " + preset("cut.json") + " --set integrator.method=rk4 --duration 1 --sample-rate " + rate +
                      " --out " + out, err),
              0)
        << rate << ": " << err;
  }
  const auto at = [&](const char* rate) {
    return nlohmann::json::parse(std::ifstream(scratch() / (std::string("rate") + rate + ".json")))["balls"];
  };
  EXPECT_EQ(at("1"), at("1000"));  // and the same end state
}

// The cut shot rests after about 6 s; the rest of an hour is nothing to integrate.
TEST(Hardening, ARunWhoseBallsSleepJumpsToItsEnd) {
  const std::string out = (scratch() / "hour.json").string();
  std::string err;
  ASSERT_EQ(cli("run " + preset("cut.json") + " --duration 3600 --out " + out, err), 0) << err;
  const nlohmann::json r = nlohmann::json::parse(std::ifstream(out));
  EXPECT_DOUBLE_EQ(r["time"].get<double>(), 3600.0);
  EXPECT_LT(r["stats"]["steps"].get<long>(), 20000);
}

TEST(Hardening, FailedWritesAreErrors) {
  std::string err;
  EXPECT_EQ(cli("run " + preset("sliding_to_rolling.json") + " --duration 0.1 --trajectory /dev/full", err), 1);
  EXPECT_NE(err.find("/dev/full"), std::string::npos) << err;
  EXPECT_EQ(cli("run " + preset("sliding_to_rolling.json") + " --duration 0.1 --out /nonexistent-dir/r.json", err), 1);
  EXPECT_NE(err.find("/nonexistent-dir/r.json"), std::string::npos) << err;
}

// --out and --trajectory replace their targets together or not at all: one failing keeps the other's old file.
TEST(Hardening, AFailedOutputKeepsTheOtherOutputsOldFile) {
  const std::string kept = write("kept.json", "{\"kept\": true}\n");
  std::string err;
  const std::string scene = preset("sliding_to_rolling.json");
  EXPECT_EQ(cli("run " + scene + " --duration 0.1 --out " + kept + " --trajectory /dev/full", err), 1);
  EXPECT_EQ(cli("run " + scene + " --duration 0.1 --trajectory " + kept + " --out /nonexistent/r.json", err), 1);
  EXPECT_EQ(nlohmann::json::parse(std::ifstream(kept)), nlohmann::json::parse("{\"kept\": true}"));
}

TEST(Hardening, BenchRefusesBadOptionsBeforeRunning) {
  std::string err;
  EXPECT_EQ(cli("bench --scenes S1 --out-dir /dev/null/x", err), 1);
  EXPECT_NE(err.find("--out-dir /dev/null/x"), std::string::npos) << err;
  EXPECT_EQ(cli("bench --scenes S99", err), 1);
  EXPECT_NE(err.find("S99"), std::string::npos) << err;
  EXPECT_EQ(cli("bench --scenes S1 --budget nan", err), 1);
  EXPECT_NE(err.find("--budget"), std::string::npos) << err;
  EXPECT_EQ(cli("bench --scenes S1 --methods rigid,rk5", err), 1);
  EXPECT_NE(err.find("--methods: no method 'rk5'"), std::string::npos) << err;
}

TEST(Hardening, CsvQuotesIdsAsRfc4180Says) {
  const std::string scene = write("ids.json", R"({"balls": [{"id": "a,b\"c", "position": [0, 0.028575, 0]}],
    "colliders": [{"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "material": "ball_cloth"}]})");
  const std::string csv = (scratch() / "ids.csv").string();
  std::string err;
  ASSERT_EQ(cli("run " + scene + " --duration 0.05 --trajectory " + csv, err), 0) << err;
  std::ifstream in(csv);
  std::string header, row;
  std::getline(in, header);
  std::getline(in, row);
  EXPECT_NE(row.find(",\"a,b\"\"c\","), std::string::npos) << row;
}

TEST(Hardening, BadCommandLinesExitOne) {
  std::string err;
  EXPECT_EQ(cli("--bogus", err), 1);
  EXPECT_EQ(cli("run", err), 1);
  EXPECT_EQ(cli("--width -5", err), 1);
  EXPECT_NE(err.find("--width"), std::string::npos) << err;
  EXPECT_EQ(cli("--help", err), 0);
}

// Without a display, a scene asked for is checked and the reason the window cannot open is given.
TEST(Hardening, NoDisplaySaysWhy) {
  std::string err;
  EXPECT_EQ(cli("--scene /nonexistent/scene.json", err, "env -u DISPLAY -u WAYLAND_DISPLAY "), 1);
  EXPECT_NE(err.find("/nonexistent/scene.json"), std::string::npos) << err;
  EXPECT_EQ(cli("--scene " + preset("cut.json"), err, "env -u DISPLAY -u WAYLAND_DISPLAY "), 1);
  EXPECT_NE(err.find("no display"), std::string::npos) << err;
}

}  // namespace
}  // namespace shotlab::test
