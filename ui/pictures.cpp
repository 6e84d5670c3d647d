#include "ui/pictures.hpp"

#include <stb_image_write.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include "ui/files.hpp"
#include "ui/framing.hpp"
#include "ui/gl.hpp"

namespace shotlab {

namespace {

void append(void* context, void* data, int size) {
  auto* out = static_cast<std::string*>(context);
  out->append(static_cast<const char*>(data), static_cast<size_t>(size));
}

}  // namespace

void draw_balls(Renderer& renderer, const Lab& lab, const Frame& f, float alpha) {
  for (int i = 0; i < f.state.ball_count() && i < static_cast<int>(lab.scene.balls.size()); ++i) {
    if (!f.state.in_play[i] && position(f.state.x, i).y < -0.1) continue;  // gone down a pocket
    const BallSpec& b = lab.scene.balls[i].spec;
    renderer.draw_ball(position(f.state.x, i), f.orientation[i], b.radius, ball_look(b.id), alpha);
  }
}

bool write_window_png(const std::string& path, int x, int y, int w, int h, int window_h) {
  if (w <= 0 || h <= 0) return false;
  std::vector<unsigned char> pixels(static_cast<size_t>(w) * h * 3);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadBuffer(GL_BACK);
  glReadPixels(x, window_h - y - h, w, h, GL_RGB, GL_UNSIGNED_BYTE, pixels.data());
  stbi_flip_vertically_on_write(1);
  std::string png;
  if (!stbi_write_png_to_func(append, &png, w, h, 3, pixels.data(), w * 3)) return false;
  try {
    write_file_atomic(path, png);
    return true;
  } catch (const std::exception&) {
    return false;
  }
}

void write_screenshot(Lab& lab, int window_w, int window_h) {
  Rect r{0, 0, static_cast<float>(window_w), static_cast<float>(window_h)};
  if (lab.screenshot_crop) r = *lab.screenshot_crop;
  const int x = std::clamp(static_cast<int>(r.x), 0, window_w), y = std::clamp(static_cast<int>(r.y), 0, window_h);
  const int w = std::min(static_cast<int>(r.w), window_w - x), h = std::min(static_cast<int>(r.h), window_h - y);
  const std::string path = lab.screenshot_request;
  const bool plot_gone = !lab.plot_capture.empty() && !lab.plot_capture_drawn;
  lab.screenshot_request.clear();
  lab.screenshot_crop.reset();
  lab.plot_capture.clear();
  if (plot_gone) return lab.say(MessageKind::Refused, "the plot closed before its picture was taken: nothing written");
  if (write_window_png(path, x, y, w, h, window_h)) lab.say(MessageKind::Note, "wrote " + path);
  else lab.say(MessageKind::Refused, "cannot write " + path);
}

namespace {

// The screen box of the table's framed corners at the foot and the top of its rails; none without a table or where a
// corner is behind the camera (zoomed in close: the box would leave the near part out).
std::optional<Rect> table_on_screen(const Scene& scene, const Viewport& vp) {
  if (!scene.table) return std::nullopt;
  double lo_x = INFINITY, hi_x = -INFINITY, lo_y = INFINITY, hi_y = -INFINITY;
  for (const Vec3& c : framed_points(scene, false))
    for (const double up : {0.0, rail_top(*scene.table)}) {
      const auto s = vp.project(c + Vec3{0, up, 0});
      if (!s) return std::nullopt;
      lo_x = std::min(lo_x, s->x), hi_x = std::max(hi_x, s->x);
      lo_y = std::min(lo_y, s->y), hi_y = std::max(hi_y, s->y);
    }
  return Rect{float(lo_x), float(lo_y), float(hi_x - lo_x), float(hi_y - lo_y)};
}

}  // namespace

void write_strobe(Lab& lab, Renderer& renderer, const Viewport& vp, int window_h) {
  const std::string path = lab.strobe_request;
  lab.strobe_request.clear();
  if (!lab.shot) return lab.say(MessageKind::Refused, "shoot first: a strobe picture shows a shot");
  Shot& shot = *lab.shot;
  renderer.begin(vp);
  renderer.draw_scene(lab.scene, shot.sim().model());
  const double end = shot.sim().time();
  for (int k = 0; k < kStrobeExposures; ++k) {
    const double t = end * k / (kStrobeExposures - 1);
    draw_balls(renderer, lab, shot.frame_at(t), 0.45f + 0.55f * k / (kStrobeExposures - 1));
  }
  // The picture holds the table (its rails and a margin), not the whole view: the view between the panels is taller
  // than wide on a narrow window, and the table filled a third of the picture.
  double x0 = vp.x0, x1 = vp.x0 + vp.width, y0 = 0, y1 = window_h;
  if (const auto box = table_on_screen(lab.scene, vp)) {
    const double margin = 12 + 0.06 * (box->right() - box->x);  // the drawn rails reach past the framed corners
    x0 = std::max(x0, box->x - margin), x1 = std::min(x1, box->right() + margin);
    y0 = std::max(y0, box->y - margin), y1 = std::min(y1, box->bottom() + margin);
  }
  if (x1 - x0 < 1 || y1 - y0 < 1) x0 = vp.x0, x1 = vp.x0 + vp.width, y0 = 0, y1 = window_h;  // the table is off screen
  if (write_window_png(path, static_cast<int>(x0), static_cast<int>(y0), static_cast<int>(x1 - x0),
                       static_cast<int>(y1 - y0), window_h))
    lab.say(MessageKind::Note, "wrote " + path);
  else
    lab.say(MessageKind::Refused, "cannot write " + path);
}

}  // namespace shotlab
