#include "sim/balls/balls.h"

#include <cmath>
#include <cstdio>
#include <cstring>
#include <glm/gtc/matrix_transform.hpp>

#include "balls/bindings.glsl"
#include "base/error.h"
#include "sim/balls/balls_init.h"

namespace tidepool::balls {
namespace {
constexpr float kPi = 3.14159265358979f;
constexpr int kGroup = 128;                                        // local size of the balls kernels
constexpr int kStatsValues = 10;                                   // per work group, see shaders/balls/stats.comp
constexpr std::size_t kMaxCheckpointBalls = std::size_t(4) << 20;  // larger runs keep no copy to go back to

std::string mib(std::size_t bytes) { return std::to_string((bytes + (1 << 20) - 1) >> 20) + " MiB"; }
}  // namespace

Balls::Balls(gl::ShaderLibrary& shaders, const Params& params)
    : m_shaders(shaders), m_ops(shaders), m_params(params), m_obstacles(shaders) {
  reset();
}

void Balls::allocate(std::size_t count, std::size_t capacity) {
  if (capacity > std::size_t(m_params.maxParticles))
    throw Error("balls: " + std::to_string(capacity) +
                " balls requested, more than max_particles = " + std::to_string(m_params.maxParticles));
  const std::size_t bytes = std::max<std::size_t>(capacity, 1) * sizeof(glm::vec4);
  GLint64 maxBlock = 0;
  glGetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &maxBlock);
  if (bytes > std::size_t(maxBlock))
    throw Error("balls: " + std::to_string(capacity) + " balls need " + mib(bytes) +
                " per state array, more than this GPU's storage-buffer limit of " + mib(std::size_t(maxBlock)));
  const std::size_t total = bytes * 5 + capacity * 8;
  if (GLAD_GL_NVX_gpu_memory_info) {
    GLint freeKb = 0;
    glGetIntegerv(GL_GPU_MEMORY_INFO_CURRENT_AVAILABLE_VIDMEM_NVX, &freeKb);
    if (freeKb > 0 && total > std::size_t(freeKb) * 1024)
      throw Error("balls: " + std::to_string(capacity) + " balls need about " + mib(total) + ", but only " +
                  mib(std::size_t(freeKb) * 1024) + " of GPU memory are free");
  }
  m_count = count;
  if (m_capacity == capacity && m_pos[0].size() == bytes) return;
  for (int k = 0; k < 2; ++k) {
    m_pos[k] = gl::Buffer(bytes);
    m_vel[k] = gl::Buffer(bytes);
  }
  m_acc = gl::Buffer(bytes);
  m_permutation = gl::Buffer(std::max<std::size_t>(capacity, 1) * sizeof(GLuint));
  m_stats = gl::Buffer(((capacity + kGroup - 1) / kGroup + 1) * kStatsValues * sizeof(float));
  m_capacity = capacity;
  m_health = gl::Buffer(4 * sizeof(GLuint));
  const bool checkpoints = capacity <= kMaxCheckpointBalls;
  for (gl::Buffer* b : {&m_pendingPos, &m_pendingVel, &m_goodPos, &m_goodVel})
    *b = checkpoints ? gl::Buffer(bytes) : gl::Buffer();
}

void Balls::reset() {
  const Params p = resolved(m_params);
  if (glm::any(glm::lessThanEqual(p.domainMax, p.domainMin)))
    throw Error("balls: domain_max must exceed domain_min on every axis");
  m_obstacles.build(m_params.obstacles, p.radius);  // first: a bad mesh fails before anything is allocated
  m_radius = p.radius;
  m_obstacles.place(m_params.obstacles, 0.0, p.domainMin, p.domainMax);
  const std::vector<glm::vec4> water =
      waterParticles(m_params, [this](glm::vec3 q) { return m_obstacles.occupied(q); });
  allocate(water.size(), water.size() + (m_params.tap ? std::size_t(m_params.tapMax) : 0));
  m_tapEmitted = 0;
  m_tapNextLayer = 0;
  m_hasGood = false;
  m_divergence.reset();
  m_checks.restart();
  m_pos[0].upload(water.data(), water.size() * sizeof(glm::vec4));
  m_vel[0].fillZero();
  m_acc.fillZero();
  m_posIndex = m_velIndex = 0;
  m_time = 0;
  m_accValid = false;
  grid::GridParams gp{
      .domainMin = p.domainMin, .domainMax = p.domainMax, .cellSize = 2.0f * m_radius, .reorder = p.gridReorder};
  m_grid = std::make_unique<grid::UniformGrid>(m_shaders, gp, m_capacity);
  m_obstacleError.clear();
  updateWalls();
}

void Balls::emitFromTap() {
  const Params& p = m_params;
  if (!p.tap || m_tapEmitted >= std::size_t(p.tapMax) || m_time < m_tapNextLayer || p.tapSpeed <= 0) return;
  // One hexagonal layer of the nozzle disc, then wait until the jet has moved on by a spacing.
  const glm::vec3 dir = glm::length(p.tapDirection) > 0 ? glm::normalize(p.tapDirection) : glm::vec3(0, 0, 1);
  const glm::vec3 u = glm::normalize(std::abs(dir.z) < 0.9f ? glm::cross(dir, glm::vec3(0, 0, 1))
                                                            : glm::cross(dir, glm::vec3(1, 0, 0)));
  const glm::vec3 w = glm::cross(dir, u);
  const float s = 2.0f * m_radius * 1.02f;
  std::vector<glm::vec4> pos, vel;
  const int n = int(std::ceil(p.tapRadius / s));
  for (int j = -n; j <= n; ++j)
    for (int i = -n; i <= n; ++i) {
      const glm::vec2 q((float(i) + 0.5f * float(j & 1)) * s, float(j) * s * 0.8660254f);
      if (glm::length(q) > p.tapRadius + 1e-6f) continue;
      if (m_tapEmitted + pos.size() >= std::size_t(p.tapMax) || m_count + pos.size() >= m_capacity) break;
      pos.emplace_back(p.tapPosition + q.x * u + q.y * w, 1.0f);
      vel.emplace_back(p.tapSpeed * dir, 0.0f);
    }
  if (pos.empty()) return;
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);  // shader writes land before the uploads
  const std::size_t at = m_count * sizeof(glm::vec4), bytes = pos.size() * sizeof(glm::vec4);
  m_pos[m_posIndex].upload(pos.data(), bytes, at);
  m_vel[m_velIndex].upload(vel.data(), bytes, at);
  const std::vector<glm::vec4> zeros(pos.size(), glm::vec4(0.0f));
  m_acc.upload(zeros.data(), bytes, at);
  m_count += pos.size();
  m_tapEmitted += pos.size();
  m_tapNextLayer = m_time + s * 0.8165 / p.tapSpeed;  // HCP layer spacing 2r·√(2/3)
}

glm::vec3 Balls::gravity() const {
  const float a = domainRotation();
  const glm::vec3 g = resolved(m_params).gravity;
  return {g.x, std::cos(a) * g.y - std::sin(a) * g.z, std::sin(a) * g.y + std::cos(a) * g.z};
}

float Balls::domainRotation() const {
  return (m_params.rotation + m_params.rotationRate * float(m_time)) * kPi / 180.0f;
}

void Balls::updateWalls() {
  const Params& p = m_params;
  m_wallMin = p.domainMin;
  m_wallMax = p.domainMax;
  m_wallMinVel = m_wallMaxVel = glm::vec3(0.0f);
  if (p.pistonAxis >= 1 && p.pistonAxis <= 3) {
    // The max wall of the axis travels in and out: offset = travel·extent·(1 − cos(2πt/T))/2.
    const int k = p.pistonAxis - 1;
    const float extent = p.domainMax[k] - p.domainMin[k], w = 2.0f * kPi / p.pistonPeriod;
    const float t = float(m_time);
    m_wallMax[k] = p.domainMax[k] - p.pistonTravel * extent * 0.5f * (1.0f - std::cos(w * t));
    m_wallMaxVel[k] = -p.pistonTravel * extent * 0.5f * w * std::sin(w * t);
  }
}

std::vector<gl::ShaderDefine> Balls::defines(bool verlet) const {
  std::vector<gl::ShaderDefine> d;
  switch (m_params.contact) {
    case Contact::Penalty: d.push_back({"CONTACT_PENALTY", ""}); break;
    case Contact::CudaSample: d.push_back({"CONTACT_CUDA", ""}); break;
    case Contact::SpringDashpot: d.push_back({"CONTACT_SPRING", ""}); break;
  }
  if (verlet)
    d.push_back({"INTEGRATOR_VERLET", ""});
  else if (m_params.integrator == Integrator::ExplicitEuler)
    d.push_back({"INTEGRATOR_EXPLICIT", ""});
  if (m_obstacles.active()) d.push_back({"HAS_OBSTACLE", ""});
  return d;
}

void Balls::bindCommon(gl::Program& p) const {
  const Params& q = m_params;
  p.use();
  p.set("uCount", GLuint(m_count));
  p.set("uRadius", m_radius);
  p.set("uDt", q.dt);
  p.set("uGravity", gravity());
  p.set("uDecay", std::exp(-q.damping * q.dt));
  p.set("uPenaltyFactor", q.penaltyFactor);
  p.set("uSpringK1", springPerMass(q));
  p.set("uDashpotG1", dashpotPerMass(q));
  p.set("uFriction", q.friction);
  p.set("uCudaSpring", q.cudaSpring);
  p.set("uCudaDamping", q.cudaDamping);
  p.set("uCudaShear", q.cudaShear);
  p.set("uBoundaryDamping", q.cudaBoundaryDamping);
  p.set("uWallMin", m_wallMin);
  p.set("uWallMax", m_wallMax);
  p.set("uWallMinVel", m_wallMinVel);
  p.set("uWallMaxVel", m_wallMaxVel);
  p.set("uFoamGain", q.foamGain);
  p.set("uFoamDecay", std::pow(q.foamDecay, q.dt / 0.0005f));  // the seed's decay per 0.5 ms
  m_grid->setUniforms(p);
  if (m_obstacles.active()) m_obstacles.bind(p);
  m_grid->cellStart().bindBase(GL_SHADER_STORAGE_BUFFER, BALLS_CELL_START);
}

void Balls::gridAndCollide(gl::GpuProfiler* profiler, bool verlet, float kick) {
  auto scope = [&](const char* name) { return profiler ? profiler->scope(name) : gl::GpuProfiler::Scope(nullptr); };
  const int p = m_posIndex, v = m_velIndex;
  {
    auto s = scope("balls.count");
    m_grid->countParticles(m_pos[p], m_count);
  }
  {
    auto s = scope("balls.scan");
    m_grid->scanCells();
  }
  {
    auto s = scope("balls.reorder");
    m_grid->setReorderMode(m_params.gridReorder);  // may change while running
    m_grid->reorder(m_pos[p], {{&m_pos[p], &m_pos[1 - p]}, {&m_vel[v], &m_vel[1 - v]}},
                    m_trackOrder ? &m_permutation : nullptr);
  }
  auto s = scope("balls.collide");
  gl::Program& collide = m_shaders.program({"balls/collide.comp"}, defines(verlet));
  bindCommon(collide);
  m_pos[1 - p].bindBase(GL_SHADER_STORAGE_BUFFER, BALLS_POS_IN);
  m_vel[1 - v].bindBase(GL_SHADER_STORAGE_BUFFER, BALLS_VEL_IN);
  m_vel[v].bindBase(GL_SHADER_STORAGE_BUFFER, BALLS_VEL_OUT);
  if (verlet) {
    collide.set("uKick", kick);
    m_acc.bindBase(GL_SHADER_STORAGE_BUFFER, BALLS_ACC);
    m_posIndex = 1 - p;  // positions stay in cell order; velocities come back to v
  } else {
    m_pos[p].bindBase(GL_SHADER_STORAGE_BUFFER, BALLS_POS_OUT);
  }
  collide.dispatchThreads(m_count);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
}

void Balls::stepOnce(gl::GpuProfiler* profiler) {
  updateWalls();
  // Obstacles added, removed or reshaped while running are rebuilt; all are placed where they are
  // when the forces act: at t, or at t + dt for Verlet's forces on the drifted positions.
  if (std::string error; m_obstacles.update(m_params.obstacles, m_radius, error)) m_obstacleError = error;
  emitFromTap();
  const bool verlet = m_params.integrator == Integrator::VelocityVerlet;
  const auto placeObstacles = [&](double time, gl::GpuProfiler* p) {
    m_obstacles.place(m_params.obstacles, time, m_params.domainMin, m_params.domainMax, p);
  };
  if (verlet && !m_accValid && m_count > 0) {  // a(x0) for the first drift
    placeObstacles(m_time, nullptr);
    gridAndCollide(nullptr, true, 0.0f);
  }
  placeObstacles(verlet ? m_time + m_params.dt : m_time, profiler);
  if (m_count > 0) {
    if (verlet) {
      auto s = profiler ? profiler->scope("balls.drift") : gl::GpuProfiler::Scope(nullptr);
      gl::Program& drift = m_shaders.program({"balls/drift.comp"}, defines(false));
      bindCommon(drift);
      m_pos[m_posIndex].bindBase(GL_SHADER_STORAGE_BUFFER, BALLS_POS_OUT);
      m_vel[m_velIndex].bindBase(GL_SHADER_STORAGE_BUFFER, BALLS_VEL_OUT);
      m_acc.bindBase(GL_SHADER_STORAGE_BUFFER, BALLS_ACC);
      drift.dispatchThreads(m_count);
      glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    }
    gridAndCollide(profiler, verlet, 0.5f);
    m_accValid = verlet;
  }
  m_time += m_params.dt;
}

void Balls::step(gl::GpuProfiler& profiler) {
  for (int i = 0; i < m_params.substeps; ++i) stepOnce(&profiler);
  watch();
}

double Balls::speedBound() const { return 2.0 * m_radius / m_params.dt; }

void Balls::watch() {
  m_checks.frame(
      m_time, !m_divergence && m_count > 0, judgeFn(),
      [this] {
        m_health.fillZero();
        gl::Program& p = m_shaders.program({"balls/health.comp"});
        p.use();
        p.set("uCount", GLuint(m_count));
        p.set("uWallMin", m_wallMin);
        p.set("uWallMax", m_wallMax);
        positions().bindBase(GL_SHADER_STORAGE_BUFFER, BALLS_POS_IN);
        velocities().bindBase(GL_SHADER_STORAGE_BUFFER, BALLS_VEL_IN);
        m_health.bindBase(GL_SHADER_STORAGE_BUFFER, BALLS_STATS);
        p.dispatchThreads(m_count);
        glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
        if (m_pendingPos) {
          const std::size_t bytes = m_count * sizeof(glm::vec4);
          m_ops.copy(positions(), m_pendingPos, bytes);
          m_ops.copy(velocities(), m_pendingVel, bytes);
        }
        m_pendingCount = m_count;
      },
      m_health);
}

CheckCycle::Judge Balls::judgeFn() {
  return [this](const CheckCycle::Words& v, double time) { judge(v.data(), time); };
}

void Balls::judge(const GLuint v[4], double time) {
  const float maxSpeed = healthFloat(v[1]);
  if (v[0] == 0 && v[2] == 0 && maxSpeed <= speedBound()) {
    std::swap(m_pendingPos, m_goodPos);
    std::swap(m_pendingVel, m_goodVel);
    m_goodTime = time;
    m_goodCount = m_pendingCount;
    m_hasGood = bool(m_goodPos);
    return;
  }
  char what[160], method[160];
  if (v[0] > 0)
    std::snprintf(what, sizeof what, "%u balls are NaN or infinite", v[0]);
  else if (v[2] > 0)
    std::snprintf(what, sizeof what, "%u balls left the domain", v[2]);
  else
    std::snprintf(what, sizeof what, "a ball moves at %.3g m/s, more than its diameter per step (%.3g m/s)", maxSpeed,
                  speedBound());
  std::snprintf(method, sizeof method, "%s contacts, %s, dt = %.3g s", kContactNames[int(m_params.contact)],
                kIntegratorNames[int(m_params.integrator)], m_params.dt);
  m_divergence = divergenceReport("balls", time, what, method, m_hasGood);
}

bool Balls::recover() {
  if (!m_divergence || !m_hasGood) return false;
  const std::size_t bytes = m_goodCount * sizeof(glm::vec4);
  m_ops.copy(m_goodPos, m_pos[m_posIndex], bytes);
  m_ops.copy(m_goodVel, m_vel[m_velIndex], bytes);
  m_count = m_goodCount;
  m_time = m_goodTime;
  m_accValid = false;  // Verlet re-evaluates a(x) for the restored state
  m_params.dt *= 0.5f;
  m_params.substeps = std::min(m_params.substeps * 2, 1000);  // same simulated time per frame
  m_divergence.reset();
  m_checks.restart();
  return true;
}

void Balls::flushChecks() { m_checks.flush(judgeFn()); }

Stats Balls::stats() {
  Stats st;
  st.time = m_time;
  st.count = m_count;
  if (m_count == 0) return st;
  // The stats pass needs the balls in cell order: sort copies into the scratch buffers, leaving
  // the state (and Verlet's accelerations, which follow its order) untouched.
  const int p = m_posIndex, v = m_velIndex;
  m_grid->build(m_pos[p], m_count);
  m_grid->reorder(m_pos[p], {{&m_pos[p], &m_pos[1 - p]}, {&m_vel[v], &m_vel[1 - v]}});
  gl::Program& prog = m_shaders.program({"balls/stats.comp"}, defines(false));
  bindCommon(prog);
  prog.set("uDomainMin", m_params.domainMin);
  m_pos[1 - p].bindBase(GL_SHADER_STORAGE_BUFFER, BALLS_POS_IN);
  m_vel[1 - v].bindBase(GL_SHADER_STORAGE_BUFFER, BALLS_VEL_IN);
  m_stats.bindBase(GL_SHADER_STORAGE_BUFFER, BALLS_STATS);
  prog.dispatchThreads(m_count);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  const std::size_t groups = (m_count + kGroup - 1) / kGroup;
  const std::vector<float> partials = m_stats.read<float>(groups * kStatsValues);
  double front = -1e30, height = -1e30;
  double contacts = 0, overlapSum = 0;
  for (std::size_t g = 0; g < groups; ++g) {
    const float* x = &partials[g * kStatsValues];
    front = std::max(front, double(x[8]));
    height = std::max(height, double(x[9]));
    st.kinetic += x[0];
    st.potential += x[1];
    overlapSum += x[2];
    contacts += x[3];
    st.maxOverlap = std::max(st.maxOverlap, double(x[4]));
    st.maxSpeed = std::max(st.maxSpeed, double(x[5]));
    st.nonFinite += std::size_t(x[6]);
    st.outside += std::size_t(x[7]);
  }
  st.meanOverlap = contacts > 0 ? overlapSum / contacts : 0.0;
  st.front = front > -1e29 ? front : std::nan("");
  st.backHeight = height > -1e29 ? height : std::nan("");
  st.contactsPerBall = contacts / double(m_count);
  return st;
}

std::size_t Balls::bytesPerBall() const {
  if (m_count == 0) return 0;
  const std::size_t own = m_pos[0].size() * 2 + m_vel[0].size() * 2 + m_acc.size() + m_permutation.size();
  return (own + m_grid->memoryBytes()) / m_count;
}

void Balls::upload(const std::vector<glm::vec4>& pos, const std::vector<glm::vec4>& vel) {
  if (pos.size() != vel.size()) throw Error("balls: upload needs as many velocities as positions");
  allocate(pos.size(), std::max(pos.size(), m_capacity));
  m_posIndex = m_velIndex = 0;
  m_pos[0].upload(pos.data(), pos.size() * sizeof(glm::vec4));
  m_vel[0].upload(vel.data(), vel.size() * sizeof(glm::vec4));
  m_accValid = false;
}

std::vector<GLuint> Balls::lastOrder() const { return m_permutation.read<GLuint>(m_count); }

}  // namespace tidepool::balls
