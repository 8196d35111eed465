#include "gl/gpu_profiler.h"

#include <algorithm>

namespace tidepool::gl {
namespace {
constexpr double kSmoothing = 0.1;  // EMA weight of the newest frame
// Completed frames kept for takeCompleted(): a few, so that a run that never takes them (the
// window, render, soak) holds no history. With 4096 it grew ~5 KiB a frame (one name and time per
// pass, 125 passes a frame at 25 substeps) for 4096 frames (docs/RELIABILITY.md, "Long runs");
// benchmarks take them every frame.
constexpr std::size_t kMaxCompleted = 16;
}  // namespace

GpuProfiler::Scope::~Scope() {
  if (m_profiler) m_profiler->endScope();
}

bool GpuProfiler::ready(const Slot& slot) const {
  if (slot.names.empty()) return true;
  GLint available = 0;
  glGetQueryObjectiv(slot.queries[slot.names.size() - 1].id(), GL_QUERY_RESULT_AVAILABLE, &available);
  return available != 0;
}

void GpuProfiler::harvest(Slot& slot) {
  FrameTimes frame;
  for (std::size_t i = 0; i < slot.names.size(); ++i) {
    GLuint64 ns = 0;
    glGetQueryObjectui64v(slot.queries[i].id(), GL_QUERY_RESULT, &ns);
    const double ms = double(ns) * 1e-6;
    frame.passes.emplace_back(slot.names[i], ms);
  }
  // Passes issued several times in a frame are summed.
  std::vector<Pass> next;
  for (const auto& [name, ms] : frame.passes) {
    // An init-capture: clang 14 (the fuzz build) cannot capture a structured binding implicitly.
    auto it = std::find_if(next.begin(), next.end(), [&n = name](const Pass& p) { return p.name == n; });
    if (it == next.end())
      next.push_back({name, ms, ms});
    else
      it->ms += ms;
  }
  for (Pass& p : next) {
    auto old = std::find_if(m_passes.begin(), m_passes.end(), [&](const Pass& q) { return q.name == p.name; });
    p.smoothedMs = old == m_passes.end() ? p.ms : old->smoothedMs + kSmoothing * (p.ms - old->smoothedMs);
  }
  m_passes = std::move(next);
  m_completed.push_back(std::move(frame));
  if (m_completed.size() > kMaxCompleted) m_completed.pop_front();
  slot.pending = false;
}

void GpuProfiler::beginFrame() {
  if (!m_enabled) return;
  if (m_inFrame) throw GlError("GpuProfiler::beginFrame called twice without endFrame");
  m_current = (m_current + 1) % int(m_slots.size());
  // Oldest first: the slot about to be reused (three frames old), then the two younger ones.
  for (std::size_t k = 0; k < m_slots.size(); ++k) {
    Slot& s = m_slots[(m_current + k) % m_slots.size()];
    if (!s.pending) continue;
    if (ready(s))
      harvest(s);
    else if (k == 0)
      ++m_dropped;  // never wait: this frame's times are lost
    else
      break;  // younger frames finish later; keep order
  }
  Slot& slot = m_slots[m_current];
  slot.names.clear();
  slot.pending = false;
  m_inFrame = true;
}

GpuProfiler::Scope GpuProfiler::scope(std::string_view name) {
  if (!m_enabled || !m_inFrame) return Scope(nullptr);
  if (m_inScope)
    throw GlError("profiler scope '" + std::string(name) + "' opened inside another: GL timer queries cannot nest");
  Slot& slot = m_slots[m_current];
  if (slot.queries.size() <= slot.names.size()) slot.queries.push_back(Query::create());
  slot.names.emplace_back(name);
  glBeginQuery(GL_TIME_ELAPSED, slot.queries[slot.names.size() - 1].id());
  m_inScope = true;
  return Scope(this);
}

void GpuProfiler::endScope() {
  glEndQuery(GL_TIME_ELAPSED);
  m_inScope = false;
}

void GpuProfiler::endFrame() {
  if (!m_enabled || !m_inFrame) return;
  m_slots[m_current].pending = !m_slots[m_current].names.empty();
  m_inFrame = false;
}

void GpuProfiler::finish() {
  for (std::size_t k = 1; k <= m_slots.size(); ++k) {
    Slot& s = m_slots[(m_current + k) % m_slots.size()];
    if (s.pending) harvest(s);  // GL_QUERY_RESULT waits
  }
}

double GpuProfiler::totalMs() const {
  double t = 0;
  for (const Pass& p : m_passes) t += p.ms;
  return t;
}

double GpuProfiler::totalSmoothedMs() const {
  double t = 0;
  for (const Pass& p : m_passes) t += p.smoothedMs;
  return t;
}

std::vector<GpuProfiler::FrameTimes> GpuProfiler::takeCompleted() {
  std::vector<FrameTimes> out(m_completed.begin(), m_completed.end());
  m_completed.clear();
  return out;
}

}  // namespace tidepool::gl
