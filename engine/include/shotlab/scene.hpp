// A scene: a model, the balls' initial state, an optional cue strike and how long to run. This is what a preset file
// holds (engine/io reads and writes it); the engine itself never touches files.
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "shotlab/cue.hpp"
#include "shotlab/model.hpp"
#include "shotlab/state.hpp"
#include "shotlab/table.hpp"

namespace shotlab {

// Standard balls (docs/model.md#parameters).
struct BallKind {
  const char* name;
  double mass;    // kg
  double radius;  // m
};
inline constexpr BallKind kPoolBall{"pool", 0.17, 0.028575};
inline constexpr BallKind kSnookerBall{"snooker", 0.1406, 0.02625};
inline constexpr BallKind kCaromBall{"carom", 0.21, 0.03075};
const BallKind* find_ball_kind(const std::string& name);

struct InitialBall {
  BallSpec spec;
  Vec3 position{0.0};          // m
  Vec3 velocity{0.0};          // m/s
  Vec3 angular_velocity{0.0};  // rad/s
};

// s: the longest run a scene or a command may ask for (an hour; a shot rests within a minute, a Newton's cradle
// swings for ever, so the bound is what stops a typo from running for days).
inline constexpr double kMaxDuration = 3600.0;
// m/s: the fastest a ball (or its surface, R |w|) or a cue may start. A record break is about 14 m/s; beyond this a
// scene is a typo (1e6 m/s), not a shot.
inline constexpr double kMaxStartSpeed = 30.0;

// A rack of object balls (rack.hpp builds it): a triangle, or snooker's reds and colours.
enum class RackType { Triangle, Snooker };
struct RackSpec {
  RackType type = RackType::Triangle;
  int rows = 5;                // 5 rows = 15 balls
  double apex_x = 0.635;       // m, the front ball's centre (foot spot of a 9 ft table)
  double apex_z = 0.0;         // m
  double gap = 0.0;            // m, extra spacing between neighbours (0 = frozen, touching)
  double jitter = 0.0;         // each ball displaced uniformly within this many ball radii in x and z
  uint32_t seed = 1;           // for the jitter: the same seed gives the same rack on every machine
  int first_number = 1;        // ids are the numbers first_number, first_number + 1, ... (snooker: red1 ... red15)
  double table_length = 3.569; // m, snooker: the spots are placed for a table this long (the scene's table)
};

// Where a scene's racked balls came from: kept so that a saved scene writes its rack back (seed and jitter included)
// while the racked balls are as racked, and so that a message about them names the rack.
struct RackOrigin {
  RackSpec spec;
  std::string kind;   // BallKind name
  size_t first = 0;   // index in Scene::balls of the first racked ball
};

struct Scene {
  std::string name;
  std::string description;        // what to look for
  Model model;                    // balls filled in from `balls`
  std::vector<InitialBall> balls;
  std::optional<TableSpec> table;
  std::optional<CueStrike> cue;
  double duration = 5.0;          // s, at most kMaxDuration
  bool allow_overlap = false;     // balls may start interpenetrating (a deliberate pre-loaded contact)
  std::optional<RackOrigin> rack;
};

// Checks what the types cannot (overlaps, positive sizes, balls over the table's bed, start speeds up to
// kMaxStartSpeed, rods and cue naming real balls); throws std::invalid_argument with a message naming the ball or
// field.
void validate(const Scene& scene);

// The model and state ready to simulate: table colliders added, balls resting on the bed lowered to their static
// sink depth (so a scene starts at rest instead of dropping a few micrometres), the cue strike applied.
struct Prepared {
  Model model;
  State state;
  std::optional<StrikeResult> strike;
};
Prepared prepare(const Scene& scene);

}  // namespace shotlab
