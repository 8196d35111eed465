#include "sim/life/life.h"

#include <cmath>
#include <cstdio>

#include "base/error.h"
#include "life/bindings.glsl"

namespace tidepool::life {
namespace {
constexpr std::size_t kMaxDispatchGroupsSpill = 65536;  // dispatchThreads may round groups up by a row
}

Life::Life(gl::ShaderLibrary& shaders, const Rules& rules, const Params& params)
    : m_shaders(shaders), m_params(params) {
  setRules(rules, true);
}

void Life::setRules(const Rules& rules, bool respawn) {
  validateRules(rules, "life rules");
  const bool sameShape = m_grid && rules.particleCount == m_rules.particleCount && rules.size == m_rules.size &&
                         rules.speciesCount() == m_rules.speciesCount();
  const bool newGrid = !m_grid || rules.size != m_rules.size || rules.maxRadius() != m_rules.maxRadius();
  m_rules = rules;
  if (newGrid) {
    // Cell = the largest radius, but no more cells than particles (or 2048 per axis): tiny radii
    // would otherwise make the per-step scan of cell counts the dominant cost.
    const float perParticle = std::sqrt(m_rules.size.x * m_rules.size.y / float(m_rules.particleCount));
    const float cell = std::max({m_rules.maxRadius(), perParticle, std::max(m_rules.size.x, m_rules.size.y) / 2048.0f});
    const glm::vec2 half = 0.5f * m_rules.size;
    m_grid = std::make_unique<grid::UniformGrid>(
        m_shaders, grid::GridParams{{-half.x, -half.y, 0.0f}, {half.x, half.y, 0.0f}, cell},
        std::size_t(m_rules.particleCount));
  }
  uploadTable();
  if (respawn || !sameShape) {
    allocate();
    reset();
  }
  m_needAccel = true;
}

void Life::allocate() {
  m_count = std::size_t(m_rules.particleCount);
  for (int i = 0; i < 2; ++i) {
    m_pos[i] = gl::Buffer(m_count * sizeof(glm::vec4));
    m_vel[i] = gl::Buffer(m_count * sizeof(glm::vec4));
  }
  m_accel = gl::Buffer(m_count * sizeof(glm::vec2));
  m_accel.fillZero();
  m_groupPairs = gl::Buffer((m_count / LIFE_FORCES_GROUP + 1 + kMaxDispatchGroupsSpill) * sizeof(GLuint));
}

void Life::uploadTable() {
  const std::vector<Force> table = effectiveForces(m_rules);
  std::vector<glm::vec4> packed;  // (strength, radius, |collisionStrength|, collisionRadius)
  for (const Force& f : table) packed.emplace_back(f.strength, f.radius, f.collisionStrength, f.collisionRadius);
  m_table = gl::Buffer(std::span<const glm::vec4>(packed));
  std::vector<glm::vec4> colors;
  for (const Species& s : m_rules.species) colors.emplace_back(s.color, 1.0f);
  m_colors = gl::Buffer(std::span<const glm::vec4>(colors));
}

void Life::reset() {
  const std::vector<InitialParticle> spawn = spawnParticles(m_rules);
  std::vector<glm::vec4> pos(spawn.size()), vel(spawn.size());
  for (std::size_t i = 0; i < spawn.size(); ++i) {
    pos[i] = {spawn[i].position, 0.0f, float(spawn[i].species)};
    vel[i] = {spawn[i].velocity, 0.0f, 0.0f};
  }
  upload(pos, vel);
  m_time = 0;
  m_steps = 0;
}

void Life::upload(const std::vector<glm::vec4>& pos, const std::vector<glm::vec4>& vel) {
  if (pos.size() != m_count || vel.size() != m_count)
    throw Error("life: upload of " + std::to_string(pos.size()) + " particles, the model has " +
                std::to_string(m_count));
  m_current = 0;
  m_pos[0].upload(std::span<const glm::vec4>(pos));
  m_vel[0].upload(std::span<const glm::vec4>(vel));
  m_needAccel = true;
}

std::vector<gl::ShaderDefine> Life::defines() const {
  if (m_rules.loopingBorders) return {{"LOOPING", "1"}};
  return {};
}

void Life::push(glm::vec2 point, glm::vec2 velocity, float radius) {
  m_pushPoint = point;
  m_pushVelocity = velocity;
  m_pushRadius = std::max(radius, 1e-3f);
}

void Life::sortByCell() {
  m_grid->build(m_pos[m_current], m_count);
  const int next = 1 - m_current;
  m_grid->reorder(m_pos[m_current], {{&m_pos[m_current], &m_pos[next]}, {&m_vel[m_current], &m_vel[next]}});
  m_current = next;
}

void Life::evaluateForces() { forcePass(false); }

void Life::forcePass(bool countPairs) {
  std::vector<gl::ShaderDefine> d = defines();
  if (countPairs) d.push_back({"COUNT_PAIRS", "1"});
  gl::Program& p = m_shaders.program({"life/forces.comp"}, d);
  p.use();
  m_grid->setUniforms(p);
  p.set("uBoxSize", m_rules.size);
  p.set("uCount", GLuint(m_count));
  p.set("uSpecies", GLuint(m_rules.speciesCount()));
  p.set("uCentralForce", m_rules.centralForce);
  m_pos[m_current].bindBase(GL_SHADER_STORAGE_BUFFER, LIFE_POSITIONS);
  m_accel.bindBase(GL_SHADER_STORAGE_BUFFER, LIFE_ACCELERATIONS);
  m_table.bindBase(GL_SHADER_STORAGE_BUFFER, LIFE_FORCE_TABLE);
  m_grid->cellStart().bindBase(GL_SHADER_STORAGE_BUFFER, LIFE_CELL_START);
  if (countPairs) m_groupPairs.bindBase(GL_SHADER_STORAGE_BUFFER, LIFE_GROUP_PAIRS);
  p.dispatchThreads(m_count);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
}

void Life::integrate(const char* variant, float dt) {
  std::vector<gl::ShaderDefine> d = defines();
  if (*variant) d.push_back({variant, "1"});
  gl::Program& p = m_shaders.program({"life/integrate.comp"}, d);
  p.use();
  p.set("uBoxSize", m_rules.size);
  p.set("uCount", GLuint(m_count));
  p.set("uDt", dt);
  p.set("uDamping", float(std::exp(-double(m_rules.friction) * dt)));
  p.set("uPushPoint", m_pushPoint);
  p.set("uPushVelocity", m_pushVelocity);
  p.set("uPushRadius", m_pushRadius);
  m_pos[m_current].bindBase(GL_SHADER_STORAGE_BUFFER, LIFE_POSITIONS);
  m_vel[m_current].bindBase(GL_SHADER_STORAGE_BUFFER, LIFE_VELOCITIES);
  m_accel.bindBase(GL_SHADER_STORAGE_BUFFER, LIFE_ACCELERATIONS);
  p.dispatchThreads(m_count);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_VERTEX_ATTRIB_ARRAY_BARRIER_BIT);
}

void Life::stepOnce(float dt) {
  if (m_params.integrator == Integrator::Verlet) {
    if (m_needAccel) {
      computeForces();
      integrate("STORE_ACCEL", dt);
    }
    integrate("VERLET_DRIFT", dt);
    computeForces();
    integrate("VERLET_KICK", dt);
  } else {
    computeForces();
    integrate("", dt);
  }
  // The Euler pass also leaves a in vel.zw, so switching to Verlet mid-run needs no restart.
  m_needAccel = false;
  m_pushVelocity = glm::vec2(0.0f);  // the brush acts for one step per call to push()
  m_time += dt;
  ++m_steps;
}

void Life::step(double frameSeconds, gl::GpuProfiler& profiler) {
  auto scope = profiler.scope("life.step");
  stepOnce(float(std::min(double(m_params.maxDt), frameSeconds)));
}

std::uint64_t Life::countCandidatePairs() {
  m_groupPairs.fillZero();
  forcePass(true);
  std::uint64_t total = 0;
  for (GLuint v : m_groupPairs.readAll<GLuint>()) total += v;
  return total;
}

std::string Life::status() const {
  char buf[256];
  const glm::uvec3 dims = m_grid->dims();
  std::snprintf(buf, sizeof buf, "%zu particles, %d species, box %gx%g, grid %ux%u (cell %.3g), %s%s", m_count,
                m_rules.speciesCount(), double(m_rules.size.x), double(m_rules.size.y), dims.x, dims.y,
                double(m_grid->params().cellSize), m_rules.loopingBorders ? "looping" : "walls",
                m_params.integrator == Integrator::Verlet ? ", Verlet" : "");
  return buf;
}

}  // namespace tidepool::life
