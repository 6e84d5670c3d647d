// What the contact code looks up in a Model, resolved once (docs/model.md#colliders): each collider's material as an
// index, the colliders' bounds and level floors, each ball's mobilities. Immutable once built; the stepping shares it
// by const reference, so no material is looked up by its name while the engine runs.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <vector>

#include "shotlab/colliders.hpp"
#include "shotlab/material.hpp"
#include "shotlab/model.hpp"
#include "shotlab/vec.hpp"

namespace shotlab {

// A vertical column over the rectangle lo < x < hi, lo < z < hi (m) of the table's plane; empty when lo >= hi.
struct ColumnXZ {
  double lo_x = 0, hi_x = 0, lo_z = 0, hi_z = 0;
  // Whether a ball at p with the given reach (m) lies inside, all of it.
  bool holds(const Vec3& p, double reach) const {
    return p.x - reach > lo_x && p.x + reach < hi_x && p.z - reach > lo_z && p.z + reach < hi_z;
  }
  // Greedily clear of the box [lo, hi] (its x-z extent): if the box reaches in, move the one edge that keeps the
  // most area (a cushion along an edge costs a strip of its width).
  void exclude(const Vec3& lo, const Vec3& hi);
};

// Colliders by where they lie: a grid of cells over the x-z extent of their bounds, each cell a set of bits, bit k
// for the k-th collider whose bounds reach into it. A ball near the cushions is probed against the colliders of the
// few cells its reach covers, not against all of them.
class ColliderGrid {
 public:
  // Over the given colliders' bounds (none: no grid, nor where a bound is not finite).
  void build(const std::vector<Bounds>& bounds);
  // Visits, in ascending order, every k whose bounds' x-z extent may come within `reach` (m) of p: a superset of those
  // Bounds::may_touch(p, reach) accepts. False, having visited none, where there is no grid, p or the reach is not
  // finite, the reach is negative or it covers more than kMostCells cells: the caller then probes every collider.
  template <class Fn>
  bool visit(const Vec3& p, double reach, Fn&& fn) const;
  bool built() const { return !mask_.empty(); }
  int words() const { return words_; }

  static constexpr int kMostCells = 16;

 private:
  int cell_x(double x) const { return cell(x, lo_x_, nx_); }
  int cell_z(double z) const { return cell(z, lo_z_, nz_); }
  int cell(double at, double lo, int n) const {
    return static_cast<int>(std::clamp(std::floor((at - lo) * per_cell_), 0.0, n - 1.0));
  }
  // Where cell (ix, iz) keeps its w-th mask word in mask_.
  size_t slot(int ix, int iz, int w) const { return static_cast<size_t>((ix * nz_ + iz) * words_ + w); }

  double lo_x_ = 0, lo_z_ = 0, per_cell_ = 0;  // m, m, cells per m
  int nx_ = 0, nz_ = 0, words_ = 0;            // words_: 64-bit masks per cell
  std::vector<uint64_t> mask_;
};

struct ModelIndex {
  // Resolves the model's material names: the one place they are looked up.
  explicit ModelIndex(const Model& model);
  // The index of `sub`, a model with the colliders and materials of `scene`'s model and balls of its own (an island):
  // the collider tables are taken over, the balls' mobilities worked out anew.
  ModelIndex(const ModelIndex& scene, const Model& sub);

  const ContactMaterial& collider_material(int c) const { return materials[material_of[c]]; }
  const ContactMaterial& ball_ball() const { return materials[ball_ball_material]; }

  std::vector<ContactMaterial> materials;  // the materials the colliders and the balls use, each once
  std::vector<int> material_of;            // each collider's material, an index into materials
  int ball_ball_material = 0;
  std::vector<Bounds> collider_bounds;     // broad phase against static colliders
  std::vector<Vec3> plane_normal;          // unit normal of each plane-like collider (Plane, BoundedPlane), else 0
  // A vertical column that no collider other than the plane-like ones reaches: a ball inside it is probed against
  // the plane-like colliders alone (on a table, the bed; the cushions and jaws line the edges).
  std::vector<int> plane_like;
  std::vector<int> others;  // the other colliders, in the order of the model
  ColliderGrid grid;        // of others: bit k for others[k]
  ColumnXZ clear;
  // For each plane-like collider (in the order of plane_like), a column over which it is a level floor (normal exactly
  // up) with no edge and no hole, at height floor_y (m; NaN and an empty column where it is none): a ball whose centre
  // is over it is probed with one subtraction instead of the shape's test of its extent and its holes.
  std::vector<ColumnXZ> floor;
  std::vector<double> floor_y;
  std::vector<int> floor_of;  // each collider's index in plane_like (and floor), or -1
  double gravity = 0;         // m/s^2, |g|: the step caps and the regimes' right-hand sides want it for every ball
  double gravity_across = 0;  // m/s^2, g's horizontal part (0 unless gravity is tilted): a flying ball's only one
  // Each ball's mobilities (contact_force.hpp): 1/m (1/kg) and r^2/I (1/kg), and 1/I (1/(kg m^2)), by which the
  // right-hand sides multiply its force and torque (a multiplication costs a fraction of a division); the largest
  // radius (m).
  std::vector<double> inv_mass, inv_inertia_r2, inv_inertia;
  double max_radius = 0;
  std::vector<int> rods_on;  // how many rods hold each ball

 private:
  void index_balls(const Model& model);
};

// The penetration of a ball (centre p, radius r) into the k-th plane-like collider where its centre is over that
// collider's level floor (ModelIndex::floor): one subtraction, none when the centre is below the floor (a plane is
// one-sided); nullopt when it is not over the floor.
inline std::optional<std::optional<Penetration>> floor_penetration(const ModelIndex& index, size_t k, const Vec3& p,
                                                                   double r) {
  if (!index.floor[k].holds(p, 0.0)) return std::nullopt;
  const double height = p.y - index.floor_y[k];
  return height >= 0 ? std::optional<Penetration>(Penetration{r - height, kUp}) : std::nullopt;
}

template <class Fn>
bool ColliderGrid::visit(const Vec3& p, double reach, Fn&& fn) const {
  if (!built() || !std::isfinite(p.x) || !std::isfinite(p.z) || !(reach >= 0 && std::isfinite(reach))) return false;
  const int x0 = cell_x(p.x - reach), x1 = cell_x(p.x + reach), z0 = cell_z(p.z - reach), z1 = cell_z(p.z + reach);
  if ((x1 - x0 + 1) * (z1 - z0 + 1) > kMostCells) return false;
  for (int w = 0; w < words_; ++w) {
    uint64_t bits = 0;
    for (int ix = x0; ix <= x1; ++ix)
      for (int iz = z0; iz <= z1; ++iz) bits |= mask_[slot(ix, iz, w)];
    // The lowest bit first; not std::countr_zero: this header is also compiled as C++17 (stepper_rosenbrock.cpp).
    for (; bits; bits &= bits - 1) fn(64 * w + __builtin_ctzll(bits));
  }
  return true;
}

}  // namespace shotlab
