// The water's loads on its boundaries (boundary_loads.h, shaders/water/loads.glsl).
#include "sim/water/boundary_loads.h"

#include <algorithm>

#include "gl/kernel.h"
#include "gl/window.h"
#include "water/loads_bindings.glsl"

namespace tidepool::water {
namespace {

struct SumUniforms {  // water/loads_sum.comp
  GLuint slots = 0, groups = 0, firstChunk = 0, chunkGroups = 0;
  static constexpr auto fields() {
    using U = SumUniforms;
    return std::tuple{gl::field("uLoadSlots", &U::slots), gl::field("uGroups", &U::groups),
                      gl::field("uFirstChunk", &U::firstChunk), gl::field("uChunkGroups", &U::chunkGroups)};
  }
};

constexpr std::size_t kSlotBytes = 2 * sizeof(glm::vec4);  // ΣΔ, Σ moment
constexpr std::size_t kChunkGroups = 1024;                 // work groups a chunk adds, where a block holds them
constexpr std::size_t kAlignGroups = 8;  // 8 groups of slots of 32 B: a multiple of 256 B, the largest offset alignment

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

void BoundaryLoads::begin(std::size_t count, std::size_t obstacles) {
  m_groups = std::max<std::size_t>(1, (count + m_groupSize - 1) / m_groupSize);
  m_slots = GLuint(kWalls + obstacles);
  const std::size_t bytes = m_groups * m_slots * kSlotBytes;
  if (m_partials.size() != bytes) m_partials.resize(bytes);
  const std::size_t fit = gl::storageBlockBytes() / (m_slots * kSlotBytes) / kAlignGroups * kAlignGroups;
  m_chunkGroups = std::clamp<std::size_t>(fit, kAlignGroups, kChunkGroups);
  m_chunks = (m_groups + m_chunkGroups - 1) / m_chunkGroups;
  if (m_sums.size() != m_chunks * m_slots * kSlotBytes) m_sums.resize(m_chunks * m_slots * kSlotBytes);
  if (count == 0) m_partials.fillZero();  // else the step's first kernel zeroes them (LOADS_FIRST)
}

void BoundaryLoads::bind(GLuint binding) const { m_partials.bindBase(GL_SHADER_STORAGE_BUFFER, binding); }

void BoundaryLoads::bindGroups(GLuint binding, std::size_t firstGroup, std::size_t groups) const {
  if (firstGroup == 0 && groups == m_groups) return bind(binding);
  const std::size_t groupBytes = m_slots * kSlotBytes;
  m_partials.bindRange(GL_SHADER_STORAGE_BUFFER, binding, firstGroup * groupBytes, groups * groupBytes);
}

void BoundaryLoads::sum() {
  const gl::Kernel<SumUniforms> kernel(m_shaders, "water/loads_sum.comp", {LOADS_PARTIALS, LOADS_SUMS});
  m_sums.bindBase(GL_SHADER_STORAGE_BUFFER, LOADS_SUMS);
  // Chunks a window at a time: as many as one storage block holds.
  const std::size_t chunkBytes = m_chunkGroups * m_slots * kSlotBytes;
  const std::size_t perWindow = std::max<std::size_t>(1, gl::storageBlockBytes() / chunkBytes);
  for (std::size_t first = 0; first < m_chunks; first += perWindow) {
    const std::size_t chunks = std::min(perWindow, m_chunks - first);
    const std::size_t firstGroup = first * m_chunkGroups;
    const std::size_t groups = std::min(m_groups - firstGroup, chunks * m_chunkGroups);
    bindGroups(LOADS_PARTIALS, firstGroup, groups);
    kernel.dispatch(glm::uvec3(GLuint(chunks), m_slots, 1),
                    {m_slots, GLuint(groups), GLuint(first), GLuint(m_chunkGroups)});
  }
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
}

Loads BoundaryLoads::read(double scale) const {
  const std::vector<glm::vec4> sums = m_sums.read<glm::vec4>(2 * m_chunks * m_slots);
  return fromSums(sums.data(), m_chunks, m_slots, scale);
}

void BoundaryLoads::request() {
  m_copy.request(m_sums, 2 * m_chunks * m_slots * sizeof(glm::vec4));
  m_copyChunks = m_chunks;
  m_copySlots = m_slots;
}

Loads BoundaryLoads::received(double scale) {
  std::vector<std::byte> bytes;
  m_copy.wait(bytes);
  if (bytes.size() != 2 * m_copyChunks * m_copySlots * sizeof(glm::vec4))
    return Loads::unmeasured(m_copySlots - kWalls);
  return fromSums(reinterpret_cast<const glm::vec4*>(bytes.data()), m_copyChunks, m_copySlots, scale);
}

Loads BoundaryLoads::fromSums(const glm::vec4* sums, std::size_t chunks, GLuint slots, double scale) const {
  Loads out;
  for (GLuint s = 0; s < slots; ++s) {
    Load load;
    for (std::size_t c = 0; c < chunks; ++c) {
      const std::size_t at = 2 * (c * slots + s);
      load.force += scale * glm::dvec3(glm::vec3(sums[at]));
      load.torque += scale * glm::dvec3(glm::vec3(sums[at + 1]));
    }
    if (s < kWalls)
      out.walls[s] = load;
    else
      out.obstacles.push_back(load);
  }
  return out;
}

}  // namespace tidepool::water
