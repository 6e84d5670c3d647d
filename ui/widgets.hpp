// Small ImGui building blocks shared by the panels: labelled fields that never clip their labels, sliders over
// doubles, the cue-tip widget, horizontal bar charts, simplified polylines, and `mark`, which names a widget's screen rectangle for the
// state dump (the real-input GUI test clicks what the dump says is where).
#pragma once
#include <imgui.h>

#include <initializer_list>
#include <map>
#include <string>
#include <vector>

#include "shotlab/cue.hpp"
#include "ui/layout.hpp"

namespace shotlab {

// A column of labels left of full-width controls: as wide as the widest label given, or, when the panel is too
// narrow for that and a usable control, each label goes on the line above its control.
class Fields {
 public:
  explicit Fields(std::initializer_list<const char*> labels);
  void label(const char* text) const;  // then the control (its own label hidden: "##id"), which fills the row
 private:
  float column_ = 0;
  bool above_ = false;
};

// A slider over a double, clamped to its range; logarithmic where the range spans decades. Fills the row. A typed
// value (ctrl+click) takes effect when its entry ends; one out of range is clamped and leaves a note (take_slider_note).
bool slider(const char* id, double& v, double lo, double hi, const char* format, bool log = false);
// What the last slider entry that had to be clamped says ("stiffness: 1e+30 is outside ..."), once; else empty.
std::string take_slider_note();
// Once a frame, before the panels: what was typed into the number field being edited that it drops ("'a', ' ' cannot
// be part of a number: ...", refused), where ImGui would drop it without a word; a decimal comma is made the point
// (a note says so). Empty when all is well.
struct TypingNote {
  std::string text;
  bool refused = false;
};
TypingNote vet_number_typing();
void integer_entry();  // right after an integer slider: its typed entry takes no e (what vet_number_typing says)

// A drawn ball face: click or drag to put the cue tip (right is the shooter's right, up is follow); the dashed
// ring is the miscue limit. Returns true while it changes the offsets.
bool tip_widget(CueStrike& cue, float size);

struct Bar {
  std::string label;
  double value;
  ImU32 colour;
};
// ImGui::Begin() of a side panel, returning what Begin returns: puts it at `where`, and collapses or opens it when
// `want_open` differs from how it was last shown (`shown`, updated by end_side_panel): a key (F2, F3) toggles it, a
// click on its arrow too. The panel draws no background: the frame clears the window to panel_background() first.
bool begin_side_panel(const char* name, const Rect& where, bool want_open, bool shown);
ImVec4 panel_background();  // the style's window background, opaque
// Before End(): records the window's rectangle under `name` and returns whether it is open.
bool end_side_panel(const std::string& name);
// What a side panel's width grip works on: the panel's preferred width and the other panel's (unscaled pixels, as the
// settings keep them), and what the layout shows of each (pixels; 0 for a collapsed one).
struct PanelWidths {
  float& width;
  float& other_width;
  float shown, other_shown;
  bool locked = false;  // presentation mode: the layout narrows the panels, and a drag would store them narrowed
};
// Inside a side panel's window: dragging `strip` (on screen: the panel's inner edge) moves the panel's inner edge with
// the pointer, `outer_x` being its edge at the window's side (`scale`: font size over the base size), from
// kMinPanelWidth up to what the layout gives it beside the other panel as shown. The drag's first move takes both
// panels' widths as shown (the layout may have narrowed them), so that it starts from what is on screen; a click that
// does not move changes nothing. A double click restores `standard`. The strip is marked as `name` (state dump),
// which also keys its drag.
void panel_width_grip(const char* name, const Rect& strip, float outer_x, PanelWidths w, float scale, float standard);

// Text wrapped at the panel's edge (or the wrap position pushed), printf-style. Lines break at spaces only, and not
// between a number and its unit (ui/text_wrap.hpp): ImGui's own wrapping (1.86) also breaks after a full stop, which
// splits a number such as "0.4" into "0." and "4".
void text_wrapped(const char* fmt, ...) IM_FMTARGS(1);
// text_wrapped in `colour`: a verdict or a warning stays whole in a narrow panel (ImGui's TextColored cuts it).
void coloured_wrapped(const ImVec4& colour, const char* fmt, ...) IM_FMTARGS(2);
// An arrow on the screen from `from` to `to` (px): a line and a head at most 10 px long; none under 2 px.
void flat_arrow(ImDrawList* d, ImVec2 from, ImVec2 to, ImU32 color, float width);

// A hint in the disabled colour, wrapped at the panel's edge: a sentence stays whole in a narrow panel.
void hint(const std::string& text);

// A collapsing header, button or checkbox labelled `label` where that fits the panel's width, else `short_label` (a narrow
// panel, presentation mode's large text), with the full label as its tooltip; its ID is the full label's either way.
bool section(const char* label, const char* short_label, ImGuiTreeNodeFlags flags = 0);
bool fitting_button(const char* label, const char* short_label);
bool fitting_checkbox(const char* label, const char* short_label, bool* value);

// Before a button labelled `next`: on the same line when it fits in what is left of the row, else on the next.
void same_line_if_fits(const char* next);
void same_line_if_checkbox_fits(const char* next);  // the same before a checkbox labelled `next`

// Horizontal bars from a zero line, scaled so that `scale` (> 0) spans the half width (signed values) or the full
// width (all values >= 0); each bar labelled with its value and unit.
void bar_chart(const char* id, const std::vector<Bar>& bars, double scale, const char* unit);

// Records the last widget's rectangle under `name` for this frame (state dump); marks() returns the last frame's.
void mark(const std::string& name);
void mark_rect(const std::string& name, const Rect& r);
void new_marks_frame();
const std::map<std::string, Rect>& marks();
// Records a value a panel shows (a readout) under `name` for the state dump, as marks() do for rectangles.
void readout(const std::string& name, double value);
const std::map<std::string, double>& readouts();

// Strokes a polyline of screen points with the fewest of them that keep it within 0.3 px (Douglas-Peucker): a software
// renderer pays for every anti-aliased segment, and trails and plots hold several points a pixel.
void simplified_polyline(ImDrawList* d, const std::vector<ImVec2>& points, ImU32 colour, float width);

// Scales a size given in unscaled pixels by the current font size (ui scale and presentation mode).
float em(float pixels);

// Called inside a scrolling box (a child window, a table with ScrollY) before its end: a wheel turned over it once it
// is at its top or bottom scrolls the window around it, as a browser does (ImGui keeps the wheel in the box, and a
// hand on the wheel over a list got stuck there).
void pass_wheel_on();

}  // namespace shotlab
