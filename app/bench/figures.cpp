// The bench's figures: one panel per case, one line per method and path (plain dashed).
#include <algorithm>
#include <cmath>
#include <map>

#include "app/bench/report.hpp"
#include "app/bench/svg.hpp"

namespace shotlab {
namespace {

// A fixed colour per method, so a method looks the same in every panel and figure.
const char* method_color(Method m) {
  switch (m) {
    case Method::Euler: return "#9e9e9e";
    case Method::RK4: return "#8d5a2b";
    case Method::CashKarp54: return "#1f77b4";
    case Method::DormandPrince5: return "#d62728";
    case Method::BulirschStoer: return "#2ca02c";
    case Method::Rosenbrock4: return "#9467bd";
  }
  return "black";
}

// Errors below the reference's own agreement are not resolved; plotting them at that floor (instead of at 0, which a
// log axis cannot show) keeps the points on the panel and honest about what is known. A blown-up run (Euler on the
// cradle reaches 1e116) would stretch its panel's axis over a hundred decades: it is drawn at 1e3, off the scale.
double floored(double error) { return std::clamp(error, 1e-14, 1e3); }

using PointOf = std::pair<double, double> (*)(const BenchRow&);

// Panels of every error-measured case; `wanted` picks the rows (and so the methods) a figure shows.
std::vector<PlotPanel> panels(const BenchReport& r, bool (*wanted)(const BenchRow&), PointOf point) {
  std::vector<PlotPanel> out;
  std::map<const BenchCase*, size_t> index;
  for (const BenchRow& row : r.rows) {
    if (row.c->until_rest || !wanted(row)) continue;
    if (!index.count(row.c)) {
      index[row.c] = out.size();
      out.push_back({row.c->label, {}});
    }
    PlotPanel& p = out[index[row.c]];
    const std::string name = line_name(row.setting);
    auto s = std::find_if(p.series.begin(), p.series.end(), [&](const PlotSeries& x) { return x.name == name; });
    if (s == p.series.end()) {
      // The plain path is drawn dashed in its method's colour.
      p.series.push_back({name, method_color(row.setting.method), {}, row.setting.plain});
      s = p.series.end() - 1;
    }
    const auto pt = point(row);
    if (pt.first > 0 && pt.second > 0 && std::isfinite(pt.first) && std::isfinite(pt.second)) s->points.push_back(pt);
  }
  return out;
}

bool all_finished(const BenchRow& row) { return row.run.status == Status::Ok; }
bool adaptive_finished(const BenchRow& row) { return is_adaptive(row.setting.method) && all_finished(row); }
bool adaptive_with_contacts(const BenchRow& row) { return adaptive_finished(row) && row.run.contacts > 0; }

}  // namespace

bool write_figures(const std::string& dir, const BenchReport& r) {
  PlotSpec wp{"Work-precision: wall time against error",
              "Lower left is better. Error = max(|dp|/R, |dv|/v0) at the end time against the reference (plain path, "
              "errors over 1e3 drawn at 1e3); dashed: plain path.",
              "error", "wall time (s), median", false, 4};
  PlotSpec te{"Achieved error against requested tolerance (adaptive methods)",
              "On or below the dashed line: the tolerance is a trustworthy knob. Far above it: error control is "
              "fooled (contact onsets, friction switch).",
              "requested tolerance", "achieved error", true, 4};
  PlotSpec sc{"Integrator steps per contact (ball-ball and cushion contacts; the thesis reports 20-60)",
              "Mean number of steps overlapping each contact. Fewer is cheaper, but a contact needs enough steps to "
              "resolve its force pulse.",
              "requested tolerance", "steps per contact", false, 4};
  const bool ok =
      write_loglog_grid(dir + "/work_precision.svg", wp,
                        panels(r, all_finished, [](const BenchRow& x) { return std::pair{floored(x.err.worst()), x.wall}; })) &&
      write_loglog_grid(dir + "/tolerance_error.svg", te,
                        panels(r, adaptive_finished,
                               [](const BenchRow& x) { return std::pair{x.setting.value, floored(x.err.worst())}; })) &&
      write_loglog_grid(dir + "/steps_per_contact.svg", sc,
                        panels(r, adaptive_with_contacts,
                               [](const BenchRow& x) { return std::pair{x.setting.value, x.run.steps_per_contact}; }));
  return ok;
}

}  // namespace shotlab
