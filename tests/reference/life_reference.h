// CPU reference of the life force pass: the O(N^2) brute force over every pair, in double, with
// the same force law and minimum-image rule as shaders/life/forces.comp. It is what the binned
// GPU result is compared against, and the plainest statement of the method.
#pragma once

#include <cmath>
#include <glm/glm.hpp>
#include <vector>

#include "sim/life/life_rules.h"

namespace tidepool::life::reference {

struct ForceSum {
  glm::dvec2 force{0.0};
  double scale = 0;  // sum of |contributions|: the size float rounding is relative to
};

// positions: (x, y, 0, species) as the GPU holds them.
inline std::vector<ForceSum> bruteForce(const Rules& rules, const std::vector<glm::vec4>& positions) {
  const std::vector<Force> table = effectiveForces(rules);
  const int s = rules.speciesCount();
  const glm::dvec2 box(rules.size);
  std::vector<ForceSum> out(positions.size());
  for (std::size_t i = 0; i < positions.size(); ++i) {
    const glm::dvec2 pi(positions[i]);
    ForceSum& sum = out[i];
    sum.force = -double(rules.centralForce) * pi;
    sum.scale = std::abs(rules.centralForce) * glm::length(pi);
    for (std::size_t j = 0; j < positions.size(); ++j) {
      if (j == i) continue;
      glm::dvec2 r = glm::dvec2(positions[j]) - pi;
      if (rules.loopingBorders) r -= box * glm::round(r / box);
      const double d = glm::length(r);
      const Force& f = table[std::size_t(positions[i].w) * s + std::size_t(positions[j].w)];
      if (!(d > 0 && d < f.radius)) continue;
      const double attraction = f.strength * std::max(0.0, 1.0 - d / f.radius);
      const double collision =
          f.collisionRadius > 0 ? f.collisionStrength * std::max(0.0, 1.0 - d / f.collisionRadius) : 0.0;
      sum.force += (attraction - collision) * (r / d);
      sum.scale += std::abs(attraction) + std::abs(collision);
    }
  }
  return out;
}

}  // namespace tidepool::life::reference
