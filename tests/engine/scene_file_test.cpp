// Scene files: every kind of bad input is refused with a message naming the file, the field and the problem;
// overrides reach any value; saving is lossless and atomic; the command line reports errors by exit status.
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <unistd.h>

#include "support.hpp"

namespace shotlab::test {
namespace {

namespace fs = std::filesystem;

// A folder of this test process's own: ctest runs tests as parallel processes (and other checkouts on the machine run
// theirs), so fixed names in /tmp let one test read another's files.
struct TestDir {
  fs::path path = fs::temp_directory_path() / ("shotlab_test_" + std::to_string(getpid()));
  TestDir() { fs::create_directories(path); }
  ~TestDir() {
    std::error_code ignored;
    fs::remove_all(path, ignored);
  }
};
const fs::path& test_dir() {
  static const TestDir dir;
  return dir.path;
}

std::string temp_file(const std::string& name, const std::string& text) {
  const fs::path p = test_dir() / name;
  std::ofstream(p) << text;
  return p.string();
}

// Loads `text` from a file and returns the error message ("" when it loads).
std::string load_error(const std::string& name, const std::string& text) {
  const std::string path = temp_file(name, text);
  try {
    load_scene(path);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

const std::string kBall = R"({"id": "a", "position": [0, 0.028575, 0]})";

struct BadInput {
  const char* name;
  std::string text;
  std::string field, problem;
};

// An arc wall collider with one field replaced by `field` (a JSON member).
std::string arc_wall(const std::string& field) {
  nlohmann::json wall = {{"type", "arc_wall"}, {"center", {0, 0, 0}}, {"radius", 0.065}, {"thickness", 0.02},
                         {"toward", {1, 0, 0}}, {"half_angle_deg", 120}, {"bottom", -0.09}, {"top", 0.05}};
  wall.update(nlohmann::json::parse("{" + field + "}"));
  return wall.dump();
}

TEST(SceneFile, BadInputNamesFileFieldAndProblem) {
  const BadInput cases[] = {
      {"malformed.json", R"({"balls": [)", "", "malformed JSON"},
      {"unknown_field.json", R"({"balls": [)" + kBall + R"(], "gravitee": [0, -9.81, 0]})", "gravitee", "unknown field"},
      {"unknown_nested.json", R"({"balls": [{"id": "a", "position": [0, 1, 0], "colour": "red"}]})", "balls[0].colour",
       "unknown field"},
      {"wrong_type.json", R"({"balls": [{"id": "a", "position": [0, 1, 0], "mass": "heavy"}]})", "balls[0].mass",
       "must be a number"},
      {"negative_mass.json", R"({"balls": [{"id": "a", "position": [0, 1, 0], "mass": -0.17}]})", "balls[0].mass",
       "must be positive"},
      {"negative_radius.json", R"({"balls": [{"id": "a", "position": [0, 1, 0], "radius": -1}]})", "balls[0].radius",
       "must be positive"},
      {"overlap.json", R"({"balls": [)" + kBall + R"(, {"id": "b", "position": [0.03, 0.028575, 0]}]})",
       "balls[1].position", "overlaps ball 'a'"},
      {"integrator.json", R"({"integrator": {"method": "leapfrog"}, "balls": [)" + kBall + "]}", "integrator.method",
       "unknown integrator 'leapfrog'"},
      {"non_finite.json", R"({"balls": [{"id": "a", "position": [0, 1e999, 0]}]})", "balls[0].position[1]",
       "finite"},
      {"short_vector.json", R"({"balls": [{"id": "a", "position": [0, 1]}]})", "balls[0].position", "3 numbers"},
      {"missing.json", R"({"balls": [{"position": [0, 1, 0]}]})", "balls[0].id", "missing required field"},
      {"misspelt.json", R"({"balls": [{"id": "a", "positon": [0, 1, 0]}]})", "balls[0].position",
       "missing required field (is 'positon' a misspelling of it?)"},
      {"misspelt_optional.json", R"({"balls": [{"id": "a", "position": [0, 1, 0], "Mass": 0.2}]})", "balls[0].Mass",
       "unknown field (did you mean 'mass'?)"},
      // The nearest name, not the first of those near: 'sped' is one edit from 'speed' and two from 'side'.
      {"misspelt_nearest.json", R"({"balls": [)" + kBall + R"(], "cue": {"ball": "a", "speed": 2, "sped": 3}})",
       "cue.sped", "unknown field (did you mean 'speed'?)"},
      {"rod.json", R"({"balls": [)" + kBall + R"(], "rods": [{"ball": "zz", "anchor": [0, 1, 0]}]})", "rods[0].ball",
       "no ball with id 'zz'"},
      {"wall_up.json", R"({"colliders": [)" + arc_wall(R"("toward": [0, 1, 0])") + "]}", "colliders[0].toward",
       "horizontal part"},
      {"wall_angle.json", R"({"colliders": [)" + arc_wall(R"("half_angle_deg": 0)") + "]}",
       "colliders[0].half_angle_deg", "more than 0"},
      {"wall_wide.json", R"({"colliders": [)" + arc_wall(R"("half_angle_deg": 400)") + "]}",
       "colliders[0].half_angle_deg", "at most 180"},
      {"wall_top.json", R"({"colliders": [)" + arc_wall(R"("top": -0.2)") + "]}", "colliders[0].top", "above bottom"},
  };
  for (const BadInput& c : cases) {
    const std::string msg = load_error(c.name, c.text);
    EXPECT_NE(msg.find(c.name), std::string::npos) << c.name << ": " << msg;
    EXPECT_NE(msg.find(c.field), std::string::npos) << c.name << ": " << msg;
    EXPECT_NE(msg.find(c.problem), std::string::npos) << c.name << ": " << msg;
  }
}

TEST(SceneFile, OverlapIsAllowedWhenAsked) {
  EXPECT_EQ(load_error("overlap_ok.json", R"({"allow_overlap": true, "balls": [)" + kBall +
                                              R"(, {"id": "b", "position": [0.03, 0.028575, 0]}]})"),
            "");
}

TEST(SceneFile, OverridesReachAnyValue) {
  const Scene s = load_scene(preset("sliding_to_rolling.json"),
                             {"materials.ball_cloth.friction=0.3", "balls.cue.velocity=[0,0,1]",
                              "integrator.method=rk4", "cue.speed=2.5", "duration=1"});
  EXPECT_DOUBLE_EQ(s.model.material(kBallCloth).friction, 0.3);
  EXPECT_DOUBLE_EQ(s.balls[0].velocity.z, 1.0);
  EXPECT_EQ(s.model.integrator.method, Method::RK4);
  EXPECT_DOUBLE_EQ(s.cue->speed, 2.5);
  EXPECT_DOUBLE_EQ(s.duration, 1.0);
  EXPECT_THROW(load_scene(preset("sliding_to_rolling.json"), {"balls.nobody.mass=1"}), InputError);
  EXPECT_THROW(load_scene(preset("sliding_to_rolling.json"), {"no_equals_sign"}), InputError);
  try {
    load_scene(preset("sliding_to_rolling.json"), {"materials.ball_cloth.frcition=0.3"});
    FAIL() << "a misspelt override must not pass";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("materials.ball_cloth.frcition: unknown field"), std::string::npos) << e.what();
  }
}

TEST(SceneFile, SaveAndLoadGiveTheSameScene) {
  for (const char* name : {"break_realistic.json", "cradle.json", "frozen.json"}) {
    const Scene s = load_scene(preset(name));
    const std::string path = (test_dir() / (std::string("roundtrip_") + name)).string();
    save_scene(path, s);
    EXPECT_EQ(scene_to_json(load_scene(path)), scene_to_json(s)) << name;
  }
}

// A scene's own arc wall comes back from its file as it was written (to the last bit of its numbers).
TEST(SceneFile, AnArcWallSurvivesSaveAndLoad) {
  const std::string path = temp_file("wall.json", R"({"colliders": [)" + arc_wall(R"("half_angle_deg": 115.25)") +
                                                      R"(], "balls": [)" + kBall + "]}");
  const Scene s = load_scene(path);
  ASSERT_EQ(s.model.colliders.size(), 1u);
  const auto* wall = std::get_if<ArcWall>(&s.model.colliders[0].shape);
  ASSERT_NE(wall, nullptr);
  EXPECT_NEAR(wall->half_angle, 115.25 * M_PI / 180, 1e-15);
  const std::string again = (test_dir() / "wall_again.json").string();
  save_scene(again, s);
  EXPECT_EQ(scene_to_json(load_scene(again)), scene_to_json(s));
}

TEST(SceneFile, FailedSaveLeavesTheOldFileAlone) {
  const std::string path = temp_file("keep.json", "{\"name\": \"old\"}");
  const std::string users_tmp = temp_file("keep.json.tmp", "the user's own file");
  const Scene s = load_scene(preset("sliding_to_rolling.json"));
  EXPECT_THROW(save_scene("/nonexistent-dir/x.json", s), InputError);
  EXPECT_THROW(save_scene(test_dir().string(), s), InputError);  // a folder is not replaced
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_EQ(text.str(), "{\"name\": \"old\"}");
  // A save goes through a temporary file of its own: a file named like a fixed temporary one is left alone.
  save_scene(path, s);
  std::ifstream other(users_tmp);
  std::stringstream other_text;
  other_text << other.rdbuf();
  EXPECT_EQ(other_text.str(), "the user's own file");
}

// A save replaces the file a symbolic link points to (the link stays) and keeps the file's permissions.
TEST(SceneFile, SaveFollowsLinksAndKeepsPermissions) {
  const std::string real = temp_file("real.json", "{}");
  const fs::path link = test_dir() / "link.json";
  fs::create_symlink(real, link);
  fs::permissions(real, fs::perms::owner_read | fs::perms::owner_write);
  save_scene(link.string(), load_scene(preset("sliding_to_rolling.json")));
  EXPECT_TRUE(fs::is_symlink(link));
  EXPECT_EQ(load_scene(real).name, load_scene(preset("sliding_to_rolling.json")).name);
  EXPECT_EQ(fs::status(real).permissions() & fs::perms::all, fs::perms::owner_read | fs::perms::owner_write);
}

// The command line: exit status and message.
int run_cli(const std::string& args, std::string& err) {
  const std::string err_file = (test_dir() / "cli_err.txt").string();
  const int status = std::system((std::string(SHOTLAB_BIN) + " " + args + " > /dev/null 2> " + err_file).c_str());
  std::ifstream in(err_file);
  std::stringstream text;
  text << in.rdbuf();
  err = text.str();
  return WEXITSTATUS(status);
}

TEST(Cli, BadSceneGivesMessageAndNonZeroExit) {
  std::string err;
  const std::string path = temp_file("cli_bad.json", R"({"balls": [{"id": "a", "position": [0, 1, 0], "mass": -1}]})");
  EXPECT_EQ(run_cli("run " + path, err), 1);
  EXPECT_NE(err.find(path + ": balls[0].mass: must be positive"), std::string::npos) << err;
  EXPECT_EQ(run_cli("run " + preset("sliding_to_rolling.json") + " --set integrator.method=magic", err), 1);
  EXPECT_NE(err.find("integrator.method"), std::string::npos) << err;
}

// `sweep --out -` writes the rows to standard output, as a missing --out does, not to a file named "-".
TEST(Cli, SweepOutDashIsStandardOutput) {
  const fs::path dir = test_dir() / "dash";
  fs::create_directories(dir);
  const std::string command = "cd " + dir.string() + " && " + SHOTLAB_BIN + " sweep " + preset("cut.json") +
                              " --vary cue.speed=1,2 -q --out - > rows.csv 2> err.txt";
  ASSERT_EQ(WEXITSTATUS(std::system(command.c_str())), 0);
  std::ifstream rows(dir / "rows.csv");
  int lines = 0;
  for (std::string line; std::getline(rows, line);) lines += !line.empty();
  EXPECT_EQ(lines, 3);  // the header and two runs
  EXPECT_FALSE(fs::exists(dir / "-"));
}

// model.path sets every solver switch at once; a switch given beside it overrides it, wherever it stands.
TEST(SceneFile, SolverPathSetsTheSwitchesAndEachMayOverrideIt) {
  const Options plain = scene({{"model", {{"path", "plain"}}}}).model.options;
  EXPECT_FALSE(plain.rolling_regime || plain.sliding_regime || plain.swing_regime || plain.flight_regime ||
               plain.bounce_regime || plain.islands);
  EXPECT_EQ(plain.sleep_time, 0.0);
  const Options mixed = scene({{"model", {{"islands", true}, {"path", "plain"}}}}).model.options;
  EXPECT_TRUE(mixed.islands);
  EXPECT_FALSE(mixed.rolling_regime);
  const Options fast = scene({{"model", {{"path", "fast"}}}}).model.options;
  EXPECT_TRUE(fast.rolling_regime && fast.sliding_regime && fast.swing_regime && fast.flight_regime &&
              fast.bounce_regime && fast.islands);
  EXPECT_EQ(fast.sleep_time, Options{}.sleep_time);
  try {
    scene({{"model", {{"path", "quick"}}}});
    ADD_FAILURE() << "an unknown path was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("model.path"), std::string::npos) << e.what();
  }
}

TEST(Cli, RunWritesResultAndTrajectory) {
  const fs::path dir = test_dir();
  std::string err;
  ASSERT_EQ(run_cli("run " + preset("sliding_to_rolling.json") + " --duration 1 --out " + (dir / "r.json").string() +
                        " --trajectory " + (dir / "t.csv").string() + " --sample-rate 100",
                    err),
            0)
      << err;
  nlohmann::json r = nlohmann::json::parse(std::ifstream(dir / "r.json"));
  EXPECT_DOUBLE_EQ(r["time"].get<double>(), 1.0);
  EXPECT_EQ(r["balls"][0]["id"], "cue");
  EXPECT_EQ(r["balls"][0]["motion"], "rolling");
  EXPECT_EQ(r["stats"]["integrator"], "cash_karp54");  // the default
  EXPECT_GT(r["stats"]["steps"].get<long>(), 0);
  EXPECT_EQ(r["events"][0]["kind"], "rolling");
  std::ifstream csv(dir / "t.csv");
  int lines = 0;
  for (std::string line; std::getline(csv, line);) ++lines;
  EXPECT_EQ(lines, 1 + 101);  // header + samples at 0, 0.01, ..., 1.0
}

TEST(Cli, BlowUpExitsWithDiagnostic) {
  std::string err;
  EXPECT_EQ(run_cli("run " + preset("bench/s8_break.json") + " --set integrator.max_steps_per_call=20", err), 3);
  EXPECT_NE(err.find("step limit"), std::string::npos) << err;
}

}  // namespace
}  // namespace shotlab::test
