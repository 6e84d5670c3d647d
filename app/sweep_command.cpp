// `shotlab sweep`: one scene run over a grid or a random sample of scene values, on every core, one CSV row per run
// (engine/include/shotlab/io/sweep.hpp; docs/sweep.md).
#include <chrono>
#include <csignal>
#include <iomanip>
#include <iostream>
#include <memory>
#include <optional>

#include "app/commands.hpp"
#include "app/progress.hpp"
#include "shotlab/io/atomic_file.hpp"
#include "shotlab/io/scene_json.hpp"
#include "shotlab/io/sweep.hpp"

namespace shotlab {
namespace {

struct SweepOptions {
  std::string scene;
  std::vector<std::string> vary, overrides;
  size_t samples = 0;  // 0: the full grid
  uint64_t seed = 1;
  int jobs = 0;        // 0: one per core
  std::optional<double> duration;
  double timeout = 60;     // s of wall time per run
  size_t max_events = 100'000;
  std::string out;         // empty or "-": standard output
  bool quiet = false;
};

std::atomic<bool> interrupted{false};
extern "C" void on_interrupt(int) {  // the runs under way finish; a second Ctrl-C ends the program at once
  interrupted = true;
  std::signal(SIGINT, SIG_DFL);
}

int sweep(const SweepOptions& o) {
  std::vector<SweepAxis> axes;
  for (const std::string& v : o.vary) axes.push_back(parse_sweep_axis(v));
  if (!(o.timeout > 0)) throw InputError("--timeout: must be a number of seconds above 0");
  SweepSettings settings{o.overrides, o.duration, {o.timeout, o.max_events, {}}};
  const Sweep sweep(read_scene_file(o.scene), o.scene, plan_sweep(axes, o.samples, o.seed), settings);
  const bool to_stdout = o.out.empty() || o.out == "-";
  std::unique_ptr<AtomicFile> file = to_stdout ? nullptr : std::make_unique<AtomicFile>(o.out);
  auto write = [&](const std::string& text) {
    if (file) file->write(text);
    else std::cout << text << std::flush;
  };
  write(sweep.header());
  size_t failed = 0;
  const auto start = std::chrono::steady_clock::now();
  auto on_row = [&](size_t, const std::string& line) {
    write(line);
    failed += sweep.status(line) != "ok";
  };
  const auto previous = std::signal(SIGINT, on_interrupt);
  sweep.run(0, sweep.size(), o.jobs, on_row, progress_bar(!o.quiet), &interrupted);
  std::signal(SIGINT, previous);
  if (interrupted) {
    const std::string rows = to_stdout ? "the rows so far are above" : o.out + " left as it was";
    std::cerr << "\nshotlab: sweep interrupted; " << rows << "\n";
    return 130;
  }
  if (file) file->commit();
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!o.quiet)
    std::cerr << "shotlab: sweep of " << sweep.size() << " runs: " << sweep.size() - failed << " ok, " << failed
              << " with another status (see the status column), " << std::setprecision(3) << wall << " s\n";
  return 0;
}

}  // namespace

void add_sweep_command(CLI::App& app) {
  auto o = std::make_shared<SweepOptions>();
  CLI::App* cmd = app.add_subcommand("sweep", "Run a scene over a grid or a random sample of scene values");
  cmd->add_option("scene", o->scene, "Scene file (JSON)")->required();
  cmd->add_option("--vary", o->vary, "PATH=VALUES: a list a,b,c, a JSON array, or a range lo:hi:n (lo:hi with --samples)")
      ->required();
  cmd->add_option("--samples", o->samples, "Random sampling: this many runs instead of the full grid")
      ->check(kNotNegative);
  cmd->add_option("--seed", o->seed, "Seed of the random sampling (default 1)")->check(kNotNegative);
  cmd->add_option("-j,--jobs", o->jobs, "Threads (default: one per core)")->check(CLI::Range(0, 1024));
  cmd->add_option("--set", o->overrides, "Override a scene value in every run: PATH=VALUE");
  cmd->add_option("--duration", o->duration,
                  "Simulated time per run in seconds (default: on to rest, up to 60 s); runs stop at rest");
  cmd->add_option("--timeout", o->timeout, "Wall seconds one run may take before it is cut (its row says so); default 60");
  cmd->add_option("--max-events", o->max_events, "Events one run may record before it is cut; default 100000");
  cmd->add_option("--out", o->out, "Write the rows to this CSV file (default, or -: standard output)");
  cmd->add_flag("-q,--quiet", o->quiet, "No progress bar, no summary");
  cmd->callback([o] {
    int code = 1;
    try {
      code = sweep(*o);
    } catch (const std::exception& e) {  // bad input (InputError), a file that cannot be written
      std::cerr << "shotlab: " << e.what() << "\n";
    }
    if (code) throw CLI::RuntimeError(code);
  });
}

}  // namespace shotlab
