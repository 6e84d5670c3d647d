// What `shotlab bench` writes: results.csv (every run) and results.md (tables with machine and date). Its figures are
// drawn from results.csv by scripts/bench_plots.py (app/plot_script.hpp).
#pragma once
#include <string>
#include <vector>

#include "app/bench/run.hpp"

namespace shotlab {

struct BenchRow {
  const BenchCase* c;
  MethodSetting setting;
  RunResult run;         // the first run (all runs are bit-identical but for the wall time)
  Errors err;            // against the reference; meaningless for until_rest cases
  double wall = 0;       // s, median over the repeats
  int repeats = 0;
};

// Per case: how the reference was obtained and how far its two methods agree (the floor of every error).
struct ReferenceInfo {
  const BenchCase* c;
  MethodSetting a, b;    // the reference and its check
  Errors agreement;      // method B against method A
  double exact_velocity; // swap_exact cases: the reference's velocity error against the exact swap, else -1
  double wall;           // s, every reference run tried
};

struct BenchReport {
  std::string command;                 // how the bench was invoked
  std::vector<BenchRow> rows;
  std::vector<ReferenceInfo> references;
  std::vector<std::string> notes;      // settings skipped and why
  double total_seconds = 0;
};

// Writes every output file into out_dir (which must exist); returns false and says why on stderr if one fails.
bool write_report(const std::string& out_dir, const BenchReport& report);

// Setting as a short string: "1e-06" for a tolerance, "h=1e-05" for a step.
std::string setting_text(const MethodSetting& s);

}  // namespace shotlab
