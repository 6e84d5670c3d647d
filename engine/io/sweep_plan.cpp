// Sweep plans: --vary options read, and the grid or the random sample of runs they make.
#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>

#include "shotlab/io/json_reader.hpp"
#include "shotlab/io/scene_json.hpp"
#include "shotlab/io/sweep.hpp"
#include "csv.hpp"

namespace shotlab {
namespace {

bool read_number(const std::string& text, double& v) {
  const char* first = text.data();
  if (!text.empty() && text[0] == '+') ++first;
  const auto [end, ec] = std::from_chars(first, text.data() + text.size(), v);
  return ec == std::errc() && end == text.data() + text.size() && std::isfinite(v);
}

// "lo:hi" or "lo:hi:n"; false when the text is not of that shape (then it is a list).
bool read_range(const std::string& text, SweepAxis& axis, const std::string& where) {
  const size_t c1 = text.find(':');
  if (c1 == std::string::npos) return false;
  const size_t c2 = text.find(':', c1 + 1);
  const std::string lo = text.substr(0, c1);
  const std::string hi = text.substr(c1 + 1, c2 == std::string::npos ? std::string::npos : c2 - c1 - 1);
  if (!read_number(lo, axis.lo) || !read_number(hi, axis.hi))
    throw InputError(where + ": a range is lo:hi:n with numbers lo and hi");
  if (c2 != std::string::npos) {
    const std::string n = text.substr(c2 + 1);
    const auto [end, ec] = std::from_chars(n.data(), n.data() + n.size(), axis.count);
    if (ec != std::errc() || end != n.data() + n.size() || axis.count < 1 || axis.count > 1'000'000)
      throw InputError(where + ": the count n of lo:hi:n must be a whole number from 1 to 1000000");
  }
  axis.range = true;
  return true;
}

// Value k of a range's n: evenly spaced from lo to hi, the ends exactly as typed, the others rounded to 12 digits of
// the range's larger end (0:0.3:7 gives 0.05, not the 0.049999999999999996 of its arithmetic, which a table of runs
// would not group with a typed 0.05; -0.2:0.4:4 gives 0, not 2.8e-17).
std::string grid_value(const SweepAxis& a, int k) {
  if (k == 0) return number_text(a.lo);
  if (k + 1 == a.count) return number_text(a.hi);
  const double v = a.lo + (a.hi - a.lo) * k / (a.count - 1);
  const double scale = std::max(std::abs(a.lo), std::abs(a.hi));
  if (!(scale > 0)) return number_text(v);
  const double quantum = std::pow(10.0, std::floor(std::log10(scale)) - 11);
  char text[32];
  std::snprintf(text, sizeof text, "%.12g", std::round(v / quantum) * quantum);
  return number_text(std::strtod(text, nullptr) + 0.0);  // + 0.0: no "-0"
}

// "a,b,c" split at commas outside brackets and quotes, so that "[1,0,0],[2,0,0]" is two values.
std::vector<std::string> split_list(const std::string& text) {
  std::vector<std::string> out(1);
  int depth = 0;
  bool quoted = false;
  for (char c : text) {
    if (c == '"') quoted = !quoted;
    if (!quoted && (c == '[' || c == '{')) ++depth;
    if (!quoted && (c == ']' || c == '}')) --depth;
    if (c == ',' && depth == 0 && !quoted) out.emplace_back();
    else out.back() += c;
  }
  return out;
}

// A random double in [0, 1) from 53 bits of the generator (std::uniform_real_distribution differs between
// standard libraries; this does not).
double unit(std::mt19937_64& gen) { return static_cast<double>(gen() >> 11) * 0x1.0p-53; }

}  // namespace

SweepAxis parse_sweep_axis(const std::string& spec) {
  const std::string where = "--vary " + describe(nlohmann::json(spec));
  const size_t eq = spec.find('=');
  if (eq == std::string::npos || eq == 0) throw InputError(where + ": expected PATH=VALUES");
  SweepAxis axis;
  axis.path = spec.substr(0, eq);
  const std::string values = spec.substr(eq + 1);
  if (values.empty()) throw InputError(where + ": no values after '='");
  const std::vector<std::string> list = split_list(values);
  if (list.size() == 1 && values[0] == '[') {  // one JSON array: its elements are the values
    for (const nlohmann::json& v : parse_json_text(values, where)) axis.values.push_back(v.dump());
  } else if (list.size() == 1 && values[0] != '"' && read_range(values, axis, where)) {
    return axis;
  } else {
    axis.values = list;
  }
  if (axis.values.empty()) throw InputError(where + ": the list of values is empty");
  for (const std::string& v : axis.values) {
    if (v.empty()) throw InputError(where + ": an empty value in the list");
    nlohmann::json probe;
    apply_override(probe, "v=" + v);  // the value must read as --set reads it
  }
  return axis;
}

SweepPlan plan_sweep(const std::vector<SweepAxis>& axes, size_t samples, uint64_t seed) {
  SweepPlan plan;
  for (const SweepAxis& a : axes) plan.paths.push_back(a.path);
  if (axes.empty()) throw InputError("--vary: no path to vary");
  if (samples > kMaxSweepRows) throw InputError("--samples: more than " + std::to_string(kMaxSweepRows) + " runs");
  if (samples > 0) {
    std::mt19937_64 gen(seed);
    plan.rows.resize(samples);
    for (std::vector<std::string>& row : plan.rows)
      for (const SweepAxis& a : axes) {
        const double u = unit(gen);
        row.push_back(a.range ? number_text(a.lo + (a.hi - a.lo) * u)
                              : a.values[std::min(a.values.size() - 1, static_cast<size_t>(u * a.values.size()))]);
      }
    return plan;
  }
  std::vector<std::vector<std::string>> values;
  double total = 1;
  for (const SweepAxis& a : axes) {
    if (a.range && a.count == 0)
      throw InputError("--vary " + a.path + ": a grid needs the range's count, lo:hi:n (or sample it with --samples N)");
    std::vector<std::string> v = a.values;
    if (a.range && a.count == 1 && a.hi != a.lo)
      throw InputError("--vary " + a.path + ": a range of one value (lo:hi:1) runs lo only: give n of 2 or more");
    for (int k = 0; a.range && k < a.count; ++k)
      v.push_back(grid_value(a, k));
    total *= static_cast<double>(v.size());
    values.push_back(std::move(v));
  }
  if (total > static_cast<double>(kMaxSweepRows))
    throw InputError("--vary: the grid has " + number_text(total) + " runs, more than " + std::to_string(kMaxSweepRows));
  plan.rows.resize(static_cast<size_t>(total));
  for (size_t i = 0; i < plan.rows.size(); ++i) {
    size_t rest = i;
    plan.rows[i].resize(axes.size());
    for (size_t a = axes.size(); a-- > 0;) {  // the last axis varies fastest
      plan.rows[i][a] = values[a][rest % values[a].size()];
      rest /= values[a].size();
    }
  }
  return plan;
}

}  // namespace shotlab
