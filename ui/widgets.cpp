#include "ui/widgets.hpp"

#include <algorithm>
#include <boost/geometry/algorithms/simplify.hpp>
#include <boost/geometry/geometries/register/linestring.hpp>
#include <boost/geometry/geometries/register/point.hpp>
#include <boost/geometry/strategies/strategies.hpp>
#include <cfloat>
#include <cstdarg>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <set>
#include <string_view>
#include <imgui_internal.h>
#include <utility>

#include "ui/text_wrap.hpp"

// Screen points as a Boost.Geometry line, for its Douglas-Peucker simplification (simplified_polyline).
BOOST_GEOMETRY_REGISTER_POINT_2D(ImVec2, float, boost::geometry::cs::cartesian, x, y)
BOOST_GEOMETRY_REGISTER_LINESTRING(std::vector<ImVec2>)

namespace shotlab {

namespace {
constexpr float kBaseFont = 15;      // px: the font size the unscaled sizes are given for
constexpr float kMinControl = 130;   // px (unscaled): narrower, a slider is hard to use
std::map<std::string, Rect> current_marks, last_marks;
std::map<std::string, double> current_readouts, last_readouts;
std::string slider_note;  // take_slider_note()
std::set<ImGuiID> current_integers, last_integers;  // integer_entry(): this frame's and the last one's
}  // namespace

float em(float pixels) { return pixels * ImGui::GetFontSize() / kBaseFont; }

void simplified_polyline(ImDrawList* d, const std::vector<ImVec2>& points, ImU32 colour, float width) {
  constexpr float kTolerance = 0.3f;  // px
  if (points.size() < 2) return;
  static thread_local std::vector<ImVec2> kept;
  kept.clear();
  boost::geometry::simplify(points, kept, kTolerance);
  d->AddPolyline(kept.data(), static_cast<int>(kept.size()), colour, ImDrawFlags_None, width);
}

Fields::Fields(std::initializer_list<const char*> labels) {
  for (const char* l : labels) column_ = std::max(column_, ImGui::CalcTextSize(l).x);
  column_ += ImGui::GetStyle().ItemInnerSpacing.x * 2;
  above_ = ImGui::GetContentRegionAvail().x - column_ < em(kMinControl);
}

void Fields::label(const char* text) const {
  ImGui::AlignTextToFramePadding();
  ImGui::TextUnformatted(text);
  if (!above_) ImGui::SameLine(column_);
  ImGui::SetNextItemWidth(-FLT_MIN);
}

bool slider(const char* id, double& v, double lo, double hi, const char* format, bool log) {
  // A typed value (ctrl+click, or a double click) goes into `typed` and reaches v only when the entry ends, so that
  // the keystrokes on the way ("1", "1e", "1e3") do not re-run the shot; out of range, it is clamped with a note.
  static ImGuiID typing = 0;
  static double typed = 0;
  const ImGuiID gid = ImGui::GetID(id);
  // Tab ends the entry before this slider is drawn again: what was typed still counts.
  const bool ended_before = typing == gid && !ImGui::TempInputIsActive(gid);
  if (ended_before) typing = 0;
  const bool was_typing = typing == gid;
  ImGui::SetNextItemWidth(-FLT_MIN);
  const bool changed = ImGui::SliderScalar(id, ImGuiDataType_Double, was_typing ? &typed : &v, &lo, &hi, format,
                                           log ? ImGuiSliderFlags_Logarithmic : 0);
  const bool typing_now = ImGui::TempInputIsActive(gid);
  if (typing_now && !was_typing) typing = gid, typed = v;
  if (typing_now) return false;
  if (!was_typing && !ended_before) return changed;
  typing = 0;  // the entry ended: Return, a click elsewhere or Tab apply it; Escape keeps v as it was (unrounded)
  if (typed == v || ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape))) return false;
  const double kept = std::isfinite(typed) ? std::clamp(typed, lo, hi) : v;
  if (kept != typed) {
    const char* name = id + std::strspn(id, "#");
    char text[200];
    std::snprintf(text, sizeof text, "%s: %g is outside this slider's range, %g to %g; set to %g", name, typed, lo,
                  hi, kept);
    slider_note = text;
  }
  const bool edited = kept != v;
  v = kept;
  return edited;
}

std::string take_slider_note() { return std::exchange(slider_note, std::string()); }

void integer_entry() { current_integers.insert(ImGui::GetItemID()); }

TypingNote vet_number_typing() {
  const ImGuiContext& g = *GImGui;
  ImGuiIO& io = ImGui::GetIO();
  // Every number entry here is a slider's or drag's typed entry (ctrl+click), whose filter lets through what this does:
  // ImGui's CharsScientific for a double, CharsDecimal (no e) for an integer.
  static ImGuiID entry = 0;    // the entry the characters dropped so far were typed into (one key a frame)
  static std::string dropped;  // all of them, named in every note of that entry
  const bool typing = g.ActiveId != 0 && g.TempInputId == g.ActiveId;
  if (!typing || entry != g.ActiveId) entry = typing ? g.ActiveId : 0, dropped.clear();  // a new entry starts afresh
  if (!typing) return {};
  const bool integer = last_integers.count(g.ActiveId) > 0;
  const char* takes = integer ? "0123456789.+-*/" : "0123456789.+-*/eE";
  const size_t before = dropped.size();
  bool comma = false;
  for (ImWchar& c : io.InputQueueCharacters) {
    // A decimal comma in a number with decimals is its point (2,5 read 25 and was clamped); in a whole number a comma
    // groups thousands, which ImGui's dropping of it keeps right.
    if (c == ',' && !integer) c = '.', comma = true;
    if (c < 0x20 || c == ',' || (c < 0x80 && c != ' ' && std::strchr(takes, static_cast<char>(c)))) continue;
    char utf8[5];
    dropped += std::string(dropped.empty() ? "'" : ", '") + ImTextCharToUtf8(utf8, c) + "'";
  }
  if (dropped.size() == before) return {comma ? "',' is taken as the decimal point" : "", false};
  return {dropped + " cannot be part of " + (integer ? "a whole number: the field takes digits and signs"
                                                    : "a number: the field takes digits, '.' or ',' for decimals, e "
                                                      "for powers of ten and signs"),
          true};
}

bool tip_widget(CueStrike& cue, float size) {
  const float r = size / 2 - 6;
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  const ImVec2 c{origin.x + size / 2, origin.y + size / 2};
  ImGui::InvisibleButton("tip", ImVec2(size, size));
  mark("tip widget");
  ImDrawList* d = ImGui::GetWindowDrawList();
  d->AddCircleFilled(c, r, IM_COL32(240, 238, 225, 255), 48);
  for (int k = 0; k < 24; k += 2) {
    const float a0 = k * 2 * float(M_PI) / 24, a1 = (k + 1) * 2 * float(M_PI) / 24;
    const float m = r * static_cast<float>(cue.miscue_limit);
    d->AddLine({c.x + m * std::cos(a0), c.y + m * std::sin(a0)}, {c.x + m * std::cos(a1), c.y + m * std::sin(a1)},
               IM_COL32(200, 60, 60, 255), 1.5f);
  }
  d->AddLine({c.x - r, c.y}, {c.x + r, c.y}, IM_COL32(150, 150, 150, 255));
  d->AddLine({c.x, c.y - r}, {c.x, c.y + r}, IM_COL32(150, 150, 150, 255));
  const ImVec2 tip{c.x + r * float(cue.side), c.y - r * float(cue.height)};
  d->AddCircleFilled(tip, std::max(4.0f, size / 18), IM_COL32(40, 90, 220, 255));
  if (!ImGui::IsItemActive()) return false;
  const ImVec2 m = ImGui::GetIO().MousePos;
  double side = (m.x - c.x) / r, height = -(m.y - c.y) / r;
  const double len = std::hypot(side, height);
  if (len > 0.9) side *= 0.9 / len, height *= 0.9 / len;  // keep the tip on the ball
  side = std::round(side * 100) / 100, height = std::round(height * 100) / 100;
  if (side == cue.side && height == cue.height) return false;
  cue.side = side;
  cue.height = height;
  return true;
}

bool begin_side_panel(const char* name, const Rect& where, bool want_open, bool shown) {
  ImGui::SetNextWindowPos(ImVec2(where.x, where.y), ImGuiCond_Always);
  ImGui::SetNextWindowSize(ImVec2(where.w, where.h), ImGuiCond_Always);
  if (want_open != shown) ImGui::SetNextWindowCollapsed(!want_open, ImGuiCond_Always);
  // No background of its own: the window is cleared to it (panel_background), which costs a software renderer far
  // less than a blended rectangle over a third of the window.
  ImGui::PushStyleColor(ImGuiCol_WindowBg, ImVec4(0, 0, 0, 0));
  // The scrollbar always there: one that came and went as sections opened moved everything under the pointer.
  const bool open = ImGui::Begin(name, nullptr, ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                                                    ImGuiWindowFlags_AlwaysVerticalScrollbar);
  ImGui::PopStyleColor();
  return open;
}

void panel_width_grip(const char* name, const Rect& strip, float outer_x, PanelWidths w, float scale, float standard) {
  if (w.locked) return;
  // The drag's state, kept by ImGui under the strip's id (values, not references: a new key may move the others).
  ImGuiStorage* storage = ImGui::GetStateStorage();
  const ImGuiID id = ImGui::GetID(name), kDragging = id, kGrab = id + 1, kStartX = id + 2, kMoved = id + 3;
  const ImGuiIO& io = ImGui::GetIO();
  const float reach = std::abs(io.MousePos.x - outer_x);  // from the outer edge to the pointer, px
  // Over the strip with nothing on top of it: this panel under the pointer, or no window at all (a strip outside it).
  const bool free = ImGui::IsWindowHovered(ImGuiHoveredFlags_ChildWindows) ||
                    !ImGui::IsWindowHovered(ImGuiHoveredFlags_AnyWindow | ImGuiHoveredFlags_AllowWhenBlockedByPopup);
  const bool over = free && !ImGui::IsPopupOpen("", ImGuiPopupFlags_AnyPopupId) &&
                    strip.contains(io.MousePos.x, io.MousePos.y);
  mark_rect(name, strip);
  bool dragging = storage->GetBool(kDragging);
  if (over && ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left)) {
    w.width = standard, dragging = false;
  } else if (over && ImGui::IsMouseClicked(ImGuiMouseButton_Left)) {
    dragging = true;
    storage->SetFloat(kGrab, w.shown - reach), storage->SetFloat(kStartX, io.MousePos.x);
    storage->SetBool(kMoved, false);
  }
  if (!ImGui::IsMouseDown(ImGuiMouseButton_Left)) dragging = false;
  storage->SetBool(kDragging, dragging);
  if (over || dragging) {
    ImGui::SetMouseCursor(ImGuiMouseCursor_ResizeEW);
    ImGui::GetForegroundDrawList()->AddRectFilled({strip.x, strip.y}, {strip.right(), strip.bottom()},
                                                  ImGui::GetColorU32(ImGuiCol_SeparatorHovered));
  }
  if (!dragging || (!storage->GetBool(kMoved) && io.MousePos.x == storage->GetFloat(kStartX))) return;
  if (!storage->GetBool(kMoved)) {
    // The drag starts from what is on screen: both widths as shown (the layout may have narrowed them). A click that
    // does not move changes nothing.
    storage->SetBool(kMoved, true);
    if (w.other_shown > 0) w.other_width = w.other_shown / scale;
  }
  const float widest = widest_panel(ImGui::GetMainViewport()->Size.x, {w.other_shown > 0, w.other_shown}) / scale;
  w.width = std::clamp((reach + storage->GetFloat(kGrab)) / scale, kMinPanelWidth, std::max(widest, kMinPanelWidth));
}

namespace {
// The lines of text_wrapped, for an already formatted text.
void wrap_lines(const char* text) {
  ImGuiWindow* window = ImGui::GetCurrentWindow();
  const float wrap_x = std::max(window->DC.TextWrapPos, 0.0f);  // 0: the content region's edge
  const float width = std::max(ImGui::CalcWrapWidthForPos(ImGui::GetCursorScreenPos(), wrap_x), 1.0f);
  auto wide = [](std::string_view s) { return ImGui::CalcTextSize(s.data(), s.data() + s.size()).x; };
  // A word wider than the line alone (a folder's path) is cut where ImGui would cut it.
  auto emit = [&](std::string_view s) {
    const bool overlong = wide(s) > width;
    if (overlong) ImGui::PushTextWrapPos(wrap_x);
    ImGui::TextUnformatted(s.data(), s.data() + s.size());
    if (overlong) ImGui::PopTextWrapPos();
  };
  ImGui::BeginGroup();  // later lines start where the first does (after a bullet, say)
  const std::string_view all(text);
  for (size_t start = 0; start <= all.size();) {  // each paragraph
    const size_t stop = std::min(all.find('\n', start), all.size());
    for (std::string_view line : wrap_paragraph(all.substr(start, stop - start), width, wide)) emit(line);
    start = stop + 1;
  }
  ImGui::EndGroup();
}
}  // namespace


void text_wrapped(const char* fmt, ...) {
  char text[4096];
  va_list args;
  va_start(args, fmt);
  std::vsnprintf(text, sizeof text, fmt, args);
  va_end(args);
  wrap_lines(text);
}

void coloured_wrapped(const ImVec4& colour, const char* fmt, ...) {
  char text[4096];
  va_list args;
  va_start(args, fmt);
  std::vsnprintf(text, sizeof text, fmt, args);
  va_end(args);
  ImGui::PushStyleColor(ImGuiCol_Text, colour);
  wrap_lines(text);
  ImGui::PopStyleColor();
}

void flat_arrow(ImDrawList* d, ImVec2 from, ImVec2 to, ImU32 color, float width) {
  const float dx = to.x - from.x, dy = to.y - from.y, len = std::hypot(dx, dy);
  if (len < 2) return;
  const float ux = dx / len, uy = dy / len, head = std::min(10.0f, len * 0.4f), w = 0.45f * head;
  d->AddLine(from, {to.x - ux * head * 0.5f, to.y - uy * head * 0.5f}, color, width);
  d->AddTriangleFilled(to, {to.x - ux * head - uy * w, to.y - uy * head + ux * w},
                       {to.x - ux * head + uy * w, to.y - uy * head - ux * w}, color);
}

void hint(const std::string& text) {
  coloured_wrapped(ImGui::GetStyle().Colors[ImGuiCol_TextDisabled], "%s", text.c_str());
}

ImVec4 panel_background() {
  ImVec4 c = ImGui::GetStyle().Colors[ImGuiCol_WindowBg];
  c.w = 1;
  return c;
}

bool end_side_panel(const std::string& name) {
  const ImVec2 p = ImGui::GetWindowPos(), size = ImGui::GetWindowSize();
  mark_rect(name, Rect{p.x, p.y, size.x, size.y});
  return !ImGui::IsWindowCollapsed();
}

namespace {
// On the same line as the last item when `width` px more fit in what is left of the row.
void same_line_if_room(float width) {
  const float right = ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x;
  if (ImGui::GetItemRectMax().x + ImGui::GetStyle().ItemSpacing.x + width <= right) ImGui::SameLine();
}

// `label` if `width` (its width with the widget's own parts) fits what is left of the row, else `short_label`; both
// under the full label's ID.
std::string fitting_label(const char* label, const char* short_label, float width, bool& shortened) {
  shortened = width > ImGui::GetContentRegionAvail().x;
  return std::string(shortened ? short_label : label) + "###" + label;
}
}  // namespace

bool section(const char* label, const char* short_label, ImGuiTreeNodeFlags flags) {
  const ImGuiStyle& st = ImGui::GetStyle();
  const float width = ImGui::CalcTextSize(label).x + ImGui::GetFontSize() + st.FramePadding.x * 3;
  bool shortened = false;
  const bool open = ImGui::CollapsingHeader(fitting_label(label, short_label, width, shortened).c_str(), flags);
  if (shortened && ImGui::IsItemHovered()) ImGui::SetTooltip("%s", label);
  return open;
}

bool fitting_button(const char* label, const char* short_label) {
  const float width = ImGui::CalcTextSize(label).x + ImGui::GetStyle().FramePadding.x * 2;
  bool shortened = false;
  const bool pressed = ImGui::Button(fitting_label(label, short_label, width, shortened).c_str());
  if (shortened && ImGui::IsItemHovered()) ImGui::SetTooltip("%s", label);
  return pressed;
}

bool fitting_checkbox(const char* label, const char* short_label, bool* value) {
  const ImGuiStyle& st = ImGui::GetStyle();
  const float width = ImGui::GetFrameHeight() + st.ItemInnerSpacing.x + ImGui::CalcTextSize(label).x;
  bool shortened = false;
  const bool changed = ImGui::Checkbox(fitting_label(label, short_label, width, shortened).c_str(), value);
  if (shortened && ImGui::IsItemHovered()) ImGui::SetTooltip("%s", label);
  return changed;
}

void same_line_if_fits(const char* next) {
  same_line_if_room(ImGui::CalcTextSize(next, nullptr, true).x + ImGui::GetStyle().FramePadding.x * 2);
}

void same_line_if_checkbox_fits(const char* next) {
  same_line_if_room(ImGui::GetFrameHeight() + ImGui::GetStyle().ItemInnerSpacing.x +
                    ImGui::CalcTextSize(next, nullptr, true).x);
}

void bar_chart(const char* id, const std::vector<Bar>& shown, double scale, const char* unit) {
  if (shown.empty() || !(scale > 0) || !std::isfinite(scale)) return;
  // Round-off (a billionth of the scale and less: 1e-16 J of height at rest) reads and draws as 0.
  std::vector<Bar> bars = shown;
  for (Bar& b : bars)
    if (std::abs(b.value) < 1e-9 * scale) b.value = 0;
  const bool signed_values = std::any_of(bars.begin(), bars.end(), [](const Bar& b) { return b.value < 0; });
  float label_w = 0;
  for (const Bar& b : bars) label_w = std::max(label_w, ImGui::CalcTextSize(b.label.c_str()).x);
  label_w += em(8);
  // The values to three digits of the scale, in fixed notation (a class read "4.19e-08 J" left at rest as something
  // still moving), and their column as wide as its widest text, so that the bars give way to it in a narrow panel.
  const int decimals = std::clamp(2 - static_cast<int>(std::floor(std::log10(scale))), 0, 4);
  const double step = std::pow(10.0, -decimals);  // what rounds to zero prints without a sign
  std::vector<std::string> values;
  float value_w = 0;
  for (const Bar& b : bars) {
    char text[48];
    const double value = std::abs(b.value) < 0.5 * step ? 0.0 : b.value;
    std::snprintf(text, sizeof text, "%.*f %s", decimals, value, unit);
    values.emplace_back(text);
    value_w = std::max(value_w, ImGui::CalcTextSize(text).x);
  }
  const float line = ImGui::GetTextLineHeightWithSpacing();
  const float width = ImGui::GetContentRegionAvail().x;
  // Values in a column of their own where that leaves the bars at least half the width; else (a narrow panel,
  // presentation mode's large text) each bar goes across the whole width under its label and value.
  const bool column = width - label_w - value_w - em(8) >= 0.5f * width;
  const float row = column ? line : 2 * line, height = row * bars.size();
  const ImVec2 o = ImGui::GetCursorScreenPos();
  ImGui::InvisibleButton(id, ImVec2(std::max(width, 1.0f), height + 2));
  ImDrawList* d = ImGui::GetWindowDrawList();
  d->PushClipRect(o, ImVec2(o.x + width, o.y + height + 2), true);
  const float x0 = column ? o.x + label_w : o.x + em(2);
  const float span = std::max(column ? width - label_w - value_w - em(8) : width - em(4), 10.0f);
  const float zero = signed_values ? x0 + span / 2 : x0, reach = signed_values ? span / 2 : span;
  const float unit_px = static_cast<float>(reach / scale);
  const ImU32 text = ImGui::GetColorU32(ImGuiCol_Text), axis = IM_COL32(160, 160, 160, 255);
  for (size_t k = 0; k < bars.size(); ++k) {
    const Bar& b = bars[k];
    const float y = o.y + k * row, bar_y = column ? y : y + line;
    d->AddText({o.x, y}, text, b.label.c_str());
    const float len = std::clamp(static_cast<float>(b.value) * unit_px, -reach, reach);  // never into the values
    d->AddRectFilled({std::min(zero, zero + len), bar_y + 2}, {std::max(zero, zero + len), bar_y + line - 3}, b.colour);
    const float vx = column ? x0 + span + em(6) : o.x + width - ImGui::CalcTextSize(values[k].c_str()).x;
    d->AddText({vx, y}, text, values[k].c_str());
    if (!column) d->AddLine({zero, bar_y}, {zero, bar_y + line}, axis);
  }
  if (column) d->AddLine({zero, o.y}, {zero, o.y + height}, axis);
  d->PopClipRect();
  const float drawn = column ? label_w + span + em(6) + value_w : width;
  mark_rect(std::string("bars ") + id, Rect{o.x, o.y, drawn, height});
  readout(std::string("bars ") + id + " share", span / std::max(width, 1.0f));  // of the width the bars may take
}

void mark(const std::string& name) {
  const ImVec2 a = ImGui::GetItemRectMin(), b = ImGui::GetItemRectMax();
  current_marks[name] = Rect{a.x, a.y, b.x - a.x, b.y - a.y};
}

void mark_rect(const std::string& name, const Rect& r) { current_marks[name] = r; }

void new_marks_frame() {
  last_marks.swap(current_marks);
  current_marks.clear();
  last_integers.swap(current_integers);
  current_integers.clear();
  last_readouts.swap(current_readouts);
  current_readouts.clear();
}

void readout(const std::string& name, double value) { current_readouts[name] = value; }

const std::map<std::string, double>& readouts() { return last_readouts; }

const std::map<std::string, Rect>& marks() { return last_marks; }

void pass_wheel_on() {
  ImGuiWindow* box = ImGui::GetCurrentWindow();
  ImGuiWindow* around = box->ParentWindow;
  const float wheel = ImGui::GetIO().MouseWheel;
  if (!around || wheel == 0 || !ImGui::IsWindowHovered()) return;
  if (wheel > 0 ? box->Scroll.y > 0 : box->Scroll.y < box->ScrollMax.y) return;  // the box scrolls itself
  ImGui::SetScrollY(around, around->Scroll.y - wheel * 5 * ImGui::GetFontSize());  // ImGui's step per notch
}

}  // namespace shotlab
