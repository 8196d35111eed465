#include "sim/fluid/density_probe.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <numbers>

#include "fluid/bindings.glsl"
#include "fluid/stats_layout.glsl"
#include "sim/fluid/rest_lattice.h"
#include "sim/fluid/sph_kernels.h"

namespace tidepool::fluid {
namespace {

// One work group's partial statistics as stats.comp writes them (fluid/stats_layout.glsl).
struct GroupStats {
  float kinetic, potential, compression, density, maxCompression, maxSpeed, nonFinite, outside, front, backHeight;
};
static_assert(sizeof(GroupStats) == FLUID_STATS_VALUES * sizeof(float));
static_assert(offsetof(GroupStats, kinetic) == FLUID_STATS_KINETIC * sizeof(float));
static_assert(offsetof(GroupStats, potential) == FLUID_STATS_POTENTIAL * sizeof(float));
static_assert(offsetof(GroupStats, compression) == FLUID_STATS_COMPRESSION * sizeof(float));
static_assert(offsetof(GroupStats, density) == FLUID_STATS_DENSITY * sizeof(float));
static_assert(offsetof(GroupStats, maxCompression) == FLUID_STATS_MAX_COMPRESSION * sizeof(float));
static_assert(offsetof(GroupStats, maxSpeed) == FLUID_STATS_MAX_SPEED * sizeof(float));
static_assert(offsetof(GroupStats, nonFinite) == FLUID_STATS_NON_FINITE * sizeof(float));
static_assert(offsetof(GroupStats, outside) == FLUID_STATS_OUTSIDE * sizeof(float));
static_assert(offsetof(GroupStats, front) == FLUID_STATS_FRONT * sizeof(float));
static_assert(offsetof(GroupStats, backHeight) == FLUID_STATS_BACK_HEIGHT * sizeof(float));

}  // namespace

SphUniforms sphUniforms(double h, const RestLattice& rest) {
  const double pi = std::numbers::pi;
  // Q(a, b) of the walls' shared quarter spaces, padded to whole vec4s (kernels.glsl).
  static const std::array<glm::vec4, 73> padded = [] {
    std::array<glm::vec4, 73> out{};
    const EdgeTable& t = edgeTable();
    std::copy(t.begin(), t.end(), &out[0].x);
    return out;
  }();
  return {float(h), float(315.0 / (64.0 * pi * h * h * h)), float(-45.0 / (pi * h * h * h * h)), float(rest.volume),
          padded};
}

std::vector<gl::ShaderDefine> boundaryDefines(const water::Obstacles& obstacles) {
  std::vector<gl::ShaderDefine> d;
  if (obstacles.active()) {
    d.push_back({"HAS_OBSTACLE", ""});
    if (obstacles.volumes()) d.push_back({"OBSTACLE_VOLUMES", ""});
  }
  return d;
}

BoundaryUniforms bindBoundary(const water::Obstacles& obstacles, double h) {
  if (!obstacles.active()) return {};
  obstacles.bind();
  return {.reach = int(std::ceil(h / obstacles.cellSize() - 1e-6)), .obstacles = obstacles.uniforms()};
}

Stats DensityProbe::measure(const water::ParticleWater& water, const DensityKernel& kernel, glm::vec3 gravity,
                            double time) {
  Stats st;
  st.time = time;
  st.count = water.count();
  const std::size_t n = water.count();
  if (n == 0) return st;
  const double h = double(kernel.smoothing) * kernel.spacing;
  if (!m_restFor || m_restFor->spacing != kernel.spacing || m_restFor->smoothing != kernel.smoothing ||
      m_restFor->packing != kernel.packing) {  // measured once per kernel, not per call
    m_rest = restLattice(kernel.spacing, h, kernel.packing);
    m_restFor = kernel;
  }
  const RestLattice& rest = m_rest;
  const water::Setup& w = water.water();
  if (!m_grid || m_grid->params().domainMin != w.domainMin || m_grid->params().domainMax != w.domainMax ||
      m_grid->params().cellSize != float(h))
    m_grid = std::make_unique<grid::UniformGrid>(
        m_shaders, grid::GridParams{.domainMin = w.domainMin, .domainMax = w.domainMax, .cellSize = float(h)}, n);
  const std::size_t bytes = n * sizeof(glm::vec4);
  if (m_pos.size() < bytes) {
    m_pos = gl::Buffer(bytes);
    m_vel = gl::Buffer(bytes);
  }
  const std::size_t groups = (n + FLUID_GROUP_SIZE - 1) / FLUID_GROUP_SIZE;
  if (m_stats.size() < groups * sizeof(GroupStats)) m_stats = gl::Buffer(groups * sizeof(GroupStats));
  m_grid->build(water.positions(), n);
  m_grid->reorder(water.positions(), {{&water.positions(), &m_pos}, {&water.velocities(), &m_vel}});

  const water::Obstacles& obstacles = water.obstacles();
  const gl::Kernel<StatsUniforms> stats(m_shaders, "fluid/stats.comp",
                                        {FLUID_CELL_START, FLUID_PRED, FLUID_VEL_IN, FLUID_OUT},
                                        boundaryDefines(obstacles));
  m_grid->cellStart().bindBase(GL_SHADER_STORAGE_BUFFER, FLUID_CELL_START);
  m_pos.bindBase(GL_SHADER_STORAGE_BUFFER, FLUID_PRED);
  m_vel.bindBase(GL_SHADER_STORAGE_BUFFER, FLUID_VEL_IN);
  m_stats.bindBase(GL_SHADER_STORAGE_BUFFER, FLUID_OUT);
  stats.dispatchThreads(n, {.count = GLuint(n),
                            .gravity = gravity,
                            .domainMin = w.domainMin,
                            .spacing = kernel.spacing,
                            .sph = sphUniforms(h, rest),
                            .walls = {water.wallMin(), water.wallMax(), float(rest.wallScale), 0.5f * kernel.spacing},
                            .neighbours = {1, m_grid->uniforms()},  // cells of h
                            .boundary = bindBoundary(obstacles, h)});
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);

  double front = -1e30, height = -1e30, compression = 0, density = 0, maxCompression = -1e30;
  for (const GroupStats& g : m_stats.read<GroupStats>(groups)) {
    st.kinetic += g.kinetic;
    st.potential += g.potential;
    compression += g.compression;
    density += g.density;
    maxCompression = std::max(maxCompression, double(g.maxCompression));
    st.maxSpeed = std::max(st.maxSpeed, double(g.maxSpeed));
    st.nonFinite += std::size_t(g.nonFinite);
    st.outside += std::size_t(g.outside);
    front = std::max(front, double(g.front));
    height = std::max(height, double(g.backHeight));
  }
  const double mass = kernel.restDensity * rest.volume;
  st.kinetic *= mass;
  st.potential *= mass;
  const std::size_t finite = n - std::min(n, st.nonFinite);
  st.compressionMean = finite > 0 ? compression / double(finite) : 0.0;
  st.densityMean = finite > 0 ? density / double(finite) : 0.0;
  st.compressionMax = maxCompression > -1e29 ? maxCompression : 0.0;
  st.front = front > -1e29 ? front : std::nan("");
  st.backHeight = height > -1e29 ? height : std::nan("");
  return st;
}

}  // namespace tidepool::fluid
