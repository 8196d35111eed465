#include "sim/ripples/ripples.h"

#include <cmath>
#include <cstdio>
#include <cstring>

#include <limits>
#include <sstream>

#include "base/log.h"
#include "ripples/bindings.glsl"
#include "sim/state_checks.h"

namespace tidepool::ripples {
namespace {
std::string fmt(const char* format, double a, double b = 0) {
  char buf[512];
  std::snprintf(buf, sizeof buf, format, a, b);
  return buf;
}

struct BodyUniforms {
  glm::ivec2 size{0};      // cells in x and y
  glm::vec3 before{0.0f};  // sphere centre at the start of the step, m
  glm::vec3 now{0.0f};     // and at its end
  float radius = 0.0f;     // m
  float cellSize = 0.0f;   // m
  float coupling = 0.0f;   // fraction of the displaced column moved per step
  static constexpr auto fields() {
    using U = BodyUniforms;
    return std::tuple{gl::field("uSize", &U::size),         gl::field("uBefore", &U::before),
                      gl::field("uNow", &U::now),           gl::field("uRadius", &U::radius),
                      gl::field("uCellSize", &U::cellSize), gl::field("uCoupling", &U::coupling)};
  }
};
struct StepUniforms {  // see ripples/step.comp
  glm::ivec2 size{0};
  float dt = 0.0f, waveFactor = 0.0f, velDecay = 1.0f, posSmoothing = 0.0f, elasticity = 0.0f;
  GLint spongeCells = 0;
  float spongeDecay = 1.0f;
  static constexpr auto fields() {
    using U = StepUniforms;
    return std::tuple{gl::field("uSize", &U::size),
                      gl::field("uDt", &U::dt),
                      gl::field("uWaveFactor", &U::waveFactor),
                      gl::field("uVelDecay", &U::velDecay),
                      gl::field("uPosSmoothing", &U::posSmoothing),
                      gl::field("uElasticity", &U::elasticity),
                      gl::field("uSpongeCells", &U::spongeCells),
                      gl::field("uSpongeDecay", &U::spongeDecay)};
  }
};
struct TouchUniforms {
  glm::ivec2 size{0};
  glm::vec2 centre{0.0f};  // cells
  float radius = 0.0f;     // cells
  float depth = 0.0f;      // m (negative pushes the surface down)
  static constexpr auto fields() {
    using U = TouchUniforms;
    return std::tuple{gl::field("uSize", &U::size), gl::field("uCentre", &U::centre), gl::field("uRadius", &U::radius),
                      gl::field("uDepth", &U::depth)};
  }
};
}  // namespace

Ripples::Ripples(gl::ShaderLibrary& shaders, const Params& params)
    : Model(shaders, "ripples", std::numeric_limits<std::size_t>::max()), m_shaders(shaders), m_params(params) {
  allocate();
}

void Ripples::allocate() {
  const std::size_t bytes = std::size_t(m_params.width) * m_params.height * 2 * sizeof(float);
  GLint64 maxBlock = 0;
  glGetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &maxBlock);
  if (bytes > std::size_t(maxBlock))
    throw Error("ripples: a " + std::to_string(m_params.width) + "x" + std::to_string(m_params.height) +
                " grid needs " + std::to_string(bytes >> 20) + " MiB per state buffer, more than this GPU's " +
                std::to_string(maxBlock >> 20) + " MiB storage-buffer limit");
  for (gl::Buffer& b : m_state) b = gl::Buffer(bytes);
  m_width = m_params.width;
  m_height = m_params.height;
  reset();
}

void Ripples::reset() {
  for (gl::Buffer& b : m_state) b.fillZero();
  m_current = 0;
  m_time = 0;
  restartWatch();
}

glm::uvec3 Ripples::cellGroups() const {
  return {GLuint((m_width + RIPPLES_TILE - 1) / RIPPLES_TILE), GLuint((m_height + RIPPLES_TILE - 1) / RIPPLES_TILE), 1};
}

void Ripples::pushBody(double dt) {
  const gl::Kernel<BodyUniforms> body(m_shaders, "ripples/body.comp", {RIPPLES_STATE_OUT});
  m_state[m_current].bindBase(GL_SHADER_STORAGE_BUFFER, RIPPLES_STATE_OUT);
  dispatchCells(body, {.size = {m_width, m_height},
                       .before = ripples::sphereCentre(m_params, m_time),
                       .now = ripples::sphereCentre(m_params, m_time + dt),
                       .radius = m_params.sphereRadius,
                       .cellSize = m_params.cellSize,
                       .coupling = m_params.sphereCoupling});
}

void Ripples::stepOnce(double dt) {
  if (m_params.width != m_width || m_params.height != m_height) allocate();
  if (m_params.sphere) pushBody(dt);
  const Params& q = m_params;
  StepUniforms u{.size = {m_width, m_height},
                 .spongeCells = q.boundary == Boundary::Absorbing ? q.spongeCells : 0,
                 .spongeDecay = float(std::exp(-q.spongeDamping * dt))};
  if (q.rule == Rule::Seed) {
    u.dt = float(q.seedTimeScale * dt);
    u.waveFactor = q.seedPropagation;
    u.elasticity = q.seedElasticity;
    u.velDecay = q.seedFriction;
  } else {
    u.dt = float(dt);
    u.waveFactor = float(double(q.waveSpeed) * q.waveSpeed * dt / (double(q.cellSize) * q.cellSize));
    u.velDecay = float(std::max(0.0, 1.0 - q.velDamping * dt));
    u.posSmoothing = float(std::min(q.posDamping * dt, 1.0));
    m_lastCourant = courant(q, dt);
  }
  std::vector<gl::ShaderDefine> defines = {{q.rule == Rule::Seed ? "RULE_SEED" : "RULE_WAVE", ""}};
  if (q.boundary == Boundary::Periodic) defines.push_back({"BOUNDARY_PERIODIC", ""});
  const gl::Kernel<StepUniforms> pass(m_shaders, "ripples/step.comp", {RIPPLES_STATE_IN, RIPPLES_STATE_OUT}, defines);
  m_state[m_current].bindBase(GL_SHADER_STORAGE_BUFFER, RIPPLES_STATE_IN);
  m_state[1 - m_current].bindBase(GL_SHADER_STORAGE_BUFFER, RIPPLES_STATE_OUT);
  dispatchCells(pass, u);
  m_current = 1 - m_current;
  m_time += dt;
  m_lastDt = dt;
}

void Ripples::step(gl::GpuProfiler& profiler) {
  const double frameSeconds = m_params.frameSeconds;
  if (m_params.width != m_width || m_params.height != m_height) allocate();
  if (m_params.rainRate > 0) {
    m_rainDebt += m_params.rainRate * frameSeconds;
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    for (; m_rainDebt >= 1.0; m_rainDebt -= 1.0)
      touch(u(m_rng), u(m_rng), m_params.touchRadius * 0.5f, m_params.touchDepth * 0.5f);
  }
  const int substeps = substepsFor(m_params);
  const bool wasStable = m_lastCourant <= kCourantLimit2D;
  {
    auto scope = profiler.scope("ripples.step");
    for (int i = 0; i < substeps; ++i) stepOnce(frameSeconds / substeps);
  }
  m_lastSubsteps = substeps;
  watch();
  if (m_params.rule == Rule::Wave && wasStable && m_lastCourant > kCourantLimit2D)
    log::warn(fmt(
        "ripples: Courant number C = %.3f exceeds the 2D stability limit 1/sqrt(2) = %.3f: the surface will blow up "
        "(more substeps, a smaller wave speed or larger cells)",
        m_lastCourant, kCourantLimit2D));
}

double Ripples::heightBound() const {
  // Heights beyond half the pool's width are no water surface any more.
  return m_params.rule == Rule::Seed ? 1e4 : 0.5 * m_width * double(m_params.cellSize);
}

std::vector<sim::StateBuffer> Ripples::stateBuffers() {
  return {{"state", &m_state[m_current], m_state[m_current].size()}};
}

void Ripples::checkHealth(const gl::Window& w) {
  const gl::Kernel<sim::HealthUniforms> health(m_shaders, "ripples/health.comp", {HEALTH_BINDING, RIPPLES_STATE_IN});
  m_state[m_current].bindBase(GL_SHADER_STORAGE_BUFFER, RIPPLES_STATE_IN);
  health.dispatchThreads(w.count, sim::HealthUniforms(w));
}

std::optional<std::string> Ripples::unhealthy(const sim::DivergenceWatch::Words& w) {
  m_lastMaxHeight = sim::DivergenceWatch::largest(w);
  if (auto what = sim::DivergenceWatch::nonFinite(w, "cells")) return what;
  if (!(m_lastMaxHeight <= heightBound())) return fmt("max |h| = %.3g exceeds %.3g", m_lastMaxHeight, heightBound());
  return std::nullopt;
}

std::string Ripples::method() const {
  const Params& q = m_params;
  if (q.rule == Rule::Seed) return fmt("seed rule, dt = %.4g seed units", q.seedTimeScale * m_lastDt);
  return fmt("wave rule, dt = %.4g s", m_lastDt) + fmt(", C = %.3f", m_lastCourant) +
         (m_lastCourant > kCourantLimit2D ? fmt(" above the limit 1/sqrt(2) = %.3f", kCourantLimit2D) : "");
}

void Ripples::resume(const sim::StateStamp& good) {
  m_time = good.time;
  if (m_params.autoSubsteps && m_params.rule == Rule::Wave)
    m_params.courantTarget *= 0.5f;
  else
    m_params.substeps = std::min(m_params.substeps * 2, 256);
}

void Ripples::visitOwnState(sim::StateVisitor& v) {
  if (v.loading() && (m_params.width != m_width || m_params.height != m_height)) allocate();
  std::uint64_t steps = 0;
  v.clock(m_time, steps);
  sim::finiteValue(v, "model.rain_debt", m_rainDebt);
  if (v.loading() && !(m_rainDebt >= 0 && m_rainDebt < 1))  // the drops still owed: a step leaves less than one
    v.fail("entry 'model.rain_debt' = " + std::to_string(m_rainDebt) + " is not in [0, 1)");
  std::ostringstream rng;
  rng << m_rng;
  std::string text = rng.str();
  v.text("model.rng", text, 1 << 16);
  if (v.loading()) {
    std::istringstream in(text);
    in >> m_rng;
    if (in.fail()) v.fail("entry 'model.rng' is not the state of a Mersenne Twister");
  }
  sim::finiteValue(v, "model.last_dt", m_lastDt);
  v.value("model.last_substeps", m_lastSubsteps);
  sim::finiteValue(v, "model.last_courant", m_lastCourant);
  sim::finiteValue(v, "model.last_max_height", m_lastMaxHeight);
}

void Ripples::touch(float x, float y, float radius, float depth) {
  const gl::Kernel<TouchUniforms> kernel(m_shaders, "ripples/touch.comp", {RIPPLES_STATE_OUT});
  m_state[m_current].bindBase(GL_SHADER_STORAGE_BUFFER, RIPPLES_STATE_OUT);
  dispatchCells(kernel,
                {{m_width, m_height}, glm::vec2(x * m_width, y * m_height), std::max(radius * m_width, 0.5f), depth});
}

void Ripples::upload(const std::vector<float>& hv) {
  if (hv.size() != std::size_t(m_width) * m_height * 2)
    throw Error("ripples: upload of " + std::to_string(hv.size()) + " floats does not match the grid");
  m_state[m_current].upload(hv.data(), hv.size() * sizeof(float));
}

std::vector<float> Ripples::download() const { return m_state[m_current].readAll<float>(); }

std::string Ripples::status() const {
  std::string s = std::to_string(m_width) + "x" + std::to_string(m_height) + " cells, " +
                  std::to_string(m_lastSubsteps) + " substeps";
  if (m_params.rule == Rule::Wave) {
    s += fmt(", C = %.3f (limit %.3f)", m_lastCourant, kCourantLimit2D);
    if (m_lastCourant > kCourantLimit2D) s += "  UNSTABLE: C above 1/sqrt(2)";
  }
  return s;
}

}  // namespace tidepool::ripples
