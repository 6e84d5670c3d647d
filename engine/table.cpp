#include "shotlab/table.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <string>

namespace shotlab {

TableSpec pool_table() { return TableSpec{}; }

TableSpec carom_table() {
  TableSpec t;
  t.kind = TableKind::Carom;
  t.length = 2.84;
  t.width = 1.42;
  t.nose_height = 0.635 * 0.0615;
  t.ball_radius = 0.0615 / 2;
  return t;
}

// The WPBSA rules fix the playing area and the spots (rack.cpp); their pocket templates are not published, so the
// openings here are typical values. The cushion contact height is Mathavan et al.'s 7R/5.
TableSpec snooker_table() {
  TableSpec t;
  t.kind = TableKind::Snooker;
  t.length = 3.569;
  t.width = 1.778;
  t.ball_radius = 0.02625;
  t.nose_height = 1.4 * t.ball_radius;
  t.corner_mouth = 0.086;
  t.side_mouth = 0.105;
  t.pocket_radius = 0.05;
  return t;
}

// The cushions' damping is the restitution wanted at 1 m/s worked out once (restitution.hpp, damping_for_restitution,
// for the table's ball against the default cushion stiffness); tests/engine/measured_test.cpp checks it still is.
void set_table_materials(TableKind kind, Model& m) {
  ContactMaterial cloth = default_ball_cloth(), cushion = default_ball_cushion();
  if (kind == TableKind::Snooker) {
    cloth.friction = 0.212, cloth.rolling_resistance = 0.0128;  // Mathavan et al. 2009/2010
    cushion.friction = 0.14, cushion.damping = kSnookerCushionDamping;  // restitution 0.98
  } else if (kind == TableKind::Carom) {
    cloth.rolling_resistance = 0.0046;  // straight runs of real three-cushion shots decelerate at 0.045 m/s^2
    cushion.damping = kCaromCushionDamping;  // restitution 0.9: gives back 0.76-0.82 of the normal speed, 0.25-3 m/s
  }
  m.materials[kBallCloth] = cloth;
  m.materials[kBallCushion] = cushion;
  if (has_pockets(kind)) m.materials[kBallPocket] = default_ball_pocket();
}

const char* table_kind_name(TableKind kind) {
  return kind == TableKind::Pool ? "pool" : kind == TableKind::Carom ? "carom" : "snooker";
}

bool has_pockets(TableKind kind) { return kind != TableKind::Carom; }

namespace {

Vec3 at(double x, double z, double y = 0.0) { return {x, y, z}; }

// The capsule's axis point over a point of the nose line on the bed.
Vec3 axis_point(const Vec3& on_nose_line, const Vec3& outward, const TableSpec& t) {
  const NoseAxis n = nose_axis(t);
  return on_nose_line + Vec3{0.0, n.up, 0.0} + n.out * outward;
}

void add_cushion(Model& m, const std::string& name, const Vec3& a, const Vec3& b, const Vec3& outward, const TableSpec& t) {
  m.colliders.push_back({name, Capsule{axis_point(a, outward, t), axis_point(b, outward, t), t.cushion_radius}, kBallCushion});
}

// Jaw (pocket facing): from a cushion end straight away from the table, so that a ball can strike the facing.
void add_jaw(Model& m, const std::string& name, const Vec3& end, const Vec3& outward, const TableSpec& t) {
  const Vec3 a = axis_point(end, outward, t);  // the cushion capsule's end
  m.colliders.push_back({name, Capsule{a, a + t.jaw_length * outward, t.cushion_radius}, kBallCushion});
}

// The wall around a pocket's hole (docs/model.md#pockets): the rail's lined body, from below the lowest ball still in
// play (one leaves once its centre is a radius below the bed) up to the rail's top. It leaves open the arc that faces
// the mouth: the rays from the hole's centre to the cushion ends (the mouth's half width `half_mouth`, the hole's
// centre `beyond` past the mouth's middle), widened on each side by the arc a ball's radius spans on the rim and 5
// degrees more, so that a ball coming through the mouth at bed level meets neither the wall nor its ends before it is
// over the hole. None if that leaves no wall.
void add_pocket_back(std::vector<Collider>& backs, const Pocket& pocket, const Vec3& outward, double half_mouth,
                     double beyond, const TableSpec& t) {
  constexpr double kBackThickness = 0.02;  // m
  const double ball_arc = 2 * std::asin(std::min(1.0, t.ball_radius / (2 * pocket.radius)));
  const double half_angle = std::numbers::pi - std::atan2(half_mouth, beyond) - ball_arc - 5.0 * std::numbers::pi / 180;
  if (half_angle <= 0) return;
  backs.push_back({pocket.name + "-back",
                   ArcWall{pocket.center, pocket.radius, kBackThickness, outward, half_angle, -3 * t.ball_radius,
                           rail_top(t)},
                   kBallPocket});
}

// The six pockets, their holes in the bed and their backs. A ball drops once its centre is over the hole, i.e.
// pocket_shelf beyond the mouth. Corner mouths run diagonally with their midpoint corner_mouth/(2 sqrt 2) inside the
// corner along each axis; the hole centre lies shelf + radius beyond it along the diagonal. Side mouths lie on the
// nose line.
std::vector<Collider> add_pockets(Model& m, const TableSpec& t, std::vector<Hole>& holes) {
  m.materials.emplace(kBallPocket, default_ball_pocket());  // kept when set_table_materials set it or a scene did
  const double hx = t.length / 2, hz = t.width / 2, beyond = t.pocket_shelf + t.pocket_radius;
  const double c = (beyond - t.corner_mouth / 2) / std::sqrt(2.0);  // corner hole centre beyond each nose line
  const double d = 1 / std::sqrt(2.0);
  struct Mouth {
    std::string name;
    Vec3 centre, outward;
    double half_width;
  };
  const std::array<Mouth, 6> mouths{{{"pocket-left-back", at(-hx - c, -hz - c), at(-d, -d), t.corner_mouth / 2},
                                     {"pocket-right-back", at(hx + c, -hz - c), at(d, -d), t.corner_mouth / 2},
                                     {"pocket-left-front", at(-hx - c, hz + c), at(-d, d), t.corner_mouth / 2},
                                     {"pocket-right-front", at(hx + c, hz + c), at(d, d), t.corner_mouth / 2},
                                     {"pocket-side-back", at(0, -hz - beyond), at(0, -1), t.side_mouth / 2},
                                     {"pocket-side-front", at(0, hz + beyond), at(0, 1), t.side_mouth / 2}}};
  std::vector<Collider> backs;
  for (const Mouth& mouth : mouths) {
    m.pockets.push_back({mouth.name, mouth.centre, t.pocket_radius});
    holes.push_back({mouth.centre, t.pocket_radius});
    add_pocket_back(backs, m.pockets.back(), mouth.outward, mouth.half_width, beyond, t);
  }
  return backs;
}

}  // namespace

double rail_top(const TableSpec& t) { return t.nose_height + t.cushion_radius + 0.004; }

// The resting ball's centre (height R), its contact point (height h) and the capsule's axis lie on one line, tilted
// by asin((h - R) / R) above the horizontal; the contact point is on the nose line.
NoseAxis nose_axis(const TableSpec& t) {
  const double tilt_sin = (t.nose_height - t.ball_radius) / t.ball_radius;
  const double tilt_cos = std::sqrt(std::max(0.0, 1 - tilt_sin * tilt_sin));
  return {t.nose_height + t.cushion_radius * tilt_sin, t.cushion_radius * tilt_cos};
}

void add_table(Model& m, const TableSpec& t) {
  const double hx = t.length / 2, hz = t.width / 2, rw = t.rail_width;
  const bool pockets = has_pockets(t.kind);
  m.balls_leave_below_bed = true;
  std::vector<Hole> holes;
  const std::vector<Collider> backs = pockets ? add_pockets(m, t, holes) : std::vector<Collider>{};  // appended last
  // The bed reaches rail_width beyond the noses; past it a ball falls off the table.
  m.colliders.push_back({"bed",
                         BoundedPlane{at(-hx - rw, hz + rw), Vec3{t.length + 2 * rw, 0, 0}, Vec3{0, 0, -(t.width + 2 * rw)},
                                      holes},
                         kBallCloth});

  // Cushions: along each rail between pocket mouths. Corner cushion ends sit corner_mouth/sqrt(2) from the corner.
  const double ce = pockets ? t.corner_mouth / std::sqrt(2.0) : 0.0;
  const double se = pockets ? t.side_mouth / 2 : 0.0;
  const Vec3 back{0, 0, -1}, front{0, 0, 1}, left{-1, 0, 0}, right{1, 0, 0};
  struct Rail {
    std::string name;
    Vec3 a, b, outward;
    bool has_pockets;  // a pocket mouth at each end
  };
  std::vector<Rail> rails;
  if (pockets) {
    rails = {{"cushion-back-left", at(-hx + ce, -hz), at(-se, -hz), back, true},
             {"cushion-back-right", at(se, -hz), at(hx - ce, -hz), back, true},
             {"cushion-front-left", at(-hx + ce, hz), at(-se, hz), front, true},
             {"cushion-front-right", at(se, hz), at(hx - ce, hz), front, true},
             {"cushion-left", at(-hx, -hz + ce), at(-hx, hz - ce), left, true},
             {"cushion-right", at(hx, -hz + ce), at(hx, hz - ce), right, true}};
  } else {
    // Carom: closed rectangle; the capsules overlap at the corners so that a corner has no gap.
    rails = {{"cushion-back", at(-hx, -hz), at(hx, -hz), back, false},
             {"cushion-front", at(-hx, hz), at(hx, hz), front, false},
             {"cushion-left", at(-hx, -hz), at(-hx, hz), left, false},
             {"cushion-right", at(hx, -hz), at(hx, hz), right, false}};
  }
  for (const Rail& r : rails) {
    add_cushion(m, r.name, r.a, r.b, r.outward, t);
    if (r.has_pockets) {
      add_jaw(m, r.name + "-jaw-a", r.a, r.outward, t);
      add_jaw(m, r.name + "-jaw-b", r.b, r.outward, t);
    }
  }
  m.colliders.insert(m.colliders.end(), backs.begin(), backs.end());
}

}  // namespace shotlab
