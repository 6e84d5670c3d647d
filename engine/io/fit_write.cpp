// A calibration written out: the JSON of `shotlab fit --out` (docs/fit.md).
#include <algorithm>
#include <cmath>

#include "shotlab/io/fit.hpp"

namespace shotlab {
namespace {

using nlohmann::json;

json number_or_null(double v) { return std::isfinite(v) ? json(v) : json(nullptr); }

json cue_json(const CueFit& c) {
  return {{"speed", number_or_null(c.speed)}, {"aim_deg", number_or_null(c.aim_deg)},
          {"side", number_or_null(c.side)}, {"height", number_or_null(c.height)},
          {"elevation_deg", number_or_null(c.elevation_deg)}, {"strike_time", number_or_null(c.strike_time)}};
}

json track_json(const std::vector<MeasuredSample>& track) {
  json out = json::array();
  for (const MeasuredSample& s : track) out.push_back({s.t, s.x, s.z});
  return out;
}

}  // namespace

json fit_to_json(const Scene& base, const std::vector<MeasuredShot>& shots, const FitResult& fit) {
  json out;
  out["method"] = "Ceres Solver: Levenberg-Marquardt, central numeric derivatives";
  out["report"] = fit.report;
  out["iterations"] = fit.iterations;
  out["seconds"] = fit.seconds;
  out["values"] = json::array();
  for (size_t k = 0; k < fit.paths.size(); ++k)
    out["values"].push_back({{"path", fit.paths[k]}, {"start", fit.start[k]}, {"value", fit.values[k]},
                             {"sd", number_or_null(fit.sd[k])}});
  std::vector<double> cue_rms;
  out["shots"] = json::array();
  for (size_t s = 0; s < fit.shots.size(); ++s) {
    const ShotFit& f = fit.shots[s];
    json rms = json::object(), measured = json::object(), simulated = json::object();
    for (const auto& [ball, v] : f.rms) rms[ball] = v * 1e3;
    for (const auto& [ball, track] : shots[s].tracks) measured[ball] = track_json(track);
    for (const auto& [ball, track] : f.simulated) simulated[ball] = track_json(track);
    cue_rms.push_back(f.rms.at(f.cue_ball));
    out["shots"].push_back({{"name", f.name}, {"cue_ball", f.cue_ball}, {"start", cue_json(f.start)},
                            {"cue", cue_json(f.cue)}, {"sd", cue_json(f.sd)}, {"rms_mm", rms},
                            {"measured", measured}, {"simulated", simulated}});
  }
  std::sort(cue_rms.begin(), cue_rms.end());
  const size_t n = cue_rms.size();
  out["median_cue_rms_mm"] = n ? 1e3 * (n % 2 ? cue_rms[n / 2] : 0.5 * (cue_rms[n / 2 - 1] + cue_rms[n / 2])) : 0.0;
  if (base.table) out["table"] = {{"length", base.table->length}, {"width", base.table->width}};
  return out;
}

}  // namespace shotlab
