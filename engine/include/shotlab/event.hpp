// What a simulation reports: each ball's motion state and the events of a run (engine/events.hpp finds them).
#pragma once
#include <string>
#include <vector>

namespace shotlab {

enum class Motion { Stationary, Spinning, Rolling, Sliding, Airborne, Pocketed };
const char* motion_name(Motion m);

struct Event {
  double time;                      // s
  std::string kind;                 // contact_begin, contact_end, sliding, rolling, spinning, stopped, airborne,
                                    // landed, pocketed, off_table, miscue
  std::vector<std::string> bodies;  // ball ids and collider names
};

}  // namespace shotlab
