#include "sim/water/cell_load.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <vector>

#include "sim/water/particle_water.h"

namespace tidepool::water {

std::size_t mostInOneCube(std::span<const glm::vec4> positions, float radius) {
  const double inv = 1.0 / (2.0 * double(radius));
  std::vector<std::uint64_t> cubes;
  cubes.reserve(positions.size());
  for (const glm::vec4& p :
       positions) {  // 21 bits an axis, wrapping: distinct far cubes may share a key (more, never fewer)
    const auto axis = [&](float x) { return std::uint64_t(std::int64_t(std::floor(double(x) * inv))) & 0x1FFFFF; };
    cubes.push_back(axis(p.x) | axis(p.y) << 21 | axis(p.z) << 42);
  }
  std::sort(cubes.begin(), cubes.end());
  std::size_t most = 0;
  for (std::size_t i = 0, j = 0; i < cubes.size(); i = j) {
    while (j < cubes.size() && cubes[j] == cubes[i]) ++j;
    most = std::max(most, j - i);
  }
  return most;
}

std::optional<std::string> overcrowded(const ParticleWater& water) {
  const std::size_t n = water.count();
  if (n <= kMaxPerDiameterCube) return std::nullopt;
  const std::vector<glm::vec4> positions = water.positions().read<glm::vec4>(n);
  const std::size_t most = mostInOneCube(positions, water.radius());
  if (most <= kMaxPerDiameterCube) return std::nullopt;
  char what[200];
  std::snprintf(what, sizeof what,
                "%zu particles in one cube of edge 2r = %.3g m, at most %zu (water at rest packs 1.41)", most,
                2.0 * double(water.radius()), kMaxPerDiameterCube);
  return what;
}

}  // namespace tidepool::water
