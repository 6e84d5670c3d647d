// `shotlab margin`: how much a shot forgives. The scene's cue strike replayed under a player's stroke noise
// (engine/include/shotlab/io/margin.hpp; docs/margin.md), written as JSON, CSV and a picture.
#include <cstdio>
#include <iomanip>
#include <iostream>
#include <memory>
#include <optional>

#include "app/commands.hpp"
#include "app/progress.hpp"
#include "app/plot_script.hpp"
#include "shotlab/io/atomic_file.hpp"
#include "shotlab/io/margin.hpp"
#include "shotlab/io/scene_json.hpp"

namespace shotlab {
namespace {

struct MarginCommand {
  std::string scene, goal, level = "amateur";
  std::optional<double> aim_sd, speed_sd, tip_sd, elevation_sd;
  std::vector<std::string> overrides;
  size_t samples = 200;
  uint64_t seed = 1;
  int jobs = 0;
  std::string map;  // "AxS": aim x speed cells
  double map_aim = 2, map_speed = 15;  // half ranges: degrees, % of the speed
  bool no_sensitivity = false, quiet = false;
  std::string out, csv, picture;
};

void print_summary(const MarginCommand& o, const MarginOptions& m, const MarginResult& r) {
  std::cout << std::fixed << std::setprecision(3) << "success " << r.probability << " +- " << r.standard_error << " ("
            << m.samples << " replays, level " << o.level << "; the intended stroke "
            << (r.nominal_success ? "succeeds" : "fails") << ")\n";
  if (m.noise.aim_deg + m.noise.speed_pct + m.noise.tip_mm + m.noise.elevation_deg == 0) return;
  for (int k = 0; k < kNoiseSources && !o.no_sensitivity; ++k) {
    std::cout << "  " << std::left << std::setw(14) << noise_source_name(k) << std::right << " alone: success "
              << r.alone[k] << "; ";
    if (!r.nominal_success)  // no window around a stroke that misses (its tolerance reads 0 to 0)
      std::cout << "no window: the intended stroke fails\n";
    else
      std::cout << "the shot holds from " << r.tolerance[k].lo << (r.tolerance[k].bounded_lo ? "" : " (or less)")
                << " to " << r.tolerance[k].hi << (r.tolerance[k].bounded_hi ? "" : " (or more)") << "\n";
  }
  std::cout << std::defaultfloat;
}

int margin(const MarginCommand& o) {
  const Scene scene = load_scene(o.scene, o.overrides);
  MarginOptions m;
  m.noise = stroke_noise(o.level);
  if (o.aim_sd) m.noise.aim_deg = *o.aim_sd;
  if (o.speed_sd) m.noise.speed_pct = *o.speed_sd;
  if (o.tip_sd) m.noise.tip_mm = *o.tip_sd;
  if (o.elevation_sd) m.noise.elevation_deg = *o.elevation_sd;
  for (double v : {m.noise.aim_deg, m.noise.speed_pct, m.noise.tip_mm, m.noise.elevation_deg})
    if (!std::isfinite(v) || v < 0 || v > 90) throw InputError("--aim-sd, --speed-sd, --tip-sd, --elevation-sd: from 0 to 90");
  m.goal = parse_goal(o.goal);
  m.samples = o.samples, m.seed = o.seed, m.jobs = o.jobs, m.sensitivity = !o.no_sensitivity;
  if (m.samples < 1 || m.samples > 1'000'000) throw InputError("--samples: from 1 to 1000000");
  int aims = 0, speeds = 0;
  if (!o.map.empty() && (std::sscanf(o.map.c_str(), "%dx%d", &aims, &speeds) != 2 || aims < 1 || speeds < 1 ||
                         aims * speeds > 10000))
    throw InputError("--map " + o.map + ": expected AIMSxSPEEDS, e.g. 40x20, at most 10000 cells");
  // Files open before the runs (a bad path fails at once) and are replaced only when everything is written.
  std::unique_ptr<AtomicFile> json_file = o.out.empty() ? nullptr : std::make_unique<AtomicFile>(o.out);
  std::unique_ptr<AtomicFile> csv_file = o.csv.empty() ? nullptr : std::make_unique<AtomicFile>(o.csv);
  const MarginResult r = shot_margin(scene, m, progress_bar(!o.quiet));
  std::optional<MarginMap> map;
  if (aims) map = margin_map(scene, m, aims, speeds, o.map_aim, o.map_speed, progress_bar(!o.quiet));
  if (json_file) json_file->write(margin_to_json(scene, m, r, map ? &*map : nullptr).dump(1) + "\n");
  if (csv_file) csv_file->write(margin_csv(r));
  for (AtomicFile* f : {json_file.get(), csv_file.get()})
    if (f) f->finish();
  for (AtomicFile* f : {json_file.get(), csv_file.get()})
    if (f) f->commit();
  if (!o.quiet) print_summary(o, m, r);
  if (!o.picture.empty())
    return run_plot_script("margin_plot.py", {o.out, o.picture}, "shotlab margin") ? 0 : 1;
  return 0;
}

}  // namespace

void add_margin_command(CLI::App& app) {
  auto o = std::make_shared<MarginCommand>();
  CLI::App* cmd = app.add_subcommand("margin", "How much a shot forgives: its cue strike replayed under stroke noise");
  cmd->add_option("scene", o->scene, "Scene file (JSON) with a cue strike")->required();
  cmd->add_option("--goal", o->goal, "pocket:BALL[@POCKET] or zone:BALL@X,Z,RADIUS (m)")->required();
  cmd->add_option("--level", o->level, "Stroke noise of a player: robot, pro, amateur (default), beginner");
  cmd->add_option("--aim-sd", o->aim_sd, "Aim error, standard deviation in degrees (overrides the level's)");
  cmd->add_option("--speed-sd", o->speed_sd, "Speed error, % of the speed");
  cmd->add_option("--tip-sd", o->tip_sd, "Tip offset error, mm (side and height each)");
  cmd->add_option("--elevation-sd", o->elevation_sd, "Elevation error, degrees");
  cmd->add_option("--samples", o->samples, "Replays (default 200; per cell with --map)");
  cmd->add_option("--seed", o->seed, "Seed of the noise (default 1)")->check(kNotNegative);
  cmd->add_option("-j,--jobs", o->jobs, "Threads (default: one per core)")->check(CLI::Range(0, 1024));
  cmd->add_option("--set", o->overrides, "Override a scene value: PATH=VALUE");
  cmd->add_option("--map", o->map, "Also a map of success over aim x speed cells around the scene's, e.g. 40x20");
  cmd->add_option("--map-aim", o->map_aim, "The map's aim half range, degrees (default 2)")->check(CLI::Range(0.0, 90.0));
  cmd->add_option("--map-speed", o->map_speed, "The map's speed half range, % (default 15)")->check(CLI::Range(0.0, 90.0));
  cmd->add_flag("--no-sensitivity", o->no_sensitivity, "Skip the per-source ensembles and tolerance searches");
  cmd->add_option("--out", o->out, "Write the result as JSON");
  cmd->add_option("--csv", o->csv, "Write one row per replay as CSV");
  cmd->add_option("--picture", o->picture, "Draw the end positions (and the map) into a PNG or SVG (needs --out)");
  cmd->add_flag("-q,--quiet", o->quiet, "No progress bar, no summary");
  cmd->callback([o] {
    int code = 1;
    try {
      if (!o->picture.empty() && o->out.empty()) throw InputError("--picture: needs --out (the picture is drawn from it)");
      code = margin(*o);
    } catch (const std::exception& e) {
      std::cerr << "shotlab: " << e.what() << "\n";
    }
    if (code) throw CLI::RuntimeError(code);
  });
}

}  // namespace shotlab
