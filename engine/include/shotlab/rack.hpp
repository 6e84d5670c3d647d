// Racks: the triangle of object balls for a break, optionally with seeded random jitter (thesis fig. 6.5).
#pragma once
#include <cstdint>
#include <vector>

#include "shotlab/scene.hpp"

namespace shotlab {

// Rows open towards +x; balls rest on the bed (y = R).
std::vector<InitialBall> triangle_rack(const RackSpec& spec, const BallKind& kind);

}  // namespace shotlab
