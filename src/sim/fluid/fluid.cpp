#include "sim/fluid/fluid.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>

#include "base/error.h"
#include "fluid/bindings.glsl"
#include "sim/particle_memory.h"
#include "sim/state_checks.h"
#include "sim/water/water_init.h"

namespace tidepool::fluid {
namespace {
constexpr std::size_t kMaxCheckpointParticles = std::size_t(4) << 20;  // larger runs keep no copy to go back to

// Particles a fill would make, from its volume (one per d³), before making them.
double estimatedParticles(const water::Setup& w, float spacing) {
  if (w.fill == water::Fill::None || w.fill == water::Fill::Random || w.fill == water::Fill::Lattice)
    return water::estimatedWater(w);
  return water::fillVolume(w) / std::pow(double(spacing), 3.0);
}

// The initial water: blocks and slabs on a cubic lattice that tiles the region exactly (particle
// centres half a spacing inside its faces), the other fills as sim/water/water_init.h makes them.
std::vector<glm::vec4> fill(const water::Setup& w, float spacing, const std::function<bool(glm::vec3)>& occupied) {
  if (w.fill != water::Fill::Block && w.fill != water::Fill::Slab) return water::waterParticles(w, occupied);
  glm::vec3 lo = glm::max(w.fillMin, w.domainMin), hi = glm::min(w.fillMax, w.domainMax);
  if (w.fill == water::Fill::Slab) {
    lo = w.domainMin;
    hi = glm::vec3(w.domainMax.x, w.domainMax.y, std::min(w.domainMax.z, w.domainMin.z + w.slabHeight));
  }
  const glm::ivec3 n = glm::max(glm::ivec3(glm::floor((hi - lo) / spacing + 1e-4f)), glm::ivec3(0));
  std::vector<glm::vec4> out;
  out.reserve(std::size_t(n.x) * std::size_t(n.y) * std::size_t(n.z));
  for (int k = 0; k < n.z; ++k)
    for (int j = 0; j < n.y; ++j)
      for (int i = 0; i < n.x; ++i) {
        const glm::vec3 q = lo + spacing * (glm::vec3(i, j, k) + 0.5f);
        if (!occupied || !occupied(q)) out.emplace_back(q, 1.0f);
      }
  return out;
}
}  // namespace

Fluid::Fluid(gl::ShaderLibrary& shaders, const Params& params)
    : Model(shaders, "fluid", kMaxCheckpointParticles),
      m_shaders(shaders),
      m_params(params),
      m_obstacles(shaders),
      m_probe(shaders),
      m_loads(shaders, FLUID_GROUP_SIZE),
      m_coupling(m_loads, m_obstacles) {
  // Obstacle particles weigh in the density sum with their rest volumes (rest_lattice.h).
  m_obstacles.setVolumes([this](const water::ObstacleBody& b) {
    return boundaryVolumes(b.particles, b.built.shell, m_params.h(), m_solidVolume);
  });
  reset();
}

void Fluid::calibrate() {
  if (m_restSpacing == m_params.spacing() && m_restSmoothing == m_params.smoothing) return;
  m_rest = restLattice(m_params.spacing(), m_params.h(), Packing::Cubic);
  m_solidVolume = restLattice(m_params.spacing(), m_params.h(), Packing::Hcp).volume;
  m_restSpacing = m_params.spacing();
  m_restSmoothing = m_params.smoothing;
  m_obstacles.refreshVolumes();
}

// GPU: x, v, p, two scratch arrays (vec4 each), λ (two floats), the permutation, the grid's cell,
// index in cell and stable members (a word each). Host: the initial water (vec4) and the lattice
// it is cut from (vec4).
sim::ParticleCost Fluid::cost() const {
  return {.maxParticles = std::size_t(m_params.maxParticles),
          .arrayBytes = sizeof(glm::vec4),
          .gpuBytes = 5 * sizeof(glm::vec4) + 3 * sizeof(float) + 4 * sizeof(GLuint),
          .hostBytes = 2 * sizeof(glm::vec4)};
}

void Fluid::allocate(std::size_t count, std::size_t capacity) {
  const std::size_t n = std::max<std::size_t>(capacity, 1), bytes = n * sizeof(glm::vec4);
  sim::checkParticleRequest("fluid", "particle", double(capacity), std::to_string(capacity) + " particles requested",
                            cost(), "lower it or raise max_particles");
  m_count = count;
  if (m_capacity == capacity && m_x.size() == bytes) return;
  m_x = gl::Buffer(bytes);
  m_v = gl::Buffer(bytes);
  m_pred = gl::Buffer(bytes);
  for (gl::Buffer& s : m_scratch) s = gl::Buffer(bytes);
  m_lambda = gl::Buffer(n * 2 * sizeof(float));
  m_lambdaSum = gl::Buffer(n * sizeof(float));
  m_permutation = gl::Buffer(n * sizeof(GLuint));
  m_capacity = capacity;
}

void Fluid::reset() {
  const water::Setup& w = m_params;
  if (glm::any(glm::lessThanEqual(w.domainMax, w.domainMin)))
    throw Error("fluid: domain_max must exceed domain_min on every axis");
  // First the count, from the fill's volume: a spacing that asks for 10^11 particles fails here,
  // with the numbers, before any array is built.
  char spacing[48];
  std::snprintf(spacing, sizeof spacing, "particles.spacing = %g m", double(m_params.spacing()));
  water::checkWaterRequest("fluid", "particle", spacing, estimatedParticles(w, m_params.spacing()), w, cost());
  m_restSpacing = m_restSmoothing = 0;
  calibrate();
  m_obstacles.build(w.obstacles, w.radius);  // first: a bad mesh fails before anything is allocated
  m_coupling.reset(w.obstacles);
  m_obstacles.place(w.obstacles, bodies().poses(w.obstacles, 0.0), w.domainMin, w.domainMax);
  const std::vector<glm::vec4> water =
      fill(w, m_params.spacing(), [this](glm::vec3 q) { return m_obstacles.occupied(q); });
  allocate(water.size(), water.size() + (w.tap ? std::size_t(w.tapMax) : 0));
  m_tapEmitted = 0;
  m_tapNextLayer = 0;
  restartWatch();
  m_x.upload(water.data(), water.size() * sizeof(glm::vec4));
  m_v.fillZero();
  m_time = 0;
  m_steps = 0;
  m_densitiesValid = false;
  m_loadsOn = false;
  grid::GridParams gp{
      .domainMin = w.domainMin, .domainMax = w.domainMax, .cellSize = cellSize(), .stable = w.deterministic};
  m_grid = std::make_unique<grid::UniformGrid>(m_shaders, gp, m_capacity);
  m_obstacleError.clear();
  m_walls = water::wallsAt(w, 0.0);
}

void Fluid::emitFromTap() {
  const water::Setup& w = m_params;
  if (!w.tap || m_tapEmitted >= std::size_t(w.tapMax) || m_time < m_tapNextLayer || w.tapSpeed <= 0) return;
  // The jet at the fluid's rest density (one particle per d³): hexagonal layers of spacing s, one
  // every s of travel (a stack of hexagonal prisms, 2/√3 particles per s³), so s = d·(2/√3)^(1/3).
  // The balls' layers (s = 2r·1.02 at r = d/2, 0.82 s apart) would start the jet 60% compressed
  // and burst it into spray.
  const float s = m_params.spacing() * std::cbrt(2.0f / std::sqrt(3.0f));
  const water::TapLayer layer =
      water::tapLayer(w, s / 2.04f, std::min(std::size_t(w.tapMax) - m_tapEmitted, m_capacity - m_count));
  if (layer.pos.empty()) return;
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);  // shader writes land before the uploads
  const std::size_t at = m_count * sizeof(glm::vec4), bytes = layer.pos.size() * sizeof(glm::vec4);
  m_x.upload(layer.pos.data(), bytes, at);
  m_v.upload(layer.vel.data(), bytes, at);
  m_count += layer.pos.size();
  m_tapEmitted += layer.pos.size();
  m_tapNextLayer = m_time + s / w.tapSpeed;
}

float Fluid::domainRotation() const { return water::domainRotation(m_params, m_time); }

glm::vec3 Fluid::gravity() const { return water::gravityAt(m_params, m_time); }

double Fluid::speedBound() const { return m_params.h() / m_params.dt; }

std::string Fluid::status() const {
  char buf[200];
  std::snprintf(buf, sizeof buf, "%zu particles + %zu boundary, d = %.4g m, h = %.4g m, m = %.4g kg", m_count,
                obstacleCount(), double(m_params.spacing()), m_params.h(), mass());
  return m_obstacleError.empty() ? std::string(buf) : m_obstacleError + "\n" + buf;
}

std::vector<sim::StateBuffer> Fluid::stateBuffers() {
  const std::size_t bytes = m_count * sizeof(glm::vec4);
  std::vector<sim::StateBuffer> buffers = {{"positions", &m_x, bytes}, {"velocities", &m_v, bytes}};
  if (const auto bodies = m_coupling.stateBuffer(loadScale())) buffers.push_back(*bodies);
  return buffers;
}

Stats Fluid::stats() {
  return m_probe.measure(*this, {m_params.spacing(), m_params.smoothing, m_params.restDensity, Packing::Cubic},
                         gravity(), m_time);
}

void Fluid::checkHealth(const gl::Window& w) {
  const gl::Kernel<water::HealthUniforms> health(m_shaders, "fluid/health.comp",
                                                 {HEALTH_BINDING, FLUID_POS, FLUID_VEL_IN});
  m_x.bindBase(GL_SHADER_STORAGE_BUFFER, FLUID_POS);
  m_v.bindBase(GL_SHADER_STORAGE_BUFFER, FLUID_VEL_IN);
  health.dispatchThreads(w.count, {sim::HealthUniforms(w), m_walls.min, m_walls.max});
}

std::optional<std::string> Fluid::unhealthy(const sim::DivergenceWatch::Words& words) {
  return sim::DivergenceWatch::particles(words, "fluid particles", "particle", "h per step", speedBound());
}

std::string Fluid::method() const {
  char method[160];
  std::snprintf(method, sizeof method, "PBF, %d iterations, dt = %.3g s", m_params.iterations, m_params.dt);
  return method;
}

void Fluid::resume(const sim::StateStamp& good) {
  m_count = good.count;
  m_time = good.time;
  m_steps = good.steps;
  m_densitiesValid = false;
  m_coupling.restored();  // the watch's copy of the bodies' states
  m_params.dt *= 0.5f;
  m_params.substeps = std::min(m_params.substeps * 2, 1000);  // same simulated time per frame
}

void Fluid::visitOwnState(sim::StateVisitor& v) {
  v.clock(m_time, m_steps);
  if (v.loading()) {
    m_densitiesValid = false;  // λ is not saved: the next step makes it anew
    m_coupling.restored();     // the bodies' states come with the state buffers
  }
  sim::capacityEntry(v, m_capacity, [&](std::size_t capacity) { allocate(0, capacity); });
  v.count("model.count", m_count, m_capacity);
  v.count("model.tap_emitted", m_tapEmitted, m_capacity);
  sim::finiteValue(v, "model.tap_next_layer", m_tapNextLayer);
  if (v.loading()) m_walls = water::wallsAt(m_params, m_time);  // as the last step left them, for the watch
}

std::size_t Fluid::bytesPerParticle() const {
  if (m_count == 0) return 0;
  const std::size_t own = m_x.size() + m_v.size() + m_pred.size() + m_scratch[0].size() + m_scratch[1].size() +
                          m_lambda.size() + m_lambdaSum.size() + m_permutation.size() +
                          (m_loadsOn ? m_loads.bytes() + m_unpushed.size() : 0);
  return (own + m_grid->memoryBytes()) / m_count;
}

void Fluid::upload(const std::vector<glm::vec4>& pos, const std::vector<glm::vec4>& vel) {
  if (pos.size() != vel.size()) throw Error("fluid: upload needs as many velocities as positions");
  allocate(pos.size(), std::max(pos.size(), m_capacity));
  m_x.upload(pos.data(), pos.size() * sizeof(glm::vec4));
  m_v.upload(vel.data(), vel.size() * sizeof(glm::vec4));
  m_densitiesValid = false;
  restartWatch();
}

}  // namespace tidepool::fluid
