#include "run_command.hpp"

#include <cmath>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>

#include "app/commands.hpp"
#include "shotlab/io/atomic_file.hpp"
#include "shotlab/io/result_json.hpp"
#include "shotlab/io/run.hpp"
#include "shotlab/io/scene_json.hpp"
#include "shotlab/simulation.hpp"

namespace shotlab {

namespace {

// The options a run refuses before it starts: a duration beyond kMaxDuration, a sample rate out of range, an output
// of more samples than max_samples. Returns the problem, empty when there is none.
std::string check_run(const RunOptions& o, double duration) {
  std::ostringstream why;
  if (!std::isfinite(duration) || !(duration > 0) || duration > kMaxDuration)
    why << "--duration: must be a number of seconds above 0 and at most " << kMaxDuration;
  else if (!std::isfinite(o.sample_rate) || o.sample_rate < kMinSampleRate || o.sample_rate > kMaxSampleRate)
    why << "--sample-rate: must be between " << kMinSampleRate << " and " << kMaxSampleRate << " per second";
  else if (duration * o.sample_rate > o.max_samples) {
    if (o.duration) why << "--duration " << duration << " s";
    else why << "a run " << (o.until_rest ? "to rest, up to " : "of the scene's ") << duration << " s";
    why << " at --sample-rate " << o.sample_rate << " is " << duration * o.sample_rate << " samples, more than "
        << o.max_samples << " (" << (o.duration ? "" : "give a shorter --duration, or ") << "raise the limit with "
        << "--max-samples N)";
  }
  return why.str();
}

int run(const RunOptions& o) {
  Scene scene = load_scene(o.scene, o.overrides);
  const double duration = run_duration(scene, o.duration, o.until_rest);
  if (const std::string problem = check_run(o, duration); !problem.empty()) {
    std::cerr << "shotlab: " << problem << "\n";
    return 1;
  }
  HeadlessRun headless = start_run(scene);
  if (headless.miscue)
    std::cerr << "shotlab: warning: miscue: the tip offset is beyond " << scene.cue->miscue_limit
              << " of the radius; the strike is simulated as if the tip held\n";
  Simulation& sim = *headless.sim;
  // Both files are opened before the run (a bad path fails at once) and replace their targets only once both are
  // written: a failure leaves every existing file as it was.
  std::unique_ptr<AtomicFile> out = o.out.empty() ? nullptr : std::make_unique<AtomicFile>(o.out);
  std::unique_ptr<AtomicFile> csv;
  if (!o.trajectory.empty()) {
    csv = std::make_unique<AtomicFile>(o.trajectory);
    std::ostringstream head;
    head.precision(10);
    write_trajectory_header(head);
    write_trajectory_rows(head, sim);
    csv->write(head.str());
  }
  std::ostringstream rows;
  rows.precision(10);
  auto sample = [&] {  // a trajectory row set after each slice
    rows.str("");
    write_trajectory_rows(rows, sim);
    csv->write(rows.str());
  };
  advance_run(sim, duration, o.sample_rate, o.until_rest, csv ? std::function<void()>(sample) : nullptr);
  if (out) out->write(result_to_json(sim, headless.extra).dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n");
  for (AtomicFile* f : {out.get(), csv.get()})
    if (f) f->finish();
  for (AtomicFile* f : {out.get(), csv.get()})
    if (f) f->commit();
  const Stats& st = sim.stats();
  if (!o.quiet) {
    std::cout << (scene.name.empty() ? o.scene : scene.name) << ": t = " << sim.time() << " s, ";
    if (sim.model().options.contact == ContactModel::Rigid)  // no steps: one impulse or change of kind an event
      std::cout << "rigid model, " << st.steps << " collisions and changes of motion, ";
    else
      std::cout << method_name(sim.model().integrator.method) << " " << st.steps << " steps (" << st.rejected_steps
                << " rejected), " << st.rhs_evaluations << " rhs evaluations, ";
    std::cout << sim.events().size() << " events, wall " << st.wall_seconds << " s\n";
  }
  if (std::string why = unfinished_rest(sim, o.until_rest); !why.empty())
    std::cerr << "shotlab: warning: " << o.scene << ": " << why << " (a longer --duration runs on to rest)\n";
  if (sim.status() != Status::Ok) {
    std::cerr << "shotlab: " << o.scene << ": simulation stopped (" << status_name(sim.status())
              << "): " << sim.diagnostic() << "\n";
    return 3;
  }
  return 0;
}

}  // namespace

int run_scene(const RunOptions& o) {
  try {
    return run(o);
  } catch (const std::exception& e) {  // bad input (InputError), a file that cannot be written, anything else
    std::cerr << "shotlab: " << e.what() << "\n";
    return 1;
  }
}

void add_run_command(CLI::App& app) {
  auto o = std::make_shared<RunOptions>();
  CLI::App* cmd = app.add_subcommand("run", "Simulate a scene file headless");
  cmd->add_option("scene", o->scene, "Scene file (JSON)")->required();
  cmd->add_option("--duration", o->duration, "Simulated time in seconds (default: the scene's)");
  cmd->add_option("--set", o->overrides, "Override a scene value: PATH=VALUE, e.g. materials.ball_cloth.friction=0.3");
  cmd->add_option("--out", o->out, "Write the result (final state, events, stats) as JSON");
  cmd->add_option("--trajectory", o->trajectory, "Write every ball's state as CSV");
  cmd->add_option("--sample-rate", o->sample_rate, "Trajectory samples per second (0.001 to 100000)");
  cmd->add_option("--max-samples", o->max_samples, "Refuse runs of more samples than this (default 1000000)");
  cmd->add_flag("--until-rest", o->until_rest,
                "Stop once every ball is at rest; without --duration, run up to 60 s (or the scene's duration if longer)");
  cmd->add_flag("-q,--quiet", o->quiet, "No summary line");
  cmd->callback([o] {
    if (const int code = run_scene(*o)) throw CLI::RuntimeError(code);
  });
}

}  // namespace shotlab
