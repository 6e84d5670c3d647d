// Shot margin (players and coaches): the success of the shot being aimed under a player's stroke noise, which error
// hurts most, how far each can drift, and a map of success over aim x speed that sets the aim when clicked. The
// work runs in the background (margin_view.hpp); this draws and edits the choices.
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <string>

#include "ui/aim.hpp"
#include "ui/margin_view.hpp"
#include "ui/panels.hpp"
#include "ui/ticks.hpp"
#include "ui/widgets.hpp"

namespace shotlab {
namespace {

constexpr double kDeg = 180 / std::numbers::pi;

// A dark-blue to green to yellow ramp for probabilities 0..1 (perceptually ordered, readable on a projector).
ImU32 ramp(double p) {
  static const float stops[3][3] = {{68, 1, 84}, {33, 145, 140}, {253, 231, 37}};
  const double t = std::clamp(p, 0.0, 1.0) * 2;
  const int k = std::min(1, static_cast<int>(t));
  const float f = static_cast<float>(t - k);
  auto c = [&](int i) { return static_cast<int>(stops[k][i] + f * (stops[k + 1][i] - stops[k][i])); };
  return IM_COL32(c(0), c(1), c(2), 255);
}

ImVec4 verdict_colour(double p) {
  return p >= 0.7 ? ImVec4(0.5f, 1, 0.5f, 1) : p >= 0.3 ? ImVec4(1, 0.8f, 0.3f, 1) : ImVec4(1, 0.45f, 0.4f, 1);
}

void goal_choice(Lab& lab, MarginView& v) {
  const auto& pockets = lab.table_model.pockets;
  std::string shown = v.target_goal ? "cue ball stops in the target"
                      : v.pocket == 0 || v.pocket > static_cast<int>(pockets.size())
                          ? "aimed-at ball into any pocket"
                          : "aimed-at ball into " + pocket_label(pockets[v.pocket - 1].name);
  const Fields f({"goal", "player"});
  f.label("goal");
  if (ImGui::BeginCombo("##margin goal", shown.c_str())) {
    if (ImGui::Selectable("aimed-at ball into any pocket", !v.target_goal && v.pocket == 0)) v.target_goal = false, v.pocket = 0;
    for (size_t k = 0; k < pockets.size(); ++k)
      if (ImGui::Selectable(("aimed-at ball into " + pocket_label(pockets[k].name)).c_str(),
                            !v.target_goal && v.pocket == int(k) + 1))
        v.target_goal = false, v.pocket = static_cast<int>(k) + 1;
    if (ImGui::Selectable("cue ball stops in the target", v.target_goal)) v.target_goal = true;
    ImGui::EndCombo();
  }
  mark("margin goal");
  f.label("player");
  const std::vector<std::string> levels = stroke_levels();
  if (ImGui::BeginCombo("##margin level", levels[static_cast<size_t>(v.level)].c_str())) {
    for (size_t k = 0; k < levels.size(); ++k) {
      if (ImGui::Selectable(levels[k].c_str(), v.level == static_cast<int>(k))) v.level = static_cast<int>(k);
      if (ImGui::IsItemHovered()) {
        const StrokeNoise n = stroke_noise(levels[k]);
        ImGui::SetTooltip("stroke errors (standard deviations): aim %.3g deg, speed %.3g %%, tip %.3g mm, "
                          "elevation %.3g deg", n.aim_deg, n.speed_pct, n.tip_mm, n.elevation_deg);
      }
    }
    ImGui::EndCombo();
  }
  mark("margin level");
}

// What each error alone leaves of the success and the window it holds within: a table of three columns where they
// fit; in a narrow panel (presentation mode's large text, where a third column shrank to a digit a line) two lines
// an error, the window indented under its name and share.
void sources_table(const MarginResult& r) {
  static const char* names[] = {"aim (deg)", "speed (%)", "side (mm)", "height (mm)", "elevation (deg)"};
  auto share = [&](int k) { return std::to_string(static_cast<int>(std::lround(100 * r.alone[k]))) + " %"; };
  auto window = [&](int k) {
    const Tolerance& t = r.tolerance[k];
    if (!r.nominal_success) ImGui::TextDisabled("-");  // no window around a stroke that misses
    else text_wrapped("%s%.3g .. %s%.3g", t.bounded_lo ? "" : "<", t.lo, t.bounded_hi ? "" : ">", t.hi);
  };
  const float pad = ImGui::GetStyle().CellPadding.x * 2;
  if (ImGui::CalcTextSize(names[4]).x + ImGui::CalcTextSize("100 %").x + ImGui::CalcTextSize("<-0.123 .. >0.123").x +
          3 * pad > ImGui::GetContentRegionAvail().x) {
    hint("error: success with it alone, the window it holds within");
    for (int k = 0; k < kNoiseSources; ++k) {
      ImGui::TextUnformatted(names[k]);
      same_line_if_fits(share(k).c_str());
      ImGui::TextColored(verdict_colour(r.alone[k]), "%s", share(k).c_str());
      ImGui::Indent(), window(k), ImGui::Unindent();
    }
    return;
  }
  if (!ImGui::BeginTable("margin sources", 3, ImGuiTableFlags_SizingStretchProp)) return;
  ImGui::TableSetupColumn("error", ImGuiTableColumnFlags_WidthFixed);
  ImGui::TableSetupColumn("alone", ImGuiTableColumnFlags_WidthFixed);
  ImGui::TableSetupColumn("holds within", ImGuiTableColumnFlags_WidthStretch);
  ImGui::TableHeadersRow();
  for (int k = 0; k < kNoiseSources; ++k) {
    ImGui::TableNextRow();
    ImGui::TableNextColumn(), ImGui::TextUnformatted(names[k]);
    ImGui::TableNextColumn(), ImGui::TextColored(verdict_colour(r.alone[k]), "%s", share(k).c_str());
    ImGui::TableNextColumn(), window(k);
  }
  ImGui::EndTable();
}

// The estimate's verdict and its table of errors alone. `stale` (0..1, the new estimate's progress): an earlier
// estimate, dimmed, with the progress in its verdict's line, so that the panel keeps its height (the map below stays
// under the pointer) while the new one is worked out; it says nothing to the readouts.
void estimate_lines(const MarginEstimate& e, std::optional<double> stale) {
  const MarginResult& r = e.result;
  const std::string where = e.options.goal.kind == ShotGoal::Zone ? "in the target"
                            : e.options.goal.pocket.empty()       ? "into a pocket"
                                                                  : "into " + pocket_label(e.options.goal.pocket);
  if (stale) {
    ImGui::ProgressBar(static_cast<float>(*stale), ImVec2(-1, ImGui::GetTextLineHeight()), "replaying...");
  } else {
    readout("margin success", r.probability);
    coloured_wrapped(verdict_colour(r.probability), "%s %s: %.0f %% (+-%.0f) of %zu tries",
                       e.options.goal.ball.c_str(), where.c_str(), 100 * r.probability, 100 * r.standard_error,
                       r.samples.size());
    mark("margin success");
  }
  // Always a line, either way: the section keeps its height from one estimate to the next.
  if (r.nominal_success) coloured_wrapped(ImVec4(0.5f, 1, 0.5f, 1), "as aimed, without error: works");
  else coloured_wrapped(ImVec4(1, 0.6f, 0.3f, 1), "as aimed, without error: misses");
  sources_table(r);
}

void estimate_readout(Lab& lab, MarginView& v) {
  if (const auto e = fresh_estimate(lab, v)) return estimate_lines(*e, std::nullopt);
  const auto old = v.estimate.result();
  if (v.estimate.busy() && old) {
    ImGui::BeginDisabled();
    estimate_lines(*old, v.estimate.progress());
    ImGui::EndDisabled();
  } else if (v.estimate.busy()) {
    ImGui::ProgressBar(static_cast<float>(v.estimate.progress()), ImVec2(-1, 0), "replaying...");
  } else if (!v.estimate.error().empty()) {
    text_wrapped("%s", v.estimate.error().c_str());
  }
}

// Where value v of a range [lo, hi] over n cells of `size` pixels sits: cell centres span the first to the last.
float cell_place(double v, double lo, double hi, int n, float size) {
  const float cell = size / static_cast<float>(n);
  return hi > lo ? static_cast<float>((v - lo) / (hi - lo)) * (size - cell) + cell / 2 : size / 2;
}

// Tick labels on the map's axes: speeds (m/s) in a gutter left of the cells, aims (deg) under them.
void map_axes(ImDrawList* d, const MarginMap& m, const Ticks& sv, ImVec2 p0, float w, float h, float gutter) {
  const ImU32 ink = ImGui::GetColorU32(ImGuiCol_Text), tick = ImGui::GetColorU32(ImGuiCol_TextDisabled);
  const float line = ImGui::GetTextLineHeight();
  for (double v : sv.values) {
    const float y = p0.y + h - cell_place(v, m.speed_lo, m.speed_hi, m.speeds, h);
    const std::string text = format_tick(v, sv);
    const float tw = ImGui::CalcTextSize(text.c_str()).x;
    d->AddLine(ImVec2(p0.x - em(4), y), ImVec2(p0.x, y), tick);
    d->AddText(ImVec2(p0.x - em(6) - tw, y - line / 2), ink, text.c_str());
  }
  const Ticks av = nice_ticks(m.aim_lo_deg, m.aim_hi_deg, std::max(2, static_cast<int>(w / em(50))));
  for (double v : av.values) {
    const float x = p0.x + cell_place(v, m.aim_lo_deg, m.aim_hi_deg, m.aims, w);
    const std::string text = format_tick(v, av);
    const float tw = ImGui::CalcTextSize(text.c_str()).x;
    const float left = std::clamp(x - tw / 2, p0.x - gutter, p0.x + w - tw);
    d->AddLine(ImVec2(x, p0.y + h), ImVec2(x, p0.y + h + em(4)), tick);
    d->AddText(ImVec2(left, p0.y + h + em(4)), ink, text.c_str());
  }
}

// The colour key: the ramp from 0 % to 100 % success, labelled at its ends and middle.
void map_key() {
  ImGui::TextUnformatted("success");
  ImGui::SameLine();
  const float w = ImGui::GetContentRegionAvail().x, line = ImGui::GetTextLineHeight();
  const ImVec2 p0 = ImGui::GetCursorScreenPos();
  ImGui::Dummy(ImVec2(w, 2 * line + em(2)));
  mark("margin key");
  ImDrawList* d = ImGui::GetWindowDrawList();
  const float left = p0.x + ImGui::CalcTextSize("0 %").x / 2;
  const float span = p0.x + w - ImGui::CalcTextSize("100 %").x / 2 - left;
  constexpr int kSteps = 32;
  for (int k = 0; k < kSteps; ++k) {
    const float a = left + span * k / kSteps, b = left + span * (k + 1) / kSteps;
    d->AddRectFilled(ImVec2(a, p0.y), ImVec2(b + 0.5f, p0.y + line * 0.8f), ramp((k + 0.5) / kSteps));
  }
  const ImU32 ink = ImGui::GetColorU32(ImGuiCol_Text);
  const char* labels[] = {"0 %", "50 %", "100 %"};
  for (int k = 0; k < 3; ++k) {
    const float x = left + span * k / 2 - ImGui::CalcTextSize(labels[k]).x / 2;
    d->AddText(ImVec2(x, p0.y + line * 0.8f + em(2)), ink, labels[k]);
  }
}

// The map as coloured cells (speed up, aim across) with labelled axes and a colour key, the current aim and speed
// marked; a click aims there.
void map_picture(Lab& lab, const MarginMap& m) {
  ImGui::TextUnformatted("speed (m/s) up, aim (deg) across");
  // The speed ticks for a map as tall as the panel allows (the gutter's width depends on them, the height on it).
  const float line = ImGui::GetTextLineHeight(), tall = std::max(em(80), 0.5f * ImGui::GetContentRegionAvail().x);
  const Ticks sv = nice_ticks(m.speed_lo, m.speed_hi, std::max(4, static_cast<int>(tall / (2 * line))));
  float gutter = 0;
  for (double v : sv.values) gutter = std::max(gutter, ImGui::CalcTextSize(format_tick(v, sv).c_str()).x);
  gutter += em(8);
  const float w = ImGui::GetContentRegionAvail().x - gutter, h = std::max(em(80), w * 0.5f);
  const ImVec2 origin = ImGui::GetCursorScreenPos(), p0(origin.x + gutter, origin.y + line / 2);
  ImGui::SetCursorScreenPos(p0);
  ImGui::InvisibleButton("margin map", ImVec2(w, h));
  mark("margin map");
  ImDrawList* d = ImGui::GetWindowDrawList();
  const float cw = w / static_cast<float>(m.aims), ch = h / static_cast<float>(m.speeds);
  for (int i = 0; i < m.speeds; ++i)
    for (int j = 0; j < m.aims; ++j) {
      const ImVec2 a(p0.x + j * cw, p0.y + h - (i + 1) * ch);
      d->AddRectFilled(a, ImVec2(a.x + cw + 0.5f, a.y + ch + 0.5f), ramp(m.cells[i * m.aims + j]));
    }
  map_axes(d, m, sv, p0, w, h, gutter);
  const bool hovered = ImGui::IsItemHovered(), clicked = ImGui::IsItemClicked();
  ImGui::SetCursorScreenPos(ImVec2(origin.x, p0.y + h + em(6) + line));
  ImGui::Dummy(ImVec2(0, 0));
  map_key();
  auto centre = [](double lo, double hi, int n, int k) { return n == 1 ? 0.5 * (lo + hi) : lo + (hi - lo) * k / (n - 1); };
  const CueStrike& cue = *lab.scene.cue;
  const float mx = p0.x + cell_place(cue.aim * kDeg, m.aim_lo_deg, m.aim_hi_deg, m.aims, w);
  const float my = p0.y + h - cell_place(cue.speed, m.speed_lo, m.speed_hi, m.speeds, h);
  d->AddLine(ImVec2(mx - 7, my), ImVec2(mx + 7, my), IM_COL32(255, 255, 255, 255), 2);
  d->AddLine(ImVec2(mx, my - 7), ImVec2(mx, my + 7), IM_COL32(255, 255, 255, 255), 2);
  if (!hovered) return;
  const ImVec2 q = ImGui::GetIO().MousePos;
  const int j = std::clamp(static_cast<int>((q.x - p0.x) / cw), 0, m.aims - 1);
  const int i = std::clamp(static_cast<int>((p0.y + h - q.y) / ch), 0, m.speeds - 1);
  const double aim = centre(m.aim_lo_deg, m.aim_hi_deg, m.aims, j), speed = centre(m.speed_lo, m.speed_hi, m.speeds, i);
  ImGui::SetTooltip("aim %.2f deg, speed %.2f m/s: %.0f %%\nclick to take this aim and speed (S shoots)", aim, speed,
                    100 * m.cells[i * m.aims + j]);
  if (clicked) {
    CueStrike c = cue;
    c.aim = aim / kDeg, c.speed = speed;
    lab.set_cue(c, "aim from the margin map");
  }
}

void map_section(Lab& lab, MarginView& v) {
  const Fields f({"cells", "replays"});
  f.label("cells");
  const char* sizes[] = {"20 x 10", "40 x 20"};
  ImGui::Combo("##map cells", &v.map_size, sizes, 2);
  f.label("replays");
  ImGui::SliderInt("##map replays", &v.map_samples, 10, 200, "%d per cell");
  integer_entry();
  mark("map replays");
  if (!v.map_wanted) {
    if (ImGui::Button("Map aim x speed")) v.map_wanted = true;
    mark("Map aim x speed");
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip("success over the aim (+-%.2g deg) and the speed (+-%.0f %%) around the current ones, on every "
                        "core; kept up to date as you aim", v.map_aim(), v.map_speed);
  } else {
    if (ImGui::Button(v.map.busy() ? "Cancel map" : "Hide map")) v.map_wanted = false, v.map.cancel(), v.map_asked.clear();
    mark("Cancel map");
  }
  if (v.map.busy()) ImGui::ProgressBar(static_cast<float>(v.map.progress()), ImVec2(-1, 0));
  readout("margin map progress", v.map.busy() ? v.map.progress() : v.map.result() ? 1.0 : 0.0);
  // A map of another table or goal, or one the aim has left, is not drawn (nor clicked) while the new one comes.
  const auto done = v.map.result();
  if (v.map_wanted && done && v.map_current) map_picture(lab, done->map);
}

}  // namespace

void margin_section(Lab& lab) {
  MarginView& v = lab.margin;
  text_wrapped("How often does this shot work when the stroke is a little off?");
  goal_choice(lab, v);
  update_margin(lab, v);
  if (lab.shot) hint("back to aiming (Undo or Next) to work it out");
  else if (!v.problem.empty()) hint(v.problem);
  else estimate_readout(lab, v);
  fitting_checkbox("draw where the tries end", "draw try ends", &v.scatter);
  ImGui::Separator();
  map_section(lab, v);
}

}  // namespace shotlab
