#include "shotlab/collision_probe.hpp"

#include <algorithm>
#include <cmath>

#include "shotlab/simulation.hpp"

namespace shotlab {

CollisionProbe probe_collision(const ContactMaterial& material, double mass, double radius, double speed,
                               bool ball_ball, const IntegratorOptions& integrator) {
  Model model = empty_model();
  model.options.gravity = Vec3{0.0};
  model.integrator = integrator;
  ContactMaterial normal_only = material;
  normal_only.friction = normal_only.rolling_resistance = normal_only.spin_friction = 0;
  State state;
  const double gap = 1e-4;  // m: start just apart so that the whole contact is resolved
  if (ball_ball) {
    model.materials[kBallBall] = normal_only;
    model.balls = {{"a", mass, radius}, {"b", mass, radius}};
    state.x.assign(18, 0.0);
    set_position(state.x, 0, {-radius - gap / 2, 0, 0});
    set_position(state.x, 1, {radius + gap / 2, 0, 0});
    // Equal and opposite speeds: the relative speed is `speed`, the centre of mass stays put.
    set_velocity(state.x, 0, {speed / 2, 0, 0});
    set_velocity(state.x, 1, {-speed / 2, 0, 0});
    state.in_play = {1, 1};
  } else {
    model.materials["probe"] = normal_only;
    model.colliders.push_back({"wall", Plane{{radius + gap, 0, 0}, {-1, 0, 0}, {}}, "probe"});
    model.balls = {{"a", mass, radius}};
    state.x.assign(9, 0.0);
    set_velocity(state.x, 0, {speed, 0, 0});
    state.in_play = {1};
  }
  Simulation sim(model, state);
  CollisionProbe out;
  sim.set_observer([&](const StepView& step) {
    const auto list = contacts(step.model, step.state);
    if (list.empty()) return;
    ++out.steps;
    double force = 0;
    for (const Contact& c : list) {
      out.peak_penetration = std::max(out.peak_penetration, c.depth);
      force = std::max(force, c.force.normal);
    }
    out.peak_force = std::max(out.peak_force, force);
    out.time.push_back(step.t1);
    out.force.push_back(force);
  });
  double begin = -1, end = -1;
  // The contact lasts well under a millisecond for any realistic material; allow a second for soft ones, and a
  // fifth of one in contact (overdamped balls creep apart for ever).
  const double slice = 1e-4, stuck = 0.2;
  for (int k = 0; k < 10000 && end < 0 && sim.status() == Status::Ok; ++k) {
    if (begin >= 0 && sim.time() > begin + stuck) break;
    sim.advance(slice);
    for (const Event& e : sim.events()) {
      if (e.kind == "contact_begin" && begin < 0) begin = e.time;
      if (e.kind == "contact_end" && begin >= 0) end = e.time;
    }
  }
  if (sim.status() != Status::Ok) out.failure = sim.diagnostic();
  out.parted = begin < 0 || end > begin || !out.failure.empty();
  out.contact_time = begin < 0 ? 0 : out.parted ? end - begin : sim.time() - begin;
  for (double& t : out.time) t -= std::max(begin, 0.0);
  // An overdamped contact pushes no more long before it ends (the clamp holds its force at zero while the ball creeps
  // out), and the step that ends past it sees no contact: the curve goes on at zero to the end it reports.
  if (!out.time.empty() && out.time.back() < out.contact_time) {
    out.time.push_back(out.contact_time);
    out.force.push_back(0.0);
  }
  const double after = ball_ball ? velocity(sim.state().x, 1).x - velocity(sim.state().x, 0).x
                                 : -velocity(sim.state().x, 0).x;
  out.restitution = after / speed;
  return out;
}

}  // namespace shotlab
