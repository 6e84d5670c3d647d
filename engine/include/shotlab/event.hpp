// What a simulation reports: each ball's motion state and the events of a run (engine/events.hpp finds them).
#pragma once
#include <string>
#include <vector>

namespace shotlab {

// Pocketed and OffTable: out of play, through a pocket or over a rail.
enum class Motion { Stationary, Spinning, Rolling, Sliding, Airborne, Pocketed, OffTable };
const char* motion_name(Motion m);
inline bool out_of_play(Motion m) { return m == Motion::Pocketed || m == Motion::OffTable; }

struct Event {
  double time;                      // s
  std::string kind;                 // contact_begin, contact_end, sliding, rolling, spinning, stopped, airborne,
                                    // landed, pocketed, off_table, miscue
  std::vector<std::string> bodies;  // ball ids and collider names
};

}  // namespace shotlab
