// Racks: the triangle of object balls for a break, optionally with seeded random jitter (thesis fig. 6.5).
#pragma once
#include <cstdint>
#include <vector>

#include "shotlab/scene.hpp"

namespace shotlab {

// Rows open towards +x; balls rest on the bed (y = R).
std::vector<InitialBall> triangle_rack(const RackSpec& spec, const BallKind& kind);

// Snooker, the black end at +x: the six colours on their spots and the 15 reds (red1 ... red15) in a triangle behind
// the pink, its apex 1 mm short of touching it (spec's rows, gap, jitter and seed apply to the reds).
std::vector<InitialBall> snooker_rack(const RackSpec& spec, const BallKind& kind);

// The rack spec.type asks for.
std::vector<InitialBall> make_rack(const RackSpec& spec, const BallKind& kind);

}  // namespace shotlab
