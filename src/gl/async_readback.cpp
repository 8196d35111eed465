#include "gl/async_readback.h"

namespace tidepool::gl {

AsyncReadback::~AsyncReadback() { dropFence(); }

void AsyncReadback::dropFence() {
  if (m_fence) glDeleteSync(m_fence);
  m_fence = nullptr;
}

void AsyncReadback::request(const Buffer& src, std::size_t bytes, std::size_t offset) {
  const Range range{&src, bytes, offset};
  request(std::span<const Range>(&range, 1));
}

void AsyncReadback::request(std::span<const Range> ranges) {
  std::size_t bytes = 0;
  for (const Range& r : ranges) bytes += r.bytes;
  if (m_staging.size() < bytes) m_staging = Buffer(bytes, nullptr, GL_STREAM_READ);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);  // shader writes to the sources are visible to the copy
  std::size_t at = 0;
  for (const Range& r : ranges) {
    if (r.bytes > 0) r.buffer->copyTo(m_staging, r.bytes, r.offset, at);
    at += r.bytes;
  }
  dropFence();
  m_fence = glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
  glFlush();  // the fence must reach the GPU, or polling it would never see it pass
  m_bytes = bytes;
}

bool AsyncReadback::poll(std::vector<std::byte>& out) {
  if (!m_fence) return false;
  const GLenum state = glClientWaitSync(m_fence, 0, 0);
  if (state != GL_ALREADY_SIGNALED && state != GL_CONDITION_SATISFIED) return false;
  dropFence();
  out.resize(m_bytes);
  m_staging.download(out.data(), m_bytes);  // complete: no stall
  return true;
}

void AsyncReadback::wait(std::vector<std::byte>& out) {
  if (!m_fence) return;
  glClientWaitSync(m_fence, GL_SYNC_FLUSH_COMMANDS_BIT, GLuint64(10'000'000'000));
  poll(out);
}

}  // namespace tidepool::gl
