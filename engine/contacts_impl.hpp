// Template body of for_each_contact (contacts.hpp); not for direct inclusion.
#pragma once

namespace shotlab {

template <class Fn>
void for_each_contact(const Model& model, const State& state, const double* x, ContactCache& cache, Fn&& fn,
                      bool with_inactive) {
  const double k = model.options.friction_sharpness;
  const int n = state.ball_count();
  // Ball against static colliders: B has zero velocity.
  for (int i = 0; i < n; ++i) {
    if (!state.in_play[i] || ((state.sleeping(i) || state.rolling(i)) && !with_inactive)) continue;
    const double r = model.balls[i].radius;
    const Vec3 p = position(x, i), v = velocity(x, i), w = spin(x, i);
    for (size_t c = 0; c < model.colliders.size(); ++c) {
      if (!cache.collider_bounds[c].may_touch(p, r)) continue;
      const auto pen = penetration(model.colliders[c].shape, p, r, 0.0);
      if (!pen || pen->depth <= 0) continue;
      const Vec3& nrm = pen->normal;
      const ContactKinematics kin{nrm, pen->depth, v, v + r * glm::cross(nrm, w), glm::dot(w, nrm), r};
      const ContactForce f = contact_force(*cache.collider_material[c], kin, k);
      fn(Contact{i, -1, static_cast<int>(c), pen->depth, nrm, p - r * nrm, f});
    }
  }
  // Ball against ball: n points from j to i; A's contact point is at -R_i n, B's at +R_j n.
  overlapping_pairs(model, state, x, cache);
  const ContactMaterial& bb = *cache.ball_ball;
  for (const auto& [i, j] : cache.pairs) {
    if (state.sleeping(i) && state.sleeping(j) && !with_inactive) continue;
    const double ri = model.balls[i].radius, rj = model.balls[j].radius;
    const Vec3 d = position(x, i) - position(x, j);
    const double dist = glm::length(d);
    const Vec3 nrm = dist > 0 ? d / dist : kUp;
    const Vec3 wi = spin(x, i), wj = spin(x, j);
    const Vec3 vrel = velocity(x, i) - velocity(x, j);
    const Vec3 slip = vrel + ri * glm::cross(nrm, wi) + rj * glm::cross(nrm, wj);
    const ContactKinematics kin{nrm, ri + rj - dist, vrel, slip, glm::dot(wi - wj, nrm), ri};
    fn(Contact{i, j, -1, kin.depth, nrm, position(x, i) - ri * nrm, contact_force(bb, kin, k)});
  }
}

}  // namespace shotlab
