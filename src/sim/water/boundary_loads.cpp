// The water's loads on its boundaries (boundary_loads.h, shaders/water/loads.glsl and
// obstacle_loads.glsl).
#include "sim/water/boundary_loads.h"

#include <algorithm>
#include <string>

#include "base/error.h"
#include "gl/kernel.h"
#include "gl/window.h"
#include "water/loads_bindings.glsl"

namespace tidepool::water {
namespace {

struct SumUniforms {  // water/loads_sum.comp
  GLuint groups = 0, firstChunk = 0, chunkGroups = 0, sumsFirst = 0;
  static constexpr auto fields() {
    using U = SumUniforms;
    return std::tuple{gl::field("uGroups", &U::groups), gl::field("uFirstChunk", &U::firstChunk),
                      gl::field("uChunkGroups", &U::chunkGroups), gl::field("uSumsFirst", &U::sumsFirst)};
  }
};

struct ObstacleSumUniforms {  // water/obstacle_loads_sum.comp
  GLuint obstacles = 0;
  static constexpr auto fields() { return std::tuple{gl::field("uObstacles", &ObstacleSumUniforms::obstacles)}; }
};

constexpr std::size_t kPairBytes = 2 * sizeof(glm::vec4);  // a group's wall partials, an obstacle's or a chunk's sums
constexpr std::size_t kChunkGroups = 1024;                 // work groups a chunk adds, where a block holds them
constexpr std::size_t kAlignGroups = 8;  // 8 groups of 32 B: a multiple of 256 B, the largest offset alignment

}  // namespace

LoadsWanted loadsWanted(const std::vector<ProbeParams>& probes, bool bodies) {
  LoadsWanted want{.any = bodies};
  for (const ProbeParams& p : probes)
    if (p.kind == ProbeKind::Force) {
      want.any = true;
      want.walls = want.walls || p.wall != ProbeWall::None;
    }
  return want;
}

void BoundaryLoads::begin(std::size_t count, bool walls, const Obstacles& obstacles) {
  m_walls = walls;
  m_groups = walls ? std::max<std::size_t>(1, (count + m_groupSize - 1) / m_groupSize) : 0;
  const std::size_t partials = m_groups * kPairBytes;
  if (m_partials.size() < partials) m_partials.resize(partials);
  const std::size_t fit = gl::storageBlockBytes() / kPairBytes / kAlignGroups * kAlignGroups;
  m_chunkGroups = std::clamp<std::size_t>(fit, kAlignGroups, kChunkGroups);
  m_layout = {obstacles.size(), (m_groups + m_chunkGroups - 1) / m_chunkGroups};

  m_obstacleParticles = obstacles.particles();
  const std::size_t shares = m_obstacleParticles * sizeof(glm::vec4);
  if (shares > gl::storageBlockBytes())  // as their placed positions (obstacles.h)
    throw Error("loads: " + std::to_string(m_obstacleParticles) + " obstacle particles, over the " +
                std::to_string(gl::storageBlockBytes() / sizeof(glm::vec4)) +
                " whose shares one storage block holds (" + gl::sizeText(gl::storageBlockBytes()) +
                "): raise particles.radius or make the obstacles smaller");
  if (m_shares.size() < shares) {
    m_shares.resize(shares);
    m_moments.resize(shares);
  }
  const std::size_t sums = m_layout.vec4s() * sizeof(glm::vec4);
  if (m_sums.size() < sums) m_sums.resize(sums);
  if (count == 0) {  // no kernel measures: nothing pushed
    if (walls) m_partials.fillZero();
    if (m_obstacleParticles > 0) {
      m_shares.fillZero();
      m_moments.fillZero();
    }
  }
  if (m_layout.obstacles > 0 && m_obstacleParticles == 0) m_sums.fillZero();  // no particles: no loads
}

void BoundaryLoads::bindWalls(GLuint binding) const { bindWallGroups(binding, 0, m_groups); }

void BoundaryLoads::bindWallGroups(GLuint binding, std::size_t firstGroup, std::size_t groups) const {
  m_partials.bindRange(GL_SHADER_STORAGE_BUFFER, binding, firstGroup * kPairBytes, groups * kPairBytes);
}

void BoundaryLoads::bindShares(GLuint shares, GLuint moments) const {
  m_shares.bindRange(GL_SHADER_STORAGE_BUFFER, shares, 0, m_obstacleParticles * sizeof(glm::vec4));
  m_moments.bindRange(GL_SHADER_STORAGE_BUFFER, moments, 0, m_obstacleParticles * sizeof(glm::vec4));
}

void BoundaryLoads::sum(const Obstacles& obstacles) {
  if (m_obstacleParticles > 0) {
    const gl::Kernel<ObstacleSumUniforms> kernel(m_shaders, "water/obstacle_loads_sum.comp",
                                                 {LOADS_SHARES, LOADS_MOMENTS, LOADS_SUMS});
    obstacles.bind();
    bindShares(LOADS_SHARES, LOADS_MOMENTS);
    m_sums.bindBase(GL_SHADER_STORAGE_BUFFER, LOADS_SUMS);
    kernel.dispatch(glm::uvec3(GLuint(m_layout.obstacles), 1, 1), {GLuint(m_layout.obstacles)});
  }
  if (m_walls) {
    const gl::Kernel<SumUniforms> kernel(m_shaders, "water/loads_sum.comp", {LOADS_PARTIALS, LOADS_SUMS});
    m_sums.bindBase(GL_SHADER_STORAGE_BUFFER, LOADS_SUMS);
    // Chunks a window at a time: as many as one storage block holds.
    const std::size_t perWindow = std::max<std::size_t>(1, gl::storageBlockBytes() / (m_chunkGroups * kPairBytes));
    for (std::size_t first = 0; first < m_layout.chunks; first += perWindow) {
      const std::size_t chunks = std::min(perWindow, m_layout.chunks - first);
      const std::size_t firstGroup = first * m_chunkGroups;
      const std::size_t groups = std::min(m_groups - firstGroup, chunks * m_chunkGroups);
      bindWallGroups(LOADS_PARTIALS, firstGroup, groups);
      kernel.dispatch(glm::uvec3(GLuint(chunks), 1, 1), {.groups = GLuint(groups),
                                                         .firstChunk = GLuint(first),
                                                         .chunkGroups = GLuint(m_chunkGroups),
                                                         .sumsFirst = GLuint(2 * m_layout.obstacles)});
    }
  }
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
}

Loads BoundaryLoads::read(double scale) const {
  const std::vector<glm::vec4> sums = m_sums.read<glm::vec4>(m_layout.vec4s());
  return fromSums(sums.data(), m_layout, scale);
}

void BoundaryLoads::request() {
  m_copy.request(m_sums, m_layout.vec4s() * sizeof(glm::vec4));
  m_copyLayout = m_layout;
}

Loads BoundaryLoads::received(double scale) {
  std::vector<std::byte> bytes;
  m_copy.wait(bytes);
  if (bytes.size() != m_copyLayout.vec4s() * sizeof(glm::vec4)) return Loads::unmeasured(m_copyLayout.obstacles);
  return fromSums(reinterpret_cast<const glm::vec4*>(bytes.data()), m_copyLayout, scale);
}

Loads BoundaryLoads::fromSums(const glm::vec4* sums, Layout layout, double scale) {
  Loads out;
  for (std::size_t k = 0; k < layout.obstacles; ++k)
    out.obstacles.push_back(
        {scale * glm::dvec3(glm::vec3(sums[2 * k])), scale * glm::dvec3(glm::vec3(sums[2 * k + 1]))});
  const glm::vec4* walls = sums + 2 * layout.obstacles;
  for (std::size_t w = 0; w < kWalls; ++w) {
    double push = 0;
    for (std::size_t c = 0; c < layout.chunks; ++c) push += scale * double(walls[2 * c + w / 4][int(w % 4)]);
    out.walls[w].force[int(w / 2)] = push;
  }
  return out;
}

}  // namespace tidepool::water
