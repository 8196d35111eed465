#include "sim/fluid/rest_lattice.h"

#include <cmath>
#include <unordered_map>

#include "sim/fluid/sph_kernels.h"
#include "sim/water/water_init.h"

namespace tidepool::fluid {

RestLattice restLattice(double spacing, double h, Packing packing) {
  const float d = float(spacing), reach = float(h) + 3.0f * d;
  std::vector<glm::vec3> lattice;
  if (packing == Packing::Hcp) {
    lattice = water::hcpLattice(glm::vec3(-reach), glm::vec3(reach), 0.5f * d);
  } else {
    const int n = int(std::ceil(reach / d));
    for (int k = -n; k <= n; ++k)
      for (int j = -n; j <= n; ++j)
        for (int i = -n; i <= n; ++i) lattice.emplace_back(float(i) * d, float(j) * d, float(k) * d);
  }
  glm::dvec3 centre(0.0);
  double best = 1e30;
  for (const glm::vec3& q : lattice)  // the lattice point nearest the middle
    if (double r = glm::length(glm::dvec3(q)); r < best) {
      best = r;
      centre = glm::dvec3(q);
    }
  double sum = 0;
  for (const glm::vec3& q : lattice) sum += poly6(glm::dot(glm::dvec3(q) - centre, glm::dvec3(q) - centre), h);
  RestLattice rest;
  rest.volume = 1.0 / sum;
  for (const glm::vec3& q : lattice) {
    const glm::dvec3 g = rest.volume * spikyGradient(centre - glm::dvec3(q), h);
    rest.gradients += glm::dot(g, g);
  }
  // The same particle as the first layer over a wall half a spacing below it: its own layer and
  // those above, and the wall.
  double half = 0;
  for (const glm::vec3& q : lattice)
    if (double(q.z) >= centre.z - 1e-6 * spacing)
      half += rest.volume * poly6(glm::dot(glm::dvec3(q) - centre, glm::dvec3(q) - centre), h);
  rest.wallScale = (1.0 - half) / wallDensity(0.5 * spacing, h);
  return rest;
}

std::vector<float> boundaryVolumes(const std::vector<glm::vec4>& particles, bool shell, double h, double solidVolume) {
  std::vector<float> volume(particles.size(), float(solidVolume));
  if (!shell || particles.empty()) return volume;
  // A hash of cells of size h: each particle's neighbours are in the 27 cells around it.
  auto cellOf = [h](const glm::vec4& p) { return glm::ivec3(glm::floor(glm::dvec3(glm::vec3(p)) / h)); };
  auto key = [](glm::ivec3 c) {
    return (std::int64_t(c.x) & 0x1fffff) | ((std::int64_t(c.y) & 0x1fffff) << 21) |
           ((std::int64_t(c.z) & 0x1fffff) << 42);
  };
  std::unordered_map<std::int64_t, std::vector<std::size_t>> cells;
  for (std::size_t i = 0; i < particles.size(); ++i) cells[key(cellOf(particles[i]))].push_back(i);
  for (std::size_t i = 0; i < particles.size(); ++i) {
    const glm::ivec3 c = cellOf(particles[i]);
    const glm::dvec3 p{glm::vec3(particles[i])};  // braces: clang reads p(...) as a function
    double sum = 0;
    for (int dz = -1; dz <= 1; ++dz)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const auto it = cells.find(key(c + glm::ivec3(dx, dy, dz)));
          if (it == cells.end()) continue;
          for (std::size_t j : it->second) {
            const glm::dvec3 r = p - glm::dvec3(glm::vec3(particles[j]));
            sum += poly6(glm::dot(r, r), h);
          }
        }
    volume[i] = float(1.0 / sum);  // sum > 0: the particle itself
  }
  return volume;
}

}  // namespace tidepool::fluid
