// Aiming geometry for players: where the cue ball's line first meets a ball (the ghost ball), the cut angle, the aim
// that sends an object ball to a pocket, and where the cue ball may be placed with ball in hand (behind the head
// string for a break). Pure functions of the scene: the overlay draws them, the lab's snap actions use them.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "shotlab/scene.hpp"

namespace shotlab {

struct AimLine {
  Vec3 from{0.0};      // cue ball centre
  Vec3 ghost{0.0};     // cue ball centre where the line ends: touching the first ball hit, or at a cushion
  int hit = -1;        // ball index of the first ball hit, -1: none
  Vec3 object_dir{0.0};  // unit, the hit ball's line of departure (the line of centres at contact)
  double cut_deg = 0;  // angle between the aim and the object ball's departure
};
// The aim line of the scene's cue strike (nullopt without one): along the heading the cue ball leaves on, the cue's
// turned by the squirt of side spin (docs/model.md#cue).
std::optional<AimLine> aim_line(const Scene& scene);

// The heading (rad, CueStrike::aim) from a to b in the table plane.
double heading(const Vec3& a, const Vec3& b);
// rad: how far the scene's cue ball leaves off the cue's line (the squirt of side spin, + to the left; 0 without a
// cue strike): the cue's aim for a launch heading H is H - squirt_of(scene).
double squirt_of(const Scene& scene);

// The cue heading that sends ball `object` straight at a pocket (ghost-ball aim; throw and squirt not counted), with
// the cut angle it takes. Only pockets the object ball can reach with a cut under 85 degrees, easiest cut first.
struct PocketAim {
  std::string pocket;
  double aim;      // rad
  double cut_deg;
  bool drops = false;  // set by check_drops()
  double window_deg = 0;  // check_drops(): the aim may turn this far either way (deg) with the ball still dropping,
                          // 0 where the window was not worked out (the ghost-ball aim then)
};
std::vector<PocketAim> pocket_aims(const Scene& scene, const std::vector<Pocket>& pockets, int cue_ball, int object);
// Simulates the scene's shot at each aim (its speed, spin and the other balls as they are; each aim on a thread of its
// own, each shot until ball `object` drops or stops) and sets `drops` where it falls into that aim's pocket; the aims
// that drop come first, each part easiest cut first. An aim that drops moves to the middle of the aims around it that
// drop too (window_deg: half their width).
void check_drops(const Scene& scene, int object, std::vector<PocketAim>& aims);
// A pocket's name as a player says it: "pocket-right-front" -> "the right front pocket" (other names unchanged).
std::string pocket_label(const std::string& name);
// The ball P aims for: the one the aim line meets, else the object ball whose centre is nearest the aim in heading
// (-1 when there is no cue strike or no other ball).
int pocket_object(const Scene& scene);

// Where the cue ball may go with ball in hand, and any ball a drag moves: the whole bed inside the cushions, up to
// touching a cushion's nose, or for a break the part behind the head string (the quarter of a pool table's length
// nearest the head rail).
struct Zone {
  double lo_x, hi_x, lo_z, hi_z;  // m, ball centres
  Vec3 clamp(const Vec3& p) const;
};
Zone hand_zone(const TableSpec& table, double radius, bool behind_head_string);
// The scene is a racked break: a pool table, three or more object balls, all of them in the foot quarter.
bool break_position(const Scene& scene);

// A 15-ball rack at the foot spot, the cue ball on the head spot with a level, centre-ball cue strike at the apex.
// Keeps the table, the materials and the cue ball's size; needs a pool table.
Scene break_scene(const Scene& from);

}  // namespace shotlab
