#include "ui/plot_data.hpp"

#include <algorithm>
#include <sstream>

#include "ui/files.hpp"
#include "ui/ticks.hpp"

namespace shotlab {

void write_plot_csv(const std::string& path, const PlotSpec& spec, const std::vector<PlotSeries>& series) {
  std::ostringstream out;
  out.precision(10);
  const bool shared = !series.empty() && std::all_of(series.begin(), series.end(), [&](const PlotSeries& s) {
    return s.time == series.front().time;
  });
  // The shot's time, and the time the plot's axis counts (since a contact began) where it has an origin.
  const bool since = !spec.origin_name.empty();
  std::string unit;  // ASCII in the file: a spreadsheet may not read the micro sign as UTF-8
  for (size_t k = 0; k < spec.unit.size(); ++k)
    if (spec.unit.compare(k, 2, kMicro) == 0) unit += 'u', ++k;  // its 2 bytes
    else unit += spec.unit[k];
  const std::string time_columns = since ? "time_s,\"time since " + spec.origin_name + " (s)\"" : "time_s";
  auto times = [&](double t) { since ? out << t << ',' << t - spec.origin : out << t; };
  if (shared) {
    out << time_columns;
    for (const PlotSeries& s : series) out << ",\"" << s.name << " (" << unit << ")\"";
    out << '\n';
    for (size_t k = 0; k < series.front().time.size(); ++k) {
      times(series.front().time[k]);
      for (const PlotSeries& s : series) out << ',' << s.value[k];
      out << '\n';
    }
  } else {
    out << "series," << time_columns << ",value (" << unit << ")\n";
    for (const PlotSeries& s : series)
      for (size_t k = 0; k < s.time.size(); ++k) {
        out << '"' << s.name << "\",";
        times(s.time[k]);
        out << ',' << s.value[k] << '\n';
      }
  }
  write_file_atomic(path, out.str());
}

}  // namespace shotlab
