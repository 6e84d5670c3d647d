// Measured shots: ball centres tracked on a real table, as CSV rows `time,ball,x,z` (s, m; origin at the table's
// centre, x along its length, z across; docs/fit.md). What `shotlab fit` fits the model to.
#pragma once
#include <map>
#include <string>
#include <vector>

namespace shotlab {

struct MeasuredSample {
  double t, x, z;  // s, m, m
};

struct MeasuredShot {
  std::string name;                 // the file's name without folder and extension
  std::vector<std::string> balls;   // in the order they first appear
  std::map<std::string, std::vector<MeasuredSample>> tracks;  // per ball, in time order
  std::string cue_ball;             // the ball that moves first (more than kFirstMove from its first sample)
  double first_move = 0;            // s: the time of the cue ball's first moved sample
};

inline constexpr double kFirstMove = 0.005;  // m: a ball has moved once it is this far from where it was first seen

// Reads a measured shot: columns time, ball, x and z by the header's names, in any order among others (a trajectory
// that `shotlab run --trajectory` wrote reads as one). Throws InputError naming the file, the line and the field: a
// header without those columns, a row of another length, a number that is not one, time going backwards for a ball,
// fewer than two balls, no ball that moves.
MeasuredShot read_measured(const std::string& path);
// The same from CSV text; `source` names it in messages.
MeasuredShot parse_measured(const std::string& text, const std::string& source);

}  // namespace shotlab
