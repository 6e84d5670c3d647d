#include "scaling.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <iostream>
#include <random>

#include "app/bench/cases.hpp"
#include "shotlab/simulation.hpp"

namespace shotlab {
namespace {

constexpr double kCell = 0.2;  // m, grid spacing: 3.5 diameters, so neighbours never touch

Scene flat_bed(const std::string& name) {
  Scene s;
  s.name = name;
  s.model = empty_model();
  s.model.colliders.push_back({"bed", Plane{Vec3(0.0), kUp, {}}, kBallCloth});
  return s;
}

InitialBall pool_ball(int i, const Vec3& centre_on_bed) {
  std::string id = "b";  // appended, not "b" + ...: GCC 12 warns falsely (-Wrestrict) on that concatenation
  id += std::to_string(i);
  return {{id, kPoolBall.mass, kPoolBall.radius},
          centre_on_bed + Vec3(0.0, kPoolBall.radius, 0.0)};  // prepare() lowers it to its sink depth
}

struct FieldRun {
  int resting;
  bool plain;
  double wall = 0;  // s, median
  double simulated = 0;
  Stats stats;
};

FieldRun time_field(int resting, bool plain, int repeats) {
  FieldRun out;
  out.resting = resting;
  out.plain = plain;
  std::vector<double> walls;
  for (int k = 0; k < repeats; ++k) {
    Scene scene = resting_field(resting);
    if (plain) use_path(scene.model.options, SolverPath::Plain);
    Prepared p = prepare(scene);
    Simulation sim(std::move(p.model), std::move(p.state));
    while (sim.time() < scene.duration && sim.status() == Status::Ok && !sim.at_rest()) sim.advance(1.0 / 60);
    walls.push_back(sim.stats().wall_seconds);
    out.simulated = sim.time();
    out.stats = sim.stats();
    // A slow run (the plain path with 1000 balls) is not repeated: its spread is small next to the effect.
    if (sim.stats().wall_seconds > 5) break;
  }
  std::sort(walls.begin(), walls.end());
  out.wall = walls[walls.size() / 2];
  return out;
}

}  // namespace

Scene scattered_scene(int balls, unsigned seed) {
  Scene s = flat_bed("scattered " + std::to_string(balls));
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const int side = static_cast<int>(std::ceil(std::sqrt(balls)));
  const double play = kCell / 2 - kPoolBall.radius - 1e-3;  // jitter that keeps a ball inside its cell
  for (int i = 0; i < balls; ++i) {
    const Vec3 cell((i % side + 0.5) * kCell, 0.0, (i / side + 0.5) * kCell);
    InitialBall b = pool_ball(i, cell + Vec3((2 * unit(rng) - 1) * play, 0.0, (2 * unit(rng) - 1) * play));
    const double speed = 0.2 + 1.8 * unit(rng), heading = 2 * M_PI * unit(rng);
    b.velocity = {speed * std::cos(heading), 0.0, speed * std::sin(heading)};
    s.balls.push_back(b);
  }
  s.duration = 1.0;
  return s;
}

Scene resting_field(int resting) {
  Scene s = flat_bed(std::to_string(resting) + " resting balls, one moving");
  const double v = 0.5, r = kPoolBall.radius;
  InitialBall mover = pool_ball(0, Vec3(-0.3, 0.0, 0.0));
  mover.velocity = {v, 0.0, 0.0};
  mover.angular_velocity = {0.0, 0.0, -v / r};  // rolling without slip along +x
  s.balls.push_back(mover);
  s.balls.push_back(pool_ball(1, Vec3(0.0)));
  // The rest fill a square grid whose near edge is 0.7 m behind the moving ball: after the hit both move along +x.
  const int others = resting - 1, side = static_cast<int>(std::ceil(std::sqrt(others)));
  for (int i = 0; i < others; ++i)
    s.balls.push_back(pool_ball(i + 2, Vec3(-1.0 - (i % side) * kCell, 0.0, (i / side - 0.5 * (side - 1)) * kCell)));
  s.duration = 30.0;
  return s;
}

bool run_scaling(const std::string& out_dir, int repeats) {
  std::vector<FieldRun> runs;
  std::cout << "| resting balls | path | simulated s | wall ms | steps | rejected | rhs |\n|---|---|---|---|---|---|---|\n";
  for (bool plain : {false, true})
    for (int n : {16, 100, 1000}) {
      runs.push_back(time_field(n, plain, repeats));
      const FieldRun& f = runs.back();
      std::cout << "| " << n << " | " << (plain ? "plain" : "fast") << " | " << f.simulated << " | " << f.wall * 1e3
                << " | " << f.stats.steps << " | " << f.stats.rejected_steps << " | " << f.stats.rhs_evaluations
                << " |" << std::endl;
    }
  // scripts/bench_plots.py draws scaling_scenes.svg from this file.
  std::ofstream csv(out_dir + "/scaling.csv");
  csv << "resting_balls,path,simulated_s,wall_s,steps,rejected,rhs\n";
  for (const FieldRun& f : runs)
    csv << f.resting << "," << (f.plain ? "plain" : "fast") << "," << f.simulated << "," << f.wall << ","
        << f.stats.steps << "," << f.stats.rejected_steps << "," << f.stats.rhs_evaluations << "\n";
  if (!csv) std::cerr << "shotlab bench: " << out_dir << ": cannot write scaling.csv\n";
  return static_cast<bool>(csv);
}

}  // namespace shotlab
