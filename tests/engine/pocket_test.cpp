// Pockets (docs/model.md#pockets): a firm pot stays down, the back of the pocket stops it, and the back stands where no
// ball coming through the mouth along the bed can touch it before it is over the hole.
#include <cmath>
#include <map>
#include <random>

#include "engine/contacts.hpp"
#include "shotlab/restitution.hpp"
#include "shotlab/table.hpp"
#include "support.hpp"

namespace shotlab::test {
namespace {

// The pocket a ball went into, "" if it went off the table or stayed on it: the scene run to rest.
std::string pocket_of(const Scene& s, const std::string& ball) {
  auto sim = simulate(s);
  run_until(*sim, 10.0, [&] { return sim->at_rest(); }, 1.0 / 60);
  for (const Event& e : sim->events())
    if (e.kind == "pocketed" && e.bodies.size() == 2 && e.bodies[0] == ball) return e.bodies[1];
  return "";
}

// The cut preset pots ball 1 into the right front corner from a soft to a slammed stroke (12 m/s of cue, the object
// ball at 10 m/s into the pocket). Without the pocket's back, 2.5 m/s of cue and more threw it over the hole's far rim
// and off the table; with a back of linear damping (restitution rising with speed, 0.45 at 10 m/s) 6 m/s and more
// bounced it back over the near rim onto the table or off it.
TEST(Pocket, AFirmCutStaysDown) {
  for (const char* speed : {"1.5", "2.5", "3.5", "4.5", "5", "6", "7", "8", "9", "10", "12"})
    EXPECT_EQ(pocket_of(load_scene(preset("cut.json"), {std::string("cue.speed=") + speed}), "1"),
              "pocket-right-front")
        << "cue speed " << speed << " m/s";
}

// A ball that drops is out of play from that moment: no event has it land on the pocket's floor or touch the back
// afterwards (the step it left in used to report what its interpolant did there: "landed", then "contact_begin" with
// the back, which the contact log drew as a 5 s contact of no force).
TEST(Pocket, NoEventFollowsABallOutOfPlay) {
  for (const char* name : {"cut.json", "follow.json", "break.json"}) {
    auto sim = simulate(load_scene(preset(name)));
    run_until(*sim, 10.0, [&] { return sim->at_rest(); }, 1.0 / 60);
    std::map<std::string, double> gone;  // ball -> when it left play
    int exits = 0;
    for (const Event& e : sim->events()) {
      if (e.kind == "pocketed" || e.kind == "off_table") gone.emplace(e.bodies[0], e.time), ++exits;
      for (const std::string& body : e.bodies)
        if (const auto it = gone.find(body); it != gone.end() && e.time > it->second)
          ADD_FAILURE() << name << ": " << e.kind << " of " << body << " at " << e.time << " s, out of play since "
                        << it->second << " s";
    }
    EXPECT_GT(exits, 0) << name << ": a ball goes down";
  }
}

// A ball rolled along the front rail into the corner pocket, 1 mm off the cushion: it crosses the hole off its axis
// and meets the back's side, which used to be the bare rim (the ball went off the table at 1.5 m/s already).
TEST(Pocket, ABallRunDownTheRailStaysDown) {
  for (double v : {1.5, 3.0, 4.0}) {
    const nlohmann::json doc = {
        {"table", {{"type", "pool"}}},
        {"balls", {{{"id", "a"}, {"position", {0.9, kR, 0.6065}}, {"velocity", {v, 0, 0}},
                    {"angular_velocity", {0, 0, -v / kR}}}}}};
    EXPECT_EQ(pocket_of(scene(doc), "a"), "pocket-right-front") << v << " m/s";
  }
}

// Straight paths along the bed from 15 cm inside the table through each pocket's mouth, at every offset across it and
// up to 60 degrees off its axis, stepped 1 mm until the centre is over the hole or a cushion or jaw stops the ball:
// the back never touches the ball on the way (pool and snooker tables).
TEST(Pocket, TheBackStandsClearOfTheMouth) {
  for (const TableSpec& t : {pool_table(), snooker_table()}) {
    Model m = empty_model();
    add_table(m, t);
    const double r = t.ball_radius;
    for (const Pocket& pocket : m.pockets) {
      const Collider* back = nullptr;
      for (const Collider& c : m.colliders)
        if (c.name == pocket.name + "-back") back = &c;
      ASSERT_NE(back, nullptr) << pocket.name;
      const Vec3 out = std::get<ArcWall>(back->shape).toward, side{-out.z, 0.0, out.x};
      const Vec3 mouth = pocket.center - (t.pocket_shelf + pocket.radius) * out;
      int paths = 0;
      for (double across = -0.07; across <= 0.07; across += 0.0025)
        for (double angle = -60; angle <= 60; angle += 5) {
          const double a = angle * M_PI / 180;
          const Vec3 dir = std::cos(a) * out + std::sin(a) * side;
          Vec3 p = mouth + across * side - 0.15 * out;
          p.y = r;
          for (int k = 0; k < 300; ++k, p += 0.001 * dir) {
            const Vec3 d{p.x - pocket.center.x, 0.0, p.z - pocket.center.z};
            if (glm::length(d) < pocket.radius) break;
            bool blocked = false;
            for (const Collider& c : m.colliders)
              if (std::holds_alternative<Capsule>(c.shape)) blocked = blocked || penetration(c.shape, p, r)->depth > 0;
            if (blocked) break;
            if (k == 0) ++paths;
            const auto pen = penetration(back->shape, p, r);
            ASSERT_TRUE(!pen || pen->depth <= 0) << pocket.name << ": touched at x = " << p.x << ", z = " << p.z;
          }
        }
      EXPECT_GT(paths, 500) << pocket.name;
    }
  }
}

// A lone pocket back (0.065 m inner radius, 2 cm thick, 115 degrees either side of +x, from -0.09 m to 0.05 m) and
// one ball "a" at its axis in no regime, under `gravity` (m/s^2).
Prepared lone_back(const Vec3& gravity = {0, -kG, 0}) {
  const nlohmann::json wall = {{"type", "arc_wall"}, {"center", {0, 0, 0}}, {"radius", 0.065}, {"thickness", 0.02},
                               {"toward", {1, 0, 0}}, {"half_angle_deg", 115}, {"bottom", -0.09}, {"top", 0.05}};
  Prepared p = prepare(scene({{"colliders", {wall}},
                              {"balls", {{{"id", "a"}, {"position", {0, kR, 0}}}}},
                              {"gravity", {gravity.x, gravity.y, gravity.z}}}));
  p.state.rolling_on.assign(1, -1), p.state.sliding_on.assign(1, -1), p.state.asleep.assign(1, 0);
  return p;
}

// The step cap against a pocket's back (contacts.cpp, arc_wall_closing_time) is a lower bound on when a ball comes
// contact_margin into it: a lone wall, balls started inside the cylinder within it and outside the one around it, at up
// to 5 m/s in any direction, over horizons from 0.1 ms to 0.25 s, pushed at the full acceleration bound straight away
// from the axis (from inside) or towards it (from outside), or flying under gravity alone (from inside, the bound
// having nothing across), their paths sampled at 400 points up to the cap.
TEST(Pocket, TheCapNeverPassesTheBack) {
  Prepared p = lone_back();
  const ModelIndex index(p.model);
  State& state = p.state;
  const ArcWall& wall = std::get<ArcWall>(p.model.colliders[0].shape);
  const double margin = p.model.options.contact_margin, a = 2 * kG;
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> unit(-1.0, 1.0), one(0.0, 1.0);
  int inside = 0, outside = 0, flying = 0;
  for (int trial = 0; trial < 30000; ++trial) {
    const bool in = trial % 3 != 1, flies = trial % 3 == 2;
    const double angle = M_PI * unit(rng);
    const double rho = in ? 0.999 * (wall.radius - kR) * std::sqrt(one(rng))
                          : wall.radius + wall.thickness + kR + 1e-4 + 0.1 * one(rng);
    const Vec3 e{std::cos(angle), 0.0, std::sin(angle)};
    const Vec3 p0 = rho * e + Vec3{0.0, 0.05 * unit(rng), 0.0};
    const Vec3 v0 = 5.0 * one(rng) * glm::normalize(Vec3{unit(rng), unit(rng), unit(rng)} + Vec3{1e-9});
    const double horizon = std::pow(10.0, -4 + 3.4 * one(rng));
    const Vec3 push = flies ? Vec3{0.0, -kG, 0.0} : (in ? a : -a) * e;
    const AccelBound bound = flies ? AccelBound{kG, 0.0} : AccelBound{a};
    if (const auto pen = penetration(wall, p0, kR); pen && pen->depth > -margin) continue;
    set_position(state.x, 0, p0);
    set_velocity(state.x, 0, v0);
    const double cap =
        std::min(horizon, collider_contact_time(p.model, index, state, state.x.data(), 0, horizon, bound));
    ++(flies ? flying : in ? inside : outside);
    // A flying ball's cap is exact: at the cap itself it may be contact_margin in, to rounding.
    for (int k = 1; k <= 400; ++k) {
      const double t = cap * k / 400;
      const auto pen = penetration(wall, p0 + v0 * t + 0.5 * t * t * push, kR);
      ASSERT_TRUE(!pen || pen->depth < margin + 1e-15)
          << "trial " << trial << (flies ? " (flying)" : in ? " (inside)" : " (outside)") << ": " << pen->depth
          << " m in at t = " << t << " s, before the cap " << cap;
    }
  }
  EXPECT_GT(inside, 9000);
  EXPECT_GT(outside, 9000);
  EXPECT_GT(flying, 9000);
}

// The cap is also no shorter than it needs to be inside the back, where a ball leaving it used to fly off in ever
// growing steps and close on its far side in ever smaller ones (24 steps in the cut): a ball flying across the axis at
// 1 m/s is capped where its straight path leaves the cylinder, and one moving along the wall 5 mm inside it, pushed
// at 2g across, at more than twice the time in which it could close those 5 mm at its speed.
TEST(Pocket, TheCapLetsABallCrossTheHole) {
  Prepared p = lone_back();
  const ModelIndex index(p.model);
  State& state = p.state;
  const double inner = 0.065 - kR + p.model.options.contact_margin;
  auto cap = [&](const Vec3& at, const Vec3& v, const AccelBound& a) {
    set_position(state.x, 0, at);
    set_velocity(state.x, 0, v);
    return collider_contact_time(p.model, index, state, state.x.data(), 0, 0.25, a);
  };
  EXPECT_NEAR(cap({0, 0, 0}, {0, -0.5, 1.0}, {kG, 0.0}), inner / 1.0, 1e-12) << "flying across the axis";
  const double along = cap({inner - 0.005, 0, 0}, {0, 0, 1.0}, 2 * kG);  // toward the back
  EXPECT_GT(along, 2 * 0.005 / 1.0) << "along the wall";
}

// In a flight step (time_to_possible_contact with `flight`) a flying ball's path bends across only by gravity's
// horizontal part: under plain gravity a ball moving along the back 5 mm inside it is capped exactly where its
// straight path comes contact_margin in; under gravity tilted by 1 m/s^2 the cap still holds on the exact parabola.
TEST(Pocket, AFlightStepBendsThePathByGravityAcrossAlone) {
  for (const double tilt : {0.0, 1.0}) {
    Prepared p = lone_back({tilt, -kG, 0});
    const ModelIndex index(p.model);
    State& state = p.state;
    const double margin = p.model.options.contact_margin, inner = 0.065 - kR + margin;
    const Vec3 p0{inner - 0.005, 0, 0}, v0{0, -0.2, 1.0}, g = p.model.options.gravity;
    set_position(state.x, 0, p0);
    set_velocity(state.x, 0, v0);
    BroadPhase broad;
    const double cap = time_to_possible_contact(p.model, index, state, state.x.data(), 0.25, broad, nullptr, true);
    if (tilt == 0) {
      EXPECT_NEAR(cap, std::sqrt(inner * inner - p0.x * p0.x) / v0.z, 1e-12) << "the straight path's";
    }
    ASSERT_LT(cap, 0.25);
    for (int k = 1; k <= 1000; ++k) {
      const double t = cap * k / 1000;
      const auto pen = penetration(p.model.colliders[0].shape, p0 + v0 * t + 0.5 * t * t * g, kR);
      ASSERT_TRUE(!pen || pen->depth < margin + 1e-15) << "tilt " << tilt << ": " << pen->depth << " m in at t = " << t
                                                      << " s, before the cap " << cap;
    }
  }
}

// The back's lining: restitution 0.3 for a pool ball at 1 m/s (material.cpp says so and gives the damping for it),
// falling with speed under Hunt-Crossley's law.
TEST(Pocket, TheLiningGivesBackAThird) {
  EXPECT_NEAR(restitution_at(default_ball_pocket(), kM, 1.0), 0.3, 1e-4);
  EXPECT_LT(restitution_at(default_ball_pocket(), kM, 10.0), 0.05);
  EXPECT_NEAR(damping_for_restitution(default_ball_pocket(), kM, 1.0, 0.3), default_ball_pocket().damping, 1e-6);
}

// The rigid model pockets a ball as its centre crosses the rim, before the back could touch it: it runs pool tables,
// backs and all, and refuses any other wall, also one centred on a pocket that reaches out over the table.
TEST(Pocket, TheRigidModelLeavesTheBackOut) {
  Scene s = load_scene(preset("cut.json"));
  s.model.options.contact = ContactModel::Rigid;
  EXPECT_EQ(pocket_of(s, "1"), "pocket-right-front");
  const Prepared p = prepare(s);
  const Pocket& pocket = p.model.pockets.front();
  const ArcWall out_on_table{{0, 0, 0}, 0.2, 0.02, {1, 0, 0}, 1.0, -0.1, 0.1};
  const ArcWall over_the_table{pocket.center, 1.0, 0.02, {1, 0, 0}, 0.6, -0.1, 0.1};  // centred on the pocket
  for (const Collider& wall : {Collider{"wall", out_on_table, kBallCushion},
                               Collider{"wall", over_the_table, kBallCushion},
                               Collider{pocket.name + "-back", over_the_table, kBallCushion}}) {
    Scene with = s;
    with.model.colliders.push_back(wall);
    try {
      simulate(with);
      ADD_FAILURE() << "a wall out on the table must be refused";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("collider '" + wall.name + "'"), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace shotlab::test
