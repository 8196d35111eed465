#include "gl/frame_pacer.h"

#include <algorithm>

namespace tidepool::gl {
namespace {
constexpr GLuint64 kWaitNs = 100'000'000;  // per wait call; a lost context would spin, not hang
}

FramePacer::FramePacer(int maxInFlight) : m_max(std::clamp(maxInFlight, 1, 8)) {}

FramePacer::~FramePacer() {
  for (GLsync f : m_fences) glDeleteSync(f);
}

void FramePacer::retireSignalled() {
  while (!m_fences.empty()) {
    const GLenum state = glClientWaitSync(m_fences.front(), 0, 0);
    if (state != GL_ALREADY_SIGNALED && state != GL_CONDITION_SATISFIED) return;
    glDeleteSync(m_fences.front());
    m_fences.pop_front();
  }
}

void FramePacer::waitForSlot() {
  retireSignalled();
  if (int(m_fences.size()) >= m_max) ++m_waits;
  while (int(m_fences.size()) >= m_max) {
    // The fence's commands were flushed when it was made, so waiting cannot deadlock.
    const GLenum state = glClientWaitSync(m_fences.front(), 0, kWaitNs);
    if (state == GL_WAIT_FAILED || state == GL_ALREADY_SIGNALED || state == GL_CONDITION_SATISFIED) {
      glDeleteSync(m_fences.front());
      m_fences.pop_front();
    }
  }
}

void FramePacer::frameSubmitted() {
  if (int(m_fences.size()) >= m_max) waitForSlot();  // a caller that skipped waitForSlot() stays bounded
  m_fences.push_back(glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0));
  glFlush();  // the fence reaches the GPU: a later wait on it returns
}

}  // namespace tidepool::gl
