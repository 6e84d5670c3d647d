// Cost of one right-hand-side call (shotlab::Dynamics::operator()) against the number of balls: issue 5 asks for
// O(n), not O(n^2). n balls scattered over a large flat bed (app/bench/scaling.hpp: same density at every n, no
// overlaps, all awake and sliding, so every ball takes the full model: bed contact and smoothed friction), no
// cushions. The counter per_ball is the time per call divided by n: flat across n means O(n).
//   ./rhs_benchmark [--csv=docs/bench/scaling_rhs.csv] [Google Benchmark options]
// --csv also writes the calls' times, from which scripts/bench_plots.py draws docs/bench/scaling_rhs.svg.
#include <benchmark/benchmark.h>

#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include "app/bench/scaling.hpp"
#include "engine/dynamics.hpp"

namespace {

void BM_Rhs(benchmark::State& st) {
  const int n = static_cast<int>(st.range(0));
  const shotlab::Prepared p = shotlab::prepare(shotlab::scattered_scene(n, 20261122));
  const shotlab::ModelIndex index(p.model);
  shotlab::Dynamics f(p.model, index, p.state);
  shotlab::StateVector dxdt(p.state.x.size());
  for (auto _ : st) {
    f(p.state.x, dxdt, 0.0);
    benchmark::DoNotOptimize(dxdt.data());
    benchmark::ClobberMemory();
  }
  st.counters["balls"] = n;
  st.counters["per_ball"] =
      benchmark::Counter(n, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_Rhs)->Arg(16)->Arg(100)->Arg(1000)->Arg(10000)->Unit(benchmark::kMicrosecond);

// Prints as usual and keeps (balls, seconds per call) for the CSV.
class Collector : public benchmark::ConsoleReporter {
 public:
  std::vector<std::pair<double, double>> calls;
  void ReportRuns(const std::vector<Run>& runs) override {
    for (const Run& r : runs)
      if (r.run_type == Run::RT_Iteration && !r.error_occurred)
        calls.push_back({r.counters.at("balls").value, r.GetAdjustedRealTime() / benchmark::GetTimeUnitMultiplier(r.time_unit)});
    ConsoleReporter::ReportRuns(runs);
  }
};

bool write_csv(const std::string& path, const std::vector<std::pair<double, double>>& calls) {
  if (calls.empty()) return true;
  std::ofstream csv(path);
  csv << "balls,seconds_per_call\n";
  for (const auto& [n, s] : calls) csv << n << "," << s << "\n";
  if (!csv) std::cerr << "rhs_benchmark: cannot write " << path << "\n";
  return static_cast<bool>(csv);
}

}  // namespace

int main(int argc, char** argv) {
  std::string csv;
  std::vector<char*> args;
  for (int i = 0; i < argc; ++i) {
    const std::string a = argv[i];
    if (a.rfind("--csv=", 0) == 0) csv = a.substr(6);
    else args.push_back(argv[i]);
  }
  int count = static_cast<int>(args.size());
  benchmark::Initialize(&count, args.data());
  if (benchmark::ReportUnrecognizedArguments(count, args.data())) return 1;
  Collector collector;
  benchmark::RunSpecifiedBenchmarks(&collector);
  benchmark::Shutdown();
  return csv.empty() || write_csv(csv, collector.calls) ? 0 : 1;
}
