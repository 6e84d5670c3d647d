#include "ui/layout.hpp"

#include <algorithm>

namespace shotlab {

Layout layout_panels(float W, float H, const PanelRequest& left, const PanelRequest& right, float view_share) {
  W = std::max(W, 1.0f);
  H = std::max(H, 1.0f);
  float lw = std::max(left.width, 1.0f), rw = std::max(right.width, 1.0f);
  // Open panels share at most (1 - view_share) of the width, narrowed in proportion, each down to kMinPanelWidth;
  // in a window too small even for that, they split what is left over after the view's share.
  const float budget = widest_panel(W, {false, 0, 0}, view_share);  // the panels' share: one's with the other closed
  const float wanted = (left.open ? lw : 0) + (right.open ? rw : 0);
  if (wanted > budget) {
    const float k = budget / wanted;
    const int open = left.open + right.open;
    const float floor = std::min(kMinPanelWidth, budget / std::max(open, 1));
    lw *= k, rw *= k;
    // Each open panel at least `floor`, taken from the other: the two still share no more than the budget.
    if (left.open && lw < floor) rw -= floor - lw, lw = floor;
    if (right.open && rw < floor) lw -= floor - rw, rw = floor;
  }
  lw = std::min(lw, W);
  rw = std::min(rw, W);
  Layout out;
  const float grip = left.open ? std::min(kLeftGripPx, 0.5f * lw) : 0;
  out.left = left.open ? Rect{0, 0, lw - grip, H} : Rect{0, 0, lw, std::min(left.bar, H)};
  if (left.open) out.left_grip = Rect{lw - grip, 0, grip, H};
  out.right = right.open ? Rect{W - rw, 0, rw, H} : Rect{W - rw, 0, rw, std::min(right.bar, H)};
  const float x0 = left.open ? lw : 0, x1 = right.open ? W - rw : W;
  out.view = Rect{x0, 0, std::max(x1 - x0, 1.0f), H};
  return out;
}

float widest_panel(float window_w, const PanelRequest& other, float view_share) {
  return window_w * (1 - view_share) - (other.open ? other.width : 0);
}

}  // namespace shotlab
