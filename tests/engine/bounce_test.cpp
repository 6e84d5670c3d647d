// The bounce (Options::bounce_regime, bounce.hpp): a ball sliding onto the bed alone lands, hops and settles in
// reduced form. Against Coulomb's law over whole landings (while a contact slides, its friction impulse is mu times
// its normal impulse: Routh's impulse relation), against the integrated full model, and only where that form holds.
#include <cmath>

#include "engine/bounce.hpp"
#include "engine/model_index.hpp"
#include "support.hpp"

namespace shotlab::test {
namespace {

constexpr double kMu = 0.2;  // the default cloth's friction

// A ball let go `drop` m above the cloth, moving along x at vx with spin w.
nlohmann::json drop_scene(double drop, double vx, const Vec3& w, bool bounce, double tol = 1e-7) {
  nlohmann::json doc = cloth_scene({{{"id", "b"}, {"position", {0, kR + drop, 0}}, {"velocity", {vx, 0, 0}},
                                     {"angular_velocity", {w.x, w.y, w.z}}}});
  doc["integrator"] = {{"method", "cash_karp54"}, {"abs_tol", tol}, {"rel_tol", tol}, {"max_steps_per_call", 1000000}};
  doc["model"] = {{"bounce_regime", bounce}};
  return doc;
}

StateVector state_at(const nlohmann::json& doc, double t) {
  auto sim = simulate(scene(doc));
  advance_to(*sim, t);
  return sim->state().x;
}

// Sliding through its landings, the ball loses mu P / m of its speed along the bed and gains 5 mu P / (2 m R) of
// spin, P the bed's normal impulse, which its vertical motion gives: m dv_y = P - m g dt. Between any two times.
TEST(Bounce, ASlidingLandingTradesMuTimesItsNormalImpulse) {
  const nlohmann::json doc = drop_scene(0.01, 2.0, {0, 0, 0}, true);
  auto sim = simulate(scene(doc));
  advance_to(*sim, 0.2);
  const int landings = static_cast<int>(std::count_if(sim->events().begin(), sim->events().end(), [](const Event& e) {
    return e.kind == "contact_begin";
  }));
  ASSERT_GE(landings, 3) << "three landings or more within 0.2 s";
  for (double t : {0.05, 0.1, 0.2}) {
    const StateVector x0 = state_at(doc, 0.0), x1 = state_at(doc, t);
    const double impulse = kM * (velocity(x1, 0).y - velocity(x0, 0).y) + kM * kG * t;  // N s
    ASSERT_GT(impulse, 0.1 * kM * kG * t) << "at " << t << " s the bed has pushed";
    EXPECT_NEAR(velocity(x1, 0).x - velocity(x0, 0).x, -kMu * impulse / kM, 1e-9) << "at " << t << " s";
    EXPECT_NEAR(spin(x1, 0).z - spin(x0, 0).z, -2.5 * kMu * impulse / (kM * kR), 1e-7) << "at " << t << " s";
  }
}

// Landings, hops and settling at the default tolerance, bounced, against the full model integrated at 1e-11: the
// same path to within the tolerance, at a fraction of the right-hand sides of the same run integrated.
TEST(Bounce, FollowsTheIntegratedFullModel) {
  const Vec3 spin_about_up{0, 25, 0}, draw{0, 0, 40};
  for (const Vec3& w : {Vec3{0.0}, spin_about_up, draw}) {
    auto fast = simulate(scene(drop_scene(0.01, 1.5, w, true)));
    auto integrated = simulate(scene(drop_scene(0.01, 1.5, w, false)));
    auto reference = simulate(scene(drop_scene(0.01, 1.5, w, false, 1e-11)));
    for (double t : {0.04, 0.08, 0.12, 0.16}) {
      advance_to(*fast, t);
      advance_to(*integrated, t);
      advance_to(*reference, t);
      const StateVector &x = fast->state().x, &ref = reference->state().x;
      EXPECT_LT(glm::length(position(x, 0) - position(ref, 0)), 1e-7) << "spin " << w.y << ", " << w.z << " at " << t;
      EXPECT_LT(glm::length(velocity(x, 0) - velocity(ref, 0)), 1e-7) << "spin " << w.y << ", " << w.z << " at " << t;
      EXPECT_LT(kR * glm::length(spin(x, 0) - spin(ref, 0)), 1e-7) << "spin " << w.y << ", " << w.z << " at " << t;
    }
    std::printf("[ bounce   ] spin (%g, %g): %ld steps, %ld right-hand sides bounced; %ld, %ld integrated\n", w.y, w.z,
                fast->stats().steps, fast->stats().rhs_evaluations, integrated->stats().steps,
                integrated->stats().rhs_evaluations);
    EXPECT_LT(3 * fast->stats().rhs_evaluations, integrated->stats().rhs_evaluations);
    // The contacts begin and end where the reference's do.
    for (const char* kind : {"contact_begin", "contact_end", "airborne", "landed"}) {
      const double a = event_time(*fast, kind, "b"), b = event_time(*reference, kind, "b");
      ASSERT_GE(b, 0) << kind;
      EXPECT_NEAR(a, b, 1e-8) << kind;
    }
  }
}

// The jump preset's hops down to rest on the cloth: every contact with the bed begins and ends, and the ball takes
// off and lands (rises past kSupportGap and comes back), when the full model integrated at 1e-11 throughout has it do
// so (the onset of a contact at zero depth, its end 1 nm deep, as for integrated steps), to well under the
// tolerance's worth of time.
TEST(Bounce, AJumpShotsHopsHappenWhenTheFullModelsDo) {
  auto events = [](bool bounce, double tol) {
    Scene s = load_scene(preset("jump.json"));
    s.model.options.bounce_regime = s.model.options.flight_regime = bounce;  // the reference integrates every hop
    s.model.integrator.abs_tol = s.model.integrator.rel_tol = tol;
    auto sim = simulate(s);
    advance_to(*sim, 0.5);
    std::vector<Event> out;
    for (const Event& e : sim->events())
      if (e.kind == "contact_begin" || e.kind == "contact_end" || e.kind == "airborne" || e.kind == "landed")
        out.push_back(e);
    return out;
  };
  const std::vector<Event> bounced = events(true, 1e-7), reference = events(false, 1e-11);
  ASSERT_GE(reference.size(), 15u) << "the hops of the jump";
  ASSERT_EQ(bounced.size(), reference.size());
  for (size_t k = 0; k < reference.size(); ++k) {
    EXPECT_EQ(bounced[k].kind, reference[k].kind) << k;
    EXPECT_EQ(bounced[k].bodies, reference[k].bodies) << k;
    EXPECT_NEAR(bounced[k].time, reference[k].time, 5e-8) << k << ": " << reference[k].kind;
  }
}

// A landing whose friction stops the slip inside the contact: the bounce ends before the slip comes near its band
// (also when one step of its equation takes the slip from one side of the band to the other) and the island integrates
// the rest, as the full model at 1e-11 has it.
TEST(Bounce, ASlipThatStopsInTheContactIsLeftToTheFullModel) {
  for (double vy : {-0.1, -0.2}) {
    auto run = [&](bool bounce, double tol) {
      nlohmann::json doc = drop_scene(0.0, 0.0, {0, 0, 0}, bounce, tol);
      doc["balls"][0]["velocity"] = {0.003, vy, 0};
      return simulate(scene(doc));
    };
    auto fast = run(true, 1e-7), reference = run(false, 1e-11);
    for (double t : {6e-4, 2e-3}) {  // after the contact (inside it the integrated steps' own error is up to 9e-7)
      ASSERT_EQ(fast->advance(t - fast->time()), Status::Ok);
      ASSERT_EQ(reference->advance(t - reference->time()), Status::Ok);
      const StateVector &x = fast->state().x, &ref = reference->state().x;
      EXPECT_LT(glm::length(velocity(x, 0) - velocity(ref, 0)), 1e-7) << vy << " at " << t;
      EXPECT_LT(kR * glm::length(spin(x, 0) - spin(ref, 0)), 1e-7) << vy << " at " << t;
    }
  }
}

// Only a ball alone on the level bed, its slip and spin saturated or zero, in the full model, bounces.
TEST(Bounce, OnlyWhereItsFormHolds) {
  auto bounces = [](const nlohmann::json& doc, double horizon = 1e-3) {
    Prepared p = prepare(scene(doc));
    const ModelIndex index(p.model);
    auto b = bed_bounce_of(p.model, p.state, index, p.state.x.data(), 0);
    return b && follow(p.model, index, *b, horizon);
  };
  EXPECT_TRUE(bounces(drop_scene(0.0, 1.0, {0, 0, 0}, true))) << "sliding on the bed";
  EXPECT_TRUE(bounces(drop_scene(-1e-6, 0.0, {0, 0, 0}, true))) << "at rest, pressed in: no tangential force at all";
  EXPECT_FALSE(bounces(drop_scene(0.0, 1.0, {0, 0, 0}, false))) << "the model option off";
  EXPECT_FALSE(bounces(drop_scene(1e-3, 1.0, {0, 0, 0}, true))) << "above the margin: a flight";
  EXPECT_FALSE(bounces(drop_scene(0.0, 1.0, {0, 0, -1.0 / kR}, true))) << "rolling: rolling resistance would act";
  EXPECT_FALSE(bounces(drop_scene(0.0, 1.0, {0, 0, -(1.0 - 4e-4) / kR}, true))) << "its slip inside the band";
  EXPECT_FALSE(bounces(drop_scene(0.0, 1.0, {0, 5e-4 / kR, 0}, true))) << "its spin about the normal inside the band";
  nlohmann::json fixed = drop_scene(0.0, 1.0, {0, 0, 0}, true);
  fixed["integrator"] = {{"method", "rk4"}, {"fixed_step", 1e-5}};
  EXPECT_FALSE(bounces(fixed)) << "a fixed step would not end at an impact";
  {  // resting exactly on the surface, unmoving: the bounce it starts moves on
    Prepared at_rest = prepare(scene(drop_scene(0.0, 0.0, {0, 0, 0}, true)));
    at_rest.state.x[1] = kR;
    const ModelIndex index(at_rest.model);
    auto b = bed_bounce_of(at_rest.model, at_rest.state, index, at_rest.state.x.data(), 0);
    ASSERT_TRUE(b && follow(at_rest.model, index, *b, 1.0));
    EXPECT_GT(b->end, 1e-9) << "not a step of round-off";
  }
  nlohmann::json pair = drop_scene(0.0, 1.0, {0, 0, 0}, true);
  pair["balls"].push_back({{"id", "c"}, {"position", {2 * kR + 5e-7, kR, 0}}});
  EXPECT_FALSE(bounces(pair)) << "another ball within the margin";
}

// A step cut short of its bounce's end (by another ball's cap) leaves the next step to go on along the same track, from
// exactly where the ball got to; a ball moved by anything else, or a bounce at its end, is followed anew.
TEST(Bounce, GoesOnOverTheNextStepOnlyFromWhereItLed) {
  Prepared p = prepare(scene(drop_scene(0.0, 1.0, {0, 0, 0}, true)));
  p.state.x[4] = -0.05;  // landing at 5 cm/s
  const ModelIndex index(p.model);
  auto b = bed_bounce_of(p.model, p.state, index, p.state.x.data(), 0);
  ASSERT_TRUE(b && follow(p.model, index, *b, 1.0));
  const double h = 0.4 * b->end;
  StateVector x = p.state.x;
  b->apply(h, x.data());
  BedBounce last = *b;
  last.from += h;  // as the island moves it on to its step's end
  BedBounce next = *bed_bounce_of(p.model, p.state, index, x.data(), 0);
  ASSERT_TRUE(goes_on(last, x.data(), next));
  EXPECT_EQ(next.track, b->track);
  EXPECT_DOUBLE_EQ(next.left(), 0.6 * b->end);
  StateVector at = x;
  next.apply(0.0, at.data());
  EXPECT_EQ(at, x) << "it starts exactly where the last step ended";
  x[3] = std::nextafter(x[3], 2.0);  // snapped by a regime, say
  EXPECT_FALSE(goes_on(last, x.data(), next));
  last.from = b->end;
  b->apply(b->end, x.data());
  EXPECT_FALSE(goes_on(last, x.data(), next)) << "at its end";
}

}  // namespace
}  // namespace shotlab::test
