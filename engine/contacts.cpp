#include "contacts.hpp"

#include <algorithm>
#include <limits>
#include <numeric>

namespace shotlab {

ContactCache::ContactCache(const Model& model) : ball_ball(&model.material(kBallBall)) {
  for (const Collider& c : model.colliders) collider_material.push_back(&model.material(c.material));
}

namespace {

// In-play balls sorted by the left end of their x extent, for sweep-and-prune.
void sort_by_x(const Model& model, const State& state, const double* x, std::vector<int>& order) {
  order.clear();
  for (int i = 0; i < state.ball_count(); ++i)
    if (state.in_play[i]) order.push_back(i);
  std::sort(order.begin(), order.end(), [&](int a, int b) {
    return x[9 * a] - model.balls[a].radius < x[9 * b] - model.balls[b].radius;
  });
}

// Time for a gap (m) to close at initial closing speed s (m/s) and closing acceleration at most a (m/s^2):
// the positive root of gap = s t + a t^2 / 2, written to stay accurate when a or s is small.
double closing_time(double gap, double s, double a) {
  const double den = s + std::sqrt(s * s + 2.0 * a * gap);
  return den > 0 ? 2.0 * gap / den : std::numeric_limits<double>::infinity();
}

}  // namespace

void overlapping_pairs(const Model& model, const State& state, const double* x, ContactCache& cache, double slack) {
  cache.pairs.clear();
  sort_by_x(model, state, x, cache.order);
  const auto& order = cache.order;
  for (size_t a = 0; a < order.size(); ++a) {
    const int i = order[a];
    const Vec3 pi = position(x, i);
    const double ri = model.balls[i].radius;
    for (size_t b = a + 1; b < order.size(); ++b) {
      const int j = order[b];
      const double rj = model.balls[j].radius;
      if (x[9 * j] - rj >= pi.x + ri + slack) break;  // sorted: no later ball reaches i along x
      const Vec3 d = pi - position(x, j);
      const double reach = ri + rj + slack;
      if (glm::dot(d, d) < reach * reach) cache.pairs.emplace_back(i, j);
    }
  }
}

double time_to_possible_contact(const Model& model, const State& state, const double* x) {
  // Relative acceleration bound outside contacts: gravity plus cloth friction, generously twice |g|.
  const double a = 2.0 * glm::length(model.options.gravity);
  const double margin = model.options.contact_margin;
  double best = std::numeric_limits<double>::infinity();
  double vmax = 0;
  const int n = state.ball_count();
  for (int i = 0; i < n; ++i) {
    if (!state.active(i)) continue;  // a sleeping ball does not move towards anything
    const Vec3 p = position(x, i);
    const double s = glm::length(velocity(x, i));
    vmax = std::max(vmax, s);
    for (const Collider& c : model.colliders) {
      const auto pen = penetration(c.shape, p, model.balls[i].radius);
      if (pen && pen->depth <= 0) best = std::min(best, closing_time(margin - pen->depth, s, a));
      // A ball in the rolling regime ignores its support's geometry: it must not roll far over a pocket's edge.
      if (state.rolling(i)) best = std::min(best, closing_time(hole_gap(c.shape, p) + margin, s, a));
    }
  }
  // Ball pairs: sweep along x, and skip pairs whose x gap is larger than anything closable before `best`.
  std::vector<int> order;
  sort_by_x(model, state, x, order);
  for (size_t ia = 0; ia < order.size(); ++ia) {
    const int i = order[ia];
    const Vec3 pi = position(x, i), vi = velocity(x, i);
    const double ri = model.balls[i].radius;
    for (size_t ib = ia + 1; ib < order.size(); ++ib) {
      const int j = order[ib];
      const double rj = model.balls[j].radius;
      const double closable = std::isfinite(best) ? 2.0 * vmax * best + a * best * best : best;
      if (x[9 * j] - rj - (pi.x + ri) > closable) break;
      if (state.sleeping(i) && state.sleeping(j)) continue;
      const double gap = glm::length(pi - position(x, j)) - ri - rj;
      if (gap <= 0) continue;  // already touching: the contact force is resolved by error control
      const double s = glm::length(vi) + glm::length(velocity(x, j));
      best = std::min(best, closing_time(gap + margin, s, a));
    }
  }
  return best;
}

}  // namespace shotlab
