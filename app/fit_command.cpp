// `shotlab fit`: the cue strikes of measured shots and the scene values they share, fitted to the tracked balls
// (engine/include/shotlab/io/fit.hpp; docs/fit.md).
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <memory>

#include "app/commands.hpp"
#include "app/plot_script.hpp"
#include "shotlab/io/atomic_file.hpp"
#include "shotlab/io/fit.hpp"
#include "shotlab/io/scene_json.hpp"

namespace shotlab {
namespace {

struct FitCommand {
  std::vector<std::string> measured, paths, overrides;
  std::string scene, out, picture, scenes;
  bool elevation = false, quiet = false;
  int jobs = 0, iterations = 100;
};

void print_table(const FitResult& r, int max_iterations) {
  std::cout << std::fixed << std::setprecision(1);
  for (const ShotFit& f : r.shots) {
    std::cout << f.name << ": cue " << f.cue_ball << " " << std::setprecision(3) << f.cue.speed << " m/s, aim "
              << f.cue.aim_deg << " deg, side " << f.cue.side << ", height " << f.cue.height << "; rms (mm)"
              << std::setprecision(1);
    for (const auto& [ball, v] : f.rms) std::cout << " " << ball << " " << v * 1e3;
    std::cout << "\n";
  }
  for (size_t k = 0; k < r.paths.size(); ++k)
    std::cout << std::defaultfloat << std::setprecision(5) << r.paths[k] << ": " << r.start[k] << " -> " << r.values[k]
              << " (sd " << std::setprecision(2) << r.sd[k] << ")\n";
  std::cout << std::defaultfloat << r.iterations << " iterations over the joint fit's rounds (at most " << max_iterations
            << " a round), " << std::setprecision(3) << r.seconds << " s\n";
}

int fit(const FitCommand& o) {
  const Scene base = load_scene(o.scene, o.overrides);
  std::vector<MeasuredShot> shots;
  for (const std::string& path : o.measured) shots.push_back(read_measured(path));
  if (!o.scenes.empty() && !std::filesystem::is_directory(o.scenes))
    throw InputError("--scenes " + o.scenes + ": not a folder");
  std::unique_ptr<AtomicFile> file = o.out.empty() ? nullptr : std::make_unique<AtomicFile>(o.out);
  FitSettings settings;
  settings.paths = o.paths, settings.elevation = o.elevation, settings.threads = o.jobs;
  settings.max_iterations = o.iterations;
  if (!o.quiet) settings.log = [](const std::string& line) { std::cerr << "shotlab fit: " << line << std::endl; };
  const FitResult r = fit_measured(base, shots, settings);
  if (file) file->write(fit_to_json(base, shots, r).dump(1) + "\n"), file->commit();
  if (!o.scenes.empty()) {
    const Scene fitted = fitted_scene(base, r);
    for (size_t s = 0; s < shots.size(); ++s) {
      Scene one = measured_scene(fitted, shots[s], r.shots[s].cue);
      one.name = shots[s].name + " (fitted)";
      save_scene((std::filesystem::path(o.scenes) / (shots[s].name + ".json")).string(), one);
    }
  }
  if (!o.quiet) print_table(r, o.iterations);
  if (r.report.find("NO_CONVERGENCE") != std::string::npos)  // also with -q: a script's fit that did not settle
    std::cerr << "shotlab fit: warning: the last joint round stopped at " << o.iterations
              << " iterations before it converged: the values may still move (raise --iterations)\n";
  if (!o.picture.empty()) return run_plot_script("fit_plot.py", {o.out, o.picture}, "shotlab fit") ? 0 : 1;
  return 0;
}

}  // namespace

void add_fit_command(CLI::App& app) {
  auto o = std::make_shared<FitCommand>();
  CLI::App* cmd = app.add_subcommand("fit", "Fit cue strikes and shared scene values to measured shots");
  cmd->add_option("measured", o->measured, "Measured shots: CSV files of time,ball,x,z")->required();
  cmd->add_option("--scene", o->scene, "The scene whose table, materials and cue the shots are played with")->required();
  cmd->add_option("--fit", o->paths, "A scene value fitted in common to every shot, e.g. materials.ball_cloth.friction");
  cmd->add_option("--set", o->overrides, "Override a value of the scene first: PATH=VALUE");
  cmd->add_flag("--elevation", o->elevation, "Fit each cue's elevation too (else a level cue)");
  cmd->add_option("-j,--jobs", o->jobs, "Threads (default: one per core)")->check(CLI::Range(0, 1024));
  cmd->add_option("--iterations", o->iterations, "Iterations a round of the joint fit may take (default 100)")->check(CLI::Range(1, 10000));
  cmd->add_option("--out", o->out, "Write the fit as JSON");
  cmd->add_option("--picture", o->picture, "Draw measured and fitted paths into a PNG or SVG (needs --out)");
  cmd->add_option("--scenes", o->scenes, "Write each shot as a scene with its fitted strike into this folder");
  cmd->add_flag("-q,--quiet", o->quiet, "No progress, no table");
  cmd->callback([o] {
    int code = 1;
    try {
      if (!o->picture.empty() && o->out.empty()) throw InputError("--picture: needs --out (the picture is drawn from it)");
      code = fit(*o);
    } catch (const std::exception& e) {
      std::cerr << "shotlab: " << e.what() << "\n";
    }
    if (code) throw CLI::RuntimeError(code);
  });
}

}  // namespace shotlab
