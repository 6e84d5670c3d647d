// shotlab: the desktop shot lab (no arguments), or a headless command (run, ...).
#include <CLI/CLI.hpp>
#include <cstdlib>
#include <iostream>

#include "run_command.hpp"
#include "app/paths.hpp"

int main(int argc, char** argv) {
  CLI::App app{"shotlab: billiard-ball physics shot lab"};
  app.require_subcommand(0, 1);

  shotlab::RunOptions run;
  CLI::App* run_cmd = app.add_subcommand("run", "Simulate a scene file headless");
  run_cmd->add_option("scene", run.scene, "Scene file (JSON)")->required();
  run_cmd->add_option("--duration", run.duration, "Simulated time in seconds (default: the scene's)");
  run_cmd->add_option("--set", run.overrides, "Override a scene value: PATH=VALUE, e.g. materials.ball_cloth.friction=0.3");
  run_cmd->add_option("--out", run.out, "Write the result (final state, events, stats) as JSON");
  run_cmd->add_option("--trajectory", run.trajectory, "Write every ball's state as CSV");
  run_cmd->add_option("--sample-rate", run.sample_rate, "Trajectory samples per second")->check(CLI::PositiveNumber);
  run_cmd->add_flag("--until-rest", run.until_rest, "Stop early once every ball is at rest");
  run_cmd->add_flag("-q,--quiet", run.quiet, "No summary line");

  CLI11_PARSE(app, argc, argv);
  if (run_cmd->parsed()) return shotlab::run_scene(run);

  // No subcommand: the GUI when there is a display, else a headless run of the break preset.
  if (!std::getenv("DISPLAY") && !std::getenv("WAYLAND_DISPLAY")) {
    std::cout << "shotlab: no display; running the break preset headless instead of the GUI\n";
    shotlab::RunOptions preset;
    preset.scene = shotlab::preset_path("break.json");
    preset.until_rest = true;
    return shotlab::run_scene(preset);
  }
  return shotlab::run_gui(argc, argv);
}
