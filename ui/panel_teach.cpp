// The inspector (right panel) and its Teaching tab: what each ball does at the time on screen (a table that exports
// as CSV), energy and momentum as bar charts, the centre of mass, the shot's events (click one to go there), and
// the plots (panel_plots.cpp).
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>
#include <string>

#include "ui/files.hpp"
#include "ui/panels.hpp"
#include "ui/renderer.hpp"
#include "ui/ticks.hpp"
#include "ui/widgets.hpp"

namespace shotlab {

namespace {

// J: the energy bars span at least this, so that a resting ball's micro-joules in its cloth contact do not fill one.
constexpr double kEnergyBarFloor = 1e-3;
constexpr double kMomentumBarFloor = 1e-3;  // kg m/s, likewise for a ball creeping to rest

// What a ball's state in the table means, for its tooltip.
const char* motion_meaning(Motion m) {
  switch (m) {
    case Motion::Stationary: return "at rest";
    case Motion::Spinning: return "turning in place about the vertical; cloth friction slows the spin";
    case Motion::Rolling:
      return "rolling without slipping: the point on the cloth is still; rolling resistance slows it";
    case Motion::Sliding: return "the ball slips over the cloth: friction changes its speed and spin until it rolls";
    case Motion::Airborne:
      return "off the cloth: after a hit a ball hops a little (friction between the balls lifts it), or it jumps";
    case Motion::Pocketed: return "in a pocket";
    case Motion::OffTable: return "off the table";
  }
  return "";
}

const Model& shown_model(const Lab& lab) { return lab.shot ? lab.shot->sim().model() : lab.table_model; }

std::string table_csv(const Lab& lab) {
  const Frame& f = lab.frame();
  const Model& m = shown_model(lab);
  std::ostringstream out;
  out.precision(9);
  out << "time_s,ball,x_m,y_m,z_m,vx_m_s,vy_m_s,vz_m_s,wx_rad_s,wy_rad_s,wz_rad_s,kinetic_J,state\n";
  for (int i = 0; i < f.state.ball_count(); ++i) {
    const Vec3 p = position(f.state.x, i), v = velocity(f.state.x, i), w = spin(f.state.x, i);
    const BallMotion b = ball_motion(m, f.state, i);
    out << f.time << ",\"" << lab.scene.balls[i].spec.id << "\"," << p.x << ',' << p.y << ',' << p.z << ',' << v.x << ','
        << v.y << ',' << v.z << ',' << w.x << ',' << w.y << ',' << w.z << ',' << b.translation + b.rotation << ','
        << motion_name(f.motion[i]) << '\n';
  }
  return out.str();
}

constexpr const char* kBallColumns[6] = {"ball", "state", "v (m/s)", "w (rad/s)", "KE (J)", "x, z (cm)"};

// One ball's row of the table, as text: the cells of kBallColumns.
struct BallRow {
  std::string cells[6];
  Motion motion = Motion::Stationary;
  std::string speed_tip;  // the speed cell's tooltip ("" for none)
  std::string rod_tip;    // the state's tooltip for a ball on a rod ("" for the motion's meaning)
  std::string spin_tip;   // the spin cell's: top- or backspin, side spin (the cell is the spin's size alone)
};

// The spin split as a player reads it: about the horizontal axis across the ball's path (positive: topspin, the way
// it rolls), about the vertical (side spin), about the path itself. y is up.
std::string spin_parts(const Vec3& w, const Vec3& v, double radius, double rest_speed) {
  // y up, right-handed: a positive spin about it turns counter-clockwise seen from above.
  auto turn = [](double about_up) {
    return about_up >= 0 ? "counter-clockwise seen from above" : "clockwise seen from above";
  };
  char out[240];
  const double along = std::hypot(v.x, v.z);
  if (along < rest_speed) {
    std::snprintf(out, sizeof out, "side spin (about the vertical): %.1f rad/s %s; about horizontal axes: %.1f rad/s",
                  std::abs(w.y), turn(w.y), std::hypot(w.x, w.z));
    return out;
  }
  const Vec3 path{v.x / along, 0, v.z / along}, across{path.z, 0, -path.x};  // across = up x path
  const double roll = glm::dot(w, across);
  std::snprintf(out, sizeof out, "%.1f rad/s of %s (rolling at this speed: %.1f of topspin)\nside spin (about the "
                "vertical): %.1f rad/s %s; about its path: %.1f rad/s", std::abs(roll),
                roll >= 0 ? "topspin" : "backspin", along / radius, std::abs(w.y), turn(w.y), glm::dot(w, path));
  return out;
}

BallRow ball_row(const Lab& lab, const Model& m, const Frame& f, int i) {
  BallRow r;
  auto text = [](const char* fmt, double a, double b = 0) {
    char out[96];
    std::snprintf(out, sizeof out, fmt, a, b);
    return std::string(out);
  };
  r.cells[0] = lab.scene.balls[i].spec.id;
  r.motion = i < static_cast<int>(f.motion.size()) ? f.motion[i] : Motion::Stationary;
  r.cells[1] = r.motion == Motion::Stationary ? "at rest" : motion_name(r.motion);  // short: the table fits
  const double v = glm::length(velocity(f.state.x, i));  // under the rest speed the engine counts it stopped
  // A pendulum's ball (a cradle's) is off any cloth but not flying: it hangs or swings on its rod.
  const bool on_rod = std::any_of(m.rods.begin(), m.rods.end(), [i](const Rod& rod) { return rod.ball == i; });
  if (on_rod && r.motion == Motion::Airborne) {
    r.cells[1] = v < m.options.rest_speed ? "hanging" : "swinging";
    r.rod_tip = v < m.options.rest_speed ? "hanging still on its rod" : "swinging on its rod, off any cloth";
  }
  if (v > 0 && v < m.options.rest_speed) {
    // As wide as "0.000": "<.001", not "<0.001".
    const std::string below = text("%g", m.options.rest_speed);
    r.cells[2] = "<" + (below.rfind("0.", 0) == 0 ? below.substr(1) : below);
    r.speed_tip = text("under the rest speed, %g m/s: the engine counts the ball stopped", m.options.rest_speed);
  } else {
    r.cells[2] = text("%.3f", v);
  }
  r.cells[3] = text("%.1f", glm::length(spin(f.state.x, i)));
  r.spin_tip = spin_parts(spin(f.state.x, i), velocity(f.state.x, i), m.balls[i].radius, m.options.rest_speed);
  const BallMotion b = ball_motion(m, f.state, i);
  r.cells[4] = text("%.4f", b.translation + b.rotation);
  const Vec3 p = position(f.state.x, i);
  r.cells[5] = text("%.0f, %.0f", 100 * p.x, 100 * p.z);  // in cm, short (the CSV has it in full)
  return r;
}

// Lines of text a ball table is high: at most 8 rows, the header, and the sideways scroll bar when it has one.
float table_lines(size_t rows, bool scrolls) {
  return std::min(static_cast<float>(rows), 8.0f) + (scrolls ? 2.5f : 1.6f);
}

// The table of `columns` (indices into BallRow::cells; the first is the ball's name, a row selects its ball).
// Returns how far (px) it scrolls sideways, as ImGui laid it out.
float ball_rows(Lab& lab, const char* id, const std::vector<BallRow>& rows, const std::vector<int>& columns,
                bool scrolls) {
  const float shown = table_lines(rows.size(), scrolls);
  // Cells padded a little less than ImGui's default, so that the six columns fit a 1280 px window's inspector.
  ImGui::PushStyleVar(ImGuiStyleVar_CellPadding, ImVec2(em(2), ImGui::GetStyle().CellPadding.y));
  constexpr ImGuiTableFlags flags = ImGuiTableFlags_RowBg | ImGuiTableFlags_ScrollY | ImGuiTableFlags_ScrollX |
                                    ImGuiTableFlags_BordersInnerV | ImGuiTableFlags_SizingFixedFit;
  const bool open = ImGui::BeginTable(id, static_cast<int>(columns.size()), flags,
                                      ImVec2(0, ImGui::GetTextLineHeightWithSpacing() * shown));
  ImGui::PopStyleVar();
  if (!open) return 0;
  ImGui::TableSetupScrollFreeze(0, 1);
  for (int c : columns) ImGui::TableSetupColumn(kBallColumns[c]);
  ImGui::TableHeadersRow();
  for (size_t i = 0; i < rows.size(); ++i) {
    const BallRow& r = rows[i];
    ImGui::TableNextRow();
    for (int c : columns) {
      ImGui::TableNextColumn();
      if (c == 0) {
        const int ball = static_cast<int>(i);
        if (ImGui::Selectable(r.cells[0].c_str(), lab.selected == ball, ImGuiSelectableFlags_SpanAllColumns))
          lab.selected = ball;
      } else if (c == 1) {
        ImGui::PushStyleColor(ImGuiCol_Text, motion_color(r.motion));
        ImGui::TextUnformatted(r.cells[1].c_str());
        ImGui::PopStyleColor();
        if (ImGui::IsItemHovered())
          ImGui::SetTooltip("%s", r.rod_tip.empty() ? motion_meaning(r.motion) : r.rod_tip.c_str());
      } else {
        ImGui::TextUnformatted(r.cells[c].c_str());
        if (c == 2 && !r.speed_tip.empty() && ImGui::IsItemHovered()) ImGui::SetTooltip("%s", r.speed_tip.c_str());
        if (c == 3 && ImGui::IsItemHovered()) ImGui::SetTooltip("%s", r.spin_tip.c_str());
      }
    }
  }
  const float overflow = ImGui::GetScrollMaxX();  // the table's own scrolling region
  pass_wheel_on();
  ImGui::EndTable();
  return overflow;
}

// The width (px) the table of `columns` needs to show every cell without scrolling sideways: more than 8 rows bring
// a vertical scroll bar.
float rows_width(const std::vector<BallRow>& rows, const std::vector<int>& columns) {
  float width = rows.size() > 8 ? ImGui::GetStyle().ScrollbarSize : 0;
  for (int c : columns) {
    float widest = ImGui::CalcTextSize(kBallColumns[c]).x;
    for (const BallRow& r : rows) widest = std::max(widest, ImGui::CalcTextSize(r.cells[c].c_str()).x);
    width += widest + 2 * em(2) + 1;  // the cell's padding and the border between columns
  }
  return width;
}

// Every ball at the time shown. Where the six columns do not fit (a narrow inspector, presentation mode's large
// text) they go into as many tables as it takes, each led by the ball's name, instead of scrolling sideways: as many
// as fit the height of three tables of eight rows (five of a few balls), beyond that the last scrolls sideways.
void ball_table(Lab& lab) {
  const Frame& f = lab.frame();
  const Model& m = shown_model(lab);
  std::vector<BallRow> rows;
  for (int i = 0; i < f.state.ball_count(); ++i) rows.push_back(ball_row(lab, m, f, i));
  const float room = ImGui::GetContentRegionAvail().x;
  const size_t most =
      std::max<size_t>(3, static_cast<size_t>(3 * table_lines(8, false) / table_lines(rows.size(), false)));
  std::vector<std::vector<int>> tables{{0}};
  for (int c = 1; c < 6; ++c) {
    std::vector<int> wider = tables.back();
    wider.push_back(c);
    const bool last = tables.size() == most;
    if (last || tables.back().size() == 1 || rows_width(rows, wider) <= room) tables.back() = std::move(wider);
    else tables.push_back({0, c});
  }
  float overflow = 0;  // px the widest table scrolls sideways
  for (size_t k = 0; k < tables.size(); ++k) {
    const std::string id = k == 0 ? "balls" : "balls " + std::to_string(k + 1);
    overflow = std::max(overflow, ball_rows(lab, id.c_str(), rows, tables[k], rows_width(rows, tables[k]) > room));
  }
  readout("ball tables", static_cast<double>(tables.size()));
  readout("ball table overflow px", overflow);
  if (ImGui::SmallButton("Export table (CSV)")) try {
      const std::string path = export_path(lab, "table", "csv");
      write_file_atomic(path, table_csv(lab));
      lab.say(MessageKind::Note, "wrote " + path);
    } catch (const std::exception& e) {
      lab.say(MessageKind::Refused, e.what());
    }
}

// Gravity's energy (J) of the balls on rods at the start above the bottom of their swing: a pendulum let go from a
// height starts with it, as a textbook draws it (from the start alone, a cradle's bars added up to 0 J).
double height_to_swing(const Model& m, const State& start) {
  const double g = glm::length(m.options.gravity);
  if (g == 0) return 0;
  double e = 0;
  for (const Rod& rod : m.rods)
    if (start.in_play[rod.ball]) {
      const Vec3 lowest = rod.anchor + rod.length * m.options.gravity / g;
      e -= m.balls[rod.ball].mass * glm::dot(m.options.gravity, position(start.x, rod.ball) - lowest);
    }
  return e;
}

// Energy as bars that always add up to what the shot started with: what moves, what is stored in contacts, what
// gravity holds (relative to the start, or for a ball on a rod to the bottom of its swing) and what friction and
// damping have turned into heat and sound.
void energy_bars(const Lab& lab) {
  const Frame& f = lab.frame();
  const Model& m = shown_model(lab);
  const Frame& first = lab.shot ? lab.shot->frames().front() : f;
  const Energy start = first.energy;
  const double swing = height_to_swing(m, first.state);
  double translation = 0, rotation = 0;
  for (int i = 0; i < f.state.ball_count(); ++i)
    if (f.state.in_play[i]) {
      const BallMotion b = ball_motion(m, f.state, i);
      translation += b.translation, rotation += b.rotation;
    }
  const double potential = f.energy.potential - start.potential + swing;
  const double lost = start.total() - f.energy.total();
  const double at_start = start.kinetic + start.elastic + swing;  // J, what the bars add up to
  double scale = at_start;  // the largest energy of the shot spans the bars
  if (lab.shot)
    for (const Frame& fr : lab.shot->frames()) scale = std::max(scale, fr.energy.kinetic + fr.energy.elastic);
  // A ball dropped into a pocket turns height into heat and sound beyond what ever moved: those bars fit too.
  scale = std::max({scale, kEnergyBarFloor, std::abs(potential), std::abs(lost)});
  readout("energy at the start", at_start);
  text_wrapped("Energy (J): the bars add up to the energy at the start, %.4f J", at_start);  // as the bars read
  bar_chart("energy", {{"moving", translation, IM_COL32(80, 170, 255, 255)},
                       {"spinning", rotation, IM_COL32(255, 220, 80, 255)},
                       {"in contacts", f.energy.elastic, IM_COL32(120, 230, 120, 255)},
                       {"height", potential, IM_COL32(200, 140, 255, 255)},
                       {"heat, sound", lost, IM_COL32(255, 110, 90, 255)}},
            scale, "J");
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("in contacts: elastic energy of squeezed contacts (a resting ball's weight presses it about a "
                      "micrometre into the cloth: a few microjoules);\nheight: gravity's potential energy, counted from "
                      "where a ball starts (it sinks into the cloth, hops, falls into a pocket) or, on a rod, from the "
                      "bottom of its swing;\nheat, sound: what friction and "
                      "contact damping have taken out of the motion");
}

constexpr ImU32 kTotalColour = IM_COL32(90, 220, 255, 255);  // the total momentum, bar and arrow

// The momenta in the table's plane as seen from above (x right, z down), head to tail from a common start: their sum,
// the total (cyan), closes the chain; dashed, the total at the start, which holds while the balls only push each
// other. Two balls moving apart after a hit: the angle between their momenta (the 90-degree rule of a cut).
void momentum_diagram(const Lab& lab, const std::vector<std::pair<int, Vec3>>& momenta, const Vec3& start_total) {
  std::vector<ImVec2> chain{{0, 0}};  // in kg m/s
  for (const auto& [i, p] : momenta) chain.push_back({chain.back().x + float(p.x), chain.back().y + float(p.z)});
  const ImVec2 start{float(start_total.x), float(start_total.z)};
  ImVec2 lo = start, hi = start;
  for (const ImVec2& c : chain)
    lo = {std::min(lo.x, c.x), std::min(lo.y, c.y)}, hi = {std::max(hi.x, c.x), std::max(hi.y, c.y)};
  const float w = ImGui::GetContentRegionAvail().x, pad = ImGui::GetFontSize();
  const float h = std::clamp(0.35f * w, 6 * pad, 10 * pad);  // a wide panel draws it larger
  const float k = std::min((w - 2 * pad) / std::max(hi.x - lo.x, 1e-9f), (h - 2 * pad) / std::max(hi.y - lo.y, 1e-9f));
  const ImVec2 at = ImGui::GetCursorScreenPos();
  const ImVec2 o{at.x + w / 2 - k * (lo.x + hi.x) / 2, at.y + h / 2 - k * (lo.y + hi.y) / 2};
  auto screen = [&](ImVec2 q) { return ImVec2{o.x + k * q.x, o.y + k * q.y}; };
  ImDrawList* d = ImGui::GetWindowDrawList();
  d->AddRect(at, {at.x + w, at.y + h}, IM_COL32(90, 90, 90, 255));
  const ImVec2 s0 = screen({0, 0}), s1 = screen(start);
  const float len = std::hypot(s1.x - s0.x, s1.y - s0.y);
  for (float t = 0; t < len; t += 8)  // dashed
    d->AddLine({s0.x + (s1.x - s0.x) * t / len, s0.y + (s1.y - s0.y) * t / len},
               {s0.x + (s1.x - s0.x) * std::min(t + 4, len) / len, s0.y + (s1.y - s0.y) * std::min(t + 4, len) / len},
               IM_COL32(160, 160, 160, 255), 1.5f);
  for (size_t n = 0; n < momenta.size(); ++n) {
    const glm::vec3 c = ball_look(lab.scene.balls[momenta[n].first].spec.id).color;
    flat_arrow(d, screen(chain[n]), screen(chain[n + 1]), ImGui::GetColorU32(ImVec4(c.r, c.g, c.b, 1)), 3.0f);
  }
  flat_arrow(d, s0, screen(chain.back()), kTotalColour, 2.0f);
  ImGui::Dummy({w, h});
  mark("momentum diagram");
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("Each ball's momentum (its colour), head to tail: they add up to the total (cyan).\nDashed: the "
                      "total at the start. Collisions keep it; friction with the cloth and cushions changes it.");
  // The key: a swatch of each arrow's colour (outlined, as a black ball's would not show) and whose it is.
  bool first = true;
  auto key = [&](ImU32 colour, const std::string& label) {
    const float side = ImGui::GetTextLineHeight() * 0.7f;
    if (!first) same_line_if_fits((std::string("MM") + label).c_str());
    first = false;
    const ImVec2 p = ImGui::GetCursorScreenPos();
    const float y = p.y + (ImGui::GetTextLineHeight() - side) / 2;
    d->AddRectFilled({p.x, y}, {p.x + side, y + side}, colour);
    d->AddRect({p.x, y}, {p.x + side, y + side}, IM_COL32(160, 160, 160, 255));
    ImGui::Dummy({side, ImGui::GetTextLineHeight()});
    ImGui::SameLine(0, ImGui::GetStyle().ItemInnerSpacing.x);
    text_wrapped("%s", label.c_str());
  };
  for (const auto& [i, p] : momenta) {
    const glm::vec3 c = ball_look(lab.scene.balls[i].spec.id).color;
    key(ImGui::GetColorU32(ImVec4(c.r, c.g, c.b, 1)), lab.scene.balls[i].spec.id);
  }
  key(kTotalColour, "total");
  key(IM_COL32(160, 160, 160, 255), "total at the start (dashed)");
  if (momenta.size() != 2) return;
  const Vec3 a = momenta[0].second, b = momenta[1].second;
  const double angle = std::acos(std::clamp(glm::dot(a, b) / (glm::length(a) * glm::length(b)), -1.0, 1.0));
  text_wrapped("angle between %s and %s: %.1f deg", lab.scene.balls[momenta[0].first].spec.id.c_str(),
               lab.scene.balls[momenta[1].first].spec.id.c_str(), angle * 180 / M_PI);
  readout("momentum angle deg", angle * 180 / M_PI);
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("Right after a cut with a stun hit (no spin) it is close to 90 deg: equal masses, nearly "
                      "elastic.\nThen friction bends the cue ball's path: a rolling cue ball ends near 30 deg off its "
                      "line.");
}

// The balls that take part in the shot: moving at its start, or moved by the last frame worked out or, while it is
// still worked out, in the predicted paths (which run ahead of a first playback); before a shot, the struck ball and
// those its predicted paths move. With at most 8 balls on the table (a bar each) their bars stay from the start, at
// zero until they are hit, so that a class sees the momentum pass from ball to ball; with more (a break) only the
// moving balls have bars, as the resting ones would crowd them out.
std::vector<bool> balls_in_shot(const Lab& lab, const Model& m) {
  const State* start = lab.shot ? &lab.shot->frames().front().state : &lab.frame().state;
  if (std::count_if(start->in_play.begin(), start->in_play.end(), [](uint8_t p) { return p != 0; }) > 8) return {};
  std::vector<bool> in(start->ball_count());
  const auto predicted = lab.shot && lab.shot->finished() ? std::nullopt : lab.prediction();
  for (int i = 0; i < start->ball_count(); ++i) {
    if (lab.shot) {
      const State& last = lab.shot->frames().back().state;
      in[i] = glm::length(ball_motion(m, *start, i).momentum) > 1e-6 || last.in_play[i] != start->in_play[i] ||
              glm::length(position(last.x, i) - position(start->x, i)) > 1e-6;
    } else {
      in[i] = lab.scene.cue && i < static_cast<int>(lab.scene.balls.size()) &&
              lab.scene.balls[i].spec.id == lab.scene.cue->ball;
    }
    if (predicted && i < static_cast<int>(predicted->paths.size()))
      for (const PathPoint& q : predicted->paths[i])
        in[i] = in[i] || glm::length(q.position - position(start->x, i)) > 1e-6;
  }
  return in;
}

// A ball's momentum along the table (kg m/s): the bars, the total and the diagram are all seen from above, as the
// heading's "along x, z" says (a cradle's swinging balls also move up and down).
Vec3 level_momentum(const Model& m, const State& s, int i) {
  const Vec3 p = ball_motion(m, s, i).momentum;
  return {p.x, 0.0, p.z};
}

void momentum_bars(const Lab& lab) {
  const Frame& f = lab.frame();
  const Model& m = shown_model(lab);
  std::vector<Bar> bars;
  std::vector<std::pair<int, Vec3>> momenta;  // of the balls moving, for the diagram
  Vec3 total{0.0};
  // Scaled to the shot's start too: a ball come to rest with 1e-4 kg m/s left does not fill its bar.
  double scale = kMomentumBarFloor;
  Vec3 start_total{0.0};
  if (lab.shot) {
    const State& start = lab.shot->frames().front().state;
    for (int i = 0; i < start.ball_count(); ++i) {
      const Vec3 p = level_momentum(m, start, i);
      start_total += p;
      scale = std::max(scale, glm::length(p));
    }
    scale = std::max(scale, glm::length(start_total));
  }
  const std::vector<bool> in_shot = balls_in_shot(lab, m);
  for (int i = 0; i < f.state.ball_count(); ++i) {
    if (!f.state.in_play[i]) continue;
    const Vec3 p = level_momentum(m, f.state, i);
    total += p;
    scale = std::max(scale, glm::length(p));
    if (glm::length(p) > 1e-3 * scale) momenta.emplace_back(i, p);
    const bool part = i < static_cast<int>(in_shot.size()) && in_shot[i];
    if (bars.size() < 8 && (glm::length(p) > 1e-6 || i == lab.selected || part))
      bars.push_back({lab.scene.balls[i].spec.id, glm::length(p), IM_COL32(80, 170, 255, 255)});
  }
  bars.push_back({"total", glm::length(total), kTotalColour});
  readout("momentum bars", static_cast<double>(bars.size()));
  scale = std::max(scale, glm::length(total));
  auto shown = [](double v) { return std::abs(v) < 5e-4 ? 0.0 : v; };  // no "-0.000" at rest
  // One line where it fits, else the pair on a line of its own: wrapping breaks after a '.', inside a number.
  char pair[64];
  std::snprintf(pair, sizeof pair, "(%.3f, %.3f)", shown(total.x), shown(total.z));
  const std::string line = std::string("Momentum (kg m/s), total along x, z: ") + pair;
  if (ImGui::CalcTextSize(line.c_str()).x <= ImGui::GetContentRegionAvail().x) {
    ImGui::TextUnformatted(line.c_str());
  } else {
    text_wrapped("Momentum (kg m/s), total along x, z:");
    ImGui::TextUnformatted(pair);
  }
  bar_chart("momentum", bars, scale, "kg m/s");
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("The bars are sizes: the total is the sum of the arrows below, not of the bars.");
  if (lab.shot) momentum_diagram(lab, momenta, start_total);
}

void centre_of_mass(const Lab& lab) {
  const Frame& f = lab.frame();
  const Model& m = shown_model(lab);
  double mass = 0;
  Vec3 p{0.0}, v{0.0};
  for (int i = 0; i < f.state.ball_count(); ++i)
    if (f.state.in_play[i]) {
      mass += m.balls[i].mass;
      p += m.balls[i].mass * position(f.state.x, i);
      v += ball_motion(m, f.state, i).momentum;
    }
  if (mass <= 0) return;
  const double speed = glm::length(v) / mass;  // under the rest speed, as the ball table's "<.001": round-off
  if (speed < m.options.rest_speed) text_wrapped("centre of mass (%.3f, %.3f) m, at rest", p.x / mass, p.z / mass);
  else text_wrapped("centre of mass (%.3f, %.3f) m, moving %.3f m/s", p.x / mass, p.z / mass, speed);
  same_line_if_checkbox_fits("show");
  ImGui::Checkbox("show", &lab.settings.view.centre_of_mass);
}

// A ball's motion regime (sliding, rolling, spinning, stopped) that the same ball leaves within kMomentary, as a
// ball at rest does when a collision starts to push it: a regime of the model's bookkeeping, not one a class sees.
constexpr double kMomentary = 1e-4;  // s
bool regime(const Event& e) {
  return e.bodies.size() == 1 &&
         (e.kind == "sliding" || e.kind == "rolling" || e.kind == "spinning" || e.kind == "stopped");
}
bool momentary(const std::vector<Event>& events, size_t k) {
  if (!regime(events[k])) return false;
  for (size_t j = k + 1; j < events.size() && events[j].time - events[k].time < kMomentary; ++j)
    if (regime(events[j]) && events[j].bodies == events[k].bodies) return true;
  return false;
}

// An event's kind (shotlab/event.hpp) as a class reads it.
const char* event_words(const std::string& kind) {
  static const std::map<std::string, const char*> words{
      {"contact_begin", "contact begins"}, {"contact_end", "contact ends"}, {"landed", "lands"},
      {"stopped", "stops"},                {"spinning", "spins in place"}, {"rolling", "rolls"},
      {"sliding", "slides"},               {"airborne", "leaves the cloth"}, {"pocketed", "pocketed"},
      {"off_table", "off the table"}};
  const auto it = words.find(kind);
  return it != words.end() ? it->second : kind.c_str();
}

// Two lines an event, a click on either goes there: its time, then who and what happened, wrapped (three columns had
// cut "contact begins" and "contact ends" to the same "contact" in a narrow inspector).
void events_list(Lab& lab) {
  static bool bed = false;
  fitting_checkbox("with the bed's contacts", "bed contacts", &bed);
  const auto& events = lab.shot->sim().events();
  if (!ImGui::BeginTable("events", 1, ImGuiTableFlags_RowBg | ImGuiTableFlags_ScrollY,
                         ImVec2(0, ImGui::GetTextLineHeightWithSpacing() * 12)))
    return;
  for (size_t k = 0; k < events.size(); ++k) {
    const Event& e = events[k];
    if (!bed && e.bodies.size() == 2 && e.bodies[1] == "bed") continue;
    if (momentary(events, k)) continue;
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    std::string what;
    for (const std::string& b : e.bodies) what += (what.empty() ? "" : " - ") + b;
    what += std::string(": ") + event_words(e.kind);
    // The whole event is one selectable, as high as its two lines; the text is drawn over it.
    const ImVec2 start = ImGui::GetCursorPos();
    const float indent = em(12);
    const float high = ImGui::GetTextLineHeight() +
                       ImGui::CalcTextSize(what.c_str(), nullptr, false, ImGui::GetContentRegionAvail().x - indent).y;
    ImGui::PushID(static_cast<int>(k));
    if (ImGui::Selectable("##event", std::abs(e.time - lab.view_time) < 1e-9, ImGuiSelectableFlags_AllowItemOverlap,
                          ImVec2(0, high)))
      lab.seek(e.time);
    mark("event " + std::to_string(k));
    ImGui::PopID();
    ImGui::SetCursorPos(start);
    ImGui::TextUnformatted(format_time(e.time, true).c_str());
    ImGui::Indent(indent);
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextUnformatted(what.c_str());
    ImGui::PopTextWrapPos();
    ImGui::Unindent(indent);
  }
  pass_wheel_on();
  ImGui::EndTable();
}

}  // namespace

void teach_panel(Lab& lab) {
  ImGui::Text("at t = %s", format_time(lab.view_time, lab.contact_on_screen()).c_str());
  // Sections a teacher can fold: in presentation mode the split ball table pushed the bars below the panel's edge.
  const bool balls_open = ImGui::CollapsingHeader("Balls", ImGuiTreeNodeFlags_DefaultOpen);
  mark("section Balls");
  if (balls_open) ball_table(lab);
  if (ImGui::CollapsingHeader("Energy", ImGuiTreeNodeFlags_DefaultOpen)) energy_bars(lab);
  if (ImGui::CollapsingHeader("Momentum", ImGuiTreeNodeFlags_DefaultOpen)) {
    momentum_bars(lab);
    centre_of_mass(lab);
  }
  ImGui::Checkbox("velocity", &lab.settings.view.velocity), same_line_if_checkbox_fits("spin");
  ImGui::Checkbox("spin", &lab.settings.view.spin), same_line_if_checkbox_fits("forces");
  ImGui::Checkbox("forces", &lab.settings.view.forces), same_line_if_checkbox_fits("labels");
  ImGui::Checkbox("labels", &lab.settings.view.labels);
  if (!lab.shot || lab.scene.balls.empty()) {
    hint("Plots and events appear once a shot runs.");
    return;
  }
  const bool events_open = ImGui::CollapsingHeader("Events");
  mark("Events");
  if (events_open) {
    hint("Click an event to go to that moment.");
    events_list(lab);
  }
  teach_plots(lab);
}

bool inspector_panel(Lab& lab, Tuning& tuning, const Layout& layout) {
  ViewFlags& v = lab.settings.view;
  static bool shown = true;
  static bool first = true;  // the saved tab is selected once; after that the tab bar follows the clicks
  if (first) v.tab_request = v.tab, first = false;
  if (begin_side_panel("Inspector", layout.right, lab.settings.panels.right_open, shown)) {
    PanelState& panels = lab.settings.panels;
    // Its left edge: a few pixels of its padding, where no widget lies.
    const Rect& where = layout.right;
    const float bar = ImGui::GetFrameHeight();
    const Rect edge{where.x, where.y + bar, 0.75f * ImGui::GetStyle().WindowPadding.x, where.h - bar};
    const PanelWidths widths{panels.right_width, panels.left_width, layout.right_shown(true), layout.left_shown(),
                             lab.settings.presentation};
    panel_width_grip("panel width grip", edge, where.right(), widths, ImGui::GetFontSize() / kBaseFontPx,
                     PanelState{}.right_width);
    if (ImGui::BeginTabBar("tabs")) {
      const char* names[2] = {"Teaching", "Tuning"};
      for (int i = 0; i < 2; ++i) {
        const bool open = ImGui::BeginTabItem(names[i], nullptr, v.tab_request == i ? ImGuiTabItemFlags_SetSelected : 0);
        mark(std::string("tab ") + names[i]);
        if (!open) continue;
        v.tab = i;
        if (i == 0) teach_panel(lab);
        else tune_panel(lab, tuning);
        ImGui::EndTabItem();
      }
      v.tab_request = -1;
      ImGui::EndTabBar();
    }
  }
  shown = end_side_panel("panel Inspector");
  ImGui::End();
  return shown;
}

}  // namespace shotlab
