#include "shotlab/diagnostics.hpp"

#include "contacts.hpp"

namespace shotlab {

Energy energy(const Model& model, const State& state) {
  BroadPhase broad;
  return energy(model, ModelIndex(model), state, broad, true);
}

Energy energy(const Model& model, const ModelIndex& index, const State& state, BroadPhase& broad, bool with_inactive) {
  Energy e;
  for (int i = 0; i < state.ball_count(); ++i) {
    if (!state.in_play[i] || (state.sleeping(i) && !with_inactive)) continue;
    const BallMotion b = ball_motion(model, state, i);
    e.kinetic += b.translation + b.rotation;
    e.potential -= model.balls[i].mass * glm::dot(model.options.gravity, position(state.x, i));
  }
  for_each_contact(model, index, state, state.x.data(), broad, nullptr, [&](const Contact& c) {
    const ContactMaterial& m = c.other_ball >= 0 ? index.ball_ball() : index.collider_material(c.collider);
    e.elastic += elastic_energy(m, c.depth);
  }, with_inactive);
  return e;
}

BallMotion ball_motion(const Model& model, const State& state, int i) {
  const BallSpec& b = model.balls[i];
  const Vec3 v = velocity(state.x, i), w = spin(state.x, i);
  return {0.5 * b.mass * glm::dot(v, v), 0.5 * b.inertia() * glm::dot(w, w), b.mass * v};
}

Vec3 momentum(const Model& model, const State& state) {
  Vec3 p{0.0};
  for (int i = 0; i < state.ball_count(); ++i)
    if (state.in_play[i]) p += ball_motion(model, state, i).momentum;
  return p;
}

std::vector<Contact> contacts(const Model& model, const State& state) {
  std::vector<Contact> out;
  BroadPhase broad;
  for_each_contact(model, ModelIndex(model), state, state.x.data(), broad, nullptr,
                   [&](const Contact& c) { out.push_back(c); }, true);
  return out;
}

}  // namespace shotlab
