// Log-log line plots as SVG, written by hand (no plotting package): a grid of small panels sharing one legend, so
// that a whole sweep (one panel per bench case) reads at a glance.
#pragma once
#include <string>
#include <utility>
#include <vector>

namespace shotlab {

struct PlotSeries {
  std::string name;   // legend entry; series of the same name share a colour across panels
  std::string color;  // any SVG colour
  std::vector<std::pair<double, double>> points;  // (x, y), both > 0; drawn in the given order
  bool dashed = false;
};

struct PlotPanel {
  std::string title;
  std::vector<PlotSeries> series;
};

struct PlotSpec {
  std::string title, subtitle;  // subtitle: how to read the figure
  std::string x_label, y_label;
  bool diagonal = false;        // draw y = x (achieved against requested tolerance)
  int columns = 4;
};

// Writes the figure; returns false when the file cannot be written.
bool write_loglog_grid(const std::string& path, const PlotSpec& spec, const std::vector<PlotPanel>& panels);

}  // namespace shotlab
