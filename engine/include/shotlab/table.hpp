// Tables built from the generic colliders: a bed (bounded plane at y = 0 with pocket holes), cushions as capsules
// along the rails at the nose height, pocket jaws as capsules. The playing surface is centred on the origin:
// x along the length, z along the width, y up.
#pragma once
#include "shotlab/model.hpp"

namespace shotlab {

enum class TableKind { Pool, Carom, Snooker };

struct TableSpec {
  TableKind kind = TableKind::Pool;
  double length = 2.54;          // m, between cushion noses (9 ft pool)
  double width = 1.27;           // m
  double nose_height = 0.0365;   // m above the bed where a resting ball touches the cushion: 63.9 % of a 57.15 mm
                                 // ball (WPA: 62.5-64.5 %)
  double ball_radius = 0.028575; // m, of the resting ball nose_height is measured with (the table's own balls)
  double cushion_radius = 0.01;  // m, radius of the capsule that models the rubber nose
  double corner_mouth = 0.116;   // m, pool only: opening between the cushion ends of a corner pocket
  double side_mouth = 0.13;      // m, pool only: opening of a side pocket
  double pocket_radius = 0.065;  // m, pool only: radius of the hole in the bed
  double pocket_shelf = 0.02;    // m, pool only: from the mouth (line between the cushion ends) to the hole's edge
  double jaw_length = 0.04;      // m, pool only: the facings, from each cushion end straight away from the table
  double rail_width = 0.1;       // m, bed beyond the noses (a ball that jumps the rail falls off past it)
};

// Standard specifications.
TableSpec pool_table();   // 9 ft pool: 2.54 x 1.27 m, six pockets
TableSpec carom_table();  // match carom: 2.84 x 1.42 m, no pockets, nose at 63.5 % of a 61.5 mm ball
TableSpec snooker_table();  // 12 ft snooker: 3.569 x 1.778 m, six pockets (WPBSA template)
const char* table_kind_name(TableKind kind);  // "pool", "carom", "snooker"
bool has_pockets(TableKind kind);

// Where a cushion capsule's axis lies from the nose line at bed level, in m: `up`, and `out` away from the table. A
// resting ball of ball_radius then touches the capsule at nose_height, on the nose line (docs/model.md#table).
struct NoseAxis {
  double up, out;
};
NoseAxis nose_axis(const TableSpec& spec);

// m above the bed: the top of the rails and of the pockets' backs, 4 mm over the cushion rubber's.
double rail_top(const TableSpec& spec);

// Sets the cloth (ball_cloth) and cushion (ball_cushion) a table type comes with, from measurements of that game
// (docs/model.md#parameters): pool the defaults; snooker Mathavan et al.'s cloth and cushion; carom a slow-rolling
// heated cloth and a livelier cushion. Tables with pockets also get the pockets' backs (ball_pocket).
void set_table_materials(TableKind kind, Model& model);
// N s/m: the snooker cushion's damping for restitution 0.98 at 1 m/s (a 0.1406 kg ball), the carom cushion's for 0.9
// (0.21 kg), both at the default cushion stiffness.
inline constexpr double kSnookerCushionDamping = 3.4624482939371672, kCaromCushionDamping = 23.632250567796799;

// Appends the table's colliders and pockets to the model: the bed (ball_cloth), the cushions and jaws (ball_cushion)
// and, last, each pocket's back (ball_pocket, added to the materials unless the model has it; docs/model.md#pockets).
void add_table(Model& model, const TableSpec& spec);

}  // namespace shotlab
