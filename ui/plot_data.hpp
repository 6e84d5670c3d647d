// What a time plot shows (plot.hpp draws it): its series and the spec of its axes, and the series as CSV. No ImGui
// here: the shot lab's logic and its tests use it without a window.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace shotlab {

struct PlotSeries {
  std::string name;
  uint32_t colour;  // as ImGui packs it (ImU32)
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
  bool paper = false;            // for print: a white ground, dark text and grid, the series' colours darkened
};

// The series as CSV: the time columns (the shot's time, and the time since the plot's origin where it has one) and a
// column per series when they share their times, else rows of series, time columns, value. Throws std::runtime_error
// when the file cannot be written.
void write_plot_csv(const std::string& path, const PlotSpec& spec, const std::vector<PlotSeries>& series);

}  // namespace shotlab
