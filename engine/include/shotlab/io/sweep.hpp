// Parameter sweeps: one scene run many times with scene values varied by path (as --set names them), on every core.
// The plan (which values each run takes) and the rows (what each run ended with) are spelled here once for
// `shotlab sweep`, the Python module and its Dask form. docs/sweep.md.
#pragma once
#include <atomic>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "shotlab/io/run.hpp"

namespace shotlab {

inline constexpr size_t kMaxSweepRows = 10'000'000;  // a plan with more runs than this is refused

// One varied path, from "PATH=VALUES": a list "a,b,c" (each value as --set reads it), a JSON array "[[1,0,0],[2,0,0]]"
// or a range "lo:hi:n" (n evenly spaced numbers, both ends included; "lo:hi" for random sampling).
struct SweepAxis {
  std::string path;
  std::vector<std::string> values;  // a list: each value's text
  bool range = false;
  double lo = 0, hi = 0;
  int count = 0;                    // a range's grid points (0: given without a count)
};
SweepAxis parse_sweep_axis(const std::string& spec);  // throws InputError naming the option and the problem

// Which value of each axis every run takes: rows[i][a] is the text of axis a in run i.
struct SweepPlan {
  std::vector<std::string> paths;
  std::vector<std::vector<std::string>> rows;
};
// samples == 0: the full grid, the first axis varying slowest. samples > 0: that many runs, each value drawn
// independently (a range uniformly, a list by equal chance) from a generator seeded with `seed`; the same seed gives
// the same plan on every machine. Throws InputError for an empty plan or one of more than kMaxSweepRows runs.
SweepPlan plan_sweep(const std::vector<SweepAxis>& axes, size_t samples, uint64_t seed);

struct SweepSettings {
  std::vector<std::string> overrides;  // PATH=VALUE applied to every run before the varied paths
  std::optional<double> duration;      // s; unset: run_duration's to rest. Every run stops at rest or then.
  RunLimits limits{60, 100'000, {}};     // each run: wall seconds, events
};

// A sweep over one scene. Rows are CSV lines (docs/sweep.md lists the columns): the overrides of the run, its status
// (ok, error, limit, or the engine's stop such as step_limit) and reason, and its outcomes. A run that fails is a
// row with its error; a row never throws.
class Sweep {
 public:
  // scene_text: the scene file's JSON; source names it in messages. Throws InputError when the scene with the
  // settings' overrides is not a valid scene (then no run could start).
  Sweep(const std::string& scene_text, const std::string& source, SweepPlan plan, SweepSettings settings);

  size_t size() const { return plan_.rows.size(); }
  std::string header() const;        // the CSV header line, '\n' ended
  std::string row(size_t i) const;   // runs row i and returns its CSV line, '\n' ended
  std::string status(const std::string& line) const;  // a row's status field

  // Runs rows [begin, end) on `jobs` threads (0: one per core) and hands each line to on_row in row order, whatever
  // order they finish in. progress(done, total) after each row. Stops starting rows once *cancel is set. An exception
  // from on_row stops the sweep and is rethrown here.
  void run(size_t begin, size_t end, int jobs, const std::function<void(size_t, const std::string&)>& on_row,
           const std::function<void(size_t, size_t)>& progress = {}, const std::atomic<bool>* cancel = nullptr) const;

 private:
  nlohmann::json doc_;
  std::string source_;
  SweepPlan plan_;
  SweepSettings settings_;
  std::vector<std::string> ball_ids_;  // the end-state columns, from the scene as given
  std::string cue_ball_;               // whose first contacts are reported
};

}  // namespace shotlab
