// The fluid's loads on its boundaries (boundary_loads.h, shaders/fluid/loads.glsl).
#include "sim/fluid/boundary_loads.h"

#include <algorithm>

#include "fluid/bindings.glsl"
#include "gl/kernel.h"

namespace tidepool::fluid {
namespace {

struct SumUniforms {  // fluid/loads_sum.comp
  GLuint slots = 0, groups = 0;
  static constexpr auto fields() {
    using U = SumUniforms;
    return std::tuple{gl::field("uLoadSlots", &U::slots), gl::field("uGroups", &U::groups)};
  }
};

constexpr std::size_t kSlotBytes = 2 * sizeof(glm::vec4);  // ΣΔ, Σ moment
constexpr std::size_t kChunk = 8 * FLUID_GROUP_SIZE;       // = LOADS_CHUNK in loads_sum.comp: groups per chunk

}  // namespace

void BoundaryLoads::begin(std::size_t count, std::size_t obstacles) {
  m_groups = std::max<std::size_t>(1, (count + FLUID_GROUP_SIZE - 1) / FLUID_GROUP_SIZE);
  m_slots = GLuint(water::kWalls + obstacles);
  const std::size_t bytes = m_groups * m_slots * kSlotBytes;
  if (m_partials.size() != bytes) m_partials.resize(bytes);
  m_chunks = (m_groups + kChunk - 1) / kChunk;
  if (m_sums.size() != m_chunks * m_slots * kSlotBytes) m_sums.resize(m_chunks * m_slots * kSlotBytes);
  if (count == 0) m_partials.fillZero();  // else the step's first kernel zeroes them (LOADS_FIRST)
}

void BoundaryLoads::bind() const { m_partials.bindBase(GL_SHADER_STORAGE_BUFFER, FLUID_LOADS); }

void BoundaryLoads::sum() {
  const gl::Kernel<SumUniforms> kernel(m_shaders, "fluid/loads_sum.comp", {FLUID_LOADS, FLUID_OUT});
  bind();
  m_sums.bindBase(GL_SHADER_STORAGE_BUFFER, FLUID_OUT);
  kernel.dispatch(glm::uvec3(GLuint(m_chunks), m_slots, 1), {m_slots, GLuint(m_groups)});
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
}

water::Loads BoundaryLoads::read(double scale) const {
  const std::vector<glm::vec4> sums = m_sums.read<glm::vec4>(2 * m_chunks * m_slots);
  return fromSums(sums.data(), m_chunks, m_slots, scale);
}

void BoundaryLoads::request() {
  m_copy.request(m_sums, 2 * m_chunks * m_slots * sizeof(glm::vec4));
  m_copyChunks = m_chunks;
  m_copySlots = m_slots;
}

water::Loads BoundaryLoads::received(double scale) {
  std::vector<std::byte> bytes;
  m_copy.wait(bytes);
  if (bytes.size() != 2 * m_copyChunks * m_copySlots * sizeof(glm::vec4))
    return water::Loads::unmeasured(m_copySlots - water::kWalls);
  return fromSums(reinterpret_cast<const glm::vec4*>(bytes.data()), m_copyChunks, m_copySlots, scale);
}

water::Loads BoundaryLoads::fromSums(const glm::vec4* sums, std::size_t chunks, GLuint slots, double scale) const {
  water::Loads out;
  for (GLuint s = 0; s < slots; ++s) {
    water::Load load;
    for (std::size_t c = 0; c < chunks; ++c) {
      const std::size_t at = 2 * (c * slots + s);
      load.force += scale * glm::dvec3(glm::vec3(sums[at]));
      load.torque += scale * glm::dvec3(glm::vec3(sums[at + 1]));
    }
    if (s < water::kWalls)
      out.walls[s] = load;
    else
      out.obstacles.push_back(load);
  }
  return out;
}

}  // namespace tidepool::fluid
