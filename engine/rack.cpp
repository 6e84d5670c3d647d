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

}  // namespace shotlab
