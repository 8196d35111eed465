#include "sim/ripples/ripples.h"

#include <cmath>
#include <cstdio>
#include <cstring>

#include "base/log.h"
#include "ripples/bindings.glsl"

namespace tidepool::ripples {
namespace {
constexpr int kTile = 16;  // work-group edge of step.comp and touch.comp

std::string fmt(const char* format, double a, double b = 0) {
  char buf[512];
  std::snprintf(buf, sizeof buf, format, a, b);
  return buf;
}
}  // namespace

Ripples::Ripples(gl::ShaderLibrary& shaders, const Params& params)
    : m_shaders(shaders), m_ops(shaders), m_params(params) {
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
  m_pending = gl::Buffer(bytes);
  m_good = gl::Buffer(bytes);
  m_health = gl::Buffer(4 * sizeof(GLuint));
  m_width = m_params.width;
  m_height = m_params.height;
  reset();
}

void Ripples::reset() {
  for (gl::Buffer& b : m_state) b.fillZero();
  m_current = 0;
  m_time = 0;
  m_hasGood = false;
  m_divergence.reset();
  m_checks.restart();
}

gl::Program& Ripples::stepProgram() {
  std::vector<gl::ShaderDefine> defines = {{m_params.rule == Rule::Seed ? "RULE_SEED" : "RULE_WAVE", ""}};
  if (m_params.boundary == Boundary::Periodic) defines.push_back({"BOUNDARY_PERIODIC", ""});
  return m_shaders.program({"ripples/step.comp"}, defines);
}

void Ripples::pushBody(double dt) {
  gl::Program& p = m_shaders.program({"ripples/body.comp"});
  p.use();
  p.set("uSize", glm::ivec2(m_width, m_height));
  p.set("uBefore", ripples::sphereCentre(m_params, m_time));
  p.set("uNow", ripples::sphereCentre(m_params, m_time + dt));
  p.set("uRadius", m_params.sphereRadius);
  p.set("uCellSize", m_params.cellSize);
  p.set("uCoupling", m_params.sphereCoupling);
  m_state[m_current].bindBase(GL_SHADER_STORAGE_BUFFER, RIPPLES_STATE_OUT);
  glDispatchCompute(GLuint((m_width + kTile - 1) / kTile), GLuint((m_height + kTile - 1) / kTile), 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
}

void Ripples::stepOnce(double dt) {
  if (m_params.width != m_width || m_params.height != m_height) allocate();
  if (m_params.sphere) pushBody(dt);
  gl::Program& p = stepProgram();
  const Params& q = m_params;
  p.use();
  p.set("uSize", glm::ivec2(m_width, m_height));
  if (q.rule == Rule::Seed) {
    const double seedDt = q.seedTimeScale * dt;
    p.set("uDt", float(seedDt));
    p.set("uWaveFactor", q.seedPropagation);
    p.set("uElasticity", q.seedElasticity);
    p.set("uVelDecay", q.seedFriction);
    p.set("uPosSmoothing", 0.0f);
  } else {
    p.set("uDt", float(dt));
    p.set("uWaveFactor", float(double(q.waveSpeed) * q.waveSpeed * dt / (double(q.cellSize) * q.cellSize)));
    p.set("uVelDecay", float(std::max(0.0, 1.0 - q.velDamping * dt)));
    p.set("uPosSmoothing", float(std::min(q.posDamping * dt, 1.0)));
    p.set("uElasticity", 0.0f);
    m_lastCourant = courant(q, dt);
  }
  const bool sponge = q.boundary == Boundary::Absorbing;
  p.set("uSpongeCells", sponge ? q.spongeCells : 0);
  p.set("uSpongeDecay", float(std::exp(-q.spongeDamping * dt)));
  m_state[m_current].bindBase(GL_SHADER_STORAGE_BUFFER, RIPPLES_STATE_IN);
  m_state[1 - m_current].bindBase(GL_SHADER_STORAGE_BUFFER, RIPPLES_STATE_OUT);
  glDispatchCompute(GLuint((m_width + kTile - 1) / kTile), GLuint((m_height + kTile - 1) / kTile), 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  m_current = 1 - m_current;
  m_time += dt;
  m_lastDt = dt;
}

void Ripples::step(double frameSeconds, gl::GpuProfiler& profiler) {
  if (m_params.width != m_width || m_params.height != m_height) allocate();
  if (m_params.rainRate > 0) {
    m_rainDebt += m_params.rainRate * frameSeconds;
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    for (; m_rainDebt >= 1.0; m_rainDebt -= 1.0)
      touch(u(m_rng), u(m_rng), m_params.touchRadius * 0.5f, m_params.touchDepth * 0.5f);
  }
  const int substeps = substepsFor(m_params, frameSeconds);
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

void Ripples::watch() {
  m_checks.frame(
      m_time, !m_divergence, judgeFn(),
      [this] {
        m_health.fillZero();
        gl::Program& p = m_shaders.program({"ripples/health.comp"});
        p.use();
        p.set("uCells", GLuint(m_width * m_height));
        m_state[m_current].bindBase(GL_SHADER_STORAGE_BUFFER, RIPPLES_STATE_IN);
        m_health.bindBase(GL_SHADER_STORAGE_BUFFER, RIPPLES_HEALTH);
        p.dispatchThreads(std::size_t(m_width) * m_height);
        glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
        m_ops.copy(m_state[m_current], m_pending, m_pending.size());  // the state this check judges
      },
      m_health);
}

CheckCycle::Judge Ripples::judgeFn() {
  return [this](const CheckCycle::Words& v, double time) { judge({time, double(v[2]), double(healthFloat(v[0]))}); };
}

void Ripples::judge(const Health& h) {
  m_lastMaxHeight = h.maxMagnitude;
  if (h.nanCount == 0 && h.maxMagnitude <= heightBound()) {
    std::swap(m_pending, m_good);
    m_goodTime = h.time;
    m_hasGood = true;
    return;
  }
  const Params& q = m_params;
  std::string what = h.nanCount > 0 ? std::to_string(long(h.nanCount)) + " cells are NaN or infinite"
                                    : fmt("max |h| = %.3g exceeds %.3g", h.maxMagnitude, heightBound());
  std::string method = q.rule == Rule::Seed ? fmt("seed rule, dt = %.4g seed units", q.seedTimeScale * m_lastDt)
                                            : fmt("wave rule, dt = %.4g s", m_lastDt);
  if (q.rule == Rule::Wave)
    method += fmt(", C = %.3f", m_lastCourant) +
              (m_lastCourant > kCourantLimit2D ? fmt(" above the limit 1/sqrt(2) = %.3f", kCourantLimit2D) : "");
  m_divergence = DivergenceReport{"ripples diverged by t = " + fmt("%.3f s: ", h.time) + what + " (" + method +
                                      "); halve the time step and resume from the last good state" +
                                      (m_hasGood ? fmt(" (t = %.3f s)", m_goodTime) : ""),
                                  h.time};
}

bool Ripples::recover() {
  if (!m_divergence || !m_hasGood) return false;
  m_ops.copy(m_good, m_state[m_current], m_good.size());
  m_time = m_goodTime;
  if (m_params.autoSubsteps && m_params.rule == Rule::Wave)
    m_params.courantTarget *= 0.5f;
  else
    m_params.substeps = std::min(m_params.substeps * 2, 256);
  m_divergence.reset();
  m_checks.restart();
  return true;
}

void Ripples::flushChecks() { m_checks.flush(judgeFn()); }

void Ripples::touch(float x, float y, float radius, float depth) {
  gl::Program& p = m_shaders.program({"ripples/touch.comp"});
  p.use();
  p.set("uSize", glm::ivec2(m_width, m_height));
  p.set("uCentre", glm::vec2(x * m_width, y * m_height));
  p.set("uRadius", std::max(radius * m_width, 0.5f));
  p.set("uDepth", depth);
  m_state[m_current].bindBase(GL_SHADER_STORAGE_BUFFER, RIPPLES_STATE_OUT);
  glDispatchCompute(GLuint((m_width + kTile - 1) / kTile), GLuint((m_height + kTile - 1) / kTile), 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
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
