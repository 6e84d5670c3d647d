// Axis ticks for the plots (1, 2, 5 times a power of ten) and the time readouts, which switch to finer units while
// something as short as a collision is on screen.
#pragma once
#include <string>
#include <vector>

namespace shotlab {

struct Ticks {
  std::vector<double> values;  // inside [lo, hi], ascending
  double step = 1;
  int decimals = 0;            // what the step needs: 0.25 -> 2, 50 -> 0
};

// At most max_ticks (>= 2) ticks on [lo, hi]; lo == hi gets a range around it.
Ticks nice_ticks(double lo, double hi, int max_ticks);
std::string format_tick(double value, const Ticks& ticks);

inline constexpr const char* kMicro = "\xc2\xb5";  // the micro sign in UTF-8 (the UI font has it): "us" read oddly

// A unit for a time axis spanning `span` seconds: s, ms or micro-s, with the factor that converts seconds to it.
struct TimeUnit {
  double per_second;
  const char* name;
};
TimeUnit time_unit(double span);

// "1.2345 s"; with `fine` (a contact on screen) to the microsecond: "0.111052 s".
std::string format_time(double seconds, bool fine);

}  // namespace shotlab
