#include "gl/dispatch_gate.h"

#include <string>

#include "base/error.h"

namespace tidepool::gl {
namespace {
thread_local DispatchGate* t_active = nullptr;
}  // namespace

void DispatchGate::dispatch(glm::uvec3 groups) {
  if (t_active)
    t_active->onDispatch(groups);
  else if (groups.x && groups.y && groups.z)
    glDispatchCompute(groups.x, groups.y, groups.z);
}

void DispatchGate::onDispatch(glm::uvec3 groups) {
  const std::size_t k = m_seen.size();
  m_seen.push_back(groups);
  if (m_mode != Mode::Replay) {
    if (m_mode == Mode::Record && groups.x && groups.y && groups.z) glDispatchCompute(groups.x, groups.y, groups.z);
    return;
  }
  if (k >= m_template.size() || m_template[k] != groups)
    throw Error("dispatch gate: replayed dispatch " + std::to_string(k) + " differs from the recorded section");
  glDispatchComputeIndirect(GLintptr(k * 3 * sizeof(GLuint)));
}

void DispatchGate::run(Mode mode, const std::function<void()>& section) {
  if (t_active) throw Error("dispatch gate: sections do not nest");
  m_mode = mode;
  m_seen.clear();
  if (mode == Mode::Replay) {
    glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, m_args.id());
    glMemoryBarrier(GL_COMMAND_BARRIER_BIT);  // the deciding kernel's arguments
  }
  t_active = this;
  try {
    section();
  } catch (...) {
    t_active = nullptr;
    if (mode == Mode::Replay) glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, 0);
    throw;
  }
  t_active = nullptr;
  if (mode == Mode::Replay) {
    glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, 0);
    if (m_seen.size() != m_template.size())
      throw Error("dispatch gate: replayed " + std::to_string(m_seen.size()) + " dispatches, recorded " +
                  std::to_string(m_template.size()));
  }
}

void DispatchGate::record(const std::function<void()>& section) {
  run(Mode::Record, section);
  keep();
}

void DispatchGate::note(const std::function<void()>& section) {
  run(Mode::Note, section);
  keep();
}

void DispatchGate::keep() {
  m_template = m_seen;
  std::vector<glm::uvec4> groups;
  for (const glm::uvec3& g : m_template) groups.emplace_back(g, 0u);
  const std::size_t bytes = std::max<std::size_t>(groups.size(), 1) * sizeof(glm::uvec4);
  if (m_groups.size() < bytes) m_groups = Buffer(bytes);
  if (!groups.empty()) m_groups.upload(groups.data(), groups.size() * sizeof(glm::uvec4));
  const std::size_t argBytes = std::max<std::size_t>(m_template.size(), 1) * 3 * sizeof(GLuint);
  if (m_args.size() < argBytes) m_args = Buffer(argBytes);
}

void DispatchGate::replay(const std::function<void()>& section) {
  if (!recorded()) throw Error("dispatch gate: replay before record");
  run(Mode::Replay, section);
}

}  // namespace tidepool::gl
