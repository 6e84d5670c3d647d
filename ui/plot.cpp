#include "ui/plot.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "ui/files.hpp"
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

// Title and legend above the plot area; returns the height used.
float header(ImDrawList* d, ImVec2 o, float width, const PlotSpec& spec, const std::vector<PlotSeries>& series) {
  const float line = ImGui::GetTextLineHeight();
  const std::string title = spec.title + " (" + spec.unit + ")";
  const float title_w = ImGui::CalcTextSize(title.c_str()).x;
  float x = o.x + title_w + em(16), y = o.y;
  if (title_w > width) {  // wrapped in a narrow panel; the legend starts below it
    d->AddText(ImGui::GetFont(), ImGui::GetFontSize(), o, ImGui::GetColorU32(ImGuiCol_Text), title.c_str(), nullptr,
               width);
    x = o.x + em(8), y = o.y + ImGui::CalcTextSize(title.c_str(), nullptr, false, width).y;
  } else {
    d->AddText(o, ImGui::GetColorU32(ImGuiCol_Text), title.c_str());
  }
  for (const PlotSeries& s : series) {
    const float w = ImGui::CalcTextSize(s.name.c_str()).x + em(16);
    if (x + w > o.x + width) x = o.x + em(8), y += line;
    d->AddRectFilled({x, y + line * 0.3f}, {x + em(10), y + line * 0.7f}, s.colour);
    d->AddText({x + em(13), y}, ImGui::GetColorU32(ImGuiCol_Text), s.name.c_str());
    x += w + em(8);
  }
  return y - o.y + line + em(4);
}

}  // namespace

PlotAction plot(const char* id, const PlotSpec& spec, const std::vector<PlotSeries>& series, float height) {
  PlotAction out;
  ImGui::PushID(id);
  const ImVec2 o = ImGui::GetCursorScreenPos();
  const float width = std::max(ImGui::GetContentRegionAvail().x, em(120));
  ImGui::InvisibleButton("plot", ImVec2(width, height));
  const bool hovered = ImGui::IsItemHovered(), active = ImGui::IsItemActive();
  out.rect = Rect{o.x, o.y, width, height};
  mark(std::string("plot ") + id);
  ImDrawList* d = ImGui::GetWindowDrawList();
  const float line = ImGui::GetTextLineHeight();
  const float top = o.y + header(d, o, width, spec, series);
  double t0 = spec.t0, t1 = spec.t1;
  if (t1 < t0) {
    t0 = INFINITY, t1 = -INFINITY;
    for (const PlotSeries& s : series)
      if (!s.time.empty()) t0 = std::min(t0, s.time.front()), t1 = std::max(t1, s.time.back());
    if (!(t0 < t1)) t0 = 0, t1 = 1;
  }
  const Range v = value_range(spec, series, t0, t1);
  const Ticks yt = nice_ticks(v.lo, v.hi, 4);
  float left = 0;
  for (double y : yt.values) left = std::max(left, ImGui::CalcTextSize(format_tick(y, yt).c_str()).x);
  const ImVec2 a{o.x + left + em(6), top}, b{o.x + width - em(4), o.y + height - 2 * line - em(2)};
  if (b.y - a.y < line || b.x - a.x < em(40)) return ImGui::PopID(), out;
  auto px = [&](double t) { return a.x + static_cast<float>((t - t0) / (t1 - t0)) * (b.x - a.x); };
  auto py = [&](double y) { return b.y - static_cast<float>((y - v.lo) / (v.hi - v.lo)) * (b.y - a.y); };
  const ImU32 grid = IM_COL32(90, 90, 90, 120), text = ImGui::GetColorU32(ImGuiCol_Text);
  d->AddRectFilled(a, b, IM_COL32(20, 22, 26, 255));
  for (double y : yt.values) {
    if (y < v.lo || y > v.hi) continue;
    d->AddLine({a.x, py(y)}, {b.x, py(y)}, grid);
    const std::string s = format_tick(y, yt);
    d->AddText({a.x - em(4) - ImGui::CalcTextSize(s.c_str()).x, py(y) - line / 2}, text, s.c_str());
  }
  const TimeUnit unit = time_unit(t1 - t0);
  const double from = spec.origin;
  const Ticks xt = nice_ticks((t0 - from) * unit.per_second, (t1 - from) * unit.per_second,
                              std::max(2, static_cast<int>((b.x - a.x) / em(60))));
  for (double x : xt.values) {
    const float X = px(from + x / unit.per_second);
    if (X < a.x - 0.5f || X > b.x + 0.5f) continue;
    d->AddLine({X, a.y}, {X, b.y}, grid);
    const std::string s = format_tick(x, xt);
    d->AddText({X - ImGui::CalcTextSize(s.c_str()).x / 2, b.y + 1}, text, s.c_str());
  }
  // Under the axis, centred; in a narrow panel the origin's label drops "time", then starts at the plot's left edge.
  std::string x_label =
      (spec.origin_name.empty() ? "time" : "time since " + spec.origin_name) + " (" + unit.name + ")";
  if (!spec.origin_name.empty() && ImGui::CalcTextSize(x_label.c_str()).x > width) x_label = x_label.substr(5);
  d->AddText({std::max(o.x, (a.x + b.x - ImGui::CalcTextSize(x_label.c_str()).x) / 2), b.y + line}, text,
             x_label.c_str());
  d->PushClipRect(a, b, true);
  for (const PlotSeries& s : series) {
    std::vector<ImVec2> pts;
    for (size_t k = 0; k < s.time.size(); ++k)
      if (std::isfinite(s.value[k])) pts.push_back({px(s.time[k]), py(std::clamp(s.value[k], v.lo, v.hi))});
    simplified_polyline(d, pts, s.colour, em(1.6f));
  }
  if (spec.cursor >= t0 && spec.cursor <= t1) d->AddLine({px(spec.cursor), a.y}, {px(spec.cursor), b.y}, IM_COL32(255, 255, 255, 200), 1.5f);
  d->PopClipRect();
  const ImVec2 m = ImGui::GetIO().MousePos;
  if (hovered && m.x >= a.x && m.x <= b.x) {
    const double t = t0 + (m.x - a.x) / (b.x - a.x) * (t1 - t0);
    d->AddLine({m.x, a.y}, {m.x, b.y}, IM_COL32(255, 255, 120, 120));
    std::string tip = "t = " + format_time(t, t1 - t0 < 0.05);
    if (!spec.origin_name.empty()) {
      char since[64];
      std::snprintf(since, sizeof since, " (%.4g %s since ", (t - from) * unit.per_second, unit.name);
      tip += since + spec.origin_name + ")";
    }
    for (const PlotSeries& s : series)
      if (const auto y = value_at(s, t)) tip += "\n" + s.name + ": " + with_unit(*y, spec.unit);
    ImGui::SetTooltip("%s\n(click: go to this time; right-click: export)", tip.c_str());
    if (active) out.picked = t;
  }
  if (ImGui::BeginPopupContextItem("export")) {
    out.export_csv = ImGui::MenuItem("Export CSV");
    out.export_png = ImGui::MenuItem("Export PNG");
    ImGui::EndPopup();
  }
  ImGui::PopID();
  return out;
}

void write_plot_csv(const std::string& path, const PlotSpec& spec, const std::vector<PlotSeries>& series) {
  std::ostringstream out;
  out.precision(10);
  const bool shared = !series.empty() && std::all_of(series.begin(), series.end(), [&](const PlotSeries& s) {
    return s.time == series.front().time;
  });
  if (shared) {
    out << "time_s";
    for (const PlotSeries& s : series) out << ",\"" << s.name << " (" << spec.unit << ")\"";
    out << '\n';
    for (size_t k = 0; k < series.front().time.size(); ++k) {
      out << series.front().time[k];
      for (const PlotSeries& s : series) out << ',' << s.value[k];
      out << '\n';
    }
  } else {
    out << "series,time_s,value (" << spec.unit << ")\n";
    for (const PlotSeries& s : series)
      for (size_t k = 0; k < s.time.size(); ++k) out << '"' << s.name << "\"," << s.time[k] << ',' << s.value[k] << '\n';
  }
  write_file_atomic(path, out.str());
}

}  // namespace shotlab
