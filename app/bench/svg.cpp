#include "svg.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>

namespace shotlab {
namespace {

constexpr double kPanelW = 330, kPanelH = 250;             // px per panel, margins included
constexpr double kLeft = 58, kRight = 12, kTop = 26, kBottom = 40;  // plot area inside a panel
constexpr double kHeader = 84;                               // title, subtitle and legend above the grid

std::string escape(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (c == '&') out += "&amp;";
    else if (c == '<') out += "&lt;";
    else if (c == '>') out += "&gt;";
    else out += c;
  }
  return out;
}

std::string dash(bool dashed) { return dashed ? " stroke-dasharray='6,3'" : ""; }

// Whole decades [lo, hi] that contain every value (at least one decade wide).
std::pair<int, int> decade_range(double lo, double hi) {
  int a = static_cast<int>(std::floor(std::log10(lo) + 1e-9)), b = static_cast<int>(std::ceil(std::log10(hi) - 1e-9));
  if (b <= a) b = a + 1;
  return {a, b};
}

struct Axes {
  double x0, y0, w, h;  // plot area in px
  int xa, xb, ya, yb;   // decade exponents
  double px(double x) const { return x0 + (std::log10(x) - xa) / (xb - xa) * w; }
  double py(double y) const { return y0 + h - (std::log10(y) - ya) / (yb - ya) * h; }
};

// Tick labels as 10^k with a superscript; with many decades only every second or third is labelled.
void draw_axes(std::ostream& o, const Axes& a, const PlotSpec& spec) {
  o << "<rect x='" << a.x0 << "' y='" << a.y0 << "' width='" << a.w << "' height='" << a.h
    << "' fill='white' stroke='#444'/>\n";
  const int xstep = (a.xb - a.xa + 5) / 6, ystep = (a.yb - a.ya + 4) / 5;
  for (int k = a.xa; k <= a.xb; ++k) {
    const double x = a.px(std::pow(10.0, k));
    o << "<line x1='" << x << "' y1='" << a.y0 << "' x2='" << x << "' y2='" << a.y0 + a.h << "' stroke='#e4e4e4'/>\n";
    if ((k - a.xa) % xstep == 0)
      o << "<text x='" << x << "' y='" << a.y0 + a.h + 15 << "' text-anchor='middle' font-size='11'>10<tspan dy='-5' "
        << "font-size='8'>" << k << "</tspan></text>\n";
  }
  for (int k = a.ya; k <= a.yb; ++k) {
    const double y = a.py(std::pow(10.0, k));
    o << "<line x1='" << a.x0 << "' y1='" << y << "' x2='" << a.x0 + a.w << "' y2='" << y << "' stroke='#e4e4e4'/>\n";
    if ((k - a.ya) % ystep == 0)
      o << "<text x='" << a.x0 - 4 << "' y='" << y + 4 << "' text-anchor='end' font-size='11'>10<tspan dy='-5' "
        << "font-size='8'>" << k << "</tspan></text>\n";
  }
  o << "<text x='" << a.x0 + a.w / 2 << "' y='" << a.y0 + a.h + 32 << "' text-anchor='middle' font-size='11'>"
    << escape(spec.x_label) << "</text>\n";
  o << "<text transform='translate(" << a.x0 - 42 << "," << a.y0 + a.h / 2 << ") rotate(-90)' text-anchor='middle' "
    << "font-size='11'>" << escape(spec.y_label) << "</text>\n";
}

void draw_panel(std::ostream& o, const PlotPanel& p, const PlotSpec& spec, double ox, double oy) {
  double xlo = std::numeric_limits<double>::infinity(), xhi = 0, ylo = xlo, yhi = 0;
  for (const PlotSeries& s : p.series)
    for (const auto& [x, y] : s.points) {
      xlo = std::min(xlo, x), xhi = std::max(xhi, x), ylo = std::min(ylo, y), yhi = std::max(yhi, y);
    }
  o << "<text x='" << ox + kLeft << "' y='" << oy + 16 << "' font-size='12' font-weight='bold'>" << escape(p.title)
    << "</text>\n";
  if (xhi == 0) return;  // nothing to draw
  const auto [xa, xb] = decade_range(xlo, xhi);
  const auto [ya, yb] = decade_range(ylo, yhi);
  const Axes a{ox + kLeft, oy + kTop, kPanelW - kLeft - kRight, kPanelH - kTop - kBottom, xa, xb, ya, yb};
  draw_axes(o, a, spec);
  if (spec.diagonal) {  // y = x across the part of the panel where both are in range
    const double lo = std::pow(10.0, std::max(xa, ya)), hi = std::pow(10.0, std::min(xb, yb));
    if (lo < hi)
      o << "<line x1='" << a.px(lo) << "' y1='" << a.py(lo) << "' x2='" << a.px(hi) << "' y2='" << a.py(hi)
        << "' stroke='#888' stroke-dasharray='5,4'/>\n";
  }
  for (const PlotSeries& s : p.series) {
    if (s.points.empty()) continue;
    o << "<polyline fill='none' stroke-width='1.8' stroke='" << s.color << "'" << dash(s.dashed) << " points='";
    for (const auto& [x, y] : s.points) o << a.px(x) << "," << a.py(y) << " ";
    o << "'/>\n";
    for (const auto& [x, y] : s.points)
      o << "<circle cx='" << a.px(x) << "' cy='" << a.py(y) << "' r='2.6' fill='" << s.color << "'/>\n";
  }
}

}  // namespace

bool write_loglog_grid(const std::string& path, const PlotSpec& spec, const std::vector<PlotPanel>& panels) {
  const int cols = std::max(1, std::min<int>(spec.columns, static_cast<int>(panels.size())));
  const int rows = (static_cast<int>(panels.size()) + cols - 1) / cols;
  const double width = cols * kPanelW + 20, height = kHeader + rows * kPanelH + 10;
  std::ostringstream o;
  o << "<svg xmlns='http://www.w3.org/2000/svg' width='" << width << "' height='" << height
    << "' font-family='sans-serif'>\n<rect width='100%' height='100%' fill='#fafafa'/>\n";
  o << "<text x='16' y='24' font-size='17' font-weight='bold'>" << escape(spec.title) << "</text>\n";
  o << "<text x='16' y='44' font-size='12' fill='#333'>" << escape(spec.subtitle) << "</text>\n";
  // One legend for all panels, in order of first appearance.
  std::vector<const PlotSeries*> legend;
  for (const PlotPanel& p : panels)
    for (const PlotSeries& s : p.series)
      if (std::none_of(legend.begin(), legend.end(), [&](const PlotSeries* l) { return l->name == s.name; }))
        legend.push_back(&s);
  double lx = 16;
  for (const PlotSeries* s : legend) {
    o << "<line x1='" << lx << "' y1='66' x2='" << lx + 22 << "' y2='66' stroke='" << s->color
      << "' stroke-width='3'" << dash(s->dashed) << "/><circle cx='" << lx + 11 << "' cy='66' r='3' fill='"
      << s->color << "'/>\n";
    o << "<text x='" << lx + 28 << "' y='70' font-size='13'>" << escape(s->name) << "</text>\n";
    lx += 40 + 7.5 * s->name.size();
  }
  if (spec.diagonal)
    o << "<line x1='" << lx << "' y1='66' x2='" << lx + 22 << "' y2='66' stroke='#888' stroke-dasharray='5,4'/>"
      << "<text x='" << lx + 28 << "' y='70' font-size='13'>achieved = requested</text>\n";
  for (size_t k = 0; k < panels.size(); ++k)
    draw_panel(o, panels[k], spec, 10 + (k % cols) * kPanelW, kHeader + (k / cols) * kPanelH);
  o << "</svg>\n";
  std::ofstream f(path);
  f << o.str();
  return static_cast<bool>(f);
}

}  // namespace shotlab
