#include "shotlab/rack.hpp"

#include <random>
#include <string>

namespace shotlab {

std::vector<InitialBall> triangle_rack(const RackSpec& spec, const BallKind& kind) {
  std::mt19937 rng(spec.seed);  // mt19937's sequence is fixed by the standard; map it to [-1, 1) by hand
  auto uniform = [&rng] { return static_cast<double>(rng()) / 2147483648.0 - 1.0; };
  const double d = 2 * kind.radius + spec.gap;  // centre distance of neighbours
  std::vector<InitialBall> balls;
  int number = spec.first_number;
  for (int row = 0; row < spec.rows; ++row)
    for (int k = 0; k <= row; ++k) {
      InitialBall b;
      b.spec = {std::to_string(number++), kind.mass, kind.radius};
      // Row `row` lies d*sqrt(3)/2 further along +x; its balls are spread d apart across z.
      b.position = {spec.apex_x + row * d * std::sqrt(3.0) / 2, kind.radius, spec.apex_z + (k - row / 2.0) * d};
      if (spec.jitter > 0) {
        b.position.x += spec.jitter * kind.radius * uniform();
        b.position.z += spec.jitter * kind.radius * uniform();
      }
      balls.push_back(b);
    }
  return balls;
}

// The spots of a 12 ft table (WPBSA): the baulk line 737 mm from the bottom cushion's nose, the D's radius 292 mm,
// the black 324 mm from the top cushion, the pink midway between the blue (the centre) and the top cushion; scaled to
// the table's length for smaller tables.
std::vector<InitialBall> snooker_rack(const RackSpec& spec, const BallKind& kind) {
  const double scale = spec.table_length / 3.569, half = spec.table_length / 2, r = kind.radius;
  const double baulk = -half + 0.737 * scale, d = 0.292 * scale;
  const std::pair<const char*, Vec3> colours[] = {
      {"yellow", {baulk, r, d}},  {"green", {baulk, r, -d}},      {"brown", {baulk, r, 0}},
      {"blue", {0, r, 0}},        {"pink", {half / 2, r, 0}},     {"black", {half - 0.324 * scale, r, 0}}};
  std::vector<InitialBall> balls;
  for (const auto& [id, p] : colours) {
    InitialBall b;
    b.spec = {id, kind.mass, kind.radius};
    b.position = p;
    balls.push_back(b);
  }
  RackSpec reds = spec;
  reds.apex_x = half / 2 + 2 * r + 0.001, reds.apex_z = 0;
  for (InitialBall& b : triangle_rack(reds, kind)) {
    b.spec.id = "red" + std::to_string(std::stoi(b.spec.id) - spec.first_number + 1);
    balls.push_back(std::move(b));
  }
  return balls;
}

std::vector<InitialBall> make_rack(const RackSpec& spec, const BallKind& kind) {
  return spec.type == RackType::Snooker ? snooker_rack(spec, kind) : triangle_rack(spec, kind);
}

}  // namespace shotlab
