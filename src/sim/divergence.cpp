#include "sim/divergence.h"

#include <cmath>
#include <cstdio>
#include <cstring>
#include <utility>

#include "sim/state_checks.h"

namespace tidepool {

DivergenceReport divergenceReport(const std::string& model, double time, const std::string& what,
                                  const std::string& method, bool hasGood) {
  char at[32];
  std::snprintf(at, sizeof at, "%.4f", time);
  return {
      model + " diverged by t = " + at + " s: " + what + " (" + method + ")" +
          (hasGood ? "; halve the time step and resume from the last good state" : "; halve the time step and reset"),
      time};
}

namespace sim {
namespace {
static_assert(std::tuple_size_v<DivergenceWatch::Words> == HEALTH_WORDS, "the words of common/health_layout.glsl");

// Frames from a check's start to its verdict (waiting for the read-back if it is late).
constexpr int kVerdictLag = 2;

DivergenceWatch::Words words(const std::vector<std::byte>& bytes) {
  DivergenceWatch::Words w{};
  std::memcpy(w.data(), bytes.data(), std::min(bytes.size(), sizeof w));
  return w;
}
}  // namespace

std::optional<std::string> DivergenceWatch::nonFinite(const Words& w, const char* elements) {
  if (w[HEALTH_NON_FINITE] == 0) return std::nullopt;
  return std::to_string(w[HEALTH_NON_FINITE]) + " " + elements + " are NaN or infinite";
}

float DivergenceWatch::largest(const Words& w) {
  float value = 0;  // the word holds the float's bits
  std::memcpy(&value, &w[HEALTH_MAX_BITS], sizeof value);
  return value;
}

std::uint32_t DivergenceWatch::flagged(const Words& w) { return w[HEALTH_FLAGGED]; }

std::optional<std::string> DivergenceWatch::particles(const Words& w, const char* many, const char* one,
                                                      const char* limit, double bound) {
  if (auto what = nonFinite(w, many)) return what;
  if (flagged(w) > 0) return std::to_string(flagged(w)) + " " + many + " left the domain";
  const float maxSpeed = largest(w);
  if (maxSpeed <= bound) return std::nullopt;
  char what[200];
  std::snprintf(what, sizeof what, "a %s moves at %.3g m/s, more than %s (%.3g m/s)", one, maxSpeed, limit, bound);
  return what;
}

DivergenceWatch::DivergenceWatch(gl::ShaderLibrary& shaders, std::string model, std::size_t maxCopied, int interval)
    : m_ops(shaders),
      m_model(std::move(model)),
      m_maxCopied(maxCopied),
      m_interval(interval),
      m_health(HEALTH_WORDS * sizeof(std::uint32_t)) {}

void DivergenceWatch::frame(Subject& s) {
  const StateStamp now = s.stamp();
  const bool allowed = !m_report && now.count > 0;  // as the frame's steps left it, before any verdict
  // The verdict lands kVerdictLag frames after its check, never when the driver happens to be done:
  // the good copy, and so a checkpoint, is the same on every GPU and in every run.
  ++m_frames;  // since the last check started
  ++m_pending.frames;
  ++m_good.frames;
  if (m_readback.pending() && m_frames >= kVerdictLag) flush(s);
  if (m_frames < m_interval || !allowed || m_readback.pending()) return;
  m_frames = 0;
  start(s, now);
}

void DivergenceWatch::reduce(Subject& s, std::size_t count, gl::Buffer& words) {
  words.fillZero();
  words.bindBase(GL_SHADER_STORAGE_BUFFER, HEALTH_BINDING);
  for (const gl::Window& w : s.healthWindows(count)) s.checkHealth(w);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
}

std::optional<std::string> DivergenceWatch::checkNow(Subject& s) {
  const StateStamp now = s.stamp();
  if (now.count == 0) return std::nullopt;
  if (!m_healthNow) m_healthNow = gl::Buffer(HEALTH_WORDS * sizeof(std::uint32_t));
  reduce(s, now.count, m_healthNow);
  Words w{};
  m_healthNow.download(w.data(), sizeof w);
  return s.unhealthy(w);
}

void DivergenceWatch::visitState(StateVisitor& v, Subject& s) {
  int frames = m_frames;
  v.value("watch.frames", frames);
  if (frames < 0) v.fail("entry 'watch.frames' = " + std::to_string(frames) + " is not a frame count");
  std::string report = m_report ? m_report->message : "";
  double reportTime = m_report ? m_report->time : 0.0;
  v.text("watch.report", report, 4096);
  sim::finiteValue(v, "watch.report_time", reportTime);
  // The last good copy, so that a resumed run can recover before its first healthy check.
  const std::vector<StateBuffer> state = s.stateBuffers();
  bool hasGood = m_hasGood && m_good.buffers.size() == state.size();
  v.flag("watch.has_good", hasGood);
  Copy good;
  if (hasGood) {
    Copy& copy = v.loading() ? good : m_good;
    copy.kept = true;
    copy.buffers.resize(state.size());
    copy.bytes.resize(state.size());
    v.value("watch.good.time", copy.stamp.time);
    if (!(copy.stamp.time >= 0) || !std::isfinite(copy.stamp.time))
      v.fail("entry 'watch.good.time' = " + std::to_string(copy.stamp.time) + " is not a time");
    v.count("watch.good.count", copy.stamp.count, m_maxCopied);
    v.value("watch.good.steps", copy.stamp.steps);
    if (v.has("watch.good.frames")) v.value("watch.good.frames", copy.frames);
    const StateStamp now = s.stamp();
    if (v.loading() && copy.stamp.time > now.time)
      v.fail("entry 'watch.good.time' = " + std::to_string(copy.stamp.time) + " is after the state's time " +
             std::to_string(now.time));
    for (std::size_t k = 0; k < state.size(); ++k) {
      const std::string name = std::string("watch.good.") + state[k].name;
      v.count((name + ".bytes").c_str(), copy.bytes[k], state[k].buffer->size());
      // The copy's count must be what its buffers hold, at the live state's bytes per element:
      // recovery resumes the model at that count over those bytes.
      if (v.loading() && (now.count == 0 ? copy.stamp.count != 0 || copy.bytes[k] != 0
                                         : copy.bytes[k] * now.count != copy.stamp.count * state[k].bytes))
        v.fail("entry 'watch.good.count' = " + std::to_string(copy.stamp.count) + " does not match '" + name + "' of " +
               std::to_string(copy.bytes[k]) + " bytes");
      if (v.loading() && copy.bytes[k] > 0) copy.buffers[k] = gl::Buffer(copy.bytes[k]);
      v.buffer(name.c_str(), copy.buffers[k], copy.bytes[k]);
    }
  }
  if (!v.loading()) return;
  restart();
  m_frames = frames;
  if (!report.empty()) m_report = DivergenceReport{report, reportTime};
  if (hasGood) {
    m_good = std::move(good);
    m_hasGood = true;
  }
}

void DivergenceWatch::start(Subject& s, const StateStamp& now) {
  reduce(s, now.count, m_health);
  // The state this check judges, copied now: the buffers grow to the largest state seen.
  m_pending.stamp = now;
  m_pending.frames = 0;
  m_pending.kept = now.count <= m_maxCopied;
  if (m_pending.kept) {
    const std::vector<StateBuffer> state = s.stateBuffers();
    m_pending.buffers.resize(state.size());
    m_pending.bytes.resize(state.size());
    for (std::size_t k = 0; k < state.size(); ++k) {
      gl::Buffer& copy = m_pending.buffers[k];
      if (copy.size() < state[k].bytes) copy = gl::Buffer(state[k].bytes);
      m_ops.copy(*state[k].buffer, copy, state[k].bytes);
      m_pending.bytes[k] = state[k].bytes;
    }
  }
  m_readback.request(m_health, m_health.size());
}

void DivergenceWatch::judge(Subject& s, const Words& w) {
  const std::optional<std::string> what = s.unhealthy(w);
  if (!what) {
    std::swap(m_pending, m_good);
    m_hasGood = m_good.kept;
    return;
  }
  m_report = divergenceReport(m_model, m_pending.stamp.time, *what, s.method(), m_hasGood);
}

void DivergenceWatch::flush(Subject& s) {
  if (!m_readback.pending()) return;
  std::vector<std::byte> bytes;
  m_readback.wait(bytes);
  judge(s, words(bytes));
}

std::optional<std::uint64_t> DivergenceWatch::recover(Subject& s) {
  if (!m_report || !m_hasGood) return std::nullopt;
  const std::vector<StateBuffer> state = s.stateBuffers();
  if (state.size() != m_good.buffers.size()) return std::nullopt;
  for (std::size_t k = 0; k < state.size(); ++k)
    if (m_good.bytes[k] > state[k].buffer->size()) return std::nullopt;  // the state was rebuilt smaller since
  for (std::size_t k = 0; k < m_good.buffers.size(); ++k)
    m_ops.copy(m_good.buffers[k], *state[k].buffer, m_good.bytes[k]);
  s.resume(m_good.stamp);
  m_report.reset();
  dropCheck();
  return std::exchange(m_good.frames, 0);
}

void DivergenceWatch::restart() {
  m_hasGood = false;
  m_report.reset();
  dropCheck();
  m_pending = Copy();  // the copies are made again, at the new state's size
  m_good = Copy();
}

void DivergenceWatch::dropCheck() {
  m_frames = 0;
  std::vector<std::byte> discard;
  m_readback.wait(discard);  // a check of the old state must not judge the new one
}

}  // namespace sim
}  // namespace tidepool
