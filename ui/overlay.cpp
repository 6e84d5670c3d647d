// The 2D overlay over the 3D view (ImGui's background draw list): trails, predicted paths, the aim line with its
// ghost ball and cut angle, kept shots and the A trails of the A/B comparison, the position target, ball labels, the
// centre of mass, the ball-in-hand zone, and velocity, spin and contact-force vectors.
#include <imgui_internal.h>  // ImRect

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include "ui/aim.hpp"
#include "ui/panels.hpp"
#include "ui/widgets.hpp"

namespace shotlab {

ImU32 motion_color(Motion m, float alpha) {
  const int a = static_cast<int>(alpha * 255);
  switch (m) {
    case Motion::Sliding: return IM_COL32(255, 140, 30, a);
    case Motion::Rolling: return IM_COL32(60, 200, 255, a);
    case Motion::Airborne: return IM_COL32(255, 60, 220, a);
    case Motion::Spinning: return IM_COL32(255, 240, 60, a);
    case Motion::Stationary: return IM_COL32(200, 200, 200, a);
    case Motion::Pocketed:
    case Motion::OffTable: return IM_COL32(90, 90, 90, a);
  }
  return IM_COL32(255, 255, 255, a);
}

namespace {

ImVec2 v2(const glm::dvec2& p) { return {static_cast<float>(p.x), static_cast<float>(p.y)}; }

// The view's text labels (ball names, contact forces, the cut angle, the centre of mass, the target's miss), placed
// once all are known so that none covers another: in order of priority (ball names first), each takes the first free
// spot of its wanted one and the spots around its anchor, or the least covered when none is free. Each has a dark
// backing so that it reads over trails and cloth.
class Labels {
  static constexpr float kHiddenShare = 0.35f;  // of a label's area covered at its best spot: it is left out
  static constexpr int kSpots = 8;               // where a label may go, around its anchor

 public:
  explicit Labels(const ImRect& view) : view_(view) {}
  void add(int priority, ImVec2 anchor, ImVec2 wanted, std::string text, ImU32 colour) {
    items_.push_back({priority, anchor, wanted, std::move(text), colour});
  }
  // Something drawn that no label should cover (an arrow's head).
  void avoid(const ImRect& r) { clear_.push_back(r); }
  void draw(ImDrawList* d) {
    std::stable_sort(items_.begin(), items_.end(), [](const Item& a, const Item& b) { return a.priority < b.priority; });
    std::vector<ImRect> taken = clear_;
    int shown = 0;
    for (const Item& it : items_) {
      const ImVec2 size = ImGui::CalcTextSize(it.text.c_str());
      const float gap = em(5), x = it.anchor.x, y = it.anchor.y;
      const ImVec2 spots[kSpots] = {it.wanted,
                              {x + gap, y - size.y / 2},           // right
                              {x - size.x - gap, y - size.y / 2},  // left
                              {x - size.x / 2, y + gap},           // below
                              {x - size.x / 2, y - size.y - gap},  // above
                              {it.wanted.x, it.wanted.y + size.y + 2},
                              {it.wanted.x, it.wanted.y - size.y - 2},
                              {it.wanted.x, it.wanted.y + 2 * (size.y + 2)}};
      ImRect best;
      float least = INFINITY;
      int& last = last_spot()[it.text];  // a free spot it took last frame is tried first: labels do not flit about
      const int before = last;
      for (int k = 0; k < kSpots; ++k) {
        const int n = k == 0 ? before : k <= before ? k - 1 : k;  // before, then the others in their order
        const ImRect r(spots[n].x - 3, spots[n].y - 1, spots[n].x + size.x + 3, spots[n].y + size.y + 1);
        float covered = r.GetWidth() * r.GetHeight() - overlap(r, view_);  // off the view counts as covered
        for (const ImRect& t : taken) covered += overlap(r, t);
        if (covered < least) least = covered, best = r, last = n;
        if (covered == 0) break;
      }
      // Mostly hidden wherever it goes (a rack seen from afar): left out rather than stacked unreadably on the
      // labels before it, which matter more (they come first).
      if (least > kHiddenShare * best.GetWidth() * best.GetHeight()) continue;
      taken.push_back(best);
      mark_rect("label " + std::to_string(++shown) + " " + it.text,
                Rect{best.Min.x, best.Min.y, best.Max.x - best.Min.x, best.Max.y - best.Min.y});
      d->AddRectFilled(best.Min, best.Max, IM_COL32(0, 0, 0, 170), 3);
      d->AddText({best.Min.x + 3, best.Min.y + 1}, it.colour, it.text.c_str());
    }
  }

 private:
  struct Item {
    int priority;
    ImVec2 anchor, wanted;  // the point labelled; where the label's top-left corner would go
    std::string text;
    ImU32 colour;
  };
  static std::map<std::string, int>& last_spot() {  // by label text, over frames (forces' texts change: bounded)
    static std::map<std::string, int> spot;
    if (spot.size() > 512) spot.clear();
    return spot;
  }
  static float overlap(const ImRect& a, const ImRect& b) {
    const float w = std::min(a.Max.x, b.Max.x) - std::max(a.Min.x, b.Min.x);
    const float h = std::min(a.Max.y, b.Max.y) - std::max(a.Min.y, b.Min.y);
    return w > 0 && h > 0 ? w * h : 0;
  }
  ImRect view_;  // the 3D view's pixels: a label is placed inside them where it can be
  std::vector<Item> items_;
  std::vector<ImRect> clear_;
};
enum LabelPriority { kBallName, kForce, kCut, kCentre, kMiss };

void line(ImDrawList* d, const Viewport& vp, const Vec3& a, const Vec3& b, ImU32 color, float width) {
  const auto pa = vp.project(a), pb = vp.project(b);
  if (pa && pb) d->AddLine(v2(*pa), v2(*pb), color, width);
}

void arrow(ImDrawList* d, const Viewport& vp, const Vec3& from, const Vec3& to, ImU32 color, float width) {
  const auto pa = vp.project(from), pb = vp.project(to);
  if (!pa || !pb) return;
  // On a dark edge: the yellow spin arrow over the white cue ball was all but invisible.
  flat_arrow(d, v2(*pa), v2(*pb), IM_COL32(0, 0, 0, 170), width + 2.5f);
  flat_arrow(d, v2(*pa), v2(*pb), color, width);
}

// A trail's points lie 2 mm apart on the table, under a pixel at most zooms: drawn, a point comes this many pixels
// after the last one kept (more for dashes, so that they show). Thousands of sub-pixel segments a frame held a break's
// frame rate far under the display's on a software renderer. A solid run is then drawn simplified (a ball's path is
// straight between hits but where spin bends it).
constexpr float kTrailPixels = 2.0f, kDashPixels = 6.0f;
constexpr double kShownForce = 5e-3;  // N: a contact force under this is drawn as none (it would read "0 N")

// Appends p to a run of screen points, replacing the run's last point while it is within `spacing` of the one before:
// the run always ends at the latest point.
void extend(std::vector<ImVec2>& run, ImVec2 p, float spacing) {
  if (run.size() >= 2) {
    const ImVec2 a = run[run.size() - 2];
    if ((p.x - a.x) * (p.x - a.x) + (p.y - a.y) * (p.y - a.y) < spacing * spacing) {
      run.back() = p;
      return;
    }
  }
  run.push_back(p);
}

void stroke(ImDrawList* d, const std::vector<ImVec2>& run, ImU32 colour, float width, bool dashed) {
  if (run.size() < 2) return;
  if (!dashed) return simplified_polyline(d, run, colour, width);
  for (size_t k = 0; k + 1 < run.size(); k += 2) d->AddLine(run[k], run[k + 1], colour, width);
}

// Trails: by motion colour (the segment into a point takes that point's motion), or in one colour (kept shots, ghost,
// A trails), dashed when `dashed`. Each run of one colour is one polyline in screen space. The sliding runs go on top:
// a drawn-back or followed ball returns along its path rolling, and would paint over where it slid. Ball `skip`'s
// trail is left out.
void paths(ImDrawList* d, const Viewport& vp, const Trails& trails, float alpha, float width, bool by_motion,
           ImU32 colour = IM_COL32(220, 220, 220, 255), bool dashed = false, int skip = -1) {
  const ImU32 plain = (colour & ~IM_COL32_A_MASK) | (static_cast<ImU32>(alpha * 255) << IM_COL32_A_SHIFT);
  const ImU32 sliding = motion_color(Motion::Sliding, alpha);
  const float spacing = dashed ? kDashPixels : kTrailPixels;
  std::vector<ImVec2> run;
  std::vector<std::vector<ImVec2>> on_top;
  auto draw = [&](ImU32 c) {
    if (by_motion && c == sliding) on_top.push_back(run);
    else stroke(d, run, c, width, dashed);
  };
  for (size_t b = 0; b < trails.size(); ++b) {
    if (static_cast<int>(b) == skip) continue;
    const auto& path = trails[b];
    run.clear();
    ImU32 run_colour = plain;
    for (const PathPoint& point : path) {
      const auto s = vp.project(point.position);
      if (!s) {  // behind the camera: the trail breaks there
        draw(run_colour);
        run.clear();
        continue;
      }
      const ImU32 c = by_motion ? motion_color(point.motion, alpha) : plain;
      if (c != run_colour && !run.empty()) {
        draw(run_colour);
        run.erase(run.begin(), run.end() - 1);  // the new colour starts where the old one ended
      }
      run_colour = c;
      extend(run, v2(*s), spacing);
    }
    draw(run_colour);
  }
  for (const auto& r : on_top) stroke(d, r, sliding, width, dashed);
}

// Where each ball that moved in a kept shot stopped: a ring of its size in the shot's colour (the paths of straight
// shots with different tips lie over each other along the aim line; their ends tell them apart), `grow` px wider.
void ends(ImDrawList* d, const Viewport& vp, const Trails& trails, double radius, ImU32 colour, float grow = 0) {
  for (const auto& path : trails) {
    if (path.empty() || glm::length(path.back().position - path.front().position) < 0.5 * radius) continue;
    if (const auto s = vp.project(path.back().position))
      d->AddCircle(v2(*s), std::max(3.0f, static_cast<float>(vp.screen_radius(path.back().position, radius))) + grow,
                   colour, 24, 2.0f);
  }
}

void aim(ImDrawList* d, const Viewport& vp, const Lab& lab, Labels& labels) {
  const auto a = aim_line(lab.scene);
  if (!a) return;
  const CueStrike& cue = *lab.scene.cue;
  const double r = lab.scene.balls[scene_ball(lab.scene, cue.ball)].spec.radius;
  const Vec3 dir = aim_direction(cue.aim);
  line(d, vp, a->from, a->ghost, IM_COL32(255, 255, 255, 200), 1.5f);
  // Cue stick: behind the ball along the aim, raised by the elevation.
  const Vec3 back = -dir * std::cos(cue.elevation) + Vec3{0, std::sin(cue.elevation), 0};
  line(d, vp, a->from + back * (r * 1.6), a->from + back * (r * 1.6 + 1.0), IM_COL32(200, 160, 100, 230), 5.0f);
  const auto g = vp.project(a->ghost);
  if (!g) return;
  d->AddCircle(v2(*g), static_cast<float>(vp.screen_radius(a->ghost, r)), IM_COL32(255, 255, 255, 220), 32, 1.5f);
  if (a->hit < 0) return;
  const Vec3 q = lab.scene.balls[a->hit].position;
  line(d, vp, q, q + a->object_dir * 0.4, IM_COL32(255, 230, 120, 220), 1.5f);
  char text[32];
  std::snprintf(text, sizeof text, "cut %.2f deg", a->cut_deg);
  labels.add(kCut, v2(*g), ImVec2(static_cast<float>(g->x) + 14, static_cast<float>(g->y) - em(20)), text,
             IM_COL32(255, 255, 255, 255));
}

// A contact worth drawing: not a ball simply resting on the bed (its force within 20 % of its weight), which would
// put a dot under every ball.
bool notable(const Model& model, const Contact& c) {
  if (c.other_ball >= 0 || c.collider < 0) return true;
  if (model.colliders[c.collider].material != kBallCloth) return true;
  const double weight = model.balls[c.ball].mass * glm::length(model.options.gravity);
  return std::abs(c.force.normal - weight) > 0.2 * weight;
}

// What a contact's force label says: its size, and what pushes. Two balls push each other equally and oppositely
// (two arrows from the contact); a static body is named by its material.
std::string force_label(const Model& model, const Contact& c) {
  char size[32];
  std::snprintf(size, sizeof size, c.force.normal < 10 ? "%.2g N" : "%.0f N", c.force.normal);
  if (c.other_ball >= 0) return std::string(size) + " each way";
  const std::string& m = model.colliders[c.collider].material;
  const char* what = m == kBallCloth ? "cloth " : m == kBallCushion ? "cushion " : m == kBallPocket ? "pocket " : "";
  return what + std::string(size);
}

// Velocity (white, 0.15 m per m/s), spin (yellow, 2 mm per rad/s, right-hand rule), contact forces (red, length
// growing with log(1 + F / 1 N) so that a 2 N resting contact and a 2 kN collision both show; between two balls one
// arrow into each, Newton's third law).
void vectors(ImDrawList* d, const Viewport& vp, const Lab& lab, Labels& labels) {
  const Frame& f = lab.frame();
  const ViewFlags& v = lab.settings.view;
  for (int i = 0; i < f.state.ball_count(); ++i) {
    if (!f.state.in_play[i]) continue;
    const Vec3 p = position(f.state.x, i);
    // A label beside the ball (its name) goes round the arrows' heads: a name over the spin arrow hid it.
    auto head = [&](const Vec3& tip) {
      if (const auto s = vp.project(tip)) labels.avoid(ImRect(v2(*s - 8.0), v2(*s + 8.0)));
    };
    const Vec3 to_v = p + 0.15 * velocity(f.state.x, i), to_w = p + 0.002 * spin(f.state.x, i);
    if (v.velocity) arrow(d, vp, p, to_v, IM_COL32(255, 255, 255, 255), 2.5f), head(to_v);
    if (v.spin) arrow(d, vp, p, to_w, IM_COL32(255, 230, 40, 255), 2.5f), head(to_w);
  }
  if (!v.forces) return;
  const Model& model = lab.shot ? lab.shot->sim().model() : lab.table_model;
  for (const Contact& c : contacts(model, f.state)) {
    if (!notable(model, c) || c.force.normal < kShownForce) continue;  // rack balls touching, pressing nothing
    const Vec3 along = unit_or_zero(c.force.force) * (0.03 * std::log1p(c.force.normal));
    arrow(d, vp, c.point, c.point + along, IM_COL32(255, 60, 60, 255), 2.5f);
    if (c.other_ball >= 0) arrow(d, vp, c.point, c.point - along, IM_COL32(255, 60, 60, 255), 2.5f);
    const auto s = vp.project(c.point);
    if (!s) continue;
    d->AddCircleFilled(v2(*s), 3.5f, IM_COL32(255, 60, 60, 255));
    labels.add(kForce, v2(*s), ImVec2(static_cast<float>(s->x) + 6, static_cast<float>(s->y) + 4),
               force_label(model, c), IM_COL32(255, 120, 120, 255));
  }
}

void labels_and_centre(ImDrawList* d, const Viewport& vp, const Lab& lab, Labels& labels) {
  const Frame& f = lab.frame();
  const ViewFlags& v = lab.settings.view;
  Vec3 sum{0.0};
  double mass = 0;
  int count = 0;
  for (int i = 0; i < f.state.ball_count() && i < static_cast<int>(lab.scene.balls.size()); ++i) {
    if (!f.state.in_play[i]) continue;
    const Vec3 p = position(f.state.x, i);
    const BallSpec& b = lab.scene.balls[i].spec;
    sum += b.mass * p, mass += b.mass, ++count;
    if (!v.labels) continue;
    if (const auto s = vp.project(p + Vec3{0, b.radius * 1.3, 0})) {
      const ImVec2 size = ImGui::CalcTextSize(b.id.c_str());
      labels.add(kBallName, v2(*s), ImVec2(static_cast<float>(s->x) - size.x / 2, static_cast<float>(s->y) - size.y),
                 b.id, IM_COL32(255, 255, 255, 255));
    }
  }
  if (!v.centre_of_mass || mass <= 0 || count < 2) return;  // one ball's centre of mass is the ball
  if (const auto s = vp.project(sum / mass)) {  // a cross in a circle, as in the textbooks
    const float r = em(7);
    d->AddCircle(v2(*s), r, IM_COL32(255, 255, 255, 255), 24, 2.0f);
    d->AddLine(ImVec2(v2(*s).x - r, v2(*s).y), ImVec2(v2(*s).x + r, v2(*s).y), IM_COL32(255, 255, 255, 255), 2.0f);
    d->AddLine(ImVec2(v2(*s).x, v2(*s).y - r), ImVec2(v2(*s).x, v2(*s).y + r), IM_COL32(255, 255, 255, 255), 2.0f);
    labels.add(kCentre, v2(*s), ImVec2(v2(*s).x + r + 3, v2(*s).y - r), "centre of mass", IM_COL32(255, 255, 255, 255));
  }
}

// Where the margin's tries left the goal's ball (green: the shot worked, red: it did not) and the cue ball (grey).
void margin_scatter(ImDrawList* d, const Viewport& vp, const Lab& lab) {
  if (!lab.margin.open || !lab.margin.scatter) return;
  const auto e = fresh_estimate(lab, lab.margin);
  if (!e) return;
  const int goal = scene_ball(lab.scene, e->options.goal.ball), cue = scene_ball(lab.scene, lab.scene.cue->ball);
  for (const MarginSample& s : e->result.samples)
    for (const int b : {cue, goal}) {
      if (b < 0 || b >= static_cast<int>(s.end_x.size()) || s.left[b]) continue;
      const double r = lab.scene.balls[b].spec.radius;
      const auto p = vp.project(Vec3{s.end_x[b], r, s.end_z[b]});
      if (!p) continue;
      const ImU32 c = b != goal ? IM_COL32(200, 200, 200, 150) : s.success ? IM_COL32(80, 230, 80, 200) : IM_COL32(240, 70, 60, 200);
      d->AddCircleFilled(v2(*p), 2.5f, c);
    }
}

// A measured shot's tracked centres as dots in each ball's colour, on the bed at the ball's height.
void measured_tracks(ImDrawList* d, const Viewport& vp, const Lab& lab) {
  if (!lab.measured.shot) return;
  for (const auto& [ball, track] : lab.measured.shot->tracks) {
    const int i = scene_ball(lab.scene, ball);
    const double r = i >= 0 ? lab.scene.balls[i].spec.radius : 0.03;
    const ImU32 c = ball == "yellow" ? IM_COL32(255, 215, 40, 230) : ball == "red" ? IM_COL32(235, 50, 50, 230)
                                                                               : IM_COL32(245, 245, 245, 230);
    for (const MeasuredSample& s : track)
      if (const auto p = vp.project(Vec3{s.x, r, s.z})) d->AddCircleFilled(v2(*p), 2.0f, c);
  }
}

void target(ImDrawList* d, const Viewport& vp, const Lab& lab, Labels& labels) {
  if (!lab.target) return;
  const Vec3 t = *lab.target + Vec3{0, 0.001, 0};
  const ImU32 c = IM_COL32(255, 90, 200, 255);
  Vec3 prev = t + Vec3{lab.target_radius, 0, 0};
  for (int k = 1; k <= 32; ++k) {
    const double a = 2 * M_PI * k / 32;
    const Vec3 p = t + lab.target_radius * Vec3{std::cos(a), 0, std::sin(a)};
    line(d, vp, prev, p, c, 2.0f);
    prev = p;
  }
  line(d, vp, t - Vec3{0.02, 0, 0}, t + Vec3{0.02, 0, 0}, c, 2.0f);
  line(d, vp, t - Vec3{0, 0, 0.02}, t + Vec3{0, 0, 0.02}, c, 2.0f);
  if (const auto miss = lab.target_miss(); miss && vp.project(t)) {
    char text[48];
    std::snprintf(text, sizeof text, "%s %.1f cm", lab.shot ? "missed by" : "predicted miss", *miss * 100);
    const ImVec2 at = v2(*vp.project(t));
    labels.add(kMiss, at, ImVec2(at.x + em(12), at.y), text, c);
  }
}

void hand_zone_outline(ImDrawList* d, const Viewport& vp, const Lab& lab) {
  if (!lab.in_hand || !lab.scene.table || !lab.scene.cue) return;
  const int c = scene_ball(lab.scene, lab.scene.cue->ball);
  if (c < 0) return;
  const Zone z = hand_zone(*lab.scene.table, lab.scene.balls[c].spec.radius, break_position(lab.scene));
  const double y = 0.001;
  const Vec3 a{z.lo_x, y, z.lo_z}, b{z.hi_x, y, z.lo_z}, e{z.hi_x, y, z.hi_z}, f{z.lo_x, y, z.hi_z};
  const ImU32 col = IM_COL32(255, 255, 255, 150);
  line(d, vp, a, b, col, 1.5f), line(d, vp, b, e, col, 1.5f), line(d, vp, e, f, col, 1.5f), line(d, vp, f, a, col, 1.5f);
}

}  // namespace

namespace {
void draw_all(const Lab& lab, const Viewport& vp, ImDrawList* d);
}

void draw_overlay(const Lab& lab, const Viewport& vp, ImDrawList* d) {
  d->PushClipRect(ImVec2(static_cast<float>(vp.x0), 0), ImVec2(static_cast<float>(vp.x0 + vp.width), static_cast<float>(vp.height)));
  draw_all(lab, vp, d);
  d->PopClipRect();
}

namespace {

// The predicted paths; with more than three balls on the move (a break) the others' faint and the cue ball's
// (`cue`) on top, which a rack's sixteen lines across the table otherwise hide.
void predicted_paths(ImDrawList* d, const Viewport& vp, const Trails& trails, int cue) {
  int moving = 0;
  for (const auto& path : trails)
    moving += path.size() > 1 && glm::length(path.back().position - path.front().position) > 1e-3;
  if (moving <= 3 || cue < 0 || cue >= static_cast<int>(trails.size())) return paths(d, vp, trails, 0.7f, 2.0f, true);
  paths(d, vp, trails, 0.3f, 1.5f, true, IM_COL32(220, 220, 220, 255), false, cue);
  paths(d, vp, {trails[static_cast<size_t>(cue)]}, 0.9f, 2.5f, true);
}

void draw_all(const Lab& lab, const Viewport& vp, ImDrawList* d) {
  const ViewFlags& v = lab.settings.view;
  Labels labels(ImRect(static_cast<float>(vp.x0), 0, static_cast<float>(vp.x0 + vp.width), static_cast<float>(vp.height)));
  if (v.ghost) paths(d, vp, lab.ghost, 0.35f, 1.5f, false);
  const double radius = lab.scene.balls.empty() ? kPoolBall.radius : lab.scene.balls.front().spec.radius;
  // Kept shots as wide bands under the thinner lines drawn later, their end rings outside those of the prediction:
  // a kept shot that the prediction repeats shows as a coloured edge along it instead of vanishing under it.
  for (const KeptShot& k : lab.kept)
    if (k.visible) {
      paths(d, vp, k.trails, 0.6f, 5.0f, false, kept_colour(k.colour));
      ends(d, vp, k.trails, radius, kept_colour(k.colour), 3.0f);
    }
  if (v.compare && !lab.compare.empty()) paths(d, vp, lab.compare, 0.8f, 2.0f, false, IM_COL32(255, 255, 255, 255), true);
  if (lab.shot) {
    if (v.trails) paths(d, vp, lab.trails(lab.view_time), 0.9f, 2.5f, true);
  } else {
    if (v.predicted)
      if (const auto p = lab.predicted_paths()) {
        const int c = lab.scene.cue ? scene_ball(lab.scene, lab.scene.cue->ball) : -1;
        predicted_paths(d, vp, p->paths, c);
        // Where the cue ball stops, ringed: on a straight draw or follow its path lies on the aim line or the object
        // ball's, and its end is otherwise lost.
        if (p->complete && c >= 0 && c < static_cast<int>(p->paths.size()))
          ends(d, vp, {p->paths[c]}, radius, IM_COL32(255, 255, 255, 220));
        size_t points = 0;
        for (const auto& path : p->paths) points += path.size();
        // What the frame drew, for the state dump: how much, whether finished, and how many aims ago it was asked.
        readout("predicted path points", static_cast<double>(points));
        readout("predicted paths complete", p->complete);
        readout("predicted aims behind", static_cast<double>(lab.prediction_request() - p->generation));
      }
    if (v.aim && lab.scene.cue) aim(d, vp, lab, labels);
  }
  const Frame& f = lab.frame();
  for (const Rod& rod : lab.scene.model.rods)
    if (rod.ball < f.state.ball_count())
      line(d, vp, rod.anchor, position(f.state.x, rod.ball), IM_COL32(180, 180, 190, 255), 1.5f);
  if (lab.selected >= 0 && lab.selected < f.state.ball_count() && lab.selected < static_cast<int>(lab.scene.balls.size())) {
    const Vec3 p = position(f.state.x, lab.selected);
    if (const auto s = vp.project(p))
      d->AddCircle(v2(*s), static_cast<float>(vp.screen_radius(p, lab.scene.balls[lab.selected].spec.radius)) + 4,
                   IM_COL32(120, 255, 120, 200), 32, 2.0f);
  }
  target(d, vp, lab, labels);
  margin_scatter(d, vp, lab);
  measured_tracks(d, vp, lab);
  hand_zone_outline(d, vp, lab);
  labels_and_centre(d, vp, lab, labels);
  vectors(d, vp, lab, labels);
  labels.draw(d);
}

}  // namespace

}  // namespace shotlab
