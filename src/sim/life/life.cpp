#include "sim/life/life.h"

#include <cmath>
#include <cstdio>
#include <cstring>
#include <glm/gtc/packing.hpp>

#include "base/error.h"
#include "life/bindings.glsl"
#include "sim/particle_memory.h"
#include "sim/state_checks.h"

namespace tidepool::life {
namespace {
constexpr std::size_t kMaxDispatchGroupsSpill = 65536;                 // dispatchThreads may round groups up by a row
constexpr std::size_t kMaxCheckpointParticles = std::size_t(4) << 20;  // larger runs keep no copy to go back to
constexpr double kCellsPerStepBound = 10;  // the watch's speed bound, in grid cells per step

struct ForceUniforms {
  grid::GridUniforms grid;
  PairUniforms pair;
  static constexpr auto fields() {
    return std::tuple{gl::field(&ForceUniforms::grid), gl::field(&ForceUniforms::pair)};
  }
};
struct IntegrateUniforms {
  glm::vec2 boxSize{0.0f};       // world units
  GLuint count = 0;              // particles
  float dt = 0.0f;               // s
  float damping = 1.0f;          // exp(-friction·dt)
  glm::vec2 pushPoint{0.0f};     // world units
  glm::vec2 pushVelocity{0.0f};  // world units / s at the brush centre (0: no brush)
  float pushRadius = 0.0f;       // world units
  static constexpr auto fields() {
    using U = IntegrateUniforms;
    return std::tuple{gl::field("uBoxSize", &U::boxSize),
                      gl::field("uCount", &U::count),
                      gl::field("uDt", &U::dt),
                      gl::field("uDamping", &U::damping),
                      gl::field("uPushPoint", &U::pushPoint),
                      gl::field("uPushVelocity", &U::pushVelocity),
                      gl::field("uPushRadius", &U::pushRadius)};
  }
};
}  // namespace

Life::Life(gl::ShaderLibrary& shaders, const Rules& rules, const Params& params)
    : Model(shaders, "life", kMaxCheckpointParticles), m_shaders(shaders), m_params(params) {
  setRules(rules, true);
}

void Life::setRules(const Rules& rules, bool respawn) {
  validateRules(rules, "life rules");
  checkCount(rules, m_grid ? m_storage : m_params.storage);  // before anything changes
  const bool sameShape = m_grid && rules.particleCount == m_rules.particleCount && rules.size == m_rules.size &&
                         rules.speciesCount() == m_rules.speciesCount();
  const bool newGrid = !m_grid || rules.size != m_rules.size || rules.maxRadius() != m_rules.maxRadius();
  m_rules = rules;
  if (!m_grid) m_storage = m_params.storage;
  if (newGrid) makeGrid();
  uploadTable();
  if (respawn || !sameShape) {
    allocate();
    reset();
  }
  m_needAccel = true;
}

void Life::checkCount(const Rules& rules, Storage storage) {
  // Positions and velocities twice, ids when tracked (layout elements each), the grid's words;
  // the host builds the initial positions and velocities as vec4.
  const std::size_t element = storage == Storage::Fp16 ? sizeof(glm::uvec2) : sizeof(glm::vec4);
  sim::checkParticleRequest("life", "particle", double(rules.particleCount),
                            "particle_count = " + std::to_string(rules.particleCount),
                            {.maxParticles = std::size_t(kMaxParticles),
                             .arrayBytes = element,
                             .gpuBytes = 6 * element + 3 * sizeof(GLuint),
                             .hostBytes = 2 * sizeof(glm::vec4)},
                            "lower particle_count (or use storage fp16: half the bytes)");
}

void Life::makeGrid() {
  // Cell = the largest radius, but no more cells than particles (or 2048 per axis): tiny radii
  // would otherwise make the per-step scan of cell counts the dominant cost.
  const float perParticle = std::sqrt(m_rules.size.x * m_rules.size.y / float(m_rules.particleCount));
  const float cell = std::max({m_rules.maxRadius(), perParticle, std::max(m_rules.size.x, m_rules.size.y) / 2048.0f});
  const glm::vec2 half = 0.5f * m_rules.size;
  const grid::Layout layout = m_storage == Storage::Fp16 ? grid::Layout::Half2 : grid::Layout::Vec4;
  m_grid = std::make_unique<grid::UniformGrid>(
      m_shaders, grid::GridParams{{-half.x, -half.y, 0.0f}, {half.x, half.y, 0.0f}, cell, layout},
      std::size_t(m_rules.particleCount));
}

void Life::applyStorage() {
  if (m_params.storage == m_storage) return;
  const std::vector<glm::vec4> pos = downloadPositions(), vel = downloadVelocities();
  const double time = m_time;
  const std::uint64_t steps = m_steps;
  m_storage = m_params.storage;
  makeGrid();
  allocate();
  upload(pos, vel);
  m_time = time;
  m_steps = steps;
}

void Life::allocate() {
  m_count = std::size_t(m_rules.particleCount);
  for (int i = 0; i < 2; ++i) {
    m_pos[i] = gl::Buffer(m_count * m_grid->elementBytes());
    m_vel[i] = gl::Buffer(m_count * m_grid->elementBytes());
    m_ids[i] = gl::Buffer();
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

void Life::respawn(std::uint32_t stream) {
  const std::vector<InitialParticle> spawn = spawnParticles(m_rules, stream);
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
  if (m_storage == Storage::Fp32) {
    m_pos[0].upload(std::span<const glm::vec4>(pos));
    m_vel[0].upload(std::span<const glm::vec4>(vel));
  } else {
    std::vector<glm::uvec2> packedPos(m_count), packedVel(m_count);
    for (std::size_t i = 0; i < m_count; ++i) {
      packedPos[i] = {glm::packHalf2x16(glm::vec2(pos[i])), GLuint(pos[i].w)};
      packedVel[i] = {glm::packHalf2x16(glm::vec2(vel[i])), glm::packHalf2x16(glm::vec2(vel[i].z, vel[i].w))};
    }
    m_pos[0].upload(std::span<const glm::uvec2>(packedPos));
    m_vel[0].upload(std::span<const glm::uvec2>(packedVel));
  }
  if (m_trackIds) resetIds();
  m_needAccel = true;
  restartWatch();  // a new state: nothing judged yet
}

std::vector<glm::vec4> Life::downloadPositions() const {
  if (m_storage == Storage::Fp32) return positions().read<glm::vec4>(m_count);
  std::vector<glm::vec4> out;
  for (const glm::uvec2& p : positions().read<glm::uvec2>(m_count))
    out.emplace_back(glm::unpackHalf2x16(p.x), 0.0f, float(p.y));
  return out;
}

std::vector<glm::vec4> Life::downloadVelocities() const {
  if (m_storage == Storage::Fp32) return velocities().read<glm::vec4>(m_count);
  std::vector<glm::vec4> out;
  for (const glm::uvec2& v : velocities().read<glm::uvec2>(m_count))
    out.emplace_back(glm::unpackHalf2x16(v.x), glm::unpackHalf2x16(v.y));
  return out;
}

void Life::trackIds(bool on) {
  m_trackIds = on;
  for (gl::Buffer& b : m_ids) b = gl::Buffer();
  if (on) resetIds();
}

void Life::resetIds() {
  const std::size_t words = m_grid->elementBytes() / sizeof(GLuint);  // ids in the first word of each element
  std::vector<GLuint> ids(m_count * words, 0u);
  for (std::size_t i = 0; i < m_count; ++i) ids[i * words] = GLuint(i);
  for (gl::Buffer& b : m_ids) b = gl::Buffer(std::span<const GLuint>(ids));
}

std::vector<std::uint32_t> Life::ids() const {
  if (!m_trackIds) return {};
  const std::size_t words = m_grid->elementBytes() / sizeof(GLuint);
  const std::vector<GLuint> all = m_ids[m_current].read<GLuint>(m_count * words);
  std::vector<std::uint32_t> out(m_count);
  for (std::size_t i = 0; i < m_count; ++i) out[i] = all[i * words];
  return out;
}

std::vector<gl::ShaderDefine> Life::defines() const {
  std::vector<gl::ShaderDefine> d = {{"LIFE_FP16", m_storage == Storage::Fp16 ? "1" : "0"}};
  if (m_rules.loopingBorders) d.push_back({"LOOPING", "1"});
  return d;
}

void Life::push(glm::vec2 point, glm::vec2 velocity, float radius) {
  m_pushPoint = point;
  m_pushVelocity = velocity;
  m_pushRadius = std::max(radius, 1e-3f);
}

void Life::sortByCell() {
  m_grid->setStable(m_params.deterministic);
  m_grid->build(m_pos[m_current], m_count);
  const int next = 1 - m_current;
  if (m_trackIds)
    m_grid->reorder(
        m_pos[m_current],
        {{&m_pos[m_current], &m_pos[next]}, {&m_vel[m_current], &m_vel[next]}, {&m_ids[m_current], &m_ids[next]}});
  else
    m_grid->reorder(m_pos[m_current], {{&m_pos[m_current], &m_pos[next]}, {&m_vel[m_current], &m_vel[next]}});
  m_current = next;
}

void Life::evaluateForces() { forcePass(false); }

PairUniforms Life::pairUniforms() const {
  return {m_rules.size, GLuint(m_count), GLuint(m_rules.speciesCount()), m_rules.centralForce};
}

void Life::forcePass(bool countPairs) {
  std::vector<gl::ShaderDefine> d = defines();
  if (countPairs) d.push_back({"COUNT_PAIRS", "1"});
  const gl::Kernel<ForceUniforms> forces(
      m_shaders, "life/forces.comp",
      {LIFE_POSITIONS, LIFE_ACCELERATIONS, LIFE_FORCE_TABLE, LIFE_CELL_START, LIFE_GROUP_PAIRS}, d);
  m_pos[m_current].bindBase(GL_SHADER_STORAGE_BUFFER, LIFE_POSITIONS);
  m_accel.bindBase(GL_SHADER_STORAGE_BUFFER, LIFE_ACCELERATIONS);
  m_table.bindBase(GL_SHADER_STORAGE_BUFFER, LIFE_FORCE_TABLE);
  m_grid->cellStart().bindBase(GL_SHADER_STORAGE_BUFFER, LIFE_CELL_START);
  if (countPairs) m_groupPairs.bindBase(GL_SHADER_STORAGE_BUFFER, LIFE_GROUP_PAIRS);
  forces.dispatchThreads(m_count, {m_grid->uniforms(), pairUniforms()});
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
}

void Life::integrate(const char* variant, float dt) {
  std::vector<gl::ShaderDefine> d = defines();
  if (*variant) d.push_back({variant, "1"});
  const gl::Kernel<IntegrateUniforms> pass(m_shaders, "life/integrate.comp",
                                           {LIFE_POSITIONS, LIFE_VELOCITIES, LIFE_ACCELERATIONS}, d);
  m_pos[m_current].bindBase(GL_SHADER_STORAGE_BUFFER, LIFE_POSITIONS);
  m_vel[m_current].bindBase(GL_SHADER_STORAGE_BUFFER, LIFE_VELOCITIES);
  m_accel.bindBase(GL_SHADER_STORAGE_BUFFER, LIFE_ACCELERATIONS);
  pass.dispatchThreads(m_count, {.boxSize = m_rules.size,
                                 .count = GLuint(m_count),
                                 .dt = dt,
                                 .damping = float(std::exp(-double(m_rules.friction) * dt)),
                                 .pushPoint = m_pushPoint,
                                 .pushVelocity = m_pushVelocity,
                                 .pushRadius = m_pushRadius});
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_VERTEX_ATTRIB_ARRAY_BARRIER_BIT);
}

void Life::stepOnce(float dt) {
  applyStorage();
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
  m_lastDt = dt;
  ++m_steps;
}

void Life::step(gl::GpuProfiler& profiler) {
  {
    auto scope = profiler.scope("life.step");
    stepOnce(m_params.maxDt);
  }
  watch();
}

double Life::speedBound() const {
  // A particle that moves more than a cell (>= the largest force radius) per step passes
  // neighbours without feeling them; ten cells per step is no particle life any more.
  return kCellsPerStepBound * double(m_grid->params().cellSize) / double(m_lastDt > 0 ? m_lastDt : m_params.maxDt);
}

std::vector<sim::StateBuffer> Life::stateBuffers() {
  return {{"positions", &m_pos[m_current], m_pos[m_current].size()},
          {"velocities", &m_vel[m_current], m_vel[m_current].size()}};
}

void Life::checkHealth(const gl::Window& w) {
  const gl::Kernel<sim::HealthUniforms> health(m_shaders, "life/health.comp",
                                               {HEALTH_BINDING, LIFE_POSITIONS, LIFE_VELOCITIES}, defines());
  positions().bindBase(GL_SHADER_STORAGE_BUFFER, LIFE_POSITIONS);
  velocities().bindBase(GL_SHADER_STORAGE_BUFFER, LIFE_VELOCITIES);
  health.dispatchThreads(w.count, sim::HealthUniforms(w));
}

std::optional<std::string> Life::unhealthy(const sim::DivergenceWatch::Words& w) {
  if (auto what = sim::DivergenceWatch::nonFinite(w, "particles")) return what;
  const float maxSpeed = sim::DivergenceWatch::largest(w);
  if (maxSpeed <= speedBound()) return std::nullopt;
  char what[200];
  std::snprintf(what, sizeof what, "a particle moves at %.3g units/s, more than 10 grid cells per step (%.3g units/s)",
                double(maxSpeed), speedBound());
  return what;
}

std::string Life::method() const {
  char method[160];
  std::snprintf(method, sizeof method, "%s, %s, dt = %.3g s", kIntegratorNames[int(m_params.integrator)],
                kStorageNames[int(m_storage)], double(m_lastDt));
  return method;
}

void Life::resume(const sim::StateStamp& good) {
  m_time = good.time;
  m_steps = good.steps;
  m_needAccel = true;                                 // Verlet re-evaluates a(x) for the restored state
  m_params.maxDt = std::max(0.5f * m_lastDt, 1e-4f);  // each frame is one step of maxDt: halve what ran
  m_lastDt = m_params.maxDt;
}

void Life::visitOwnState(sim::StateVisitor& v) {
  v.clock(m_time, m_steps);
  Storage storage = m_storage;
  v.choice("model.storage", storage, kStorageNames.size());
  if (v.loading() && storage != m_storage) {  // the buffers as they were, whatever params().storage says now
    m_storage = storage;
    makeGrid();
    allocate();
  }
  std::size_t count = m_count;
  v.count("model.count", count, m_count);
  if (count != m_count)
    v.fail("entry 'model.count' = " + std::to_string(count) + ", the rules have " + std::to_string(m_count) +
           " particles");
  v.flag("model.need_accel", m_needAccel);
  sim::finiteValue(v, "model.push_point", m_pushPoint);
  sim::finiteValue(v, "model.push_velocity", m_pushVelocity);
  sim::finiteValue(v, "model.push_radius", m_pushRadius);
  sim::finiteValue(v, "model.last_dt", m_lastDt);
  if (v.loading()) {
    m_current = 0;
    if (m_trackIds) resetIds();
  }
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
  std::snprintf(buf, sizeof buf, "%zu particles, %d species, box %gx%g, grid %ux%u (cell %.3g), %s%s%s", m_count,
                m_rules.speciesCount(), double(m_rules.size.x), double(m_rules.size.y), dims.x, dims.y,
                double(m_grid->params().cellSize), m_rules.loopingBorders ? "looping" : "walls",
                m_params.integrator == Integrator::Verlet ? ", Verlet" : "",
                m_storage == Storage::Fp16 ? ", fp16 state" : "");
  return buf;
}

}  // namespace tidepool::life
