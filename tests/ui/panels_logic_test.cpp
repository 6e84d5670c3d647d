// The logic under the panels, without a window: the undo stack, the panel layout, plot ticks and time readouts,
// files written atomically, and the frame times of a play.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <pwd.h>
#include <unistd.h>

#include "ui/files.hpp"
#include "ui/frame_times.hpp"
#include "ui/history.hpp"
#include "ui/layout.hpp"
#include "ui/plot_data.hpp"
#include "ui/text_wrap.hpp"
#include "ui/ticks.hpp"

namespace shotlab {
namespace {

Scene named(const std::string& name) {
  Scene s;
  s.name = name;
  return s;
}

// What a plain edit's undo or redo is handed for the current file: it must not be asked for (it copies the workbench).
History::FileOf not_asked(int& asked) {
  return [&asked] {
    ++asked;
    return SceneFile{};
  };
}

History::FileOf file(SceneFile f) {
  return [f] { return f; };
}

TEST(History, UndoRedoWalkTheEditsInOrder) {
  History h;
  int asked = 0;
  h.record("move 1", named("a"));
  h.record("remove 2", named("b"));
  EXPECT_EQ(h.undo_label(), "remove 2");
  EXPECT_EQ(h.undo(named("c"), not_asked(asked)).scene.name, "b");
  EXPECT_EQ(h.undo(named("b"), not_asked(asked)).scene.name, "a");
  EXPECT_FALSE(h.can_undo());
  EXPECT_EQ(h.redo(named("a"), not_asked(asked)).scene.name, "b");
  EXPECT_EQ(h.redo(named("b"), not_asked(asked)).scene.name, "c");
  EXPECT_FALSE(h.can_redo());
  EXPECT_EQ(asked, 0);
}

TEST(History, AGestureIsOneEntryAndANewEditClearsRedo) {
  History h;
  int asked = 0;
  h.record("aim", named("before drag"), "aim");
  h.record("aim", named("mid drag"), "aim");
  h.record("aim", named("late drag"), "aim");
  EXPECT_EQ(h.size(), 1u);
  h.seal();
  h.record("aim", named("second drag"), "aim");
  EXPECT_EQ(h.size(), 2u);
  h.undo(named("now"), not_asked(asked));
  EXPECT_TRUE(h.can_redo());
  h.record("move cue", named("x"));
  EXPECT_FALSE(h.can_redo());
  EXPECT_EQ(h.undo(named("y"), not_asked(asked)).scene.name, "x");
  EXPECT_EQ(h.undo(named("x"), not_asked(asked)).scene.name, "before drag");
  EXPECT_EQ(asked, 0);
}

// A load's entry carries the file it replaced, and its redo entry the file that was current at the undo; only a step
// across a load asks for the current file.
TEST(History, ALoadStepCarriesItsFileBothWays) {
  History h;
  int asked = 0;
  h.record("move 1", named("a"));
  h.record_load("open break.json", named("b"), {"cut.json", named("cut as loaded"), {}});
  HistoryStep back = h.undo(named("break"), file({"break.json", named("break as loaded"), {}}));
  EXPECT_EQ(back.scene.name, "b");
  ASSERT_TRUE(back.file);
  EXPECT_EQ(back.file->path, "cut.json");
  EXPECT_EQ(back.file->loaded.name, "cut as loaded");
  EXPECT_FALSE(h.undo(named("b"), not_asked(asked)).file);  // a plain edit's step has none
  EXPECT_FALSE(h.redo(named("a"), not_asked(asked)).file);
  EXPECT_EQ(asked, 0);
  HistoryStep again = h.redo(named("b"), file({"cut.json", named("cut as loaded"), {}}));
  EXPECT_EQ(again.scene.name, "break");
  ASSERT_TRUE(again.file);
  EXPECT_EQ(again.file->path, "break.json");
}

// Issue 28: at 1280x720, 1920x1080 and 1024x600 the panels stay at the window's edges and the 3D view keeps the
// middle, never less than kMinViewShare of the width.
TEST(Layout, PanelsStayAtTheEdgesAtEveryWindowSize) {
  for (auto [w, h] : {std::pair{1280.f, 720.f}, {1920.f, 1080.f}, {1024.f, 600.f}, {1600.f, 900.f}, {640.f, 480.f}}) {
    const Layout l = layout_panels(w, h, {true, 330, 20}, {true, 360, 20});
    SCOPED_TRACE(w);
    EXPECT_EQ(l.left.x, 0);
    EXPECT_FLOAT_EQ(l.right.right(), w);
    EXPECT_FLOAT_EQ(l.left_grip.x, l.left.right());  // the left panel's grip, then the view
    EXPECT_FLOAT_EQ(l.view.x, l.left_grip.right());
    EXPECT_EQ(l.left_grip.h, h);
    EXPECT_FLOAT_EQ(l.view.right(), l.right.x);
    EXPECT_GE(l.view.w, kMinViewShare * w - 0.5f);
    EXPECT_EQ(l.left.h, h);
  }
  const Layout wide = layout_panels(1920, 1080, {true, 330, 20}, {true, 360, 20});
  EXPECT_EQ(wide.left.w + wide.left_grip.w, 330);  // room for both at their preferred widths
  EXPECT_EQ(wide.left_grip.w, kLeftGripPx);
  EXPECT_EQ(wide.right.w, 360);
}

// Presentation mode's 1.7x text would widen both panels to leave the table 45 % of a 1920 px window (a teacher's
// trial: "F5 enlarges the text, not the table"); presenting, the panels leave it 60 %, each still usable.
TEST(Layout, PresentingKeepsTheTableLarge) {
  const PanelRequest left{true, 330 * 1.7f, 34}, right{true, 360 * 1.7f, 34};
  const Layout normal = layout_panels(1920, 1080, {true, 330, 20}, {true, 360, 20});
  const Layout presenting = layout_panels(1920, 1080, left, right, kPresentationViewShare);
  EXPECT_NEAR(layout_panels(1920, 1080, left, right).view.w, kMinViewShare * 1920, 1.0f);
  EXPECT_NEAR(presenting.view.w, kPresentationViewShare * 1920, 1.0f);
  EXPECT_GT(presenting.view.w, 0.9f * normal.view.w);
  EXPECT_GE(presenting.left.w + presenting.left_grip.w, 1.7f * kMinPanelWidth);  // usable at the larger text
  EXPECT_GE(presenting.right.w, 1.7f * kMinPanelWidth);
}

TEST(Layout, ACollapsedPanelGivesItsWidthToTheView) {
  const Layout l = layout_panels(1280, 720, {false, 330, 20}, {true, 360, 20});
  EXPECT_EQ(l.view.x, 0);
  EXPECT_EQ(l.left.h, 20);  // its title bar only
  EXPECT_EQ(l.left_grip.w, 0);
  const Layout both = layout_panels(1280, 720, {false, 330, 20}, {false, 360, 20});
  EXPECT_EQ(both.view.w, 1280);
}

TEST(Ticks, OneTwoFiveStepsInsideTheRange) {
  const Ticks t = nice_ticks(0, 6.05, 8);
  EXPECT_DOUBLE_EQ(t.step, 1);
  ASSERT_EQ(t.values.size(), 7u);
  EXPECT_DOUBLE_EQ(t.values.front(), 0);
  EXPECT_DOUBLE_EQ(t.values.back(), 6);
  const Ticks small = nice_ticks(-0.013, 0.021, 5);
  EXPECT_NEAR(small.step, 0.01, 1e-15);
  EXPECT_EQ(small.decimals, 2);
  EXPECT_EQ(format_tick(small.values[0], small), "-0.01");
  const Ticks big = nice_ticks(0, 1758, 5);
  EXPECT_DOUBLE_EQ(big.step, 500);
  for (double v : big.values) EXPECT_TRUE(v >= 0 && v <= 1758);
  EXPECT_FALSE(nice_ticks(3, 3, 5).values.empty());  // a flat line still gets an axis
}

// A 0.35 ms collision needs microseconds: the readouts and plot axes switch unit with the span shown.
TEST(Ticks, TimeUnitsResolveACollision) {
  EXPECT_EQ(time_unit(3.5e-4).name, std::string(kMicro) + "s");
  EXPECT_STREQ(time_unit(0.05).name, "ms");
  EXPECT_STREQ(time_unit(6.0).name, "s");
  EXPECT_EQ(format_time(0.11105234, true), "0.111052 s");
  EXPECT_EQ(format_time(0.11105234, false), "0.1111 s");
}

std::string read(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// From a teacher's trial: a collision's plot counts microseconds since the contact began, its CSV only the shot's time.
// The CSV now has both, so a student's table matches the picture.
TEST(PlotCsv, ACollisionPlotWritesTheTimeSinceTheContactToo) {
  const auto file = std::filesystem::temp_directory_path() / ("shotlab-plot-" + std::to_string(::getpid()) + ".csv");
  PlotSpec spec;
  spec.unit = "N";
  spec.origin = 0.25;
  spec.origin_name = "contact start";
  write_plot_csv(file.string(), spec, {{"cue - 1", 0, {0.25, 0.2501}, {0.0, 150.0}}});
  std::istringstream lines(read(file));
  std::string header, first, second;
  std::getline(lines, header), std::getline(lines, first), std::getline(lines, second);
  EXPECT_EQ(header, "time_s,\"time since contact start (s)\",\"cue - 1 (N)\"");
  EXPECT_EQ(first, "0.25,0,0");
  EXPECT_EQ(second.substr(0, 7), "0.2501,");
  EXPECT_NEAR(std::stod(second.substr(7)), 1e-4, 1e-12);
  std::filesystem::remove(file);
}

// On screen a depth reads in micrometres with the micro sign; the CSV keeps to ASCII, "um", for any spreadsheet.
TEST(PlotCsv, TheMicroSignIsWrittenAsU) {
  const auto file = std::filesystem::temp_directory_path() / ("shotlab-plot-u-" + std::to_string(::getpid()) + ".csv");
  PlotSpec spec;
  spec.unit = std::string(kMicro) + "m";
  write_plot_csv(file.string(), spec, {{"depth", 0, {0.25}, {12.5}}});
  std::istringstream lines(read(file));
  std::string header;
  std::getline(lines, header);
  EXPECT_EQ(header, "time_s,\"depth (um)\"");
  std::filesystem::remove(file);
}

TEST(Files, AtomicWriteReplacesWholeAndLeavesNoTemporaries) {
  const auto dir = std::filesystem::temp_directory_path() / ("shotlab-files-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const auto file = dir / "scene.json";
  write_file_atomic(file.string(), "first");
  write_file_atomic(file.string(), "second, longer");
  EXPECT_EQ(read(file), "second, longer");
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir), {}), 1);
  EXPECT_THROW(write_file_atomic((dir / "missing" / "x.json").string(), "x"), std::runtime_error);
  EXPECT_EQ(unique_path(dir.string(), "cut shot", "png"), (dir / "cut-shot-1.png").string());
  write_file_atomic((dir / "cut-shot-1.png").string(), "");
  EXPECT_EQ(unique_path(dir.string(), "cut shot", "png"), (dir / "cut-shot-2.png").string());
  EXPECT_TRUE(inside(file.string(), dir.string()));
  EXPECT_FALSE(inside(dir.string() + "/../x.json", dir.string()));
  // Typed in a dialog showing `dir`: relative names are inside it, absolute ones stand, "~" is home.
  EXPECT_EQ(typed_path(" scene.json ", "/data/shots"), "/data/shots/scene.json");
  EXPECT_EQ(typed_path("../a/b.json", "/data/shots"), "/data/a/b.json");
  EXPECT_EQ(typed_path("/elsewhere/c.json", "/data/shots"), "/elsewhere/c.json");
  EXPECT_EQ(typed_path("   ", "/data/shots"), "");
  EXPECT_EQ(typed_path("sub/", "/data/shots"), "/data/shots/sub");  // a folder, as Up expects it
  EXPECT_EQ(typed_path("/", "/data/shots"), "/");
  // Save as adds .json to a bare name (the browser lists .json scenes), not to a name with its own extension.
  EXPECT_EQ(scene_file_path("my draw", "/data/shots"), "/data/shots/my draw.json");
  EXPECT_EQ(scene_file_path("b.json", "/data/shots"), "/data/shots/b.json");
  EXPECT_EQ(scene_file_path("notes.txt", "/data/shots"), "/data/shots/notes.txt");
  EXPECT_EQ(scene_file_path(dir.string(), "/data/shots"), dir.string());  // a folder stays a folder (Save refuses it)
  std::filesystem::remove_all(dir);
  if (const char* home = std::getenv("HOME"); home && *home) {
    EXPECT_EQ(typed_path("~/d.json", "/data/shots"), (std::filesystem::path(home) / "d.json").lexically_normal().string());
    // With HOME unset (a desktop entry started with env -i) "~" is still the account's home, not a folder named "~".
    const std::string saved = home;
    unsetenv("HOME");
    const std::string account = home_folder();
    const std::string typed = typed_path("~/d.json", "/data/shots");
    setenv("HOME", saved.c_str(), 1);
    if (getpwuid(getuid()) == nullptr) GTEST_SKIP() << "this account has no entry in the password database";
    ASSERT_FALSE(account.empty());
    EXPECT_EQ(typed, (std::filesystem::path(account) / "d.json").lexically_normal().string());
  }
}

// The frame times of a shot: only frames a shot played in count, a pause leaves the record to go on, another shot
// starts a new one, and the summary's figures are the sorted frames' median, 95th percentile and largest, with those
// over the budget counted.
TEST(FrameTimes, APauseKeepsTheRecordAndAnotherShotStartsANewOne) {
  FrameTimes f;
  f.add(false, 1, 0.5);  // idle: not counted
  for (int k = 1; k <= 60; ++k) f.add(true, 1, k * 1e-3);  // 1 to 60 ms
  f.add(false, 1, 0.2);  // paused: the record stays as it was
  EXPECT_EQ(f.summary(1e3 / 60).frames, 60u);
  EXPECT_DOUBLE_EQ(f.summary(1e3 / 60).worst_ms, 60.0);
  for (int k = 61; k <= 100; ++k) f.add(true, 1, k * 1e-3);  // played on: 61 to 100 ms
  FrameTimes::Summary s = f.summary(1e3 / 60);
  EXPECT_EQ(s.frames, 100u);
  EXPECT_DOUBLE_EQ(s.median_ms, 50.0);  // the 50th of 100 sorted (index 49.5, rounded down)
  EXPECT_DOUBLE_EQ(s.p95_ms, 95.0);
  EXPECT_DOUBLE_EQ(s.worst_ms, 100.0);
  EXPECT_EQ(s.over_budget, 84u);  // 17 to 100 ms
  f.add(true, 2, 0.010);  // another shot: only this one
  s = f.summary(1e3 / 60);
  EXPECT_EQ(s.frames, 1u);
  EXPECT_DOUBLE_EQ(s.worst_ms, 10.0);
  EXPECT_EQ(s.over_budget, 0u);
}

// Lines break at spaces, and a unit stays with its number: a teacher's trial saw "every ball at rest after 1.23" with
// "s" alone on the next line. A character is 1 wide here.
TEST(TextWrap, AUnitStaysWithItsNumber) {
  auto wide = [](std::string_view s) { return static_cast<float>(s.size()); };
  using Lines = std::vector<std::string_view>;
  EXPECT_EQ(wrap_paragraph("every ball at rest after 1.23 s", 30, wide), (Lines{"every ball at rest after", "1.23 s"}));
  EXPECT_EQ(wrap_paragraph("the angle is 86.0 deg.", 20, wide), (Lines{"the angle is", "86.0 deg."}));
  EXPECT_EQ(wrap_paragraph("a speed of 2 s and more", 13, wide), (Lines{"a speed of", "2 s and more"}));
  EXPECT_EQ(wrap_paragraph("pots 3 sides", 7, wide), (Lines{"pots 3", "sides"}));  // a word, not a unit
  EXPECT_EQ(wrap_paragraph("1.23 s", 3, wide), (Lines{"1.23", "s"}));  // no room for the pair on any line
  EXPECT_EQ(wrap_paragraph("", 10, wide), (Lines{""}));
}

}  // namespace
}  // namespace shotlab
