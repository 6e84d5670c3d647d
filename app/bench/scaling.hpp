// Issue 5's scaling measurements: scenes of many balls on a large flat bed (a plane, no cushions, no pockets).
//  - scattered_scene: n balls all moving, for the cost of one right-hand-side call (tests/benchmarks/rhs_benchmark);
//  - resting_field: n resting balls and one moving ball that hits one of them, for `shotlab bench --scaling`,
//    which times it on the fast and on the plain path.
#pragma once
#include <string>

#include "shotlab/scene.hpp"

namespace shotlab {

// `balls` pool balls on a jittered grid of 0.2 m cells (no overlaps by construction, the same density at every n),
// resting on the bed, each sliding at 0.2-2 m/s in a random direction; deterministic for a given seed.
Scene scattered_scene(int balls, unsigned seed);

// `resting` balls at rest: one 0.3 m ahead of a ball rolling at 0.5 m/s straight at it, the others on a 0.2 m grid
// behind the moving ball, out of the way of both. Runs until everything is at rest again.
Scene resting_field(int resting);

// `shotlab bench --scaling`: times resting_field at 16, 100 and 1000 resting balls on both paths; prints the table
// and writes scaling.csv into out_dir (scripts/bench_plots.py draws scaling_scenes.svg from it). Returns false, and
// says so, when the file cannot be written.
bool run_scaling(const std::string& out_dir, int repeats);

}  // namespace shotlab
