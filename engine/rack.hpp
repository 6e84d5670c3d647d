// Racks: the triangle of object balls for a break, optionally with seeded random jitter (thesis fig. 6.5).
#pragma once
#include <cstdint>
#include <vector>

#include "scene.hpp"

namespace shotlab {

struct RackSpec {
  int rows = 5;                // 5 rows = 15 balls
  double apex_x = 0.635;       // m, the front ball's centre (foot spot of a 9 ft table)
  double apex_z = 0.0;         // m
  double gap = 0.0;            // m, extra spacing between neighbours (0 = frozen, touching)
  double jitter = 0.0;         // each ball displaced uniformly within this many ball radii in x and z
  uint32_t seed = 1;           // for the jitter: the same seed gives the same rack on every machine
  int first_number = 1;        // ids are the numbers first_number, first_number + 1, ...
};

// Rows open towards +x; balls rest on the bed (y = R).
std::vector<InitialBall> triangle_rack(const RackSpec& spec, const BallKind& kind);

}  // namespace shotlab
