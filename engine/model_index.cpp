#include "model_index.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <string>

#include "numerics.hpp"

namespace shotlab {

namespace {

// The height (m) of a plane-like shape if it is a level floor over the column: normal exactly up, a bounded plane
// spanned by level edges and covering the column (its four corners do: the region is convex); NaN for any other
// shape. The column is cleared of each hole's square. Over what is left, Probe::surface reduces to depth =
// r - (p.y - y) and normal up, exactly: the dot product with (0, 1, 0) adds two zeros.
double level_floor(const Shape& shape, ColumnXZ& column) {
  constexpr double no = std::numeric_limits<double>::quiet_NaN();
  const std::vector<Hole>* holes = nullptr;
  double y = no;
  if (const auto* s = std::get_if<Plane>(&shape)) {
    if (s->normal != kUp) return no;
    holes = &s->holes, y = s->point.y;
  } else if (const auto* s = std::get_if<BoundedPlane>(&shape)) {
    if (s->normal != kUp || s->u.y != 0 || s->v.y != 0) return no;
    for (const double x : {column.lo_x, column.hi_x})
      for (const double z : {column.lo_z, column.hi_z}) {
        const Vec3 d = Vec3{x, s->origin.y, z} - s->origin;
        const double du = glm::dot(d, s->u), dv = glm::dot(d, s->v);
        if (du <= 0 || du >= s->uu || dv <= 0 || dv >= s->vv) return no;
      }
    holes = &s->holes, y = s->origin.y;
  } else {
    return no;
  }
  for (const Hole& h : *holes) column.exclude(h.center - h.radius, h.center + h.radius);
  return y;
}

Vec3 plane_normal_of(const Shape& shape) {
  if (const auto* s = std::get_if<Plane>(&shape)) return s->normal;
  if (const auto* s = std::get_if<BoundedPlane>(&shape)) return s->normal;
  return Vec3{0.0};
}

}  // namespace

void ColumnXZ::exclude(const Vec3& lo, const Vec3& hi) {
  if (hi.x <= lo_x || lo.x >= hi_x || hi.z <= lo_z || lo.z >= hi_z) return;
  const double w = hi_x - lo_x, d = hi_z - lo_z;
  const double keep[4] = {(hi_x - hi.x) * d, (lo.x - lo_x) * d, (hi_z - hi.z) * w, (lo.z - lo_z) * w};
  switch (std::max_element(keep, keep + 4) - keep) {
    case 0: lo_x = hi.x; break;
    case 1: hi_x = lo.x; break;
    case 2: lo_z = hi.z; break;
    default: hi_z = lo.z;
  }
}

ModelIndex::ModelIndex(const Model& model)
    : gravity(glm::length(model.options.gravity)),
      gravity_across(std::hypot(model.options.gravity.x, model.options.gravity.z)) {
  std::map<std::string, int> resolved;
  auto resolve = [&](const std::string& name) {
    const auto [it, added] = resolved.emplace(name, static_cast<int>(materials.size()));
    if (added) materials.push_back(model.material(name));
    return it->second;
  };
  ball_ball_material = resolve(kBallBall);
  for (const Collider& c : model.colliders) {
    material_of.push_back(resolve(c.material));
    collider_bounds.push_back(bounds(c.shape));
    plane_normal.push_back(plane_normal_of(c.shape));
  }
  // The clear column: the span of the other colliders' bounds, cleared of each of them in the order of the model.
  bool any = false;
  for (size_t c = 0; c < model.colliders.size(); ++c) {
    if (plane_normal[c] != Vec3{0.0}) {
      plane_like.push_back(static_cast<int>(c));
      continue;
    }
    others.push_back(static_cast<int>(c));
    const Bounds& b = collider_bounds[c];
    if (!any) clear = {b.lo.x, b.hi.x, b.lo.z, b.hi.z}, any = true;
    clear.lo_x = std::min(clear.lo_x, b.lo.x), clear.hi_x = std::max(clear.hi_x, b.hi.x);
    clear.lo_z = std::min(clear.lo_z, b.lo.z), clear.hi_z = std::max(clear.hi_z, b.hi.z);
  }
  std::vector<Bounds> others_bounds;
  for (int c : others) {
    clear.exclude(collider_bounds[c].lo, collider_bounds[c].hi);
    others_bounds.push_back(collider_bounds[c]);
  }
  grid.build(others_bounds);
  floor_of.assign(model.colliders.size(), -1);
  for (size_t k = 0; k < plane_like.size(); ++k) floor_of[plane_like[k]] = static_cast<int>(k);
  // A bounded plane's floor is worked out over its own extent (inset by kFloorInset: level_floor wants the corners
  // strictly inside), so that a ball near a cushion, outside the clear column, finds the bed the fast way too.
  for (int c : plane_like) {
    const Bounds& b = collider_bounds[c];
    const bool bounded = std::holds_alternative<BoundedPlane>(model.colliders[c].shape);
    floor.push_back(bounded ? ColumnXZ{b.lo.x + kFloorInset, b.hi.x - kFloorInset, b.lo.z + kFloorInset, b.hi.z - kFloorInset} : clear);
    floor_y.push_back(level_floor(model.colliders[c].shape, floor.back()));
    if (std::isnan(floor_y.back())) floor.back() = ColumnXZ{};
  }
  index_balls(model);
}

// About kGridCells cells along the longer side of the colliders' extent (on a pool table, 8 cm cells): a ball's reach
// over a step covers one to four of them.
void ColliderGrid::build(const std::vector<Bounds>& bounds) {
  constexpr double kGridCells = 32;
  *this = ColliderGrid{};
  double hi_x = -std::numeric_limits<double>::infinity(), hi_z = hi_x;
  lo_x_ = lo_z_ = std::numeric_limits<double>::infinity();
  for (const Bounds& b : bounds) {
    if (!std::isfinite(b.lo.x) || !std::isfinite(b.lo.z) || !std::isfinite(b.hi.x) || !std::isfinite(b.hi.z)) return;
    lo_x_ = std::min(lo_x_, b.lo.x), lo_z_ = std::min(lo_z_, b.lo.z);
    hi_x = std::max(hi_x, b.hi.x), hi_z = std::max(hi_z, b.hi.z);
  }
  if (bounds.empty() || !std::isfinite(hi_x - lo_x_) || !std::isfinite(hi_z - lo_z_)) return;
  per_cell_ = kGridCells / std::max({hi_x - lo_x_, hi_z - lo_z_, 1e-3});
  nx_ = static_cast<int>(std::ceil((hi_x - lo_x_) * per_cell_)) + 1;
  nz_ = static_cast<int>(std::ceil((hi_z - lo_z_) * per_cell_)) + 1;
  words_ = static_cast<int>((bounds.size() + 63) / 64);
  mask_.assign(static_cast<size_t>(nx_ * nz_ * words_), 0);
  for (size_t k = 0; k < bounds.size(); ++k) {
    const Bounds& b = bounds[k];
    for (int ix = cell_x(b.lo.x); ix <= cell_x(b.hi.x); ++ix)
      for (int iz = cell_z(b.lo.z); iz <= cell_z(b.hi.z); ++iz)
        mask_[slot(ix, iz, static_cast<int>(k / 64))] |= uint64_t{1} << (k % 64);
  }
}

ModelIndex::ModelIndex(const ModelIndex& scene, const Model& sub) : ModelIndex(scene) {
  index_balls(sub);
}

void ModelIndex::index_balls(const Model& model) {
  inv_mass.clear(), inv_inertia_r2.clear(), inv_inertia.clear();
  max_radius = 0;
  for (const BallSpec& b : model.balls) {
    inv_mass.push_back(1.0 / b.mass);
    inv_inertia_r2.push_back(b.radius * b.radius / b.inertia());
    inv_inertia.push_back(1.0 / b.inertia());
    max_radius = std::max(max_radius, b.radius);
  }
  rods_on.assign(model.balls.size(), 0);
  for (const Rod& rod : model.rods)
    if (rod.ball >= 0 && static_cast<size_t>(rod.ball) < rods_on.size()) ++rods_on[rod.ball];
}

}  // namespace shotlab
