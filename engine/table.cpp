#include "table.hpp"

#include <array>
#include <string>

namespace shotlab {

TableSpec pool_table() { return TableSpec{}; }

TableSpec carom_table() {
  TableSpec t;
  t.kind = TableKind::Carom;
  t.length = 2.84;
  t.width = 1.42;
  t.nose_height = 0.635 * 0.0615;
  return t;
}

namespace {

Vec3 at(double x, double z, double y = 0.0) { return {x, y, z}; }

// Capsule whose surface nearest the table reaches the nose line: the axis is set back by its radius.
void add_cushion(Model& m, const std::string& name, const Vec3& a, const Vec3& b, const Vec3& outward, const TableSpec& t) {
  const Vec3 lift{0.0, t.nose_height, 0.0};
  m.colliders.push_back({name, Capsule{a + lift + t.cushion_radius * outward, b + lift + t.cushion_radius * outward,
                                       t.cushion_radius},
                         kBallCushion});
}

// Jaw: from a cushion end to the edge of the pocket hole, so that a ball can strike the pocket's facing.
void add_jaw(Model& m, const std::string& name, const Vec3& end, const Vec3& outward, const Pocket& p, const TableSpec& t) {
  const Vec3 a = end + t.cushion_radius * outward;
  Vec3 towards = a - p.center;
  towards.y = 0;
  const double dist = glm::length(towards);
  if (dist <= p.radius) return;
  const Vec3 b = p.center + towards * (p.radius / dist);
  const Vec3 lift{0.0, t.nose_height, 0.0};
  m.colliders.push_back({name, Capsule{a + lift, Vec3{b.x, 0.0, b.z} + lift, t.cushion_radius}, kBallCushion});
}

}  // namespace

void add_table(Model& m, const TableSpec& t) {
  const double hx = t.length / 2, hz = t.width / 2, rw = t.rail_width;
  const bool pool = t.kind == TableKind::Pool;
  std::vector<Hole> holes;
  if (pool) {
    // Corner pockets sit diagonally outside the corners, side pockets just beyond the long rails.
    const double c = t.corner_mouth / std::sqrt(2.0) / 2;  // corner hole centre offset beyond each nose line
    const std::array<std::pair<std::string, Vec3>, 6> centres{{{"pocket-left-back", at(-hx - c, -hz - c)},
                                                               {"pocket-right-back", at(hx + c, -hz - c)},
                                                               {"pocket-left-front", at(-hx - c, hz + c)},
                                                               {"pocket-right-front", at(hx + c, hz + c)},
                                                               {"pocket-side-back", at(0, -hz - t.pocket_radius / 2)},
                                                               {"pocket-side-front", at(0, hz + t.pocket_radius / 2)}}};
    for (const auto& [name, centre] : centres) {
      m.pockets.push_back({name, centre, t.pocket_radius});
      holes.push_back({centre, t.pocket_radius});
    }
  }
  // The bed reaches rail_width beyond the noses; past it a ball falls off the table.
  m.colliders.push_back({"bed",
                         BoundedPlane{at(-hx - rw, hz + rw), Vec3{t.length + 2 * rw, 0, 0}, Vec3{0, 0, -(t.width + 2 * rw)},
                                      holes},
                         kBallCloth});

  // Cushions: along each rail between pocket mouths. Corner cushion ends sit corner_mouth/sqrt(2) from the corner.
  const double ce = pool ? t.corner_mouth / std::sqrt(2.0) : 0.0;
  const double se = pool ? t.side_mouth / 2 : 0.0;
  const Vec3 back{0, 0, -1}, front{0, 0, 1}, left{-1, 0, 0}, right{1, 0, 0};
  struct Rail {
    std::string name;
    Vec3 a, b, outward;
    int pocket_a, pocket_b;  // pockets at each end (-1: none)
  };
  std::vector<Rail> rails;
  if (pool) {
    rails = {{"cushion-back-left", at(-hx + ce, -hz), at(-se, -hz), back, 0, 4},
             {"cushion-back-right", at(se, -hz), at(hx - ce, -hz), back, 4, 1},
             {"cushion-front-left", at(-hx + ce, hz), at(-se, hz), front, 2, 5},
             {"cushion-front-right", at(se, hz), at(hx - ce, hz), front, 5, 3},
             {"cushion-left", at(-hx, -hz + ce), at(-hx, hz - ce), left, 0, 2},
             {"cushion-right", at(hx, -hz + ce), at(hx, hz - ce), right, 1, 3}};
  } else {
    // Carom: closed rectangle; the capsules overlap at the corners so that a corner has no gap.
    rails = {{"cushion-back", at(-hx, -hz), at(hx, -hz), back, -1, -1},
             {"cushion-front", at(-hx, hz), at(hx, hz), front, -1, -1},
             {"cushion-left", at(-hx, -hz), at(-hx, hz), left, -1, -1},
             {"cushion-right", at(hx, -hz), at(hx, hz), right, -1, -1}};
  }
  for (const Rail& r : rails) {
    add_cushion(m, r.name, r.a, r.b, r.outward, t);
    if (r.pocket_a >= 0) add_jaw(m, r.name + "-jaw-a", r.a, r.outward, m.pockets[r.pocket_a], t);
    if (r.pocket_b >= 0) add_jaw(m, r.name + "-jaw-b", r.b, r.outward, m.pockets[r.pocket_b], t);
  }
}

}  // namespace shotlab
