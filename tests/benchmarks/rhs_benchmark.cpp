// Cost of one right-hand-side call (shotlab::Dynamics::operator()) against the number of balls: issue 5 asks for
// O(n), not O(n^2). n balls scattered over a large flat bed (app/bench/scaling.hpp: same density at every n, no
// overlaps, all awake and sliding, so every ball takes the full model: bed contact and smoothed friction), no
// cushions. The counter per_ball is the time per call divided by n: flat across n means O(n).
//   ./rhs_benchmark [--svg=docs/bench/scaling_rhs.svg] [Google Benchmark options]
// --svg also writes the figure of docs/bench/scaling.md.
#include <benchmark/benchmark.h>

#include <string>
#include <vector>

#include "app/bench/scaling.hpp"
#include "app/bench/svg.hpp"
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

// Prints as usual and keeps (balls, seconds per call) for the figure.
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

// Two panels: seconds per call with the O(n) line through the smallest n, and seconds per ball.
bool write_figure(const std::string& path, const std::vector<std::pair<double, double>>& calls) {
  if (calls.empty()) return true;
  shotlab::PlotPanel per_call{"cost of one rhs call", {{"measured", "#1f77b4", {}}, {"O(n) from n = 16", "#888", {}, true}}};
  shotlab::PlotPanel per_ball{"cost per ball", {{"measured", "#1f77b4", {}}}};
  for (const auto& [n, s] : calls) {
    per_call.series[0].points.push_back({n, s});
    per_call.series[1].points.push_back({n, calls.front().second * n / calls.front().first});
    per_ball.series[0].points.push_back({n, s / n});
  }
  const shotlab::PlotSpec spec{"Right-hand side cost against ball count (rhs_benchmark)",
                               "Balls scattered over a flat bed at constant density, all sliding. Linear in n: on the "
                               "dashed line, flat per ball.",
                               "balls", "seconds", false, 2};
  return shotlab::write_loglog_grid(path, spec, {per_call, per_ball});
}

}  // namespace

int main(int argc, char** argv) {
  std::string svg;
  std::vector<char*> args;
  for (int i = 0; i < argc; ++i) {
    const std::string a = argv[i];
    if (a.rfind("--svg=", 0) == 0) svg = a.substr(6);
    else args.push_back(argv[i]);
  }
  int count = static_cast<int>(args.size());
  benchmark::Initialize(&count, args.data());
  if (benchmark::ReportUnrecognizedArguments(count, args.data())) return 1;
  Collector collector;
  benchmark::RunSpecifiedBenchmarks(&collector);
  benchmark::Shutdown();
  return svg.empty() || write_figure(svg, collector.calls) ? 0 : 1;
}
