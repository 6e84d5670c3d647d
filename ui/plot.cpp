#include "ui/plot.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

#include "ui/ticks.hpp"
#include "ui/widgets.hpp"

namespace shotlab {

namespace {

struct Range {
  double lo = 0, hi = 1;
};

Range value_range(const PlotSpec& spec, const std::vector<PlotSeries>& series, double t0, double t1) {
  double lo = spec.zero_based ? 0 : INFINITY, hi = spec.zero_based ? 0 : -INFINITY;
  for (const PlotSeries& s : series)
    for (size_t k = 0; k < s.time.size(); ++k)
      if (s.time[k] >= t0 && s.time[k] <= t1 && std::isfinite(s.value[k]))
        lo = std::min(lo, s.value[k]), hi = std::max(hi, s.value[k]);
  if (!(lo <= hi)) lo = 0, hi = 1;
  if (hi - lo < 1e-12 * std::max(1.0, std::abs(hi))) hi = lo + std::max(1e-9, std::abs(lo) * 0.1 + 1e-9);
  const double pad = 0.05 * (hi - lo);
  return {lo - (spec.zero_based && lo == 0 ? 0 : pad), hi + pad};
}

// Value of a series at time t, interpolated; nullopt outside it.
std::optional<double> value_at(const PlotSeries& s, double t) {
  if (s.time.empty() || t < s.time.front() || t > s.time.back()) return std::nullopt;
  const size_t k = std::upper_bound(s.time.begin(), s.time.end(), t) - s.time.begin();
  if (k == 0) return s.value.front();
  if (k >= s.time.size()) return s.value.back();
  const double a = s.time[k - 1], b = s.time[k];
  const double w = b > a ? (t - a) / (b - a) : 0;
  return s.value[k - 1] + w * (s.value[k] - s.value[k - 1]);
}

std::string with_unit(double v, const std::string& unit) {
  char text[64];
  std::snprintf(text, sizeof text, "%.4g %s", v, unit.c_str());
  return text;
}

constexpr ImU32 kGrid = IM_COL32(90, 90, 90, 120), kPaperGrid = IM_COL32(205, 205, 205, 255);

ImU32 grid(const PlotSpec& spec) { return spec.paper ? kPaperGrid : kGrid; }

// A series' colour on paper: darker, so that the light ones (yellow) read on white.
ImU32 ink(const PlotSpec& spec, ImU32 colour) {
  if (!spec.paper) return colour;
  ImVec4 c = ImGui::ColorConvertU32ToFloat4(colour);
  return ImGui::GetColorU32(ImVec4(0.7f * c.x, 0.7f * c.y, 0.7f * c.z, 1.0f));
}

// Title and legend above the plot area; returns the height used. With no draw list, only measures it.
float header(ImDrawList* d, ImVec2 o, float width, const PlotSpec& spec, const std::vector<PlotSeries>& series) {
  const float line = ImGui::GetTextLineHeight();
  const ImU32 text = ImGui::GetColorU32(ImGuiCol_Text);
  const std::string title = spec.title + " (" + spec.unit + ")";
  const float title_w = ImGui::CalcTextSize(title.c_str()).x;
  float x = o.x + title_w + em(16), y = o.y;
  if (title_w > width) {  // wrapped in a narrow panel; the legend starts below it
    if (d) d->AddText(ImGui::GetFont(), ImGui::GetFontSize(), o, text, title.c_str(), nullptr, width);
    x = o.x + em(8), y = o.y + ImGui::CalcTextSize(title.c_str(), nullptr, false, width).y;
  } else if (d) {
    d->AddText(o, text, title.c_str());
  }
  for (const PlotSeries& s : series) {
    const float w = ImGui::CalcTextSize(s.name.c_str()).x + em(16);
    if (x + w > o.x + width) x = o.x + em(8), y += line;
    // A name longer than the line wraps under itself (a narrow panel, presentation mode's large text).
    const float wrap = o.x + width - (x + em(13));
    if (d) {
      d->AddRectFilled({x, y + line * 0.3f}, {x + em(10), y + line * 0.7f}, ink(spec, s.colour));
      d->AddText(ImGui::GetFont(), ImGui::GetFontSize(), {x + em(13), y}, text, s.name.c_str(), nullptr, wrap);
    }
    const float lines = ImGui::CalcTextSize(s.name.c_str(), nullptr, false, wrap).y;
    if (lines > line * 1.5f) x = o.x + width, y += lines - line;  // the next name starts a line of its own
    x += w + em(8);
  }
  return y - o.y + line + em(4);
}

// The time axis: the spec's, or the series' extent.
std::pair<double, double> time_extent(const PlotSpec& spec, const std::vector<PlotSeries>& series) {
  if (spec.t1 >= spec.t0) return {spec.t0, spec.t1};
  double t0 = INFINITY, t1 = -INFINITY;
  for (const PlotSeries& s : series)
    if (!s.time.empty()) t0 = std::min(t0, s.time.front()), t1 = std::max(t1, s.time.back());
  return t0 < t1 ? std::pair{t0, t1} : std::pair{0.0, 1.0};
}

// The plot area a-b on screen and the times and values it spans.
struct Area {
  ImVec2 a, b;
  double t0, t1;
  Range v;
  float x(double t) const { return a.x + static_cast<float>((t - t0) / (t1 - t0)) * (b.x - a.x); }
  float y(double value) const { return b.y - static_cast<float>((value - v.lo) / (v.hi - v.lo)) * (b.y - a.y); }
};

void value_axis(ImDrawList* d, const Area& p, const PlotSpec& spec, const Ticks& ticks) {
  const float line = ImGui::GetTextLineHeight();
  for (double y : ticks.values) {
    if (y < p.v.lo || y > p.v.hi) continue;
    d->AddLine({p.a.x, p.y(y)}, {p.b.x, p.y(y)}, grid(spec));
    const std::string s = format_tick(y, ticks);
    d->AddText({p.a.x - em(4) - ImGui::CalcTextSize(s.c_str()).x, p.y(y) - line / 2}, ImGui::GetColorU32(ImGuiCol_Text),
               s.c_str());
  }
}

// Ticks counted from spec.origin in the span's unit, and the axis's name under them.
void time_axis(ImDrawList* d, const Area& p, const PlotSpec& spec, float left, float width) {
  const ImU32 text = ImGui::GetColorU32(ImGuiCol_Text);
  const TimeUnit unit = time_unit(p.t1 - p.t0);
  const Ticks ticks = nice_ticks((p.t0 - spec.origin) * unit.per_second, (p.t1 - spec.origin) * unit.per_second,
                                 std::max(3, static_cast<int>((p.b.x - p.a.x) / em(60))));
  for (double x : ticks.values) {
    const float X = p.x(spec.origin + x / unit.per_second);
    if (X < p.a.x - 0.5f || X > p.b.x + 0.5f) continue;
    d->AddLine({X, p.a.y}, {X, p.b.y}, grid(spec));
    const std::string s = format_tick(x, ticks);
    d->AddText({X - ImGui::CalcTextSize(s.c_str()).x / 2, p.b.y + 1}, text, s.c_str());
  }
  // Under the axis, centred; in a narrow panel the origin's label drops "time", then "since", then starts at the
  // plot's left edge.
  std::string label = (spec.origin_name.empty() ? "time" : "time since " + spec.origin_name) + " (" + unit.name + ")";
  for (size_t drop : {5, 6})
    if (!spec.origin_name.empty() && ImGui::CalcTextSize(label.c_str()).x > width) label = label.substr(drop);
  d->AddText({std::max(left, (p.a.x + p.b.x - ImGui::CalcTextSize(label.c_str()).x) / 2),
              p.b.y + ImGui::GetTextLineHeight()},
             text, label.c_str());
}

void curves(ImDrawList* d, const Area& p, const PlotSpec& spec, const std::vector<PlotSeries>& series) {
  d->PushClipRect(p.a, p.b, true);
  for (const PlotSeries& s : series) {
    std::vector<ImVec2> pts;
    for (size_t k = 0; k < s.time.size(); ++k)
      if (std::isfinite(s.value[k])) pts.push_back({p.x(s.time[k]), p.y(std::clamp(s.value[k], p.v.lo, p.v.hi))});
    simplified_polyline(d, pts, ink(spec, s.colour), em(spec.paper ? 2.4f : 1.6f));
  }
  if (spec.cursor >= p.t0 && spec.cursor <= p.t1)
    d->AddLine({p.x(spec.cursor), p.a.y}, {p.x(spec.cursor), p.b.y}, IM_COL32(255, 255, 255, 200), 1.5f);
  d->PopClipRect();
}

// Under the pointer: a line, and a tooltip with the time and each series' value there. Returns that time.
std::optional<double> hover(ImDrawList* d, const Area& p, const PlotSpec& spec, const std::vector<PlotSeries>& series) {
  const ImVec2 m = ImGui::GetIO().MousePos;
  if (m.x < p.a.x || m.x > p.b.x) return std::nullopt;
  const double t = p.t0 + (m.x - p.a.x) / (p.b.x - p.a.x) * (p.t1 - p.t0);
  d->AddLine({m.x, p.a.y}, {m.x, p.b.y}, IM_COL32(255, 255, 120, 120));
  std::string tip = "t = " + format_time(t, p.t1 - p.t0 < 0.05);
  if (!spec.origin_name.empty()) {
    const TimeUnit unit = time_unit(p.t1 - p.t0);
    char since[64];
    std::snprintf(since, sizeof since, " (%.4g %s since ", (t - spec.origin) * unit.per_second, unit.name);
    tip += since + spec.origin_name + ")";
  }
  for (const PlotSeries& s : series)
    if (const auto y = value_at(s, t)) tip += "\n" + s.name + ": " + with_unit(*y, spec.unit);
  if (!spec.hint.empty()) tip += "\n" + spec.hint;
  tip += std::string("\n(") + (spec.seekable ? "click: go to this time; " : "") + "right-click: export)";
  // Above the plot (below it where there is no room), beside the pointer: not over the curve it reads.
  const ImVec2 pad = ImGui::GetStyle().WindowPadding, size = ImGui::CalcTextSize(tip.c_str());
  const float w = size.x + 2 * pad.x, h = size.y + 2 * pad.y, right = ImGui::GetMainViewport()->Size.x;
  const bool above = p.a.y - h - 4 >= 0, leftwards = m.x + 16 + w > right;
  ImGui::SetNextWindowPos({leftwards ? m.x - 16 : m.x + 16, above ? p.a.y - 4 : p.b.y + 2 * ImGui::GetTextLineHeight()},
                          ImGuiCond_Always, {leftwards ? 1.0f : 0.0f, above ? 1.0f : 0.0f});
  ImGui::BeginTooltip();
  ImGui::TextUnformatted(tip.c_str());
  ImGui::EndTooltip();
  return t;
}

}  // namespace

PlotAction plot(const char* id, const PlotSpec& spec, const std::vector<PlotSeries>& series, float height) {
  PlotAction out;
  ImGui::PushID(id);
  const ImVec2 o = ImGui::GetCursorScreenPos();
  const float width = std::max(ImGui::GetContentRegionAvail().x, em(120));
  const float line = ImGui::GetTextLineHeight();
  // However tall the title and legend grow (wrapped in a narrow panel), the curves keep em(90) of height.
  height = std::max(height, header(nullptr, o, width, spec, series) + em(90) + 2 * line + em(2));
  ImGui::InvisibleButton("plot", ImVec2(width, height));
  const bool hovered = ImGui::IsItemHovered(), active = ImGui::IsItemActive();
  out.rect = Rect{o.x, o.y, width, height};
  mark(std::string("plot ") + id);
  ImDrawList* d = ImGui::GetWindowDrawList();
  const float top = o.y + header(d, o, width, spec, series);
  const auto [t0, t1] = time_extent(spec, series);
  const Range v = value_range(spec, series, t0, t1);
  // A tick every two and a half lines of height, at least four: a plot drawn large for a picture gets more.
  const Ticks yt = nice_ticks(v.lo, v.hi, std::max(4, static_cast<int>((o.y + height - top) / (2.5f * line)) - 1));
  float left = 0;
  for (double y : yt.values) left = std::max(left, ImGui::CalcTextSize(format_tick(y, yt).c_str()).x);
  const Area area{{o.x + left + em(6), top}, {o.x + width - em(4), o.y + height - 2 * line - em(2)}, t0, t1, v};
  if (area.b.y - area.a.y < line || area.b.x - area.a.x < em(40)) return ImGui::PopID(), out;
  d->AddRectFilled(area.a, area.b, spec.paper ? IM_COL32(255, 255, 255, 255) : IM_COL32(20, 22, 26, 255));
  value_axis(d, area, spec, yt);
  time_axis(d, area, spec, o.x, width);
  curves(d, area, spec, series);
  if (hovered && spec.hover)
    if (const auto t = hover(d, area, spec, series); t && active && spec.seekable) out.picked = *t;
  if (ImGui::BeginPopupContextItem("export")) {
    out.export_csv = ImGui::MenuItem("Export CSV");
    mark("Export CSV");
    out.export_png = ImGui::MenuItem("Export PNG");
    mark("Export PNG");
    ImGui::EndPopup();
  }
  ImGui::PopID();
  return out;
}

}  // namespace shotlab
