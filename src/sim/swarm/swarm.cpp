#include "sim/swarm/swarm.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <glm/gtc/packing.hpp>

#include "base/error.h"
#include "gl/kernel.h"
#include "sim/state_checks.h"
#include "swarm/bindings.glsl"

namespace tidepool::sim {
namespace {

std::string mib(double bytes) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.0f MiB", bytes / (1024.0 * 1024.0));
  return buf;
}

constexpr std::size_t kMaxCheckpointParticles = std::size_t(16) << 20;  // larger runs keep no copy to go back to
constexpr int kMaxSubsteps = 64;                                        // of the "substeps" parameter
constexpr double kSpeedBoundFactor = 10;  // the watch's bound over the static field's largest speed

std::string countText(std::size_t n) {
  if (n % (1 << 20) == 0) return std::to_string(n >> 20) + "M";
  return std::to_string(n);
}

struct InitUniforms {
  GLuint count = 0, seed = 0;
  static constexpr auto fields() {
    return std::tuple{gl::field("uCount", &InitUniforms::count), gl::field("uSeed", &InitUniforms::seed)};
  }
};
struct StepUniforms {
  GLuint count = 0;
  float dt = 0.0f;                                               // simulated seconds
  float damping = 1.0f;                                          // exp(-friction * dt)
  glm::vec2 aspect{1.0f};                                        // (width / height, 1)
  GLint bounce = 0;                                              // 1: mirror walls at NDC +-1
  glm::vec2 gravity{0.0f};                                       // world units/s^2
  float epsilon = 0.0f;                                          // world units^2
  GLint attractorCount = 0;                                      // per level
  std::array<glm::vec4, 3 * SWARM_MAX_ATTRACTORS> attractors{};  // at the step's start, middle, end
  static constexpr auto fields() {
    using U = StepUniforms;
    return std::tuple{gl::field("uCount", &U::count),          gl::field("uDt", &U::dt),
                      gl::field("uDamping", &U::damping),      gl::field("uAspect", &U::aspect),
                      gl::field("uBounce", &U::bounce),        gl::field("uGravity", &U::gravity),
                      gl::field("uEpsilon", &U::epsilon),      gl::field("uAttractorCount", &U::attractorCount),
                      gl::field("uAttractors", &U::attractors)};
  }
};

}  // namespace

std::size_t swarmBytesPerParticle(Storage storage) { return storage == Storage::Fp16 ? 8 : 16; }

void checkSwarmFits(std::size_t count, Storage storage, std::size_t extraBytesPerParticle) {
  const double stateBytes = double(count) * double(swarmBytesPerParticle(storage));
  const char* name = kStorageNames[std::size_t(storage)];
  GLint64 maxBlock = 0;
  glGetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &maxBlock);
  if (maxBlock > 0 && stateBytes > double(maxBlock))
    throw Error("swarm: " + countText(count) + " particles need " + mib(stateBytes) + " of " + name +
                " state, more than this GPU's GL_MAX_SHADER_STORAGE_BLOCK_SIZE (" + mib(double(maxBlock)) +
                "); use fewer particles" + (storage == Storage::Fp32 ? " or storage \"fp16\"" : ""));
  if (GLAD_GL_NVX_gpu_memory_info) {
    GLint freeKb = 0;
    glGetIntegerv(GL_GPU_MEMORY_INFO_CURRENT_AVAILABLE_VIDMEM_NVX, &freeKb);
    const double need = stateBytes + double(count) * double(extraBytesPerParticle);
    if (freeKb > 0 && need > 0.9 * double(freeKb) * 1024.0)
      throw Error("swarm: " + countText(count) + " particles need " + mib(need) + " but only " +
                  mib(double(freeKb) * 1024.0) + " of GPU memory is free; use fewer particles");
  }
}

void visit(ParamVisitor& v, SwarmParams& p) {
  v.integer({"particles", "Particles", "particle count; changing it re-allocates and resets"}, p.particles, 1,
            kMaxSwarmParticles);
  v.choice({"storage", "Storage", "fp32: 16 B/particle; fp16 (packHalf2x16): 8 B, half the memory traffic"}, p.storage,
           kStorageNames);
  v.choice({"integrator", "Integrator", "explicit Euler, symplectic Euler (the seed's), velocity Verlet, RK4"},
           p.integrator, kIntegratorNames);
  v.realDouble(
      {"frame_seconds", "Frame seconds", "s one frame stands for; simulated time advances speed x this per frame"},
      p.frameSeconds, 1e-4f, 1.0f);
  v.real({"speed", "Speed", "simulated seconds per frame second (slow motion below 1)"}, p.speed, 0.0f, 4.0f);
  v.integer({"substeps", "Substeps", "integrator steps per frame"}, p.substeps, 1, kMaxSubsteps);
  v.real({"max_dt", "Max step", "s per integrator step at most, by adding substeps (0: off); method auto sets it"},
         p.maxDt, 0.0f, 1.0f);
  v.real({"gravity", "Gravity", "world units/s^2, downwards"}, p.gravity, 0.0f, 10.0f);
  v.real({"friction", "Friction", "1/s: velocity decays as exp(-friction t), whatever the frame rate"}, p.friction,
         0.0f, 10.0f);
  v.real({"epsilon", "Softening", "world units^2 added to |d|^2 in the attractor force"}, p.epsilon, 0.0f, 1.0f);
  v.flag({"bounce", "Bounce", "mirror walls at the image border; off: free flight"}, p.bounce);
  v.choice({"preset", "Attractors", "animated attractor preset"}, p.preset, kPresetNames);
  v.real({"mouse_strength", "Mouse strength", "attractor at the cursor while the left button is held; < 0 repels"},
         p.mouseStrength, -10.0f, 10.0f);
  v.integer({"seed", "Seed", "random initial positions"}, p.seed, 0, 1000000);
}

Swarm::Swarm(gl::ShaderLibrary& shaders, const SwarmParams& params)
    : Model(shaders, "swarm", kMaxCheckpointParticles), m_shaders(shaders), m_params(params) {
  reset();
}

void Swarm::allocate(std::size_t count, Storage storage) {
  if (count == m_count && storage == m_storage && m_state) return;
  checkSwarmFits(count, storage);
  m_state = gl::Buffer();  // free the old state before asking for the new one
  m_count = 0;
  m_state = gl::Buffer(count * swarmBytesPerParticle(storage));
  m_count = count;
  m_storage = storage;
}

void Swarm::reset() {
  allocate(std::size_t(m_params.particles), m_params.storage);
  m_time = 0.0;
  restartWatch();
  const gl::Kernel<InitUniforms> init(m_shaders, "swarm/swarm_init.comp", {SWARM_STATE_BINDING},
                                      {{"STORAGE_FP16", storageDefine()}});
  m_state.bindBase(GL_SHADER_STORAGE_BUFFER, SWARM_STATE_BINDING);
  init.dispatchThreads(m_count, {GLuint(m_count), GLuint(m_params.seed)});
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_VERTEX_ATTRIB_ARRAY_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
}

void Swarm::upload(std::span<const SwarmParticle> particles) {
  allocate(particles.size(), m_params.storage);
  m_params.particles = int(particles.size());  // a later reset() keeps this count
  m_time = 0.0;
  restartWatch();
  if (m_storage == Storage::Fp32) {
    m_state.upload(particles);
    return;
  }
  std::vector<glm::uvec2> packed(particles.size());
  for (std::size_t i = 0; i < particles.size(); ++i)
    packed[i] = {glm::packHalf2x16(particles[i].pos), glm::packHalf2x16(particles[i].vel)};
  m_state.upload(std::span<const glm::uvec2>(packed));
}

std::vector<SwarmParticle> Swarm::download() const {
  if (m_storage == Storage::Fp32) return m_state.read<SwarmParticle>(m_count);
  const std::vector<glm::uvec2> packed = m_state.read<glm::uvec2>(m_count);
  std::vector<SwarmParticle> out(m_count);
  for (std::size_t i = 0; i < m_count; ++i)
    out[i] = {glm::unpackHalf2x16(packed[i].x), glm::unpackHalf2x16(packed[i].y)};
  return out;
}

std::vector<Attractor> Swarm::attractorsAt(double t) const {
  std::vector<Attractor> all = presetAttractors(m_params.preset, t);
  all.insert(all.end(), m_extra.begin(), m_extra.end());
  if (m_mouse) all.push_back({*m_mouse, double(m_params.mouseStrength)});
  if (all.size() > SWARM_MAX_ATTRACTORS) all.resize(SWARM_MAX_ATTRACTORS);
  return all;
}

void Swarm::stepOnce(double dt) {
  // Forces at the start, middle and end of the step: RK4 needs all three, Verlet the first and last.
  const double times[3] = {m_time, m_time + 0.5 * dt, m_time + dt};
  StepUniforms u{.count = GLuint(m_count),
                 .dt = float(dt),
                 .damping = float(std::exp(-double(m_params.friction) * dt)),
                 .aspect = glm::vec2(float(m_aspect), 1.0f),
                 .bounce = m_params.bounce ? 1 : 0,
                 .gravity = glm::vec2(0.0f, -m_params.gravity),
                 .epsilon = m_params.epsilon};
  for (int level = 0; level < 3; ++level) {
    const std::vector<Attractor> at = attractorsAt(times[level]);
    u.attractorCount = int(at.size());
    for (std::size_t k = 0; k < at.size(); ++k)
      u.attractors[level * SWARM_MAX_ATTRACTORS + k] = glm::vec4(glm::vec2(at[k].pos), float(at[k].strength), 0.0f);
  }
  const gl::Kernel<StepUniforms> pass(
      m_shaders, "swarm/swarm_step.comp", {SWARM_STATE_BINDING},
      {{"INTEGRATOR", std::to_string(int(m_params.integrator))}, {"STORAGE_FP16", storageDefine()}});
  m_state.bindBase(GL_SHADER_STORAGE_BUFFER, SWARM_STATE_BINDING);
  pass.dispatchThreads(m_count, u);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_VERTEX_ATTRIB_ARRAY_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
  m_time += dt;
  m_lastDt = dt;
}

double Swarm::speedBound() const {
  double strength = std::abs(double(m_params.mouseStrength));
  for (const Attractor& a : attractorsAt(m_time)) strength += std::abs(a.strength);
  const double diagonal2 = 4.0 * (m_aspect * m_aspect + 1.0), eps = std::max(double(m_params.epsilon), 1e-6);
  const double fall = strength * std::log((diagonal2 + eps) / eps) + 4.0 * std::abs(double(m_params.gravity));
  return kSpeedBoundFactor * std::sqrt(fall);
}

void Swarm::step(gl::GpuProfiler& profiler) {
  {
    auto scope = profiler.scope("swarm.step");
    const int substeps = swarmSubsteps(m_params);
    const double dt = swarmFrameSeconds(m_params) / substeps;
    for (int s = 0; s < substeps; ++s) stepOnce(dt);
  }
  watch();
}

std::string Swarm::status() const {
  char buf[160];
  std::snprintf(buf, sizeof buf, "%zu particles, %s, %s, %.0f MiB state", m_count,
                kStorageNames[std::size_t(m_storage)], kIntegratorNames[std::size_t(m_params.integrator)],
                double(stateBytes()) / 1048576.0);
  return buf;
}

std::vector<StateBuffer> Swarm::stateBuffers() { return {{"state", &m_state, stateBytes()}}; }

void Swarm::checkHealth(const gl::Window& w) {
  const gl::Kernel<sim::HealthUniforms> health(m_shaders, "swarm/health.comp", {HEALTH_BINDING, SWARM_STATE_BINDING},
                                               {{"STORAGE_FP16", storageDefine()}});
  m_state.bindBase(GL_SHADER_STORAGE_BUFFER, SWARM_STATE_BINDING);
  health.dispatchThreads(w.count, sim::HealthUniforms(w));
}

std::optional<std::string> Swarm::unhealthy(const DivergenceWatch::Words& w) {
  if (auto what = DivergenceWatch::nonFinite(w, "particles")) return what;
  const float maxSpeed = DivergenceWatch::largest(w);
  if (maxSpeed <= speedBound()) return std::nullopt;
  char what[200];
  std::snprintf(what, sizeof what,
                "a particle moves at %.3g units/s, ten times what the attractors can give one at rest (%.3g units/s)",
                double(maxSpeed), speedBound());
  return what;
}

std::string Swarm::method() const {
  char method[160];
  std::snprintf(method, sizeof method, "%s, %s, dt = %.3g s", kIntegratorNames[std::size_t(m_params.integrator)],
                kStorageNames[std::size_t(m_storage)], m_lastDt);
  return method;
}

void Swarm::visitOwnState(StateVisitor& v) {
  std::uint64_t steps = 0;
  v.clock(m_time, steps);
  sim::finiteValue(v, "model.aspect", m_aspect);
  if (v.loading() && !(m_aspect > 0))
    v.fail("entry 'model.aspect' = " + std::to_string(m_aspect) + " is not a width/height ratio");
  bool mouse = m_mouse.has_value();
  glm::dvec2 at = m_mouse.value_or(glm::dvec2(0.0));
  v.flag("model.mouse_held", mouse);
  sim::finiteValue(v, "model.mouse", at);
  m_mouse = mouse ? std::optional<glm::dvec2>(at) : std::nullopt;
  v.array("model.extra_attractors", m_extra, SWARM_MAX_ATTRACTORS);
  for (const Attractor& a : m_extra) {
    sim::requireFinite(v, "model.extra_attractors", &a.pos[0], 2);
    sim::requireFinite(v, "model.extra_attractors", &a.strength, 1);
  }
  sim::finiteValue(v, "model.last_dt", m_lastDt);
}

void Swarm::resume(const StateStamp& good) {
  m_time = good.time;
  if (m_params.substeps < kMaxSubsteps)
    m_params.substeps *= 2;  // same simulated time per frame, half the step
  else
    m_params.speed *= 0.5f;
}

}  // namespace tidepool::sim
