// Pictures the shot lab writes as PNG: the window (F12), a part of it (a plot's export), and a strobe picture of the
// shot (a multiple exposure: the balls at evenly spaced times, the earliest faintest). Each file is written
// atomically (files.hpp); the outcome is reported in the lab's message.
#pragma once
#include <string>

#include "ui/camera.hpp"
#include "ui/lab.hpp"
#include "ui/renderer.hpp"

namespace shotlab {

inline constexpr int kStrobeExposures = 16;

// The balls of a frame (pocketed ones that have fallen out of sight left out).
void draw_balls(Renderer& renderer, const Lab& lab, const Frame& frame, float alpha);
// The back buffer's rectangle (origin top-left, window height `window_h`) as PNG; false when it cannot be written.
bool write_window_png(const std::string& path, int x, int y, int w, int h, int window_h);
// lab.screenshot_request (cropped to lab.screenshot_crop when set), then clears the request.
void write_screenshot(Lab& lab, int window_w, int window_h);
// lab.strobe_request: draws the exposures into the 3D view's part of the back buffer and writes it (the normal frame
// is drawn over it afterwards), then clears the request.
void write_strobe(Lab& lab, Renderer& renderer, const Viewport& viewport, int window_h);

}  // namespace shotlab
