// Where the side panels and the 3D view go in a window of a given size. The panels stay attached to the window's
// left and right edges at every size; the 3D view gets the space between them and never less than a set share of
// the width (the panels narrow first). A collapsed panel is only its title bar, and the view runs under it.
#pragma once

namespace shotlab {

struct Rect {
  float x = 0, y = 0, w = 0, h = 0;  // pixels, origin top-left
  float right() const { return x + w; }
  float bottom() const { return y + h; }
  bool contains(float px, float py) const { return px >= x && px < x + w && py >= y && py < y + h; }
};

struct PanelRequest {
  bool open = true;     // false: collapsed to its title bar
  float width = 320;    // preferred width, pixels (already scaled)
  float bar = 20;       // title bar height, pixels
};

struct Layout {
  Rect left, right, view;
  Rect left_grip;  // the last kLeftGripPx of an open left panel's width, outside its window: its width grip
  // Pixels: each panel's width as shown, its grip included; 0 for a collapsed one.
  float left_shown() const { return left_grip.w > 0 ? left_grip.right() - left.x : 0; }
  float right_shown(bool open) const { return open ? right.w : 0; }
};

inline constexpr float kMinViewShare = 0.45f;  // of the window width, kept for the 3D view
// In presentation mode: the table is what a class watches, so the larger text wraps in narrower panels instead.
inline constexpr float kPresentationViewShare = 0.6f;
inline constexpr float kMinPanelWidth = 200;   // pixels: narrower, a panel's sliders are unusable
inline constexpr float kBaseFontPx = 15;       // the UI font at scale 1: the panels' widths are given at it
// Pixels: the gutter at the inner edge of an open left panel, its width grip (the panel's scrollbar takes the edge of
// its window, so the grip lies beside it).
inline constexpr float kLeftGripPx = 6;

// `view_share`: the share of the width kept for the view (kMinViewShare, or kPresentationViewShare).
Layout layout_panels(float window_w, float window_h, const PanelRequest& left, const PanelRequest& right,
                     float view_share = kMinViewShare);
// Pixels: the widest a panel may be beside the `other` one before layout_panels narrows either of them.
float widest_panel(float window_w, const PanelRequest& other, float view_share = kMinViewShare);

}  // namespace shotlab
