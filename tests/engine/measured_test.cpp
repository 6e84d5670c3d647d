// The carom table's cloth and cushion against real tracked three-cushion shots (../shared/reference/measured/, kept
// out of the repository; skipped where that folder is absent). Two things a player knows from the table: how fast a
// rolling ball slows on a straight run, and what share of its speed across the rail a cushion gives back.
#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "shotlab/restitution.hpp"
#include "shotlab/table.hpp"
#include "support.hpp"

namespace shotlab::test {
namespace {

struct Sample {
  double t, x, z;
};
using Tracks = std::map<std::string, std::vector<Sample>>;  // per ball, in time order

std::filesystem::path measured_dir() { return std::filesystem::path(SHOTLAB_SOURCE_DIR) / "../shared/reference/measured"; }

std::vector<Tracks> read_shots() {
  std::vector<Tracks> shots;
  std::vector<std::filesystem::path> files;
  for (const auto& e : std::filesystem::directory_iterator(measured_dir()))
    if (e.path().extension() == ".csv") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  for (const auto& f : files) {
    std::ifstream in(f);
    std::string line, ball;
    std::getline(in, line);  // time,ball,x,z
    Tracks tracks;
    while (std::getline(in, line)) {
      std::replace(line.begin(), line.end(), ',', ' ');
      std::istringstream row(line);
      Sample s;
      row >> s.t >> ball >> s.x >> s.z;
      tracks[ball].push_back(s);
    }
    shots.push_back(tracks);
  }
  return shots;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? NAN : v[v.size() / 2];
}

// m/s^2: the deceleration of each slow straight run (samples 20 ms apart, heading within 3 degrees, mean speed under
// 0.8 m/s so that the ball rolls), its first five intervals dropped (the ball may still slide off a cushion).
std::vector<double> straight_run_decelerations(const std::vector<Tracks>& shots) {
  std::vector<double> out;
  for (const Tracks& tracks : shots)
    for (const auto& [ball, s] : tracks) {
      std::vector<std::array<double, 3>> v;  // time, speed, heading
      for (size_t k = 1; k < s.size(); ++k)
        if (const double dt = s[k].t - s[k - 1].t; dt > 0 && dt < 0.1)
          v.push_back({(s[k].t + s[k - 1].t) / 2, std::hypot(s[k].x - s[k - 1].x, s[k].z - s[k - 1].z) / dt,
                       std::atan2(s[k].z - s[k - 1].z, s[k].x - s[k - 1].x)});
      for (size_t i = 0, j; i < v.size(); i = j + 1) {
        for (j = i; j + 1 < v.size() && std::abs(std::remainder(v[j + 1][2] - v[i][2], 2 * M_PI)) < 3 * M_PI / 180;) ++j;
        if (j - i + 1 < 15) continue;
        const std::vector<std::array<double, 3>> run(v.begin() + i + 5, v.begin() + j - 1);
        double mt = 0, mv = 0, stt = 0, stv = 0;
        for (const auto& p : run) mt += p[0] / run.size(), mv += p[1] / run.size();
        for (const auto& p : run) stt += (p[0] - mt) * (p[0] - mt), stv += (p[0] - mt) * (p[1] - mv);
        if (mv < 0.8) out.push_back(-stv / stt);
      }
    }
  return out;
}

// The share of the speed across the rail each bounce gives back: the velocities from the three samples before and
// after the sample nearest the rail (a ball whose centre comes within 4 mm of where it touches the cushion).
std::vector<double> cushion_ratios(const std::vector<Tracks>& shots, double reach_x, double reach_z) {
  std::vector<double> out;
  for (const Tracks& tracks : shots)
    for (const auto& [ball, s] : tracks)
      for (size_t i = 3; i + 3 < s.size(); ++i)
        for (const auto& [axis, reach] : {std::pair{0, reach_x}, std::pair{1, reach_z}}) {
          auto c = [&](size_t k) { return axis == 0 ? s[k].x : s[k].z; };
          if (std::abs(c(i)) < reach - 0.004 || std::abs(c(i)) < std::abs(c(i - 1)) || std::abs(c(i)) < std::abs(c(i + 1)))
            continue;
          if (s[i - 1].t - s[i - 3].t > 0.05 || s[i + 3].t - s[i + 1].t > 0.05) continue;
          const double before = (c(i - 1) - c(i - 3)) / (s[i - 1].t - s[i - 3].t);
          const double after = (c(i + 3) - c(i + 1)) / (s[i + 3].t - s[i + 1].t);
          if (std::abs(before) > 0.1) out.push_back(-after / before);
        }
  return out;
}

// The tables' cushion damping constants are the restitution they stand for, as restitution.hpp works it out.
TEST(Measured, TableCushionDampingIsItsRestitution) {
  const ContactMaterial c = default_ball_cushion();
  EXPECT_NEAR(damping_for_restitution(c, effective_mass(false, kSnookerBall.mass), 1.0, 0.98), kSnookerCushionDamping,
              1e-9 * kSnookerCushionDamping);
  EXPECT_NEAR(damping_for_restitution(c, effective_mass(false, kCaromBall.mass), 1.0, 0.9), kCaromCushionDamping,
              1e-9 * kCaromCushionDamping);
}

TEST(Measured, CaromClothRollsAsTheRealShotsSlow) {
  if (!std::filesystem::is_directory(measured_dir())) GTEST_SKIP() << "no measured shots at " << measured_dir();
  const std::vector<double> a = straight_run_decelerations(read_shots());
  ASSERT_GE(a.size(), 8u);
  Model m;
  set_table_materials(TableKind::Carom, m);
  const double model = m.materials.at(kBallCloth).rolling_resistance * kG;
  std::printf("straight runs: %zu, median deceleration %.4f m/s^2; carom cloth %.4f\n", a.size(), median(a), model);
  EXPECT_NEAR(median(a), model, 0.25 * model);
}

TEST(Measured, CaromCushionGivesBackWhatRealCushionsDo) {
  if (!std::filesystem::is_directory(measured_dir())) GTEST_SKIP() << "no measured shots at " << measured_dir();
  const double r = kCaromBall.radius, h = 0.635 * 0.0615, tilt = std::sqrt(1 - std::pow((h - r) / r, 2));
  const std::vector<double> measured = cushion_ratios(read_shots(), 1.42 - r * tilt, 0.71 - r * tilt);
  ASSERT_GE(measured.size(), 8u);
  for (const double v : {0.5, 1.0, 2.0}) {  // a stun ball head-on into the back cushion, 30 um short of touching
    const nlohmann::json doc = {{"ball_kind", "carom"}, {"table", {{"type", "carom"}}},
                                {"balls", {{{"id", "cue"}, {"position", {0, r, -0.71 + r * tilt + 30e-6}},
                                            {"velocity", {0, 0, -v}}}}}};
    auto sim = simulate(scene(doc));
    run_until(*sim, 0.05, [&] { return event_time(*sim, "contact_end", "cue", "cushion-back") >= 0; }, 1e-4);
    auto again = simulate(scene(doc));
    ASSERT_EQ(again->advance(event_time(*sim, "contact_end", "cue", "cushion-back")), Status::Ok);
    const double ratio = velocity(again->state().x, 0).z / v;
    std::printf("cushion at %.1f m/s: %.3f; measured median %.3f over %zu bounces\n", v, ratio, median(measured),
                measured.size());
    EXPECT_NEAR(ratio, median(measured), 0.06);
  }
}

}  // namespace
}  // namespace shotlab::test
