#include "run_command.hpp"

#include <cmath>
#include <fstream>
#include <iostream>

#include "app/commands.hpp"
#include "engine/io/result_json.hpp"
#include "engine/io/scene_json.hpp"
#include "engine/simulation.hpp"

namespace shotlab {

int run_scene(const RunOptions& o) {
  Scene scene;
  try {
    scene = load_scene(o.scene, o.overrides);
  } catch (const InputError& e) {
    std::cerr << "shotlab: " << e.what() << "\n";
    return 1;
  }
  const double duration = o.duration.value_or(scene.duration);
  if (!(duration > 0) || !std::isfinite(duration)) {
    std::cerr << "shotlab: --duration: must be a positive number of seconds\n";
    return 1;
  }
  Prepared prepared = prepare(scene);
  std::vector<Event> extra;
  if (prepared.strike && prepared.strike->miscue) {
    extra.push_back({0.0, "miscue", {scene.cue->ball}});
    std::cerr << "shotlab: warning: miscue: the tip offset is beyond " << scene.cue->miscue_limit
              << " of the radius; the strike is simulated as if the tip held\n";
  }
  Simulation sim(std::move(prepared.model), std::move(prepared.state));

  std::ofstream csv;
  if (!o.trajectory.empty()) {
    csv.open(o.trajectory);
    if (!csv) {
      std::cerr << "shotlab: " << o.trajectory << ": cannot write the trajectory file\n";
      return 1;
    }
    csv.precision(10);
    write_trajectory_header(csv);
    write_trajectory_rows(csv, sim);
  }
  // Advance in sample slices; the integrator's own steps do not depend on the slicing (simulation.hpp).
  const double slice = 1.0 / o.sample_rate;
  const long slices = static_cast<long>(std::ceil(duration / slice - 1e-9));
  for (long k = 1; k <= slices && sim.status() == Status::Ok; ++k) {
    sim.advance(std::min(k * slice, duration) - sim.time());
    if (csv.is_open()) write_trajectory_rows(csv, sim);
    if (o.until_rest && sim.at_rest()) break;
  }

  if (!o.out.empty()) {
    std::ofstream out(o.out);
    out << result_to_json(sim, extra).dump(2) << "\n";
    if (!out) {
      std::cerr << "shotlab: " << o.out << ": cannot write the result file\n";
      return 1;
    }
  }
  const Stats& st = sim.stats();
  if (!o.quiet)
    std::cout << (scene.name.empty() ? o.scene : scene.name) << ": t = " << sim.time() << " s, " << method_name(sim.model().integrator.method) << " "
              << st.steps << " steps (" << st.rejected_steps << " rejected), " << st.rhs_evaluations
              << " rhs evaluations, " << sim.events().size() << " events, wall " << st.wall_seconds << " s\n";
  if (sim.status() != Status::Ok) {
    std::cerr << "shotlab: " << o.scene << ": simulation stopped (" << status_name(sim.status())
              << "): " << sim.diagnostic() << "\n";
    return 3;
  }
  return 0;
}

void add_run_command(CLI::App& app) {
  auto o = std::make_shared<RunOptions>();
  CLI::App* cmd = app.add_subcommand("run", "Simulate a scene file headless");
  cmd->add_option("scene", o->scene, "Scene file (JSON)")->required();
  cmd->add_option("--duration", o->duration, "Simulated time in seconds (default: the scene's)");
  cmd->add_option("--set", o->overrides, "Override a scene value: PATH=VALUE, e.g. materials.ball_cloth.friction=0.3");
  cmd->add_option("--out", o->out, "Write the result (final state, events, stats) as JSON");
  cmd->add_option("--trajectory", o->trajectory, "Write every ball's state as CSV");
  cmd->add_option("--sample-rate", o->sample_rate, "Trajectory samples per second")->check(CLI::PositiveNumber);
  cmd->add_flag("--until-rest", o->until_rest, "Stop early once every ball is at rest");
  cmd->add_flag("-q,--quiet", o->quiet, "No summary line");
  cmd->callback([o] {
    if (const int code = run_scene(*o)) throw CLI::RuntimeError(code);
  });
}

}  // namespace shotlab
