#include "sim/life/measure/life_cpu.h"

#include <algorithm>
#include <cmath>
#include <thread>

namespace tidepool::life {
namespace {

// Cells along one axis: at least the largest radius wide, so that the 3x3 block around a
// particle's cell holds every neighbour; with looping, the distinct cells of the wrapped block.
struct Axis {
  int cells = 1;
  double size = 1, origin = 0;
  int cellOf(double x) const { return std::clamp(int(std::floor((x - origin) / size * cells)), 0, cells - 1); }
  std::vector<int> block(int c, bool wrap) const {
    std::vector<int> out;
    for (int d = -1; d <= 1; ++d) {
      int k = c + d;
      if (wrap) k = (k % cells + cells) % cells;
      if (k < 0 || k >= cells || std::find(out.begin(), out.end(), k) != out.end()) continue;
      out.push_back(k);
    }
    return out;
  }
};

Axis axisFor(double size, double reach) {
  return {std::max(1, int(std::floor(size / std::max(reach, 1e-9)))), size, -0.5 * size};
}

template <class Fn>
void parallelFor(std::size_t n, Fn fn) {
  const std::size_t threads = std::clamp<std::size_t>(std::thread::hardware_concurrency(), 1, 64);
  const std::size_t chunk = (n + threads - 1) / threads;
  std::vector<std::thread> pool;
  for (std::size_t begin = 0; begin < n; begin += chunk)
    pool.emplace_back([=] {
      for (std::size_t i = begin; i < std::min(n, begin + chunk); ++i) fn(i);
    });
  for (std::thread& t : pool) t.join();
}

}  // namespace

std::vector<CpuParticle> cpuState(const std::vector<glm::vec4>& positions, const std::vector<glm::vec4>& velocities) {
  std::vector<CpuParticle> out(positions.size());
  for (std::size_t i = 0; i < positions.size(); ++i)
    out[i] = {glm::dvec2(positions[i]), glm::dvec2(velocities[i]), int(positions[i].w)};
  return out;
}

glm::dvec2 cpuBoxDelta(const Rules& rules, glm::dvec2 a, glm::dvec2 b) {
  glm::dvec2 d = b - a;
  if (rules.loopingBorders) d -= glm::dvec2(rules.size) * glm::round(d / glm::dvec2(rules.size));
  return d;
}

std::vector<CpuForce> cpuForces(const Rules& rules, const std::vector<CpuParticle>& particles) {
  const std::vector<Force> table = effectiveForces(rules);
  const int s = rules.speciesCount();
  const double reach = rules.maxRadius();
  const Axis ax = axisFor(rules.size.x, reach), ay = axisFor(rules.size.y, reach);
  // Cell list: particle indices sorted by cell, cellStart as in the GPU grid.
  std::vector<int> cellOf(particles.size());
  std::vector<std::size_t> cellStart(std::size_t(ax.cells) * ay.cells + 1, 0);
  for (std::size_t i = 0; i < particles.size(); ++i) {
    cellOf[i] = ay.cellOf(particles[i].pos.y) * ax.cells + ax.cellOf(particles[i].pos.x);
    ++cellStart[std::size_t(cellOf[i]) + 1];
  }
  for (std::size_t c = 1; c < cellStart.size(); ++c) cellStart[c] += cellStart[c - 1];
  std::vector<std::size_t> fill(cellStart.begin(), cellStart.end() - 1), sorted(particles.size());
  for (std::size_t i = 0; i < particles.size(); ++i) sorted[fill[std::size_t(cellOf[i])]++] = i;

  std::vector<CpuForce> out(particles.size());
  parallelFor(particles.size(), [&](std::size_t i) {
    const CpuParticle& pi = particles[i];
    CpuForce& f = out[i];
    f.accel = -double(rules.centralForce) * pi.pos;
    f.scale = std::abs(double(rules.centralForce)) * glm::length(pi.pos);
    const int cx = ax.cellOf(pi.pos.x), cy = ay.cellOf(pi.pos.y);
    for (int y : ay.block(cy, rules.loopingBorders))
      for (int x : ax.block(cx, rules.loopingBorders)) {
        const std::size_t c = std::size_t(y) * ax.cells + x;
        for (std::size_t k = cellStart[c]; k < cellStart[c + 1]; ++k) {
          const std::size_t j = sorted[k];
          if (j == i) continue;
          const glm::dvec2 r = cpuBoxDelta(rules, pi.pos, particles[j].pos);
          const Force& t = table[std::size_t(pi.species) * s + std::size_t(particles[j].species)];
          const double d = glm::length(r);
          if (!(d > 0 && d < t.radius)) continue;
          const double attraction = t.strength * (1.0 - d / t.radius);
          const double collision =
              t.collisionRadius > 0 ? t.collisionStrength * std::max(0.0, 1.0 - d / t.collisionRadius) : 0.0;
          f.accel += (attraction - collision) * (r / d);
          f.scale += std::abs(attraction) + std::abs(collision);
        }
      }
  });
  return out;
}

void cpuStepEuler(const Rules& rules, std::vector<CpuParticle>& particles, double dt) {
  const std::vector<CpuForce> forces = cpuForces(rules, particles);
  const double damping = std::exp(-double(rules.friction) * dt);
  const glm::dvec2 size(rules.size), half = 0.5 * size;
  for (std::size_t i = 0; i < particles.size(); ++i) {
    CpuParticle& p = particles[i];
    p.vel = (p.vel + forces[i].accel * dt) * damping;
    p.pos += p.vel * dt;
    for (int k = 0; k < 2; ++k) {
      if (rules.loopingBorders) {
        p.pos[k] -= size[k] * std::floor((p.pos[k] + half[k]) / size[k]);
      } else if (p.pos[k] < -half[k] || p.pos[k] > half[k]) {
        p.pos[k] = std::clamp(p.pos[k], -half[k], half[k]);
        p.vel[k] = -p.vel[k];
      }
    }
  }
}

}  // namespace tidepool::life
