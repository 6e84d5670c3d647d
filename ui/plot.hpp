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

namespace shotlab {

struct PlotSeries {
  std::string name;
  ImU32 colour;
  std::vector<double> time;   // s, ascending
  std::vector<double> value;  // in the plot's unit
};

struct PlotSpec {
  std::string title;  // "speed", "normal force"
  std::string unit;   // "m/s", "N"
  double cursor = -1; // s: the time on screen, drawn as a vertical line (< 0: none)
  double t0 = 0, t1 = -1;  // s: the time axis; t1 < t0: the series' extent
  bool zero_based = true;  // the value axis includes 0
  double origin = 0;       // s: the time axis's labels count from here (a collision's start), named by origin_name
  std::string origin_name = "";  // "contact start": the axis reads "time since contact start"; "" for the shot's time
  std::string hint = "";         // what to look for: a last line under the pointer's readout
  bool hover = true;             // the pointer's line and readout (off while the plot is captured as a picture)
  bool seekable = true;          // a click picks a time of the shot (a probe's own collision: no)
};

struct PlotAction {
  std::optional<double> picked;  // s: clicked or dragged at
  bool export_csv = false, export_png = false;
  Rect rect;                     // the plot's screen rectangle (for a PNG crop)
};

PlotAction plot(const char* id, const PlotSpec& spec, const std::vector<PlotSeries>& series, float height);

// The series as CSV: one time column and a column per series when they share their times, else rows of
// series,time,value. Throws std::runtime_error when the file cannot be written.
void write_plot_csv(const std::string& path, const PlotSpec& spec, const std::vector<PlotSeries>& series);

}  // namespace shotlab
