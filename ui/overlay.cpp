#include <cmath>
#include <cstdio>

#include "engine/cue.hpp"
#include "ui/panels.hpp"

namespace shotlab {

ImU32 motion_color(Motion m, float alpha) {
  const int a = static_cast<int>(alpha * 255);
  switch (m) {
    case Motion::Sliding: return IM_COL32(255, 140, 30, a);
    case Motion::Rolling: return IM_COL32(60, 200, 255, a);
    case Motion::Airborne: return IM_COL32(255, 60, 220, a);
    case Motion::Spinning: return IM_COL32(255, 240, 60, a);
    case Motion::Stationary: return IM_COL32(200, 200, 200, a);
    case Motion::Pocketed: return IM_COL32(90, 90, 90, a);
  }
  return IM_COL32(255, 255, 255, a);
}

namespace {

ImVec2 v2(const glm::dvec2& p) { return {static_cast<float>(p.x), static_cast<float>(p.y)}; }

void line(ImDrawList* d, const Viewport& vp, const Vec3& a, const Vec3& b, ImU32 color, float width) {
  const auto pa = vp.project(a), pb = vp.project(b);
  if (pa && pb) d->AddLine(v2(*pa), v2(*pb), color, width);
}

void arrow(ImDrawList* d, const Viewport& vp, const Vec3& from, const Vec3& to, ImU32 color, float width) {
  const auto pa = vp.project(from), pb = vp.project(to);
  if (!pa || !pb) return;
  const glm::dvec2 dir = *pb - *pa;
  const double len = glm::length(dir);
  if (len < 2) return;
  const glm::dvec2 u = dir / len, n{-u.y, u.x};
  const double head = std::min(10.0, len * 0.4);
  d->AddLine(v2(*pa), v2(*pb - u * head * 0.5), color, width);
  d->AddTriangleFilled(v2(*pb), v2(*pb - u * head + n * head * 0.45), v2(*pb - u * head - n * head * 0.45), color);
}

void paths(ImDrawList* d, const Viewport& vp, const Trails& trails, float alpha, float width, bool by_motion) {
  for (const auto& path : trails)
    for (size_t k = 1; k < path.size(); ++k) {
      const ImU32 c = by_motion ? motion_color(path[k].motion, alpha) : IM_COL32(220, 220, 220, int(alpha * 255));
      line(d, vp, path[k - 1].position, path[k].position, c, width);
    }
}

// Aim line from the cue ball to the first ball it would hit (the ghost ball: where the cue ball's centre is at
// contact), the object ball's line of departure, the cut angle, and the cue stick behind the ball.
void aim(ImDrawList* d, const Viewport& vp, const Lab& lab) {
  const CueStrike& cue = *lab.scene.cue;
  const int c = scene_ball(lab.scene, cue.ball);
  if (c < 0) return;
  const Vec3 p = lab.scene.balls[c].position;
  const double r = lab.scene.balls[c].spec.radius;
  const Vec3 dir = aim_direction(cue.aim);
  double best = 4.0;  // m: the line's length when it hits no ball
  int hit = -1;
  for (int j = 0; j < static_cast<int>(lab.scene.balls.size()); ++j) {
    if (j == c) continue;
    // Where the centre line comes within r_c + r_j of ball j: |p + s dir - q| = R.
    const Vec3 q = lab.scene.balls[j].position, w = p - q;
    const double R = r + lab.scene.balls[j].spec.radius;
    const double b = glm::dot(w, dir), disc = b * b - (glm::dot(w, w) - R * R);
    if (disc < 0) continue;
    const double s = -b - std::sqrt(disc);
    if (s > 0 && s < best) best = s, hit = j;
  }
  if (lab.scene.table) {  // stop the line at the cushion noses
    const double hx = lab.scene.table->length / 2 - r, hz = lab.scene.table->width / 2 - r;
    if (dir.x != 0) best = std::min(best, ((dir.x > 0 ? hx : -hx) - p.x) / dir.x);
    if (dir.z != 0) best = std::min(best, ((dir.z > 0 ? hz : -hz) - p.z) / dir.z);
  }
  const Vec3 ghost = p + dir * std::max(best, 0.0);
  line(d, vp, p, ghost, IM_COL32(255, 255, 255, 200), 1.5f);
  // Cue stick: behind the ball along the aim, raised by the elevation.
  const Vec3 back = -dir * std::cos(cue.elevation) + Vec3{0, std::sin(cue.elevation), 0};
  line(d, vp, p + back * (r * 1.6), p + back * (r * 1.6 + 1.0), IM_COL32(200, 160, 100, 230), 5.0f);
  const auto g = vp.project(ghost);
  if (!g) return;
  d->AddCircle(v2(*g), static_cast<float>(vp.screen_radius(ghost, r)), IM_COL32(255, 255, 255, 220), 32, 1.5f);
  if (hit < 0) return;
  const Vec3 q = lab.scene.balls[hit].position;
  const Vec3 out = glm::normalize(Vec3{q.x - ghost.x, 0, q.z - ghost.z});
  line(d, vp, q, q + out * 0.4, IM_COL32(255, 230, 120, 220), 1.5f);
  const double cut = std::acos(std::clamp(glm::dot(out, dir), -1.0, 1.0)) * 180 / M_PI;
  char text[32];
  std::snprintf(text, sizeof text, "cut %.1f deg", cut);
  d->AddText(ImVec2(static_cast<float>(g->x) + 14, static_cast<float>(g->y) - 20), IM_COL32(255, 255, 255, 255), text);
}

// Velocity (white, 0.15 m per m/s), spin (yellow, 2 mm per rad/s, right-hand rule), contact forces (red, length
// growing with log(1 + F / 1 N) so that a 2 N resting contact and a 2 kN collision both show).
void vectors(ImDrawList* d, const Viewport& vp, const Lab& lab) {
  const Frame& f = lab.frame();
  const ViewFlags& v = lab.settings.view;
  for (int i = 0; i < f.state.ball_count(); ++i) {
    if (!f.state.in_play[i]) continue;
    const Vec3 p = position(f.state.x, i);
    if (v.velocity) arrow(d, vp, p, p + 0.15 * velocity(f.state.x, i), IM_COL32(255, 255, 255, 255), 2.5f);
    if (v.spin) arrow(d, vp, p, p + 0.002 * spin(f.state.x, i), IM_COL32(255, 230, 40, 255), 2.5f);
  }
  if (!v.forces) return;
  for (const Contact& c : contacts(lab.shot ? lab.shot->sim().model() : lab.table_model, f.state)) {
    const double len = 0.03 * std::log1p(c.force.normal);
    const Vec3 dir = unit_or_zero(c.force.force);
    arrow(d, vp, c.point, c.point + dir * len, IM_COL32(255, 60, 60, 255), 2.5f);
    if (const auto s = vp.project(c.point)) {
      d->AddCircleFilled(v2(*s), 3.5f, IM_COL32(255, 60, 60, 255));
      if (c.other_ball >= 0) {
        char text[32];
        std::snprintf(text, sizeof text, "%.0f N", c.force.normal);
        d->AddText(ImVec2(static_cast<float>(s->x) + 6, static_cast<float>(s->y) + 4), IM_COL32(255, 120, 120, 255), text);
      }
    }
  }
}

}  // namespace

void draw_overlay(const Lab& lab, const Viewport& vp, ImDrawList* d) {
  const ViewFlags& v = lab.settings.view;
  if (v.ghost) paths(d, vp, lab.ghost, 0.35f, 1.5f, false);
  if (lab.shot) {
    if (v.trails) paths(d, vp, lab.trails(lab.view_time), 0.9f, 2.5f, true);
  } else {
    if (v.predicted)
      if (const auto p = lab.prediction()) paths(d, vp, p->paths, 0.7f, 2.0f, true);
    if (v.aim && lab.scene.cue) aim(d, vp, lab);
  }
  for (const Rod& rod : lab.scene.model.rods)
    if (rod.ball < lab.frame().state.ball_count())
      line(d, vp, rod.anchor, position(lab.frame().state.x, rod.ball), IM_COL32(180, 180, 190, 255), 1.5f);
  const Frame& f = lab.frame();
  if (lab.selected < f.state.ball_count()) {
    const Vec3 p = position(f.state.x, lab.selected);
    if (const auto s = vp.project(p))
      d->AddCircle(v2(*s), static_cast<float>(vp.screen_radius(p, lab.scene.balls[lab.selected].spec.radius)) + 4,
                   IM_COL32(120, 255, 120, 200), 32, 2.0f);
  }
  vectors(d, vp, lab);
}

}  // namespace shotlab
