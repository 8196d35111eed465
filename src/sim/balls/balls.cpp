#include "sim/balls/balls.h"

#include <cmath>
#include <cstdio>
#include <cstring>
#include <glm/gtc/matrix_transform.hpp>

#include "balls/bindings.glsl"
#include "balls/stats_layout.glsl"
#include "base/error.h"
#include "sim/particle_memory.h"
#include "sim/state_checks.h"
#include "sim/water/water_frame.h"
#include "sim/water/water_init.h"

namespace tidepool::balls {
namespace {
constexpr std::size_t kMaxCheckpointBalls = std::size_t(4) << 20;  // larger runs keep no copy to go back to
}  // namespace

Balls::Balls(gl::ShaderLibrary& shaders, const Params& params)
    : Model(shaders, "balls", kMaxCheckpointBalls),
      m_shaders(shaders),
      m_params(params),
      m_obstacles(shaders),
      m_loads(shaders, BALLS_GROUP_SIZE),
      m_coupling(m_loads, m_obstacles) {
  reset();
}

// GPU: positions and velocities twice (vec4 each), with velocity Verlet the accelerations, the
// grid's cell, index in cell and stable members (a word each). Host: the initial water (vec4) and its lattice
// (vec3). The vec4 arrays may pass one storage block (they are bound a window at a time:
// gl/window.h) but not gl::kMaxWindowedBufferBytes; the words are bound whole.
sim::ParticleCost Balls::cost() const {
  const bool verlet = m_params.integrator == Integrator::VelocityVerlet;
  return {.maxParticles = std::size_t(m_params.maxParticles),
          .arrayBytes = sizeof(GLuint),
          .windowedBytes = sizeof(glm::vec4),
          .gpuBytes = (verlet ? 5 : 4) * sizeof(glm::vec4) + 3 * sizeof(GLuint),
          .hostBytes = sizeof(glm::vec4) + sizeof(glm::vec3)};
}

void Balls::allocate(std::size_t count, std::size_t capacity) {
  const std::size_t bytes = std::max<std::size_t>(capacity, 1) * sizeof(glm::vec4);
  sim::checkParticleRequest("balls", "ball", double(capacity), std::to_string(capacity) + " balls requested", cost(),
                            "lower it or raise max_particles");
  m_count = count;
  if (m_capacity == capacity && m_pos[0].size() == bytes) return;
  for (int k = 0; k < 2; ++k) {
    m_pos[k] = gl::Buffer(bytes);
    m_vel[k] = gl::Buffer(bytes);
  }
  m_acc = gl::Buffer();  // accelerations(), permutation(): when needed
  m_accValid = false;
  m_permutation = gl::Buffer();
  m_stats = gl::Buffer(((capacity + BALLS_GROUP_SIZE - 1) / BALLS_GROUP_SIZE + 1) * BALLS_STATS_VALUES * sizeof(float));
  m_capacity = capacity;
}

void Balls::reset() {
  const water::Setup p = resolved(m_params);
  if (glm::any(glm::lessThanEqual(p.domainMax, p.domainMin)))
    throw Error("balls: domain_max must exceed domain_min on every axis");
  // First the count, from the fill's volume: a radius that asks for 10^11 balls fails here, with
  // the numbers, before any array is built.
  char radius[48];
  std::snprintf(radius, sizeof radius, "particles.radius = %g m", double(p.radius));
  water::checkWaterRequest("balls", "ball", radius, water::estimatedWater(p), p, cost());
  m_obstacles.build(m_params.obstacles, p.radius);  // a bad mesh fails before anything is allocated
  m_radius = p.radius;
  m_coupling.reset(m_params.obstacles);
  m_obstacles.place(m_params.obstacles, bodies().poses(m_params.obstacles, 0.0), p.domainMin, p.domainMax);
  const std::vector<glm::vec4> water =
      water::waterParticles(p, [this](glm::vec3 q) { return m_obstacles.occupied(q); });
  allocate(water.size(), water.size() + (m_params.tap ? std::size_t(m_params.tapMax) : 0));
  m_tapEmitted = 0;
  m_tapNextLayer = 0;
  restartWatch();
  m_pos[0].upload(water.data(), water.size() * sizeof(glm::vec4));
  m_vel[0].fillZero();
  if (m_acc.size()) m_acc.fillZero();
  m_posIndex = m_velIndex = 0;
  m_time = 0;
  m_accValid = m_loadsValid = false;
  m_grid.reset();
  ensureGrid();
  m_obstacleError.clear();
  updateWalls();
}

void Balls::emitFromTap() {
  const Params& p = m_params;
  if (!p.tap || m_tapEmitted >= std::size_t(p.tapMax) || m_time < m_tapNextLayer || p.tapSpeed <= 0) return;
  // One layer of the nozzle disc, then wait until the jet has moved on by a spacing.
  const water::TapLayer layer =
      water::tapLayer(p, m_radius, std::min(std::size_t(p.tapMax) - m_tapEmitted, m_capacity - m_count));
  if (layer.pos.empty()) return;
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);  // shader writes land before the uploads
  const std::size_t at = m_count * sizeof(glm::vec4), bytes = layer.pos.size() * sizeof(glm::vec4);
  m_pos[m_posIndex].upload(layer.pos.data(), bytes, at);
  m_vel[m_velIndex].upload(layer.vel.data(), bytes, at);
  if (m_acc.size()) {  // Verlet: a = 0 until the next evaluation
    const std::vector<glm::vec4> zeros(layer.pos.size(), glm::vec4(0.0f));
    m_acc.upload(zeros.data(), bytes, at);
  }
  m_count += layer.pos.size();
  m_tapEmitted += layer.pos.size();
  m_tapNextLayer = m_time + layer.interval;
}

glm::vec3 Balls::gravity() const { return water::gravityAt(resolved(m_params), m_time); }

float Balls::domainRotation() const { return water::domainRotation(m_params, m_time); }

void Balls::updateWalls() {
  const water::Walls w = water::wallsAt(m_params, m_time);
  m_wallMin = w.min;
  m_wallMax = w.max;
  m_wallMinVel = w.minVel;
  m_wallMaxVel = w.maxVel;
}

double Balls::speedBound() const { return 2.0 * m_radius / m_params.dt; }

std::string Balls::status() const {
  char buf[160];
  std::snprintf(buf, sizeof buf, "%zu balls + %zu fixed, r = %.4g m", m_count, obstacleCount(), m_radius);
  // A refused obstacle edit (a missing or open mesh) stays in view until the next edit.
  return m_obstacleError.empty() ? std::string(buf) : m_obstacleError + "\n" + buf;
}

std::vector<sim::StateBuffer> Balls::stateBuffers() {
  const std::size_t bytes = m_count * sizeof(glm::vec4);
  std::vector<sim::StateBuffer> buffers = {{"positions", &m_pos[m_posIndex], bytes},
                                           {"velocities", &m_vel[m_velIndex], bytes}};
  if (const auto bodies = m_coupling.stateBuffer(-mass())) buffers.push_back(*bodies);
  return buffers;
}

std::vector<gl::Window> Balls::healthWindows(std::size_t count) const { return gl::windows(count, sizeof(glm::vec4)); }

void Balls::checkHealth(const gl::Window& w) {
  const gl::Kernel<water::HealthUniforms> health(m_shaders, "balls/health.comp",
                                                 {HEALTH_BINDING, BALLS_POS_IN, BALLS_VEL_IN});
  gl::bindWindow(positions(), BALLS_POS_IN, w, sizeof(glm::vec4));
  gl::bindWindow(velocities(), BALLS_VEL_IN, w, sizeof(glm::vec4));
  health.dispatchThreads(w.count, {sim::HealthUniforms(w), m_wallMin, m_wallMax});
}

std::optional<std::string> Balls::unhealthy(const sim::DivergenceWatch::Words& w) {
  return sim::DivergenceWatch::particles(w, "balls", "ball", "its diameter per step", speedBound());
}

std::string Balls::method() const {
  char method[160];
  std::snprintf(method, sizeof method, "%s contacts, %s, dt = %.3g s", kContactNames[int(m_params.contact)],
                kIntegratorNames[int(m_params.integrator)], m_params.dt);
  return method;
}

void Balls::resume(const sim::StateStamp& good) {
  m_count = good.count;
  m_time = good.time;
  m_accValid = m_loadsValid = false;  // Verlet re-evaluates a(x) for the restored state
  m_coupling.restored();              // the watch's copy of the bodies' states
  m_params.dt *= 0.5f;
  m_params.substeps = std::min(m_params.substeps * 2, 1000);  // same simulated time per frame
}

void Balls::visitOwnState(sim::StateVisitor& v) {
  std::uint64_t steps = 0;
  v.clock(m_time, steps);
  sim::capacityEntry(v, m_capacity, [&](std::size_t capacity) { allocate(0, capacity); });
  v.count("model.count", m_count, m_capacity);
  v.count("model.tap_emitted", m_tapEmitted, m_capacity);
  sim::finiteValue(v, "model.tap_next_layer", m_tapNextLayer);
  v.flag("model.acc_valid", m_accValid);
  if (m_accValid) v.buffer("model.accelerations", accelerations(), m_count * sizeof(glm::vec4));
  if (v.loading()) {
    m_loadsValid = false;
    m_coupling.restored();  // the bodies' states come with the state buffers
    ensureGrid();
    updateWalls();
  }
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
  m_accValid = m_loadsValid = false;
  ensureGrid();
  restartWatch();  // a new state: nothing judged yet
}

gl::Buffer& Balls::accelerations() {
  const std::size_t bytes = std::max<std::size_t>(m_capacity, 1) * sizeof(glm::vec4);
  if (m_acc.size() != bytes) {
    m_acc = gl::Buffer(bytes);
    m_acc.fillZero();  // allocate() voided m_accValid; a restore loads the buffer next
  }
  return m_acc;
}

gl::Buffer& Balls::permutation() {
  const std::size_t bytes = std::max<std::size_t>(m_capacity, 1) * sizeof(GLuint);
  if (m_permutation.size() != bytes) m_permutation = gl::Buffer(bytes);
  return m_permutation;
}

std::vector<GLuint> Balls::lastOrder() const {
  if (m_permutation.size() < m_count * sizeof(GLuint))
    throw Error("balls: the order of the last step is kept only with trackOrder(true) before the step");
  return m_permutation.read<GLuint>(m_count);
}

// The grid's cells of 2r reach every pair of balls in contact: made again when the radius changes.
void Balls::ensureGrid() {
  const float cell = 2.0f * m_radius;
  if (m_grid && m_grid->params().cellSize == cell) return;
  const water::Setup p = resolved(m_params);
  grid::GridParams gp{.domainMin = p.domainMin, .domainMax = p.domainMax, .cellSize = cell, .stable = p.deterministic};
  m_grid = std::make_unique<grid::UniformGrid>(m_shaders, gp, m_capacity);
  m_countedAhead = {};  // a new grid counted nothing (it may reuse the old one's address)
}

std::vector<double> Balls::pressures(const std::vector<glm::vec3>&) {
  throw Error(
      "balls: a pressure probe reads the fluid solver's pressure, which the balls do not have; run the scene "
      "as fluid (\"model\": \"fluid\")");
}

void Balls::beginLoads() {
  const water::LoadsWanted want = water::loadsWanted(m_params.probes, m_coupling.any());
  m_loadsOn = want.any;
  if (m_loadsOn) m_loads.begin(m_count, want.walls, m_obstacles);
}

double Balls::mass() const {
  return double(m_params.restDensity) * water::volumePerParticle(m_radius, Params::kPacking);
}

water::Loads Balls::loads() {
  if (!m_loadsValid) return water::Loads::unmeasured(m_obstacles.size());  // no step since reset, or none that measured
  water::Loads out = m_loads.read(-mass());
  if (!m_loads.walls() || m_params.contact == Contact::CudaSample) out.unmeasuredWalls();
  return out;
}

}  // namespace tidepool::balls
