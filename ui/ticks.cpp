#include "ui/ticks.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace shotlab {

Ticks nice_ticks(double lo, double hi, int max_ticks) {
  Ticks t;
  if (!std::isfinite(lo) || !std::isfinite(hi)) return t;
  if (hi < lo) std::swap(lo, hi);
  if (hi - lo < 1e-300) {
    const double pad = lo == 0 ? 1 : std::abs(lo) * 0.1;
    lo -= pad, hi += pad;
  }
  max_ticks = std::max(max_ticks, 2);
  const double raw = (hi - lo) / (max_ticks - 1);
  const double power = std::pow(10.0, std::floor(std::log10(raw)));
  double step = 10 * power;
  for (double m : {1.0, 2.0, 5.0, 10.0})
    if (m * power >= raw * (1 - 1e-9)) {
      step = m * power;
      break;
    }
  t.step = step;
  t.decimals = std::max(0, -static_cast<int>(std::floor(std::log10(step) + 1e-9)));
  for (double k = std::ceil(lo / step - 1e-9); k * step <= hi + step * 1e-9; k += 1)
    t.values.push_back(std::abs(k) < 1e-12 ? 0.0 : k * step);
  return t;
}

std::string format_tick(double value, const Ticks& ticks) {
  char text[32];
  std::snprintf(text, sizeof text, "%.*f", ticks.decimals, value);
  return text;
}

TimeUnit time_unit(double span) {
  static const std::string micro = std::string(kMicro) + "s";
  if (span < 2e-3) return {1e6, micro.c_str()};
  if (span < 0.2) return {1e3, "ms"};
  return {1.0, "s"};
}

std::string format_time(double seconds, bool fine) {
  char text[32];
  std::snprintf(text, sizeof text, fine ? "%.6f s" : "%.4f s", seconds);
  return text;
}

}  // namespace shotlab
