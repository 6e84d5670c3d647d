// A time plot with what a reader needs: a title naming the quantity and its unit, ticks on both axes, the time axis
// labelled in s, ms or us as its span needs, a legend, a cursor at the time on screen, and a readout of every
// series at the time under the pointer. A click or drag in the plot picks a time (the caller seeks there); the
// right-click menu exports the data as CSV or the plot as PNG.
#pragma once
#include <imgui.h>

#include <optional>
#include <string>
#include <vector>

#include "ui/layout.hpp"
#include "ui/plot_data.hpp"

namespace shotlab {

struct PlotAction {
  std::optional<double> picked;  // s: clicked or dragged at
  bool export_csv = false, export_png = false;
  Rect rect;                     // the plot's screen rectangle (for a PNG crop)
};

PlotAction plot(const char* id, const PlotSpec& spec, const std::vector<PlotSeries>& series, float height);

}  // namespace shotlab
