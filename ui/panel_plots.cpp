// The Teaching tab's plots, all over the shot's time with a cursor at the time on screen (click a plot to go to a
// time): the selected ball's speed against the surface speed its spin gives (the ball rolls where they meet), the
// energy by kind, and the normal force through a collision, its pair named.
#include <imgui.h>

#include <algorithm>
#include <cmath>

#include "ui/ticks.hpp"
#include "ui/panels.hpp"
#include "ui/widgets.hpp"

namespace shotlab {

namespace {

constexpr ImU32 kBlue = IM_COL32(80, 170, 255, 255), kYellow = IM_COL32(255, 220, 80, 255);
constexpr ImU32 kGreen = IM_COL32(120, 230, 120, 255), kPurple = IM_COL32(200, 140, 255, 255);
constexpr ImU32 kWhite = IM_COL32(240, 240, 240, 255), kRed = IM_COL32(255, 110, 90, 255);
constexpr ImU32 kFaint = IM_COL32(255, 255, 255, 110);  // a colour & kFaint: the same, mostly transparent (A's lines)

void seek_to(Lab& lab, std::optional<double> t) {
  if (t) lab.seek(std::clamp(*t, 0.0, lab.shot->sim().time()));
}

double shot_span(const Lab& lab) {
  return lab.shot->finished() ? lab.shot->sim().time() : std::max(lab.shot->sim().time(), 1e-3);
}

// The ball's speed and the speed its spin would roll it at (R times spin about the horizontal axis across the
// travel), both along its direction of travel: the second is negative with backspin, and the lines meet where the
// ball rolls. At rest the last direction of travel is kept (the spin's own direction before the ball ever moved).
// Appended to `v` and `w`, from each of `frames`.
void motion_series(const std::vector<Frame>& frames, int i, double r, PlotSeries& v, PlotSeries& w) {
  Vec3 along{0.0};
  for (const Frame& f : frames) {
    const Vec3 vel = velocity(f.state.x, i), rolls_at = r * glm::cross(spin(f.state.x, i), Vec3{0, 1, 0});
    const Vec3 flat{vel.x, 0, vel.z};
    if (glm::length(flat) > 1e-9) along = glm::normalize(flat);
    else if (along == Vec3{0.0} && glm::length(rolls_at) > 1e-9) along = glm::normalize(rolls_at);
    v.time.push_back(f.time), v.value.push_back(glm::length(vel));
    w.time.push_back(f.time), w.value.push_back(glm::dot(rolls_at, along));
  }
}

// The selected ball's motion_series, the shot as far as it has run, the cursor at the time on screen; with the A/B
// compare on, A's lines (the run before the physics changed) fainter beside them.
void motion_plot(Lab& lab) {
  const int i = lab.selected;
  const double r = lab.scene.balls[i].spec.radius;
  std::vector<PlotSeries> series{{"speed v", kBlue, {}, {}}, {"R x spin along v (< 0: backspin)", kYellow, {}, {}}};
  motion_series(lab.shot->frames(), i, r, series[0], series[1]);
  const std::vector<Frame>& a = lab.compare_frames;
  const int balls = lab.shot->frames().front().state.ball_count();
  if (lab.settings.view.compare && !a.empty() && a.front().state.ball_count() == balls) {
    series.push_back({"A: speed", kBlue & kFaint, {}, {}});
    series.push_back({"A: R x spin", kYellow & kFaint, {}, {}});
    motion_series(a, i, r, series[2], series[3]);
  }
  PlotSpec spec{"ball " + lab.scene.balls[i].spec.id + ": speed and spin", "m/s", lab.view_time, 0, shot_span(lab)};
  spec.hint = "the ball rolls without slipping where the two lines meet; below zero the spin is backspin";
  seek_to(lab, lab_plot(lab, "motion", spec, series, em(150)));
}

void energy_plot(Lab& lab) {
  const Energy start = lab.shot->frames().front().energy;
  PlotSeries k{"kinetic", kBlue, {}, {}}, e{"in contacts", kGreen, {}, {}}, h{"height", kPurple, {}, {}},
      t{"total", kWhite, {}, {}};
  for (const Frame& f : lab.shot->frames()) {
    for (PlotSeries* s : {&k, &e, &h, &t}) s->time.push_back(f.time);
    k.value.push_back(f.energy.kinetic);
    e.value.push_back(f.energy.elastic);
    h.value.push_back(f.energy.potential - start.potential);
    t.value.push_back(f.energy.total() - start.potential);
  }
  PlotSpec spec{"energy (height counted from the start)", "J", lab.view_time, 0, shot_span(lab)};
  seek_to(lab, lab_plot(lab, "energy", spec, {k, e, h, t}, em(150)));
}

// The contact shown: the one the user picked, else the latest ball-ball contact begun by the time on screen,
// else the latest contact of any kind.
int shown_contact(const ContactLog& log, double t, int picked) {
  if (picked >= 0 && picked < static_cast<int>(log.contacts.size())) return picked;
  int any = -1, balls = -1;
  for (int k = 0; k < static_cast<int>(log.contacts.size()); ++k)
    if (log.contacts[k].begin <= t) {
      any = k;
      if (log.contacts[k].ball_ball) balls = k;
    }
  return balls >= 0 ? balls : any;
}

void collision_plot(Lab& lab) {
  static int picked = -1;
  static const Shot* picked_for = nullptr;
  if (picked_for != lab.shot.get()) picked = -1, picked_for = lab.shot.get();
  const ContactLog* log = lab.contact_log();
  if (!log) return ImGui::TextDisabled("tracing the collisions...");
  if (log->contacts.empty()) return ImGui::TextDisabled("no collision yet");
  const int k = shown_contact(*log, lab.view_time, picked);
  if (k < 0) return hint("no collision before this time");
  const ContactTrace& c = log->contacts[k];
  ImGui::SetNextItemWidth(-1);
  if (ImGui::BeginCombo("##contact", (c.label() + " at " + std::to_string(c.begin).substr(0, 8) + " s").c_str())) {
    for (int j = 0; j < static_cast<int>(log->contacts.size()); ++j) {
      const ContactTrace& o = log->contacts[j];
      const std::string name = o.label() + " at " + std::to_string(o.begin).substr(0, 8) + " s";
      if (ImGui::Selectable(name.c_str(), j == k)) picked = j;
    }
    ImGui::EndCombo();
  }
  const double end = c.end >= 0 ? c.end : log->until;
  PlotSeries f{c.label(), kRed, c.time, c.force};
  PlotSpec spec{"normal force, " + c.label(), "N", lab.view_time, c.begin, std::max(end, c.begin + 1e-6)};
  spec.origin = c.begin, spec.origin_name = "contact start";
  seek_to(lab, lab_plot(lab, "collision", spec, {f}, em(150)));
  text_wrapped("peak %.0f N, lasted %.3f ms, deepest %.1f %sm", c.peak_force(), (end - c.begin) * 1e3,
               c.max_depth() * 1e6, kMicro);
  if (ImGui::SmallButton("go to its start")) lab.seek(c.begin);
}

}  // namespace

void teach_plots(Lab& lab) {
  if (lab.selected >= static_cast<int>(lab.scene.balls.size())) return;
  motion_plot(lab);
  energy_plot(lab);
  collision_plot(lab);
}

}  // namespace shotlab
