// Shot margins (shotlab/io/margin.hpp) against the geometry of a straight shot: with frictionless balls the object
// ball leaves along the line of centres, so an aim error a of the cue ball (centre distance D) sends it off at
// asin(D sin a / 2R) - a, and a zone of radius r at its end, s metres on, is hit while s sin(theta) <= r. Also: stroke
// levels, goals, and replays that do not depend on the number of threads.
#include <cmath>

#include "shotlab/io/margin.hpp"
#include "support.hpp"

namespace shotlab::test {
namespace {

constexpr double kD = 0.5;     // m, cue ball to object ball, centre to centre
constexpr double kZone = 0.02; // m, the target zone's radius

Scene straight_shot() {
  nlohmann::json doc = cloth_scene({{{"id", "cue"}, {"position", {0, kR, 0}}}, {{"id", "1"}, {"position", {kD, kR, 0}}}});
  doc["materials"]["ball_ball"] = {{"friction", 0}};
  doc["integrator"] = {{"method", "dopri5"}};
  doc["cue"] = {{"ball", "cue"}, {"speed", 1.5}, {"aim_deg", 0}};
  doc["duration"] = 10;
  return scene(doc);
}

// Where the object ball comes to rest when the shot is straight.
double straight_run_end() {
  auto sim = simulate(straight_shot());
  while (!sim->at_rest() && sim->time() < kRestLimit) sim->advance(1.0 / 60);
  EXPECT_TRUE(sim->at_rest());  // at 11.1 s: past the scene's 10 s, which the replays run on from as well
  return position(sim->state().x, 1).x;
}

MarginOptions aim_only(double sd_deg, double end_x) {
  MarginOptions o;
  o.noise.aim_deg = sd_deg;
  o.goal = parse_goal("zone:1@" + std::to_string(end_x) + ",0," + std::to_string(kZone));
  o.samples = 400;
  o.seed = 5;
  return o;
}

TEST(Margin, AimToleranceAndSuccessFollowTheGeometryOfAStraightShot) {
  const double end_x = straight_run_end(), s = end_x - kD;
  ASSERT_GT(s, 0.3);
  // The cue ball's path at a meets the object ball off its centre by b = D sin a; the line of centres then turns
  // by asin(b / 2R) from the path, so the object ball leaves at theta = asin(D sin a / 2R) - a from the x axis.
  // The zone is missed beyond theta = asin(r / s): solve for a by bisection.
  const double theta_max = std::asin(kZone / s);
  double lo = 0, hi = 0.05;  // rad
  for (int k = 0; k < 60; ++k) {
    const double a = 0.5 * (lo + hi);
    (std::asin(kD * std::sin(a) / (2 * kR)) - a < theta_max ? lo : hi) = a;
  }
  const double alpha_max = lo * 180 / M_PI;  // degrees
  const double sd = 0.1;
  const MarginResult r = shot_margin(straight_shot(), aim_only(sd, end_x));
  EXPECT_TRUE(r.nominal_success);
  EXPECT_NEAR(r.tolerance[kAim].hi, alpha_max, 0.01 * alpha_max);  // the search's resolution: 0.004 alpha_max
  EXPECT_NEAR(r.tolerance[kAim].lo, -alpha_max, 0.01 * alpha_max);
  std::printf("aim window: theory +-%.5f deg, engine %.5f .. %.5f; success: erf %.3f, engine %.3f +- %.3f\n",
              alpha_max, r.tolerance[kAim].lo, r.tolerance[kAim].hi, std::erf(alpha_max / (sd * std::sqrt(2.0))),
              r.probability, r.standard_error);
  const double expected = std::erf(alpha_max / (sd * std::sqrt(2.0)));  // P(|a| < alpha_max), a ~ N(0, sd)
  EXPECT_NEAR(r.probability, expected, 3 * r.standard_error + 0.02) << "alpha_max " << alpha_max << " deg";
  EXPECT_NEAR(r.alone[kAim], r.probability, 1e-12);  // aim is the only source: the same draws
  EXPECT_EQ(r.alone[kSpeed], 1.0);                    // the others have no noise: every replay is the straight shot
  // A level cue goes no lower: elevation's window ends there, at 0 (not "-0 or less", as a coach read it).
  EXPECT_EQ(r.tolerance[kElevation].lo, 0.0);
  EXPECT_FALSE(std::signbit(r.tolerance[kElevation].lo));
  EXPECT_TRUE(r.tolerance[kElevation].bounded_lo);
}

TEST(Margin, ReplaysDoNotDependOnThreadsAndNoNoiseMeansTheNominalOutcome) {
  const double end_x = straight_run_end();
  MarginOptions o = aim_only(0.1, end_x);
  o.samples = 40;
  o.sensitivity = false;
  o.jobs = 1;
  const MarginResult one = shot_margin(straight_shot(), o);
  o.jobs = 2;
  const MarginResult two = shot_margin(straight_shot(), o);
  ASSERT_EQ(one.samples.size(), two.samples.size());
  for (size_t i = 0; i < one.samples.size(); ++i) {
    EXPECT_EQ(one.samples[i].success, two.samples[i].success);
    EXPECT_EQ(one.samples[i].end_x, two.samples[i].end_x);
  }
  o.noise = {};
  EXPECT_EQ(shot_margin(straight_shot(), o).probability, 1.0);
  const MarginMap map = margin_map(straight_shot(), o, 5, 1, 1.0, 0);  // aims -1 .. +1 degrees, no noise
  ASSERT_EQ(map.cells.size(), 5u);
  EXPECT_EQ(map.cells, (std::vector<double>{0, 0, 1, 0, 0}));  // 0.5 degrees is outside the 0.13 degree window
}

TEST(Margin, LevelsAndGoalsAreCheckedInput) {
  EXPECT_DOUBLE_EQ(stroke_noise("robot").aim_deg, 0.125);  // the Computational Pool tournaments' noise
  EXPECT_DOUBLE_EQ(stroke_noise("robot").tip_mm, 0.5);
  EXPECT_LT(stroke_noise("pro").aim_deg, stroke_noise("amateur").aim_deg);
  EXPECT_THROW(stroke_noise("god"), InputError);
  const ShotGoal pocket = parse_goal("pocket:1@pocket-right-front");
  EXPECT_EQ(pocket.kind, ShotGoal::Pocket);
  EXPECT_EQ(pocket.pocket, "pocket-right-front");
  EXPECT_EQ(parse_goal("pocket:8").pocket, "");
  const ShotGoal zone = parse_goal("zone:cue@0.5,-0.25,0.1");
  EXPECT_EQ(zone.kind, ShotGoal::Zone);
  EXPECT_DOUBLE_EQ(zone.z, -0.25);
  for (const char* bad : {"pocket", "hole:1", "pocket:", "zone:cue@1,2", "zone:cue@1,2,0", "zone:cue@a,b,c", "zone:cue"})
    EXPECT_THROW(parse_goal(bad), InputError) << bad;
  MarginOptions o;
  o.goal = parse_goal("pocket:9");
  EXPECT_THROW(shot_margin(straight_shot(), o), InputError);  // no ball 9
  Scene no_cue = straight_shot();
  no_cue.cue.reset();
  o.goal = parse_goal("pocket:1");
  EXPECT_THROW(shot_margin(no_cue, o), InputError);
}

TEST(Margin, ThePresetCutPotsAtTheIntendedStrokeAndTheReportNamesIt) {
  MarginOptions o;
  o.noise = stroke_noise("pro");
  o.goal = parse_goal("pocket:1@pocket-right-front");
  o.samples = 60;
  const Scene cut = load_scene(preset("cut.json"));
  const MarginResult r = shot_margin(cut, o);
  EXPECT_TRUE(r.nominal_success);
  EXPECT_GT(r.probability, 0.0);
  EXPECT_LT(r.probability, 1.0);
  EXPECT_LT(r.tolerance[kAim].lo, 0);
  EXPECT_GT(r.tolerance[kAim].hi, 0);
  const nlohmann::json j = margin_to_json(cut, o, r);
  EXPECT_EQ(j["goal"]["pocket"], "pocket-right-front");
  EXPECT_EQ(j["ends"]["1"]["x"].size(), 60u);
  EXPECT_EQ(j["table"]["holes"].size(), 6u);  // six pockets to draw
  EXPECT_EQ(j["sensitivity"]["aim_deg"]["tolerance"][0], r.tolerance[kAim].lo);
  const std::string csv = margin_csv(r);
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 61);
}

// Aimed 5 degrees off, the cut misses as struck: there is no window round the stroke, and the report says none
// (a developer read "the shot holds from 0.000 to 0.000" for every source).
TEST(Margin, AStrokeThatMissesHasNoWindowInTheReport) {
  MarginOptions o;
  o.noise = stroke_noise("pro");
  o.goal = parse_goal("pocket:1@pocket-right-front");
  o.samples = 20;
  const Scene off = load_scene(preset("cut.json"), {"cue.aim_deg=-80"});
  const MarginResult r = shot_margin(off, o);
  ASSERT_FALSE(r.nominal_success);
  const nlohmann::json j = margin_to_json(off, o, r);
  EXPECT_TRUE(j["sensitivity"]["aim_deg"]["tolerance"].is_null());
  EXPECT_TRUE(j["sensitivity"]["aim_deg"]["bounded"].is_null());
}

}  // namespace
}  // namespace shotlab::test
